#include "compiler/lower.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "compiler/expr_compile.h"
#include "grammar/const_eval.h"
#include "grammar/modules.h"

namespace ramus {

namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

class Lowerer {
 public:
  Lowerer(const Program& p, const SourceManager& sm, const LowerOptions& o, DiagnosticSink& d)
      : prog_(p), sm_(sm), opt_(o), diag_(d) {}

  ir::Grammar run() {
    collect_declared();
    collect_constants();
    const ast::LSystem& ls = find_system();
    g_ = ir::make_grammar(ls.name.name);
    g_.constants = constants_;
    arity_.assign(g_.symbols.size(), -2);
    for (const auto& item : ls.items) {  // `select` may follow the productions it governs
      if (const auto* s = std::get_if<ast::Select>(&item)) select_ = s;
    }
    for (const auto& item : ls.items) lower_item(item);
    finish_symbol_sets();
    if (opt_.seed) g_.settings.seed = *opt_.seed;
    for (std::size_t s = 0; s < g_.symbols.size(); ++s) {
      g_.symbols[s].arity = std::int16_t(arity_[s] < 0 ? -1 : arity_[s]);
    }
    g_.build_tables();
    return std::move(g_);
  }

 private:
  // ---- positions and errors ---------------------------------------------------------------
  std::string where(SourceSpan span) const {
    if (span.file >= sm_.size()) return "<unknown>";
    LineCol lc = sm_.line_col(span.file, span.begin);
    return sm_.name(span.file) + ":" + std::to_string(lc.line) + ":" + std::to_string(lc.column);
  }
  void error(DiagCode code, SourceSpan span, std::string msg) {
    diag_.report(code, span, std::move(msg));
  }

  // ---- declarations at file level ---------------------------------------------------------
  void collect_declared() {
    for (const ast::File& f : prog_.files) {
      for (const ast::Decl& d : f.decls) {
        if (const auto* md = std::get_if<ast::ModuleDecl>(&d)) {
          for (const auto& m : md->modules) declared_.insert(m.name);
        }
      }
    }
  }

  // Imports first (post-order from the root), so a file sees the constants it imports.
  void visit_constants(std::uint32_t file, std::vector<std::uint8_t>& seen) {
    if (file >= prog_.files.size() || seen[file]) return;
    seen[file] = 1;
    if (file < prog_.imports.size()) {
      for (std::uint32_t dep : prog_.imports[file]) visit_constants(dep, seen);
    }
    for (const ast::Decl& d : prog_.files[file].decls) {
      if (const auto* cd = std::get_if<ast::ConstDecl>(&d)) {
        for (const auto& b : cd->bindings) add_constant(b, cd->is_param);
      }
    }
  }
  void collect_constants() {
    std::vector<std::uint8_t> seen(prog_.files.size(), 0);
    visit_constants(0, seen);
    for (const auto& define : opt_.defines) {
      const std::string& name =
          define.first;  // not a structured binding: clang 14 cannot capture one
      auto it = std::find_if(constants_.begin(), constants_.end(),
                             [&](const ir::Constant& c) { return c.name == name; });
      if (it == constants_.end()) throw LowerError("-D " + name + ": no param of that name");
      if (!it->is_param) {
        throw LowerError("-D " + name + ": '" + name + "' is a const, only a param can be set");
      }
    }
  }
  std::optional<double> lookup(std::string_view name) const {
    for (const ir::Constant& c : constants_) {
      if (c.name == name) return c.value;
    }
    return std::nullopt;
  }
  void add_constant(const ast::Binding& b, bool is_param) {
    ir::Constant c{b.name.name, 0, is_param};
    auto def = std::find_if(opt_.defines.begin(), opt_.defines.end(),
                            [&](const auto& d) { return d.first == c.name; });
    if (is_param && def != opt_.defines.end()) {
      c.value = def->second;
    } else {
      FoldResult r = evaluate_constant(b.value, [this](std::string_view n) { return lookup(n); });
      if (!r.value) {
        SourceSpan span = r.error ? r.error->span : b.value.span;
        error(DiagCode::ConstantNotFinite, span,
              r.error ? r.error->message : "'" + c.name + "' has no constant value");
        return;
      }
      c.value = *r.value;
    }
    constants_.push_back(c);
  }

