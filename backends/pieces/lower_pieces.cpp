// Lowering a `pieces` block (docs/language.md, docs/pieces.md) into a PieceSet: constants folded
// with the same arithmetic as the checks, every piece type built (built-in kinds parametrically,
// mesh("file") read from glTF/OBJ relative to the declaring file) with its levels of detail, and
// attach rules resolved to piece and rim indices.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <unordered_map>

#include "backends/pieces/piece_build.h"
#include "grammar/const_eval.h"
#include "grammar/program_constants.h"

namespace ramus::pieces {

namespace {

const ast::Pieces* find_block(const Program& program, std::string_view block) {
  for (std::size_t f = 0; f < program.files.size(); ++f) {
    for (const ast::Decl& d : program.files[f].decls) {
      const auto* p = std::get_if<ast::Pieces>(&d);
      if (!p) continue;
      if (block.empty() || p->name.name == block) return p;
    }
    if (block.empty() && f == 0) break;  // without a name: the root file's first block
  }
  return nullptr;
}

class PiecesLowering {
 public:
  PiecesLowering(const Program& program, const SourceManager& sm, const LowerPiecesOptions& opt,
                 DiagnosticSink& diags)
      : prog_(program), sm_(sm), opt_(opt), diags_(diags) {}

  PieceSet run() {
    const ast::Pieces* block = find_block(prog_, opt_.block);
    if (!block) {
      throw PiecesError(opt_.block.empty() ? "the file has no pieces block"
                                           : "no pieces block named '" + opt_.block + "'");
    }
    collect_constants();
    PieceSet set;
    set.name = block->name.name;
    set.lod_segments = {1};
    for (int s : opt_.lod_segments) {
      if (s > 1 && std::find(set.lod_segments.begin(), set.lod_segments.end(), s) ==
                       set.lod_segments.end()) {
        set.lod_segments.push_back(s);
      }
    }
    std::sort(set.lod_segments.begin(), set.lod_segments.end());
    for (const ast::PiecesItem& item : block->items) {
      if (const auto* p = std::get_if<ast::PieceDecl>(&item)) piece(set, *p);
    }
    for (const ast::PiecesItem& item : block->items) {
      if (const auto* r = std::get_if<ast::RimDecl>(&item)) rim(set, *r);
      if (const auto* a = std::get_if<ast::AttachRule>(&item)) attach(set, *a);
      if (const auto* s = std::get_if<ast::PieceSetting>(&item)) setting(set, *s);
    }
    return set;
  }

 private:
  void error(DiagCode code, SourceSpan span, std::string msg) {
    diags_.report(code, span, std::move(msg));
  }

  // const and param of every file, imports first (as the lsystem lowering does).
  void collect_constants() {
    constants_ = program_constants(
        prog_, opt_.defines,
        [this](const ast::Expr& e, const FoldResult& r) { report_not_constant(e, r); });
  }

  void report_not_constant(const ast::Expr& e, const FoldResult& r) {
    error(DiagCode::ConstantNotFinite, r.error ? r.error->span : e.span,
          r.error ? r.error->message : "the value is not a constant");
  }

  std::optional<double> value(const ast::Expr& e) {
    FoldResult r = evaluate_constant(e, lookup_in(constants_));
    if (!r.value) report_not_constant(e, r);
    return r.value;
  }

  // Named and positional arguments of a built-in kind, in the order of `names`.
  std::vector<double> arguments(const ast::Constructor& c, std::vector<std::string> names,
                                std::vector<double> defaults) {
    std::size_t pos = 0;
    for (const ast::NamedArg& a : c.args) {
      std::size_t k = names.size();
      if (a.name.name.empty()) {
        k = pos++;
      } else {
        k = std::size_t(std::find(names.begin(), names.end(), a.name.name) - names.begin());
      }
      if (k >= names.size()) {
        std::string list;
        for (std::size_t i = 0; i < names.size(); ++i) list += (i ? ", " : "") + names[i];
        error(DiagCode::PieceArguments, a.name.name.empty() ? a.value.span : a.name.span,
              a.name.name.empty() ? "'" + c.kind.name + "' takes at most " +
                                        std::to_string(names.size()) + " arguments"
                                  : "'" + c.kind.name + "' has no argument '" + a.name.name + "'");
        diags_.note(c.span, "its arguments are " + list);
        continue;
      }
      if (std::optional<double> v = value(a.value)) defaults[k] = *v;
    }
    return defaults;
  }

