#include "formats/rmb/rmb_pieces_ast.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <unordered_map>

#include "core/input_file.h"
#include "core/number_text.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompiled_number.h"
#include "grammar/const_eval.h"
#include "grammar/program_constants.h"

namespace ramus {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& block, const std::string& what) {
  throw RmbError(0, "cannot encode pieces " + block + ": " + what);
}

// const and param of every file, imports first, as backends/pieces/lower_pieces.cpp folds them.
class Constants {
 public:
  Constants(const Program& program, const RmbPiecesOptions& options)
      : values_(program_constants(program, options.defines)) {}

  std::optional<double> fold(const ast::Expr& e) const {
    return fold_constant(e, lookup_in(values_));
  }

 private:
  std::unordered_map<std::string, double> values_;
};

std::string read_bytes(const fs::path& p, const std::string& block) {
  std::string bytes, error;
  if (!read_input_file(p, bytes, error)) {
    refuse(block, "cannot read the mesh file " + p.string() + ": " + error);
  }
  return bytes;
}

// A .gltf may name its buffers and images as files beside it; embedded alone it would lose
// them. Every "uri" must be a data: URI (a .glb carries its buffer inside).
bool gltf_self_contained(std::string_view text) {
  std::size_t at = 0;
  while ((at = text.find("\"uri\"", at)) != std::string_view::npos) {
    at += 5;
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t' || text[at] == '\n' ||
                                text[at] == '\r' || text[at] == ':')) {
      ++at;
    }
    if (text.substr(at, 6) != "\"data:") return false;
  }
  return true;
}

class Builder {
 public:
  Builder(const Program& program, const std::string& root_file, const RmbPiecesOptions& options)
      : consts_(program, options), dir_(fs::path(root_file).parent_path()), opt_(options) {}

  RmbPieceSet block(const ast::Pieces& b) {
    RmbPieceSet s;
    s.name = b.name.name;
    block_ = s.name;
    for (const ast::PiecesItem& item : b.items) {
      if (const auto* p = std::get_if<ast::PieceDecl>(&item)) s.pieces.push_back(piece(*p));
    }
    if (s.pieces.empty()) refuse(block_, "it has no pieces");
    for (const ast::PiecesItem& item : b.items) {
      if (const auto* r = std::get_if<ast::RimDecl>(&item)) rim(s, *r);
      if (const auto* a = std::get_if<ast::AttachRule>(&item)) s.rules.push_back(attach(s, *a));
      if (const auto* st = std::get_if<ast::PieceSetting>(&item)) setting(s, *st);
    }
    return s;
  }

  std::vector<RmbMeshFile> meshes;

 private:
  double number(const ast::Expr& e, const char* what) {
    const std::optional<double> v = consts_.fold(e);
    if (!v) refuse(block_, std::string(what) + " is not a constant");
    return *v;
  }

  std::uint32_t piece_index(const RmbPieceSet& s, const std::string& name) {
    for (std::size_t i = 0; i < s.pieces.size(); ++i) {
      if (s.pieces[i].name == name) return std::uint32_t(i);
    }
    refuse(block_, "unknown piece '" + name + "'");
  }

