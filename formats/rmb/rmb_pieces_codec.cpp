// Section 10 of an .rmb, piece sets (docs/binary-format.md): writer and verifying reader.
#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "formats/rmb/rmb_pieces.h"

namespace ramus {

namespace {

using rmb::Reader;
using rmb::RmbError;
using rmb::Writer;

const RmbPieceKindInfo kKinds[kRmbPieceKinds] = {
    {"tube", {"length", "taper"}, {"top"}},
    {"fork", {"length", "angle", "taper"}, {"left", "right"}},
    {"trifurcation", {"length", "angle", "taper", "planar"}, {"left", "middle", "right"}},
    {"attachment", {"length", "angle", "taper", "branch"}, {"stem", "branch"}},
    {"mesh", {}, {}},
    {"mesh", {}, {}},
};

constexpr std::size_t kMaxName = 4096;

bool builtin(RmbPieceKind k) { return k != RmbPieceKind::Mesh && k != RmbPieceKind::MeshPath; }

void check(bool ok, const std::string& what) {
  if (!ok) throw RmbError(0, "cannot encode pieces: " + what);
}

std::string extension_of(std::string_view name) {
  const std::size_t dot = name.rfind('.');
  std::string ext(dot == std::string_view::npos ? std::string_view() : name.substr(dot));
  for (char& c : ext) c = char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

// Twist as the flags byte holds it (bits 2..4): 0 not written, 1..6 twist 0..5, 7 any.
std::uint8_t twist_code(const std::optional<std::uint8_t>& t) {
  if (!t) return 0;
  return *t == kRmbTwistAny ? 7 : std::uint8_t(*t + 1);
}

}  // namespace

const RmbPieceKindInfo& rmb_piece_kind(RmbPieceKind kind) { return kKinds[int(kind)]; }

std::optional<RmbPieceKind> rmb_piece_kind_named(std::string_view name) {
  for (int k = 0; k < kRmbPieceKinds; ++k) {
    if (kKinds[k].name == name) return RmbPieceKind(k);
  }
  return std::nullopt;
}

bool rmb_mesh_name_ok(std::string_view name) {
  if (name.empty() || name.size() > 255 || name[0] == '.') return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok) return false;
  }
  const std::string ext = extension_of(name);
  return ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

void write_rmb_pieces(Writer& w, const RmbPieces& pieces) {
  std::set<std::string> names;
  w.varint(pieces.meshes.size());
  for (const RmbMeshFile& m : pieces.meshes) {
    check(rmb_mesh_name_ok(m.name), "the mesh file name \"" + m.name + "\"");
    check(m.bytes.size() <= kRmbMaxMeshBytes, "mesh file " + m.name + " is over 16 MiB");
    check(names.insert(m.name).second, "two mesh files named " + m.name);
    w.str(m.name);
    w.str(m.bytes);
  }
  check(!pieces.sets.empty(), "no pieces block");
  std::vector<bool> used(pieces.meshes.size(), false);
  for (const RmbPieceSet& s : pieces.sets) {
    for (const RmbPiece& p : s.pieces) {
      if (p.kind == RmbPieceKind::Mesh && p.mesh < used.size()) used[p.mesh] = true;
    }
  }
  check(std::find(used.begin(), used.end(), false) == used.end(), "a mesh file no piece uses");
  w.varint(pieces.sets.size());
  for (const RmbPieceSet& s : pieces.sets) {
    check(!s.name.empty(), "a pieces block without a name");
    check(!s.pieces.empty() && s.pieces.size() <= kRmbMaxPiecesPerSet,
          "pieces block " + s.name + " has no pieces or more than 4096");
    check(s.root < s.pieces.size(), "the root of " + s.name + " is not one of its pieces");
    check(!s.twist || *s.twist <= kRmbTwistAny, "'twist' of " + s.name + " is not 0..5 or any");
    check(!s.depth || *s.depth <= kRmbMaxPieceDepth, "'depth' of " + s.name + " is above 4096");
    check(s.rim || !s.rim_radius, "a rim radius without a rim");
    w.str(s.name);
    w.u8(std::uint8_t((s.rim ? 1 : 0) | (s.rim_radius ? 2 : 0) | (twist_code(s.twist) << 2) |
                      (s.depth ? 32 : 0)));
    if (s.rim_radius) {
      check(w.stored_real(*s.rim_radius) > 0 && std::isfinite(*s.rim_radius),
            "the rim radius of " + s.name + " is not positive (at this tolerance)");
      w.real(*s.rim_radius);
    }
    if (s.depth) w.varint(*s.depth);
    w.varint(s.pieces.size());
    for (const RmbPiece& p : s.pieces) {
      check(!p.name.empty(), "a piece without a name");
      w.str(p.name);
      w.u8(std::uint8_t(p.kind));
      if (builtin(p.kind)) {
        const RmbPieceKindInfo& info = rmb_piece_kind(p.kind);
        check(p.args.size() == info.args.size(), "piece " + p.name + ": the argument count");
        std::uint8_t mask = 0;
        for (std::size_t k = 0; k < p.args.size(); ++k) {
          if (p.args[k]) mask = std::uint8_t(mask | (1u << k));
        }
        w.u8(mask);
        for (const std::optional<double>& a : p.args) {
          if (!a) continue;
          check(std::isfinite(*a), "piece " + p.name + ": an argument that is not finite");
          w.real(*a);
        }
      } else if (p.kind == RmbPieceKind::Mesh) {
        check(p.mesh < pieces.meshes.size(), "piece " + p.name + ": no such mesh file");
        w.varint(p.mesh);
      } else {
        check(!p.path.empty(), "piece " + p.name + ": an empty mesh path");
        w.str(p.path);
      }
    }
    w.varint(s.root);
    w.varint(s.rules.size());
    for (const RmbAttachRule& r : s.rules) {
      check(r.piece < s.pieces.size(), "an attach rule on a piece outside the block");
      w.varint(r.piece);
      const RmbPiece& from = s.pieces[r.piece];
      if (builtin(from.kind)) {
        const std::vector<std::string_view>& rims = rmb_piece_kind(from.kind).rims;
        std::size_t k = 0;
        while (k < rims.size() && rims[k] != r.rim) ++k;
        check(k < rims.size(), "piece " + from.name + " has no rim " + r.rim);
        w.varint(k);
      } else {
        check(!r.rim.empty(), "an attach rule without a rim");
        w.str(r.rim);
      }
      check(!r.targets.empty(), "an attach rule without targets");
      w.varint(r.targets.size());
      for (const RmbAttachTarget& t : r.targets) {
        check(t.piece < s.pieces.size(), "an attach target outside the block");
        w.varint((std::uint64_t(t.piece) << 1) | (t.weight ? 1 : 0));
        if (t.weight) {
          check(std::isfinite(*t.weight) && w.stored_real(*t.weight) > 0,
                "a weight in " + s.name + " is not positive (at this tolerance)");
          w.real(*t.weight);
        }
      }
    }
  }
}

RmbPieces read_rmb_pieces(Reader& r) {
  RmbPieces out;
  const std::size_t nm = r.count("mesh files", 4096, 2);
  std::set<std::string> names;
  for (std::size_t i = 0; i < nm; ++i) {
    r.heading("mesh file " + std::to_string(i));
    RmbMeshFile m;
    const std::size_t at = r.pos();
    m.name = r.str("name", 255);
    if (!rmb_mesh_name_ok(m.name)) {
      r.fail_at(
          at, "expected a plain file name ending in .obj, .gltf or .glb, found \"" + m.name + "\"");
    }
    if (!names.insert(m.name).second) r.fail_at(at, "expected a new mesh file name");
    m.bytes = std::string(r.blob("bytes", kRmbMaxMeshBytes));
    out.meshes.push_back(std::move(m));
  }
  std::vector<bool> used(nm, false);
  const std::size_t at_sets = r.pos();
  const std::size_t ns = r.count("pieces blocks", 4096, 6);
  if (ns == 0) r.fail_at(at_sets, "expected at least one pieces block");
  for (std::size_t b = 0; b < ns; ++b) {
    r.heading("pieces " + std::to_string(b));
    RmbPieceSet s;
    const std::size_t name_at = r.pos();
    s.name = r.str("name", kMaxName);
    if (s.name.empty()) r.fail_at(name_at, "expected a non-empty pieces block name");
    const std::uint8_t flags = r.u8("settings");
    if (flags > 63 || ((flags & 2) && !(flags & 1))) {
      r.fail_at(r.pos() - 1, "expected flags <= 63, the radius bit only with the rim bit");
    }
    s.rim = flags & 1;
    const std::uint8_t twist = (flags >> 2) & 7;
    if (twist == 7) s.twist = kRmbTwistAny;
    if (twist >= 1 && twist <= 6) s.twist = std::uint8_t(twist - 1);
    r.explain(std::string(s.rim ? "rim" : "no rim") + (flags & 2 ? ", radius" : "") +
              (twist == 0   ? ""
               : twist == 7 ? ", twist any"
                            : ", twist " + std::to_string(twist - 1)) +
              (flags & 32 ? ", depth" : ""));
    if (flags & 2) {
      const std::size_t at = r.pos();
      s.rim_radius = r.real("rim radius");
      if (!(*s.rim_radius > 0) || !std::isfinite(*s.rim_radius)) {
        r.fail_at(at, "expected a positive rim radius");
      }
    }
    if (flags & 32) s.depth = std::uint32_t(r.bounded("depth", kRmbMaxPieceDepth));
    const std::size_t np_at = r.pos();
    const std::size_t np = r.count("pieces", kRmbMaxPiecesPerSet, 3);
    if (np == 0) r.fail_at(np_at, "expected at least one piece");
    std::set<std::string> piece_names;
    for (std::size_t i = 0; i < np; ++i) {
      r.heading("piece " + std::to_string(i));
      RmbPiece p;
      const std::size_t at = r.pos();
      p.name = r.str("name", kMaxName);
      if (p.name.empty() || !piece_names.insert(p.name).second) {
        r.fail_at(at, "expected a new, non-empty piece name, found \"" + p.name + "\"");
      }
      const std::uint8_t kind = r.u8("kind");
      if (kind >= kRmbPieceKinds) r.fail_at(r.pos() - 1, "expected a piece kind 0..5");
      p.kind = RmbPieceKind(kind);
      r.explain(p.kind == RmbPieceKind::MeshPath ? "mesh path"
                : p.kind == RmbPieceKind::Mesh   ? "mesh file"
                                                 : std::string(rmb_piece_kind(p.kind).name));
      if (builtin(p.kind)) {
        const std::size_t nargs = rmb_piece_kind(p.kind).args.size();
        const std::uint8_t mask = r.u8("arguments given");
        if (mask >> nargs) {
          r.fail_at(r.pos() - 1, "expected an argument mask below " + std::to_string(1u << nargs));
        }
        p.args.resize(nargs);
        for (std::size_t k = 0; k < nargs; ++k) {
          if (!(mask >> k & 1)) continue;
          const std::size_t va = r.pos();
          p.args[k] = r.real(std::string(rmb_piece_kind(p.kind).args[k]).c_str());
          if (!std::isfinite(*p.args[k])) r.fail_at(va, "expected a finite argument");
        }
      } else if (p.kind == RmbPieceKind::Mesh) {
        if (nm == 0) r.fail("expected a mesh file index, but the section has no mesh files");
        p.mesh = std::uint32_t(r.bounded("mesh file", nm - 1));
        used[p.mesh] = true;
      } else {
        const std::size_t pa = r.pos();
        p.path = r.str("path", kMaxName);
        if (p.path.empty()) r.fail_at(pa, "expected a non-empty mesh path");
      }
      s.pieces.push_back(std::move(p));
    }
    s.root = std::uint32_t(r.bounded("root", np - 1));
    r.explain(s.pieces[s.root].name);
    const std::size_t nr = r.count("attach rules", kMaxName * np, 3);
    std::set<std::pair<std::uint32_t, std::string>> seen;
    for (std::size_t i = 0; i < nr; ++i) {
      r.heading("attach rule " + std::to_string(i));
      RmbAttachRule rule;
      const std::size_t at = r.pos();
      rule.piece = std::uint32_t(r.bounded("piece", np - 1));
      const RmbPiece& from = s.pieces[rule.piece];
      r.explain(from.name);
      if (builtin(from.kind)) {
        const std::vector<std::string_view>& rims = rmb_piece_kind(from.kind).rims;
        rule.rim = std::string(rims[r.bounded("rim", rims.size() - 1)]);
        r.explain(rule.rim);
      } else {
        const std::size_t ra = r.pos();
        rule.rim = r.str("rim", kMaxName);
        if (rule.rim.empty()) r.fail_at(ra, "expected a non-empty rim name");
      }
      if (!seen.emplace(rule.piece, rule.rim).second) {
        r.fail_at(at, "expected one rule per piece and rim, found a second for " + from.name + "." +
                          rule.rim);
      }
      const std::size_t nt_at = r.pos();
      const std::size_t nt = r.count("targets", np * 64, 1);
      if (nt == 0) r.fail_at(nt_at, "expected at least one target");
      for (std::size_t k = 0; k < nt; ++k) {
        RmbAttachTarget t;
        const std::uint64_t v = r.bounded("piece << 1 | weighted", (std::uint64_t(np) << 1) - 1);
        t.piece = std::uint32_t(v >> 1);
        r.explain(s.pieces[t.piece].name + (v & 1 ? ", weighted" : ""));
        if (v & 1) {
          const std::size_t wa = r.pos();
          t.weight = r.real("weight");
          if (!(*t.weight > 0) || !std::isfinite(*t.weight)) {
            r.fail_at(wa, "expected a positive weight");
          }
        }
        rule.targets.push_back(t);
      }
      s.rules.push_back(std::move(rule));
    }
    out.sets.push_back(std::move(s));
  }
  for (std::size_t i = 0; i < nm; ++i) {
    if (!used[i])
      r.fail("expected every mesh file to be used, but mesh file " + std::to_string(i) + " is not");
  }
  return out;
}

}  // namespace ramus
