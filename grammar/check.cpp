// The semantic checks: the pass list, and the context the passes share.
#include "grammar/check.h"

#include "grammar/detail/check_context.h"

namespace ramus {
namespace detail {

CheckContext::CheckContext(const Program& p, const SourceManager& s, DiagnosticSink& d,
                           const CheckOptions& o)
    : program(p), sources(s), sink(d), options(o) {
  const std::size_t n = p.files.size();
  visible.resize(n);
  consts.resize(n);
  modules.resize(n);
  // Imports are transitive: a file sees what its imports see. Breadth-first, so nearer files
  // come first; cycles (reported by the loader) end at the visited mark.
  for (std::uint32_t f = 0; f < n; ++f) {
    std::vector<bool> seen(n, false);
    std::vector<std::uint32_t>& out = visible[f];
    out.push_back(f);
    seen[f] = true;
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out[i] >= p.imports.size()) continue;
      for (std::uint32_t g : p.imports[out[i]]) {
        if (g < n && !seen[g]) {
          seen[g] = true;
          out.push_back(g);
        }
      }
    }
  }
}

ConstInfo* CheckContext::find_const(std::uint32_t file, const std::string& name) {
  for (std::uint32_t f : visible[file]) {
    auto it = consts[f].find(name);
    if (it != consts[f].end()) return &it->second;
  }
  return nullptr;
}

const ModuleInfo* CheckContext::find_module(std::uint32_t file, const std::string& name) const {
  for (std::uint32_t f : visible[file]) {
    auto it = modules[f].find(name);
    if (it != modules[f].end()) return &it->second;
  }
  return nullptr;
}

std::string plural(std::size_t n, std::string_view word) {
  std::string s = std::to_string(n) + " " + std::string(word);
  if (n != 1) s += "s";
  return s;
}

}  // namespace detail

void check_program(const Program& program, const SourceManager& sources, DiagnosticSink& sink) {
  check_program(program, sources, sink, CheckOptions{});
}

void check_program(const Program& program, const SourceManager& sources, DiagnosticSink& sink,
                   const CheckOptions& options) {
  detail::CheckContext cx(program, sources, sink, options);
  // 1. declarations of every file: duplicates, constant values (imports first).
  detail::check_declarations(cx);
  // 2. the blocks, file by file.
  for (std::uint32_t f = 0; f < program.files.size(); ++f) {
    for (const ast::Decl& decl : program.files[f].decls) {
      if (const auto* ls = std::get_if<ast::LSystem>(&decl)) {
        detail::check_lsystem(cx, f, *ls);
        detail::check_lsystem_flow(cx, f, *ls);
        detail::check_brackets(cx, *ls);
      } else if (const auto* ps = std::get_if<ast::Pieces>(&decl)) {
        detail::check_pieces(cx, f, *ps);
      } else if (const auto* vx = std::get_if<ast::Voxels>(&decl)) {
        detail::check_voxels(cx, f, *vx);
      }
    }
  }
  // 3. what was never used, once every use has been seen.
  detail::check_unused_constants(cx);
}

DefineTarget find_define_target(const Program& program, std::string_view name) {
  DefineTarget found = DefineTarget::Unknown;
  for (const ast::File& file : program.files) {
    for (const ast::Decl& decl : file.decls) {
      const auto* c = std::get_if<ast::ConstDecl>(&decl);
      if (!c) continue;
      for (const ast::Binding& b : c->bindings) {
        if (b.name.name != name) continue;
        if (c->is_param) return DefineTarget::Param;
        found = DefineTarget::Const;
      }
    }
  }
  return found;
}

}  // namespace ramus