  const ast::LSystem& find_system() const {
    for (std::size_t f = 0; f < prog_.files.size(); ++f) {
      for (const ast::Decl& d : prog_.files[f].decls) {
        const auto* ls = std::get_if<ast::LSystem>(&d);
        if (!ls) continue;
        if (opt_.system.empty()) return *ls;  // files[0] is the root: its first block
        if (ls->name.name == opt_.system) return *ls;
      }
      if (opt_.system.empty() && f == 0) break;
    }
    if (opt_.system.empty()) throw LowerError("the file has no lsystem block");
    throw LowerError("no lsystem named '" + opt_.system + "'");
  }

  // ---- module names -------------------------------------------------------------------------
  std::vector<std::string> split(const std::string& name) const {
    return split_module_name(
        name, [this](std::string_view n) { return declared_.count(std::string(n)) > 0; });
  }
  ir::SymbolId symbol(const std::string& name, int nparams) {
    ir::SymbolId s = g_.intern(name);
    if (s >= arity_.size()) arity_.resize(s + 1, -2);
    if (arity_[s] == -2) {
      arity_[s] = nparams;
    } else if (arity_[s] != nparams) {
      arity_[s] = -1;
    }
    return s;
  }

  // ---- lsystem items --------------------------------------------------------------------------
  void lower_item(const ast::LSystemItem& item) {
    std::visit(Overloaded{
                   [&](const ast::Setting& s) { lower_setting(s); },
                   [&](const ast::Axiom& a) { lower_axiom(a); },
                   [&](const ast::SymbolSet& s) { lower_symbol_set(s); },
                   [&](const ast::Select& s) {
                     g_.selection = s.mode.name == "nearest" ? ir::Selection::Nearest
                                                             : ir::Selection::FirstMatch;
                   },
                   [&](const ast::Production& p) { lower_production(p); },
               },
               item);
  }

  std::optional<double> setting_value(const ast::Setting& s, std::size_t k) {
    if (k >= s.values.size()) {
      error(DiagCode::SettingValueCount, s.span, "'" + s.key.name + "' needs more values");
      return std::nullopt;
    }
    FoldResult r = evaluate_constant(s.values[k], [this](std::string_view n) { return lookup(n); });
    if (!r.value) {
      error(DiagCode::InvalidSettingValue, s.values[k].span,
            r.error ? r.error->message : "'" + s.key.name + "' needs a constant value");
    }
    return r.value;
  }
  void lower_setting(const ast::Setting& s) {
    ir::Settings& st = g_.settings;
    const std::string& k = s.key.name;
    auto v = setting_value(s, 0);
    if (!v) return;
    auto whole = [&](double lo, double hi) {
      if (*v != std::floor(*v) || *v < lo || *v > hi) {
        error(DiagCode::InvalidSettingValue, s.values[0].span,
              "'" + k + "' must be a whole number in [" + std::to_string(std::int64_t(lo)) + ", " +
                  std::to_string(std::int64_t(hi)) + "]");
        return false;
      }
      return true;
    };
    if (k == "derive") {
      if (whole(0, 1e6)) st.derive = int(*v);
    } else if (k == "seed") {
      if (whole(0, 9007199254740992.0)) st.seed = std::uint64_t(*v);
    } else if (k == "max_depth") {
      if (whole(1, 255)) st.max_depth = int(*v);
    } else if (k == "angle") {
      st.angle = *v;
    } else if (k == "step") {
      st.step = *v;
    } else if (k == "width") {
      st.width = *v;
    } else if (k == "width_decay") {
      st.width_decay = *v;
    } else if (k == "elasticity") {
      st.elasticity = *v;
    } else if (k == "tropism") {
      auto y = setting_value(s, 1), z = setting_value(s, 2);
      if (y && z) {
        st.tropism[0] = *v;
        st.tropism[1] = *y;
        st.tropism[2] = *z;
      }
    } else {
      error(DiagCode::UnknownSetting, s.key.span, "unknown lsystem setting '" + k + "'");
    }
  }

