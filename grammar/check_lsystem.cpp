// lsystem blocks: settings, axiom, ignore/consider, select, and productions (module names and
// arities, formal parameters, guards, stochastic probabilities). The warnings about productions
// that never apply are in check_flow.cpp.
#include <cmath>
#include <cstdio>

#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

struct SettingSpec {
  std::string_view key;
  std::size_t values;
  bool count;  // a non-negative integer (a count or a seed)
};
constexpr SettingSpec kSettings[] = {
    {"derive", 1, true},   {"seed", 1, true},        {"angle", 1, false},
    {"step", 1, false},    {"width", 1, false},      {"width_decay", 1, false},
    {"tropism", 3, false}, {"elasticity", 1, false}, {"max_depth", 1, true},
};

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// The most arguments a turtle symbol takes when it is not declared (docs/language.md, "Turtle
// conventions"); nullopt for an ordinary module.
std::optional<std::size_t> turtle_max_args(std::string_view name) {
  if (name == "F" || name == "f") return 1;
  if (!is_turtle_symbol(name)) return std::nullopt;
  if (name == "|" || name == "$" || name == "[" || name == "]" || name == "%" || name == "{" ||
      name == "." || name == "}") {
    return 0;
  }
  return 1;
}

class LSystemChecker {
 public:
  LSystemChecker(CheckContext& cx, std::uint32_t file, const ast::LSystem& ls)
      : cx_(cx), file_(file), ls_(ls) {}

  void run() {
    for (const ast::LSystemItem& item : ls_.items) {
      std::visit([&](const auto& i) { this->item(i); }, item);
    }
    rule_keys();
    if (!axiom_) {
      cx_.error(DiagCode::MissingAxiom, ls_.name.span,
                "lsystem '" + ls_.name.name + "' has no axiom");
      cx_.note("add one, e.g. 'axiom F;'");
    }
  }

