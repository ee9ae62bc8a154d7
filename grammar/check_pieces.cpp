// pieces blocks: rim shapes, pieces and their kinds, attach rules (pieces and rims that exist,
// positive weights), and the settings root, twist and depth.
//
// The rims of the built-in piece kinds: tube -> top; fork -> left, right; trifurcation -> left,
// middle, right; attachment (a branch leaving a stem) -> stem, branch. A mesh("file") piece
// names its rims in the file, which is not read here, so its rims are not checked.
#include <cmath>
#include <initializer_list>

#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

struct PieceKind {
  std::string_view name;
  std::initializer_list<std::string_view> rims;
};
const PieceKind kKinds[] = {
    {"tube", {"top"}},
    {"fork", {"left", "right"}},
    {"trifurcation", {"left", "middle", "right"}},
    {"attachment", {"stem", "branch"}},
    {"mesh", {}},
};

const PieceKind* find_kind(std::string_view name) {
  for (const PieceKind& k : kKinds) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

std::string rim_list(const PieceKind& k) {
  std::string s;
  std::size_t i = 0;
  for (std::string_view r : k.rims) {
    if (i > 0) s += (i + 1 == k.rims.size()) ? " and " : ", ";
    s.append("'").append(r).append("'");
    ++i;
  }
  return s;
}

class PiecesChecker {
 public:
  PiecesChecker(CheckContext& cx, std::uint32_t file, const ast::Pieces& ps)
      : cx_(cx), file_(file), ps_(ps) {
    env_.file = file;
    env_.constant_context = "a pieces block";
  }

  void run() {
    // Pieces first: rules and settings may name a piece declared further down.
    for (const ast::PiecesItem& item : ps_.items) {
      if (const auto* p = std::get_if<ast::PieceDecl>(&item)) piece(*p);
    }
    for (const ast::PiecesItem& item : ps_.items) {
      if (const auto* r = std::get_if<ast::RimDecl>(&item)) rim(*r);
      if (const auto* a = std::get_if<ast::AttachRule>(&item)) attach(*a);
      if (const auto* s = std::get_if<ast::PieceSetting>(&item)) setting(*s);
    }
    if (!settings_.count("root")) {
      cx_.error(DiagCode::MissingRoot, ps_.name.span,
                "pieces block '" + ps_.name.name + "' has no root");
      cx_.note("name the first piece, e.g. 'root I;'");
    }
  }

 private:
  void args(const std::vector<ast::NamedArg>& args, const char* what) {
    std::unordered_map<std::string, SourceSpan> seen;
    for (const ast::NamedArg& a : args) {
      cx_.check_number(a.value, env_, what);
      if (a.name.name.empty()) continue;
      auto [it, fresh] = seen.emplace(a.name.name, a.name.span);
      if (!fresh) {
        cx_.error(DiagCode::DuplicateDefinition, a.name.span,
                  "argument '" + a.name.name + "' is given twice");
        cx_.note(it->second, "first given here");
      }
    }
  }

  void rim(const ast::RimDecl& r) {
    auto [it, fresh] = rims_.emplace(r.name.name, r.name.span);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, r.name.span,
                "rim '" + r.name.name + "' is declared twice");
      cx_.note(it->second, "first declared here");
    }
    args(r.args, "a rim argument");
  }

  void piece(const ast::PieceDecl& p) {
    auto [it, fresh] = pieces_.emplace(p.name.name, &p);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, p.name.span,
                "piece '" + p.name.name + "' is declared twice");
      cx_.note(it->second->name.span, "first declared here");
    }
    const ast::Constructor& c = p.ctor;
    const PieceKind* kind = find_kind(c.kind.name);
    if (!kind) {
      cx_.error(DiagCode::UnknownPieceKind, c.kind.span,
                "unknown piece kind '" + c.kind.name + "'");
      cx_.note("the kinds are tube, fork, trifurcation, attachment and mesh(\"file\")");
    } else if (kind->name == "mesh" && (!c.path || !c.args.empty())) {
      cx_.error(DiagCode::PieceArguments, c.span, "'mesh' takes one file name");
      cx_.note("e.g. mesh(\"pieces/psi.glb\")");
    } else if (kind->name != "mesh" && c.path) {
      cx_.error(DiagCode::PieceArguments, c.span,
                "'" + c.kind.name + "' takes numbers, not a file name");
      cx_.note("only mesh(\"file\") reads a file");
    }
    args(c.args, "a piece argument");
  }

  const ast::PieceDecl* find_piece(const ast::Identifier& id) {
    auto it = pieces_.find(id.name);
    if (it != pieces_.end()) return it->second;
    cx_.error(DiagCode::UnknownPiece, id.span, "unknown piece '" + id.name + "'");
    cx_.note(ps_.name.span, "pieces are declared with 'piece NAME = kind(...);' in this block");
    return nullptr;
  }

  void attach(const ast::AttachRule& a) {
    if (const ast::PieceDecl* p = find_piece(a.piece)) {
      const PieceKind* kind = find_kind(p->ctor.kind.name);
      bool has_rim = !kind || kind->name == "mesh";
      if (kind) {
        for (std::string_view r : kind->rims) has_rim = has_rim || r == a.rim.name;
      }
      if (!has_rim) {
        cx_.error(DiagCode::UnknownRim, a.rim.span,
                  "piece '" + a.piece.name + "' has no rim '" + a.rim.name + "'");
        cx_.note(p->span,
                 "'" + a.piece.name + "' is a " + std::string(kind->name) +
                     (kind->rims.size() == 1 ? ", whose only rim is " : ", whose rims are ") +
                     rim_list(*kind));
      }
    }
    auto [it, fresh] = rules_.emplace(a.piece.name + "." + a.rim.name, a.span);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, a.span,
                "a rule for '" + a.piece.name + "." + a.rim.name + "' is given twice");
      cx_.note(it->second, "first given here");
    }
    for (const ast::WeightedPiece& t : a.targets) {
      find_piece(t.piece);
      if (!t.weight) continue;
      cx_.check_number(*t.weight, env_, "a weight");
      std::optional<double> w = cx_.fold(*t.weight, file_);
      if (w && !(*w > 0)) {
        cx_.error(DiagCode::InvalidAttachWeight, t.weight->span,
                  "the weight of '" + t.piece.name + "' must be positive");
      }
    }
  }

  void setting(const ast::PieceSetting& s) {
    const std::string& key = s.key.name;
    if (key != "root" && key != "twist" && key != "depth" && key != "skeleton") {
      cx_.error(DiagCode::UnknownPieceSetting, s.key.span, "unknown setting '" + key + "'");
      cx_.note("the settings of a pieces block are root, twist, depth and skeleton");
      return;
    }
    auto [it, fresh] = settings_.emplace(key, s.key.span);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, s.key.span, "setting '" + key + "' is given twice");
      cx_.note(it->second, "first given here");
    }
    if (s.values.size() != 1) {
      cx_.error(DiagCode::InvalidPieceSetting, s.span,
                "'" + key + "' takes one value, found " + std::to_string(s.values.size()));
      return;
    }
    const ast::Expr& v = s.values[0];
    const auto* name = std::get_if<ast::NameRef>(&v.node);
    if (key == "skeleton") {
      skeleton_setting(v, name);
    } else if (key == "root") {
      if (!name) {
        cx_.error(DiagCode::InvalidPieceSetting, v.span, "'root' takes the name of a piece");
      } else {
        find_piece(ast::Identifier{name->name, v.span});
      }
    } else if (key == "twist" && name && name->name == "any") {
      return;  // any twist about the rim's axis
    } else {
      cx_.check_number(v, env_, "'" + key + "'");
      std::optional<double> x = cx_.fold(v, file_);
      if (key == "depth" && x && (*x < 0 || *x != std::floor(*x))) {
        cx_.error(DiagCode::InvalidPieceSetting, v.span, "'depth' must be a non-negative integer");
      }
    }
  }

  // `skeleton NAME;`: the block is fitted to the tree grown by the lsystem NAME, of this file or
  // one it imports, so it must name one and have no attach rules of its own.
  void skeleton_setting(const ast::Expr& v, const ast::NameRef* name) {
    if (!name) {
      cx_.error(DiagCode::InvalidPieceSetting, v.span, "'skeleton' takes the name of an lsystem");
      return;
    }
    bool found = false;
    for (const ast::File& f : cx_.program.files) {
      for (const ast::Decl& d : f.decls) {
        const auto* ls = std::get_if<ast::LSystem>(&d);
        found = found || (ls && ls->name.name == name->name);
      }
    }
    if (!found) {
      cx_.error(DiagCode::UnknownLSystem, v.span, "no lsystem named '" + name->name + "'");
      cx_.note("'skeleton' names an lsystem block of this file or of a file it imports");
    }
    for (const ast::PiecesItem& item : ps_.items) {
      if (const auto* rule = std::get_if<ast::AttachRule>(&item)) {
        cx_.error(
            DiagCode::InvalidPieceSetting, v.span,
            "'skeleton' fits the pieces to a grown tree, but the block also has attach rules");
        cx_.note(rule->span, "the first attach rule");
        return;
      }
    }
  }

  CheckContext& cx_;
  std::uint32_t file_;
  const ast::Pieces& ps_;
  ExprEnv env_;
  std::unordered_map<std::string, const ast::PieceDecl*> pieces_;
  std::unordered_map<std::string, SourceSpan> rims_, rules_, settings_;
};

}  // namespace

void check_pieces(CheckContext& cx, std::uint32_t file, const ast::Pieces& ps) {
  PiecesChecker(cx, file, ps).run();
}

}  // namespace ramus::detail