  void lower_symbol_set(const ast::SymbolSet& set) {
    for (const ast::Identifier& id : set.symbols) {
      for (const std::string& n : split(id.name)) {
        ir::SymbolId s = g_.intern(n);
        if (s >= arity_.size()) arity_.resize(s + 1, -2);
        (set.consider ? considered_ : ignored_).push_back(s);
      }
    }
    has_consider_ = has_consider_ || set.consider;
  }
  // Brackets structure the string and are never filtered out.
  void finish_symbol_sets() {
    g_.ignored.assign(g_.symbols.size(), has_consider_ ? 1 : 0);
    for (ir::SymbolId s : considered_) g_.ignored[s] = 0;
    for (ir::SymbolId s : ignored_) g_.ignored[s] = 1;
    g_.ignored[ir::kPush] = g_.ignored[ir::kPop] = 0;
  }

  void lower_axiom(const ast::Axiom& a) {
    ExprScope scope;
    scope.constants = &constants_;
    scope.allow_random = false;
    g_.axiom.clear();
    lower_modules(a.modules, scope, g_.axiom);
  }

  // Module calls of an axiom or successor; undeclared multi-letter names become one module per
  // letter with the arguments on the last one.
  std::uint32_t lower_modules(const ast::ModuleSeq& seq, const ExprScope& scope,
                              std::vector<ir::SuccModule>& out) {
    std::uint32_t nparams = 0;
    for (const ast::ModuleCall& call : seq) {
      if (call.args.size() > ir::kMaxSlots) {  // the derived string's limit (module_string.h)
        error(DiagCode::ModuleArityMismatch, call.span,
              "module `" + call.name + "` with " + std::to_string(call.args.size()) +
                  " arguments: a module takes at most 64");
        continue;
      }
      std::vector<std::string> parts = split(call.name);
      for (std::size_t k = 0; k < parts.size(); ++k) {
        const bool last = k + 1 == parts.size();
        ir::SuccModule m;
        m.symbol = symbol(parts[k], last ? int(call.args.size()) : 0);
        m.arg_begin = std::uint32_t(g_.args.size());
        if (last) {
          for (const ast::Expr& e : call.args) {
            g_.args.push_back(compile(e, scope));
          }
          m.nargs = std::uint16_t(call.args.size());
          nparams += m.nargs;
        }
        out.push_back(m);
      }
    }
    return nparams;
  }

  ir::CodeId compile(const ast::Expr& e, const ExprScope& scope) {
    try {
      return compile_expr(g_, e, scope, where(e.span));
    } catch (const CompileError& err) {
      error(DiagCode::ConstantNotFinite, err.span, err.what());
      return constant_code(g_, 0, where(e.span));
    }
  }

  // Patterns bind formal names to consecutive slots: left context, predecessor, right context.
  void lower_patterns(const std::vector<ast::ModulePattern>& pats, std::vector<ir::Pattern>& out,
                      ExprScope& scope) {
    for (const ast::ModulePattern& mp : pats) {
      std::vector<std::string> parts = split(mp.name);
      for (std::size_t k = 0; k < parts.size(); ++k) {
        const bool last = k + 1 == parts.size();
        out.push_back(pattern(parts[k], last ? &mp : nullptr, scope));
      }
    }
  }
  ir::Pattern pattern(const std::string& name, const ast::ModulePattern* mp, ExprScope& scope) {
    ir::Pattern p;
    const bool with_params = mp && mp->has_parens;
    p.symbol = symbol(name, with_params ? int(mp->params.size()) : 0);
    if (with_params) {
      p.any_params = false;
      p.nparams = std::uint16_t(mp->params.size());
      p.first_slot = std::uint16_t(scope.params.size());
      for (const ast::Identifier& id : mp->params) {
        if (scope.params.size() >= ir::kMaxSlots) {
          error(DiagCode::DuplicateDefinition, id.span, "more than 64 formal parameters");
          break;
        }
        scope.params.emplace_back(id.name, std::uint16_t(scope.params.size()));
      }
    }
    return p;
  }