  // The file once in the mesh table: the same file (by content and name) is shared.
  std::uint32_t embed(const std::string& path) {
    fs::path file = path;
    if (file.is_relative()) file = dir_ / file;
    std::string bytes = read_bytes(file, block_);
    std::string name = file.filename().string();
    const std::string ext = file.extension().string();
    std::string lower = ext;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (lower == ".gltf" && !gltf_self_contained(bytes)) {
      refuse(block_, path +
                         " refers to files beside it (a \"uri\" that is not data:); embed a .glb "
                         "or build with --mesh-paths");
    }
    if (!rmb_mesh_name_ok(name)) {  // keep the extension, make the rest a plain name
      std::string stem = file.stem().string();
      for (char& c : stem) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
      }
      if (stem.empty() || stem[0] == '.') stem = "mesh" + stem;
      name = stem.substr(0, 200) + ext;
      if (!rmb_mesh_name_ok(name))
        refuse(block_, "the mesh file " + path + " is no .obj, .gltf or .glb");
    }
    const std::string base = name.substr(0, name.size() - ext.size());
    for (int k = 2;; ++k) {
      auto same = std::find_if(meshes.begin(), meshes.end(),
                               [&](const RmbMeshFile& m) { return m.name == name; });
      if (same == meshes.end()) break;
      if (same->bytes == bytes) return std::uint32_t(same - meshes.begin());
      name = base + "_" + std::to_string(k) + ext;
    }
    if (bytes.size() > kRmbMaxMeshBytes)
      refuse(block_, "the mesh file " + path + " is over 16 MiB");
    meshes.push_back(RmbMeshFile{name, std::move(bytes)});
    return std::uint32_t(meshes.size() - 1);
  }

  RmbPiece piece(const ast::PieceDecl& d) {
    RmbPiece p;
    p.name = d.name.name;
    const ast::Constructor& c = d.ctor;
    const std::optional<RmbPieceKind> kind = rmb_piece_kind_named(c.kind.name);
    if (!kind) refuse(block_, "unknown piece kind '" + c.kind.name + "'");
    p.kind = *kind;
    if (p.kind == RmbPieceKind::Mesh) {
      if (!c.path || !c.args.empty()) refuse(block_, "'mesh' takes one file name");
      if (opt_.mesh_paths) {
        p.kind = RmbPieceKind::MeshPath;
        p.path = *c.path;
      } else {
        p.mesh = embed(*c.path);
      }
      return p;
    }
    if (c.path) refuse(block_, "'" + c.kind.name + "' takes numbers, not a file name");
    const RmbPieceKindInfo& info = rmb_piece_kind(p.kind);
    p.args.resize(info.args.size());
    std::size_t pos = 0;
    for (const ast::NamedArg& a : c.args) {  // positional, then by name; the last one wins
      std::size_t k = a.name.name.empty() ? pos++ : info.args.size();
      for (std::size_t i = 0; i < info.args.size() && !a.name.name.empty(); ++i) {
        if (info.args[i] == a.name.name) k = i;
      }
      if (k >= info.args.size()) {
        refuse(block_, a.name.name.empty()
                           ? "'" + c.kind.name + "' takes at most " +
                                 std::to_string(info.args.size()) + " arguments"
                           : "'" + c.kind.name + "' has no argument '" + a.name.name + "'");
      }
      p.args[k] = number(a.value, "a piece argument");
    }
    return p;
  }

  void rim(RmbPieceSet& s, const ast::RimDecl& r) {
    if (r.name.name != "hexagon") refuse(block_, "the rim is a hexagon, not '" + r.name.name + "'");
    s.rim = true;
    for (const ast::NamedArg& a : r.args) {
      if (!a.name.name.empty() && a.name.name != "radius") {
        refuse(block_, "'hexagon' has no argument '" + a.name.name + "'");
      }
      s.rim_radius = number(a.value, "the rim radius");
    }
  }

  RmbAttachRule attach(const RmbPieceSet& s, const ast::AttachRule& a) {
    RmbAttachRule rule;
    rule.piece = piece_index(s, a.piece.name);
    rule.rim = a.rim.name;
    for (const ast::WeightedPiece& w : a.targets) {
      RmbAttachTarget t;
      t.piece = piece_index(s, w.piece.name);
      if (w.weight) t.weight = number(*w.weight, "a weight");
      rule.targets.push_back(t);
    }
    return rule;
  }

  void setting(RmbPieceSet& s, const ast::PieceSetting& st) {
    const std::string& key = st.key.name;
    if (st.values.size() != 1) refuse(block_, "'" + key + "' takes one value");
    const ast::Expr& v = st.values[0];
    const auto* name = std::get_if<ast::NameRef>(&v.node);
    auto integer = [&](double hi) {
      const double x = number(v, key.c_str());
      if (!(x >= 0 && x <= hi) || x != std::floor(x)) {
        refuse(block_, "'" + key + "' " + shortest_text(x) + " is not an integer in 0.." +
                           shortest_text(hi));
      }
      return std::uint32_t(x);
    };
    if (key == "root") {
      if (!name) refuse(block_, "'root' takes the name of a piece");
      s.root = piece_index(s, name->name);
    } else if (key == "twist") {
      s.twist = name && name->name == "any" ? kRmbTwistAny : std::uint8_t(integer(5));
    } else if (key == "depth") {
      s.depth = integer(kRmbMaxPieceDepth);
    } else if (key == "skeleton") {
      // Not stored: a binary holds one lsystem, the tree a skeleton-fitted block is fitted to.
    } else {
      refuse(block_, "the setting '" + key + "'");
    }
  }

  Constants consts_;
  fs::path dir_;
  const RmbPiecesOptions& opt_;
  std::string block_;
};