  bool positive(const ast::Constructor& c, const std::vector<double>& v,
                const std::vector<std::string>& names, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      if (!(v[i] > 0)) {
        error(DiagCode::PieceArguments, c.span,
              "'" + names[i] + "' of '" + c.kind.name + "' must be positive");
        return false;
      }
    }
    return true;
  }

  void piece(PieceSet& set, const ast::PieceDecl& p) {
    const ast::Constructor& c = p.ctor;
    const std::string& kind = c.kind.name;
    const std::string& name = p.name.name;
    std::optional<PieceDraft> d;
    if (kind == "tube") {
      std::vector<std::string> n{"length", "taper"};
      auto v = arguments(c, n, {4, 0.85});
      if (positive(c, v, n, 2)) d = draft_tube(name, {v[0], v[1]});
    } else if (kind == "fork") {
      std::vector<std::string> n{"length", "angle", "taper"};
      auto v = arguments(c, n, {3, 35, 0.8});
      if (positive(c, v, n, 3)) d = draft_fork(name, {v[0], v[1], v[2]});
    } else if (kind == "trifurcation") {
      std::vector<std::string> n{"length", "angle", "taper", "planar"};
      auto v = arguments(c, n, {3, 35, 0.75, 0});
      if (positive(c, v, n, 3)) d = draft_trifurcation(name, {v[0], v[1], v[2], v[3] != 0});
    } else if (kind == "attachment") {
      std::vector<std::string> n{"length", "angle", "taper", "branch"};
      auto v = arguments(c, n, {4, 50, 0.9, 0.55});
      if (positive(c, v, n, 4)) d = draft_attachment(name, {v[0], v[1], v[2], v[3]});
    } else if (kind == "mesh" && c.path) {
      namespace fs = std::filesystem;
      fs::path file = *c.path;
      if (file.is_relative()) file = fs::path(sm_.name(p.span.file)).parent_path() / file;
      const std::string* bytes = nullptr;
      for (const auto& [held, contents] : opt_.mesh_files) {
        if (held == *c.path) bytes = &contents;
      }
      try {
        d = draft_mesh_file(name, bytes ? sm_.name(p.span.file) + ": " + *c.path : file.string(),
                            bytes);
      } catch (const PiecesError& e) {
        error(DiagCode::PieceArguments, c.span, e.what());
      }
    } else {
      error(DiagCode::UnknownPieceKind, c.kind.span, "unknown piece kind '" + kind + "'");
    }
    if (!d) {
      // A piece type without meshes takes the failed one's index, so the attach rules that name
      // later pieces keep theirs; lowering has reported the error, and the caller assembles
      // nothing once diagnostics.has_errors().
      PieceType t;
      t.name = name;
      set.types.push_back(std::move(t));
      return;
    }
    set.types.push_back(finish_piece(std::move(*d), set.lod_segments));
  }

  void rim(PieceSet& set, const ast::RimDecl& r) {
    if (r.name.name != "hexagon") {
      error(DiagCode::PieceArguments, r.name.span,
            "the universal rim is a regular hexagon, not '" + r.name.name + "'");
      diags_.note(r.span, "write 'rim hexagon(radius: 1);'");
      return;
    }
    for (const ast::NamedArg& a : r.args) {
      if (!a.name.name.empty() && a.name.name != "radius") {
        error(DiagCode::PieceArguments, a.name.span,
              "'hexagon' has no argument '" + a.name.name + "'");
        continue;
      }
      std::optional<double> v = value(a.value);
      if (v && !(*v > 0)) {
        error(DiagCode::PieceArguments, a.value.span, "the rim radius must be positive");
      } else if (v) {
        set.rim_radius = *v;
      }
    }
  }

