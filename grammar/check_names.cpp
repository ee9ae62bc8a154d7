// Declarations at file level: constants and params (values folded in order, imports first),
// module declarations and block names; duplicates (E0103) and unused constants (W0001).
#include <functional>
#include <unordered_set>

#include "grammar/const_eval.h"
#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

// Files in an order where every file comes after the files it imports (cycles are cut where
// they close; the loader reports them).
std::vector<std::uint32_t> imports_first(const Program& p) {
  const std::uint32_t n = std::uint32_t(p.files.size());
  std::vector<std::uint32_t> order;
  std::vector<char> state(n, 0);  // 0 new, 1 open, 2 done
  std::function<void(std::uint32_t)> visit = [&](std::uint32_t f) {
    state[f] = 1;
    if (f < p.imports.size()) {
      for (std::uint32_t g : p.imports[f]) {
        if (g < n && state[g] == 0) visit(g);
      }
    }
    state[f] = 2;
    order.push_back(f);
  };
  for (std::uint32_t f = 0; f < n; ++f) {
    if (state[f] == 0) visit(f);
  }
  return order;
}

class DeclChecker {
 public:
  DeclChecker(CheckContext& cx, std::uint32_t file) : cx_(cx), file_(file) {}

  void run() {
    // Every name first, so that a constant using a later one gets E0110, not "unknown".
    for (const ast::Decl& d : cx_.program.files[file_].decls) {
      if (const auto* c = std::get_if<ast::ConstDecl>(&d)) {
        for (const ast::Binding& b : c->bindings) declare(b, c->is_param);
      } else if (const auto* m = std::get_if<ast::ModuleDecl>(&d)) {
        for (const ast::ModulePattern& p : m->modules) module(p);
      } else if (const auto* ls = std::get_if<ast::LSystem>(&d)) {
        block(ls->name);
      } else if (const auto* ps = std::get_if<ast::Pieces>(&d)) {
        block(ps->name);
      } else if (const auto* vx = std::get_if<ast::Voxels>(&d)) {
        block(vx->name);
      }
    }
    // Then the values, in order.
    std::uint32_t order = 0;
    for (const ast::Decl& d : cx_.program.files[file_].decls) {
      if (const auto* c = std::get_if<ast::ConstDecl>(&d)) {
        for (const ast::Binding& b : c->bindings) evaluate(b, c->is_param, order++);
      }
    }
  }

 private:
  // Whether `name` is already taken, by this file or a visible import; reports E0103 if so.
  template <typename Table, typename SpanOf>
  bool duplicate(const Table& tables, const std::string& name, SourceSpan where, const char* what,
                 SpanOf span_of) {
    for (std::uint32_t f : cx_.visible[file_]) {
      auto it = tables[f].find(name);
      if (it == tables[f].end()) continue;
      if (f == file_) {
        cx_.error(DiagCode::DuplicateDefinition, where,
                  std::string(what) + " '" + name + "' is defined twice");
        cx_.note(span_of(it->second), "first defined here");
      } else {
        cx_.error(DiagCode::DuplicateDefinition, where,
                  std::string(what) + " '" + name + "' is already defined by an import");
        cx_.note(span_of(it->second), "defined here");
      }
      return true;
    }
    return false;
  }

  void declare(const ast::Binding& b, bool is_param) {
    const std::string& name = b.name.name;
    const char* what = is_param ? "param" : "constant";
    ConstInfo info;
    info.binding = &b;
    info.is_param = is_param;
    info.file = file_;
    info.order = order_++;
    if (!duplicate(cx_.consts, name, b.name.span, what,
                   [](const ConstInfo& c) { return c.binding->name.span; })) {
      cx_.consts[file_][name] = info;
    }
  }

  void evaluate(const ast::Binding& b, bool is_param, std::uint32_t order) {
    ExprEnv env;
    env.file = file_;
    env.constant_context = is_param ? "a param" : "a constant";
    env.defined_before = order;
    Type type = cx_.check_expr(b.value, env);
    if (is_param && type == Type::Boolean) {
      cx_.error(DiagCode::BooleanAsNumber, b.value.span,
                "a param must be a number (-D gives it a number), found a boolean");
    }
    std::optional<double> value = value_of(b, is_param);
    auto it = cx_.consts[file_].find(b.name.name);
    if (it == cx_.consts[file_].end() || it->second.binding != &b) return;  // a duplicate
    it->second.type = type;
    it->second.value = value;
  }

  std::optional<double> value_of(const ast::Binding& b, bool is_param) {
    if (is_param) {
      for (const auto& [name, value] : cx_.options.defines) {
        if (name == b.name.name) return value;
      }
    }
    FoldResult r = evaluate_constant(b.value, [&](std::string_view n) -> std::optional<double> {
      const ConstInfo* c = cx_.find_const(file_, std::string(n));
      if (c && c->file == file_ && c->binding == &b) return std::nullopt;
      return c ? c->value : std::nullopt;
    });
    if (r.error && r.error->kind == FoldError::Kind::NotFinite) {
      cx_.error(DiagCode::ConstantNotFinite, r.error->span,
                "the value of '" + b.name.name + "' is not a finite number");
      cx_.note(r.error->message);
    }
    return r.value;
  }

  void module(const ast::ModulePattern& p) {
    bool dup = duplicate(cx_.modules, p.name, p.span, "module",
                         [](const ModuleInfo& m) { return m.pattern->span; });
    std::unordered_map<std::string, SourceSpan> params;
    for (const ast::Identifier& id : p.params) {
      auto [it, fresh] = params.emplace(id.name, id.span);
      if (!fresh) {
        cx_.error(DiagCode::DuplicateDefinition, id.span,
                  "parameter '" + id.name + "' is declared twice");
        cx_.note(it->second, "first declared here");
      }
    }
    if (!dup) cx_.modules[file_][p.name] = ModuleInfo{&p, file_};
  }

  void block(const ast::Identifier& name) {
    auto [it, fresh] = blocks_.emplace(name.name, name.span);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, name.span,
                "a block named '" + name.name + "' is defined twice");
      cx_.note(it->second, "first defined here");
    }
  }

  CheckContext& cx_;
  std::uint32_t file_;
  std::uint32_t order_ = 0;
  std::unordered_map<std::string, SourceSpan> blocks_;
};

}  // namespace

void check_declarations(CheckContext& cx) {
  for (std::uint32_t f : imports_first(cx.program)) DeclChecker(cx, f).run();
}

void check_unused_constants(CheckContext& cx) {
  if (cx.program.files.empty() || !cx.warn_in(0)) return;
  // A file without blocks is a library (stdlib/): its constants exist for its importers.
  const auto& decls = cx.program.files[0].decls;
  bool has_block = false;
  for (const ast::Decl& d : decls) {
    has_block = has_block || std::holds_alternative<ast::LSystem>(d) ||
                std::holds_alternative<ast::Pieces>(d) || std::holds_alternative<ast::Voxels>(d);
  }
  if (!has_block) return;
  for (const ast::Decl& d : decls) {
    const auto* c = std::get_if<ast::ConstDecl>(&d);
    if (!c || c->is_param) continue;  // params are the file's interface (-D)
    for (const ast::Binding& b : c->bindings) {
      auto it = cx.consts[0].find(b.name.name);
      if (it == cx.consts[0].end() || it->second.binding != &b || it->second.used) continue;
      cx.error(DiagCode::UnusedConstant, b.name.span,
               "constant '" + b.name.name + "' is never used");
    }
  }
}

}  // namespace ramus::detail