ast::Identifier ident(std::string name) { return ast::Identifier{std::move(name), {}}; }
ast::Expr name_expr(std::string name) {
  return ast::Expr{ast::NameRef{std::move(name)}, {}, false};
}

}  // namespace

RmbPieces piece_sets_of(const Program& program, const std::string& root_file,
                        const RmbPiecesOptions& options) {
  RmbPieces out;
  if (program.files.empty()) return out;
  Builder b(program, root_file, options);
  for (const ast::Decl& d : program.files[0].decls) {
    if (const auto* p = std::get_if<ast::Pieces>(&d)) out.sets.push_back(b.block(*p));
  }
  out.meshes = std::move(b.meshes);
  return out;
}

ast::Pieces pieces_to_ast(const RmbPieceSet& s, const RmbPieces& all) {
  ast::Pieces out;
  out.name = ident(s.name);
  if (s.rim) {
    ast::RimDecl r;
    r.name = ident("hexagon");
    if (s.rim_radius)
      r.args.push_back(ast::NamedArg{ident("radius"), decompiled_number(*s.rim_radius)});
    out.items.emplace_back(std::move(r));
  }
  for (const RmbPiece& p : s.pieces) {
    ast::PieceDecl d;
    d.name = ident(p.name);
    const RmbPieceKindInfo& info = rmb_piece_kind(p.kind);
    d.ctor.kind = ident(std::string(info.name));
    for (std::size_t k = 0; k < p.args.size(); ++k) {
      if (p.args[k]) {
        d.ctor.args.push_back(
            ast::NamedArg{ident(std::string(info.args[k])), decompiled_number(*p.args[k])});
      }
    }
    if (p.kind == RmbPieceKind::Mesh) d.ctor.path = all.meshes.at(p.mesh).name;
    if (p.kind == RmbPieceKind::MeshPath) d.ctor.path = p.path;
    out.items.emplace_back(std::move(d));
  }
  auto setting = [&out](const char* key, ast::Expr value) {
    ast::PieceSetting st;
    st.key = ident(key);
    st.values.push_back(std::move(value));
    out.items.emplace_back(std::move(st));
  };
  setting("root", name_expr(s.pieces.at(s.root).name));
  for (const RmbAttachRule& r : s.rules) {
    ast::AttachRule a;
    a.piece = ident(s.pieces.at(r.piece).name);
    a.rim = ident(r.rim);
    for (const RmbAttachTarget& t : r.targets) {
      ast::WeightedPiece w;
      w.piece = ident(s.pieces.at(t.piece).name);
      if (t.weight) w.weight = decompiled_number(*t.weight);
      a.targets.push_back(std::move(w));
    }
    out.items.emplace_back(std::move(a));
  }
  if (s.twist) {
    setting("twist", *s.twist == kRmbTwistAny ? name_expr("any") : decompiled_number(*s.twist));
  }
  if (s.depth) setting("depth", decompiled_number(*s.depth));
  return out;
}

}  // namespace ramus