  void attach(PieceSet& set, const ast::AttachRule& a) {
    AttachRule rule;
    rule.piece = set.find(a.piece.name);
    if (rule.piece == kNone) {
      error(DiagCode::UnknownPiece, a.piece.span, "unknown piece '" + a.piece.name + "'");
      return;
    }
    const PieceType& t = set.types[rule.piece];
    rule.leaf = t.leaf_index(a.rim.name);
    if (rule.leaf == kNone) {
      if (!t.lods.empty()) {
        std::string list;
        for (const Rim& r : t.leaves) list += (list.empty() ? "'" : ", '") + r.name + "'";
        error(DiagCode::UnknownRim, a.rim.span,
              "piece '" + a.piece.name + "' has no rim '" + a.rim.name + "'");
        diags_.note(a.piece.span,
                    list.empty() ? "it has no leaf rims" : "its leaf rims are " + list);
      }
      return;
    }
    for (const ast::WeightedPiece& w : a.targets) {
      AttachTarget target;
      target.piece = set.find(w.piece.name);
      if (target.piece == kNone) {
        error(DiagCode::UnknownPiece, w.piece.span, "unknown piece '" + w.piece.name + "'");
        continue;
      }
      if (w.weight) {
        std::optional<double> v = value(*w.weight);
        if (!v) continue;
        if (!(*v > 0)) {
          error(DiagCode::InvalidAttachWeight, w.weight->span,
                "the weight of '" + w.piece.name + "' must be positive");
          continue;
        }
        target.weight = *v;
      }
      rule.targets.push_back(target);
    }
    set.rules.push_back(std::move(rule));
  }

  void setting(PieceSet& set, const ast::PieceSetting& s) {
    if (s.values.size() != 1) return;  // reported by the checks
    const ast::Expr& v = s.values[0];
    const auto* name = std::get_if<ast::NameRef>(&v.node);
    if (s.key.name == "root") {
      if (!name) return;
      set.root = set.find(name->name);
      if (set.root == kNone) {
        error(DiagCode::UnknownPiece, v.span, "unknown piece '" + name->name + "'");
        set.root = 0;
      }
    } else if (s.key.name == "twist") {
      if (name && name->name == "any") {
        set.twist_any = true;
        return;
      }
      std::optional<double> x = value(v);
      if (!x) return;
      if (*x < 0 || *x > 5 || *x != std::floor(*x)) {
        error(DiagCode::InvalidPieceSetting, v.span,
              "'twist' is 'any' or one of the six twists 0 to 5");
        return;
      }
      set.twist_any = false;
      set.twist = int(*x);
    } else if (s.key.name == "depth") {
      std::optional<double> x = value(v);
      if (!x) return;
      if (*x < 0 || *x > 4096 || *x != std::floor(*x)) {
        error(DiagCode::InvalidPieceSetting, v.span, "'depth' must be an integer from 0 to 4096");
        return;
      }
      set.depth = int(*x);
    }
  }

  const Program& prog_;
  const SourceManager& sm_;
  const LowerPiecesOptions& opt_;
  DiagnosticSink& diags_;
  std::unordered_map<std::string, double> constants_;
};

}  // namespace

PieceSet lower_pieces(const Program& program, const SourceManager& sources,
                      const LowerPiecesOptions& options, DiagnosticSink& diagnostics) {
  return PiecesLowering(program, sources, options, diagnostics).run();
}

bool pieces_block_fits_skeleton(const Program& program, std::string_view block) {
  const ast::Pieces* p = find_block(program, block);
  if (!p) return false;
  for (const ast::PiecesItem& item : p->items) {
    if (std::holds_alternative<ast::AttachRule>(item)) return false;
  }
  return true;
}

std::string pieces_skeleton_system(const Program& program, std::string_view block) {
  const ast::Pieces* p = find_block(program, block);
  if (!p) return {};
  for (const ast::PiecesItem& item : p->items) {
    const auto* s = std::get_if<ast::PieceSetting>(&item);
    if (!s || s->key.name != "skeleton" || s->values.size() != 1) continue;
    if (const auto* name = std::get_if<ast::NameRef>(&s->values[0].node)) return name->name;
  }
  return {};
}

}  // namespace ramus::pieces