 private:
  void item(const ast::Setting& s) {
    const SettingSpec* spec = nullptr;
    for (const SettingSpec& k : kSettings) {
      if (k.key == s.key.name) spec = &k;
    }
    if (!spec) {
      cx_.error(DiagCode::UnknownSetting, s.key.span, "unknown setting '" + s.key.name + "'");
      cx_.note(
          "the settings are derive, seed, angle, step, width, width_decay, tropism, "
          "elasticity and max_depth");
      return;
    }
    auto [it, fresh] = settings_.emplace(s.key.name, s.key.span);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, s.key.span,
                "setting '" + s.key.name + "' is given twice");
      cx_.note(it->second, "first given here");
    }
    if (s.values.size() != spec->values) {
      cx_.error(DiagCode::SettingValueCount, s.span,
                "'" + s.key.name + "' takes " + plural(spec->values, "value") + ", found " +
                    std::to_string(s.values.size()));
    }
    std::string where = "the setting '" + s.key.name + "'";
    ExprEnv env;
    env.file = file_;
    env.constant_context = where.c_str();
    for (const ast::Expr& v : s.values) {
      cx_.check_number(v, env, "a setting value");
      if (!spec->count) continue;
      std::optional<double> x = cx_.fold(v, file_);
      if (x && (*x < 0 || *x != std::floor(*x))) {
        cx_.error(DiagCode::InvalidSettingValue, v.span,
                  "'" + s.key.name + "' must be a non-negative integer, found " + number_text(*x));
      }
    }
  }

  void item(const ast::Axiom& a) {
    if (axiom_) {
      cx_.error(DiagCode::DuplicateAxiom, a.span,
                "lsystem '" + ls_.name.name + "' has a second axiom");
      cx_.note(axiom_->span, "the first axiom is here");
    } else {
      axiom_ = &a;
    }
    ExprEnv env;
    env.file = file_;
    module_seq(a.modules, env);
  }

  void item(const ast::SymbolSet& s) {
    for (const ast::Identifier& id : s.symbols) {
      if (module_parts(cx_, file_, id.name).empty()) unknown_module(id.name, id.span);
    }
  }

  void item(const ast::Select& s) {
    if (s.mode.name != "first" && s.mode.name != "nearest") {
      cx_.error(DiagCode::UnknownSelectMode, s.mode.span,
                "unknown selection mode '" + s.mode.name + "'");
      cx_.note("the modes are 'first' (the default) and 'nearest'");
    }
    if (select_) {
      cx_.error(DiagCode::DuplicateDefinition, s.span, "'select' is given twice");
      cx_.note(select_->span, "first given here");
    }
    select_ = &s;
    ExprEnv env;
    env.file = file_;
    env.unknown_names_ok = true;  // the keys name the parameters of every production
    for (const ast::Expr& k : s.keys) cx_.check_number(k, env, "a selection key");
  }

  void item(const ast::Production& p) {
    Formals formals;
    for (const ast::ModulePattern& m : p.left_context) pattern(m, formals, false);
    pattern(p.predecessor, formals, true);
    for (const ast::ModulePattern& m : p.right_context) pattern(m, formals, false);
    ExprEnv env;
    env.file = file_;
    env.formals = &formals;
    if (p.guard && cx_.check_expr(*p.guard, env) == Type::Number) {
      cx_.error(DiagCode::ConditionNotBoolean, p.guard->span,
                "the guard is a number, not a boolean");
      cx_.note("compare it, e.g. 'x > 0'");
    }
    probabilities(p, env, formals);
    for (const ast::Alternative& alt : p.alternatives) module_seq(alt.successor, env);
    if (!p.key.empty()) keyed_.push_back({&p, std::move(formals)});
  }

  // Rule-space keys `@ (k1, ..., kn)` and `select nearest(e1, ..., en)` (docs/language.md,
  // "Rule-space selection"): checked once the whole block is known, since `select` may follow
  // the productions it governs.
  void rule_keys() {
    const bool nearest = select_ && select_->mode.name == "nearest";
    if (nearest && select_->keys.empty()) {
      cx_.error(DiagCode::RuleKeyCount, select_->span,
                "'select nearest' needs at least one coordinate");
      cx_.note("e.g. 'select nearest(l, w);' over the predecessor's parameters");
    }
    bool query_reported = false;  // report unknown names in the query once, not per production
    for (const auto& [p, formals] : keyed_) {
      SourceSpan span = p->key.front().span;
      span.end = p->key.back().span.end;
      if (!nearest) {
        cx_.error(DiagCode::RuleKeyUnused, span,
                  "this production has a rule-space key but the lsystem does not select nearest");
        cx_.note("add 'select nearest(...)' with one expression per key coordinate");
        continue;
      }
      if (p->kind != ast::ProductionKind::Rewrite) {
        cx_.error(DiagCode::RuleKeyUnused, span,
                  std::string("an ") +
                      (p->kind == ast::ProductionKind::Interpret ? "interpret" : "decompose") +
                      " production takes no rule-space key");
        cx_.note("nearest selection chooses among rewriting productions only");
        continue;
      }
      ExprEnv constant;
      constant.file = file_;
      constant.constant_context = "a rule-space key";
      for (const ast::Expr& k : p->key) cx_.check_number(k, constant, "a rule-space key");
      if (!select_->keys.empty() && p->key.size() != select_->keys.size()) {
        cx_.error(DiagCode::RuleKeyCount, span,
                  "the key has " + plural(p->key.size(), "coordinate") +
                      " but 'select nearest' has " + std::to_string(select_->keys.size()));
        cx_.note(select_->span, "the selection is given here");
      }
      if (query_reported) continue;
      ExprEnv query;
      query.file = file_;
      query.formals = &formals;
      for (const ast::Expr& e : select_->keys) {
        if (cx_.check_expr(e, query) == Type::Error) query_reported = true;
      }
      if (query_reported) cx_.note(p->span, "for this production");
    }
  }

  void probabilities(const ast::Production& p, const ExprEnv& env, const Formals& formals) {
    double sum = 0;
    bool all_known = true, any = false;
    for (const ast::Alternative& alt : p.alternatives) {
      if (!alt.probability) continue;
      any = true;
      cx_.check_number(*alt.probability, env, "a probability");
      std::optional<double> v = cx_.fold(*alt.probability, file_, &formals);
      if (!v) {
        all_known = false;
        continue;
      }
      sum += *v;
      if (*v <= 0 || *v > 1) {
        cx_.error(DiagCode::ProbabilityOutOfRange, alt.probability->span,
                  "probability " + number_text(*v) + " is outside (0, 1]");
        all_known = false;  // one error about these probabilities is enough
      }
    }
    if (any && all_known && std::fabs(sum - 1.0) > 1e-9) {
      SourceSpan span = p.alternatives.front().span;
      span.end = p.alternatives.back().span.end;
      cx_.error(DiagCode::ProbabilitySum, span,
                "the probabilities sum to " + number_text(sum) + ", not 1");
    }
  }

  // A predecessor or context module: its name, arity, and the formal parameters it binds.
  void pattern(const ast::ModulePattern& m, Formals& formals, bool predecessor) {
    for (const ast::Identifier& id : m.params) {
      auto [it, fresh] = formals.emplace(id.name, id.span);
      if (!fresh) {
        cx_.error(DiagCode::DuplicateDefinition, id.span,
                  "parameter '" + id.name + "' is bound twice in this production");
        cx_.note(it->second, "first bound here");
      }
    }
    std::vector<std::string> parts = module_parts(cx_, file_, m.name);
    if (predecessor && parts.size() > 1) {
      cx_.error(DiagCode::PredecessorNotSingle, m.span,
                "predecessor '" + m.name + "' stands for " + plural(parts.size(), "module"));
      cx_.note("a name of several letters is one module per letter; declare it with 'module " +
               m.name + (m.params.empty() ? "" : "(...)") + ";' to make it one module");
      return;
    }
    use_module(m.name, parts, m.span, m.params.size());
  }

  void module_seq(const ast::ModuleSeq& seq, const ExprEnv& env) {
    for (const ast::ModuleCall& call : seq) {
      use_module(call.name, module_parts(cx_, file_, call.name), call.span, call.args.size());
      for (const ast::Expr& a : call.args) cx_.check_number(a, env, "a module argument");
    }
  }

  void unknown_module(const std::string& name, SourceSpan span) {
    cx_.error(DiagCode::UnknownModule, span, "unknown module '" + name + "'");
    cx_.note("a module name with digits or underscores must be declared, e.g. 'module " + name +
             "(x);'");
  }

  // `parts` from module_parts(name); arguments attach to the last part.
  void use_module(const std::string& name, const std::vector<std::string>& parts, SourceSpan span,
                  std::size_t args) {
    if (parts.empty()) return unknown_module(name, span);
    for (std::size_t i = 0; i < parts.size(); ++i) {
      arity(parts[i], i + 1 == parts.size() ? args : 0, span);
    }
  }

  void arity(const std::string& name, std::size_t n, SourceSpan span) {
    if (const ModuleInfo* decl = cx_.find_module(file_, name)) {
      std::size_t want = decl->pattern->params.size();
      if (n == want) return;
      cx_.error(DiagCode::ModuleArityMismatch, span,
                "module '" + name + "' takes " + plural(want, "argument") + ", found " +
                    std::to_string(n));
      cx_.note(decl->pattern->span, "declared here");
      return;
    }
    if (std::optional<std::size_t> max = turtle_max_args(name)) {
      if (n <= *max) return;
      cx_.error(
          DiagCode::ModuleArityMismatch, span,
          "'" + name + "' takes " +
              (*max == 0 ? std::string("no arguments") : "at most " + plural(*max, "argument")) +
              ", found " + std::to_string(n));
      return;
    }
    auto [it, fresh] = arity_.emplace(name, std::make_pair(n, span));
    if (fresh || it->second.first == n) return;
    cx_.error(DiagCode::ModuleArityMismatch, span,
              "module '" + name + "' has " + plural(n, "argument") + " here but " +
                  std::to_string(it->second.first) + " where it is first used");
    cx_.note(it->second.second, "first used here");
  }

  CheckContext& cx_;
  std::uint32_t file_;
  const ast::LSystem& ls_;
  const ast::Axiom* axiom_ = nullptr;
  const ast::Select* select_ = nullptr;
  // Productions with a rule-space key and the formal parameters they bind.
  std::vector<std::pair<const ast::Production*, Formals>> keyed_;
  std::unordered_map<std::string, SourceSpan> settings_;
  // Undeclared modules of this block: arity and place of the first use.
  std::unordered_map<std::string, std::pair<std::size_t, SourceSpan>> arity_;
};

}  // namespace

void check_lsystem(CheckContext& cx, std::uint32_t file, const ast::LSystem& ls) {
  LSystemChecker(cx, file, ls).run();
}

}  // namespace ramus::detail