  void lower_production(const ast::Production& ap) {
    ir::Production p;
    p.kind = ap.kind == ast::ProductionKind::Interpret   ? ir::Kind::Interpret
             : ap.kind == ast::ProductionKind::Decompose ? ir::Kind::Decompose
                                                         : ir::Kind::Rewrite;
    g_.locations.push_back(where(ap.span));
    p.where = std::uint32_t(g_.locations.size() - 1);
    p.text = std::string(sm_.slice(ap.span));
    ExprScope scope;
    scope.constants = &constants_;
    lower_patterns(ap.left_context, p.left, scope);
    std::vector<ir::Pattern> pred;
    lower_patterns({ap.predecessor}, pred, scope);
    if (pred.size() != 1) {
      error(DiagCode::PredecessorNotSingle, ap.predecessor.span,
            "predecessor '" + ap.predecessor.name + "' stands for several modules");
      return;
    }
    p.predecessor = pred[0];
    lower_patterns(ap.right_context, p.right, scope);
    for (const ir::Pattern& l : p.left) {
      if (l.symbol == ir::kPush || l.symbol == ir::kPop) {
        error(DiagCode::SyntaxError, ap.span, "a left context cannot contain brackets");
        return;
      }
    }
    p.nslots = std::uint16_t(scope.params.size());
    if (ap.guard) p.guard = compile(*ap.guard, scope);
    lower_rule_key(ap, p, scope);
    const std::uint32_t id = std::uint32_t(g_.productions.size());
    p.alt_begin = std::uint32_t(g_.alternatives.size());
    for (const ast::Alternative& a : ap.alternatives) {
      ir::Alternative alt;
      alt.production = id;
      if (a.probability) alt.probability = compile(*a.probability, scope);
      alt.succ_begin = std::uint32_t(g_.successors.size());
      alt.out_params = lower_modules(a.successor, scope, g_.successors);
      alt.succ_end = std::uint32_t(g_.successors.size());
      g_.alternatives.push_back(alt);
    }
    p.alt_end = std::uint32_t(g_.alternatives.size());
    g_.productions.push_back(std::move(p));
  }

  // The production's rule-space key (constants) and the `select nearest` expressions over its
  // parameters (docs/language.md, "Rule-space selection"). The checks have reported keys that
  // do not fit; here such a key is dropped with a diagnostic.
  void lower_rule_key(const ast::Production& ap, ir::Production& p, const ExprScope& scope) {
    if (ap.key.empty()) return;
    if (!select_ || select_->mode.name != "nearest" || p.kind != ir::Kind::Rewrite ||
        select_->keys.size() != ap.key.size()) {
      error(DiagCode::RuleKeyUnused, ap.key.front().span,
            "this rule-space key does not fit the lsystem's 'select nearest'");
      return;
    }
    for (const ast::Expr& k : ap.key) {
      FoldResult r = evaluate_constant(k, [this](std::string_view n) { return lookup(n); });
      if (!r.value) {
        error(DiagCode::ConstantNotFinite, k.span,
              r.error ? r.error->message : "a rule-space key must be constant");
        p.key.clear();
        return;
      }
      p.key.push_back(*r.value);
    }
    for (const ast::Expr& e : select_->keys) p.query.push_back(compile(e, scope));
  }

  const Program& prog_;
  const SourceManager& sm_;
  const LowerOptions& opt_;
  DiagnosticSink& diag_;
  ir::Grammar g_;
  std::set<std::string> declared_;
  std::vector<ir::Constant> constants_;
  std::vector<int> arity_;  // -2 unseen, -1 varies, else the parameter count
  std::vector<ir::SymbolId> ignored_, considered_;
  bool has_consider_ = false;
  const ast::Select* select_ = nullptr;
};

}  // namespace

ir::Grammar lower(const Program& program, const SourceManager& sources, const LowerOptions& options,
                  DiagnosticSink& diagnostics) {
  if (program.files.empty()) throw LowerError("no program to lower");
  return Lowerer(program, sources, options, diagnostics).run();
}

}  // namespace ramus
