// Section 12 of an .rmb, the placed-pieces stream (rmb_piece_stream.h): quantized rotations,
// the joints' local transforms, writer and verifying reader.
#include "formats/rmb/rmb_piece_stream.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace ramus {

namespace {

using rmb::Reader;
using rmb::RmbError;
using rmb::Writer;

constexpr std::size_t kMaxName = 4096;
constexpr double kRotationQuantum = 1.0 / double(1 << kRmbRotationBits);

void check(bool ok, const std::string& what) {
  if (!ok) throw RmbError(0, "cannot encode the placed-pieces stream: " + what);
}

void write_f32(Writer& w, float f) { w.u32(std::bit_cast<std::uint32_t>(f)); }

void write_trs(Writer& w, const Trs& t) {
  for (double v : {t.t.x, t.t.y, t.t.z, t.r.w, t.r.x, t.r.y, t.r.z, t.s}) w.f64(v);
}

bool trs_ok(const Trs& t) {
  for (double v : {t.t.x, t.t.y, t.t.z, t.r.w, t.r.x, t.r.y, t.r.z, t.s})
    if (!std::isfinite(v)) return false;
  return t.s > 0;
}

// A similarity stored as 8 f64: finite, with a positive scale.
Trs read_trs(Reader& r, const char* what) {
  const std::size_t at = r.pos();
  Trs t;
  t.t.x = r.f64("tx");
  t.t.y = r.f64("ty");
  t.t.z = r.f64("tz");
  t.r.w = r.f64("rw");
  t.r.x = r.f64("rx");
  t.r.y = r.f64("ry");
  t.r.z = r.f64("rz");
  t.s = r.f64("scale");
  if (!trs_ok(t)) r.fail_at(at, std::string("expected ") + what + ": finite, with a scale > 0");
  return t;
}

float read_f32(Reader& r, const char* field) {
  const std::size_t at = r.pos();
  const float f = std::bit_cast<float>(r.u32(field));
  if (!std::isfinite(f)) r.fail_at(at, std::string("expected a finite ") + field);
  return f;
}

void write_joint(Writer& w, const RmbJointPose& j) {
  check(int(j.mode) <= 2 && j.rotation.largest <= 3, "a joint mode out of range");
  if (j.mode == RmbJointMode::Rest) {
    w.u8(0);
    return;
  }
  w.u8(std::uint8_t(int(j.mode) | (j.rotation.largest << 2)));
  for (std::int32_t k : j.rotation.k) {
    check(std::abs(k) <= kRmbRotationMaxK, "a quantized rotation out of range");
    w.svarint(k);
  }
  if (j.mode == RmbJointMode::Moved) {
    check(std::isfinite(j.t[0]) && std::isfinite(j.t[1]) && std::isfinite(j.t[2]) &&
              std::isfinite(j.s) && j.s > 0,
          "a moved joint with a non-finite translation or a scale <= 0");
    for (float f : j.t) write_f32(w, f);
    write_f32(w, j.s);
  }
}

RmbJointPose read_joint(Reader& r) {
  const std::size_t at = r.pos();
  const std::uint8_t code = r.u8("joint mode");
  RmbJointPose j;
  const int mode = code & 3;
  if (code >> 4 || mode == 3 || (mode == 0 && code != 0)) {
    r.fail_at(at,
              "expected a joint mode byte: 0 (rest), or 1 (turned) or 2 (moved) plus 4 x the "
              "largest rotation component (0..3), found " +
                  std::to_string(code));
  }
  if (r.tracing()) r.explain(mode == 0 ? "rest" : mode == 1 ? "turned" : "moved");
  j.mode = RmbJointMode(mode);
  if (j.mode == RmbJointMode::Rest) return j;
  j.rotation.largest = std::uint8_t(code >> 2);
  for (std::int32_t& k : j.rotation.k) {
    const std::size_t kat = r.pos();
    const std::int64_t v = r.svarint("rotation component");
    if (v < -kRmbRotationMaxK || v > kRmbRotationMaxK) {
      r.fail_at(kat, "expected a rotation component within +-" + std::to_string(kRmbRotationMaxK) +
                         ", found " + std::to_string(v));
    }
    k = std::int32_t(v);
  }
  if (j.mode == RmbJointMode::Moved) {
    for (float& f : j.t) f = read_f32(r, "translation");
    const std::size_t sat = r.pos();
    j.s = read_f32(r, "scale");
    if (!(j.s > 0)) r.fail_at(sat, "expected a scale > 0");
  }
  return j;
}

}  // namespace

bool RmbPieceStream::operator==(const RmbPieceStream& o) const {
  return set == o.set && tiles_per_type == o.tiles_per_type && twists == o.twists &&
         types == o.types && trees == o.trees;
}

RmbRotation rmb_quantize_rotation(const Quat& q) {
  const double c[4] = {q.w, q.x, q.y, q.z};
  double n = 0;
  int largest = 0;
  for (int i = 0; i < 4; ++i) {
    n += c[i] * c[i];
    if (std::abs(c[i]) > std::abs(c[largest])) largest = i;
  }
  n = std::sqrt(n);
  RmbRotation r;
  if (!(n > 0) || !std::isfinite(n)) return r;  // no rotation: the identity
  // q and -q are the same rotation: the sign that makes the largest component positive.
  const double scale = (c[largest] < 0 ? -1.0 : 1.0) / n;
  r.largest = std::uint8_t(largest);
  int j = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == largest) continue;
    const double k = std::round(c[i] * scale / kRotationQuantum);
    r.k[j++] = std::int32_t(std::clamp<double>(k, -kRmbRotationMaxK, kRmbRotationMaxK));
  }
  return r;
}

Quat rmb_rotation(const RmbRotation& r) {
  double c[4];
  double sum = 0;
  int j = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == r.largest) continue;
    c[i] = double(r.k[j++]) * kRotationQuantum;  // exact: k has at most 17 bits
    sum += c[i] * c[i];
  }
  c[r.largest] = std::sqrt(std::max(0.0, 1.0 - sum));
  return {c[0], c[1], c[2], c[3]};
}

Trs rmb_joint_rest(const RmbPieceStream& s, const RmbPlacedTree& tree, std::size_t piece,
                   std::size_t joint) {
  const RmbPlacedPiece& p = tree.pieces[piece];
  if (joint > 0) return s.types[p.type].leaves[joint - 1];
  if (p.parent == kRmbNoParent) return tree.placement;
  // The child's root joint hangs rigidly from the parent's terminal joint: only the twist.
  return Trs{{0, 0, 0}, s.twists[p.twist], 1.0};
}

Trs rmb_joint_local(const RmbPieceStream& s, const RmbPlacedTree& tree, std::size_t piece,
                    std::size_t joint) {
  const RmbPlacedPiece& p = tree.pieces[piece];
  const RmbJointPose* pose = joint < p.joints.size() ? &p.joints[joint] : nullptr;
  if (!pose || pose->mode == RmbJointMode::Rest) return rmb_joint_rest(s, tree, piece, joint);
  if (pose->mode == RmbJointMode::Turned) {
    Trs t = rmb_joint_rest(s, tree, piece, joint);
    t.r = t.r * rmb_rotation(pose->rotation);
    return t;
  }
  return Trs{{double(pose->t[0]), double(pose->t[1]), double(pose->t[2])},
             rmb_rotation(pose->rotation),
             double(pose->s)};
}

void write_rmb_piece_stream(Writer& w, const RmbPieceStream& s) {
  check(s.set.size() <= kMaxName, "the piece set's name is too long");
  w.str(s.set);
  w.varint(s.tiles_per_type[0]);
  w.varint(s.tiles_per_type[1]);
  for (const Quat& q : s.twists) {
    // A twist turns about the rim axis z: x and y are zero and not stored.
    check(q.x == 0 && q.y == 0 && !std::signbit(q.x) && !std::signbit(q.y) &&
              trs_ok(Trs{{0, 0, 0}, q, 1.0}),
          "a twist rotation that is not a finite rotation about z");
    w.f64(q.w);
    w.f64(q.z);
  }
  check(!s.types.empty() && s.types.size() <= kRmbMaxStreamTypes, "1..4096 piece types");
  w.varint(s.types.size());
  for (const RmbStreamType& t : s.types) {
    check(t.name.size() <= kMaxName, "a piece type's name is too long");
    check(t.leaves.size() <= kRmbMaxStreamLeaves, "piece " + t.name + " has over 255 leaf rims");
    check(t.quad_tile_type.size() <= kRmbMaxStreamQuads, "piece " + t.name + " has too many quads");
    w.str(t.name);
    w.varint(t.leaves.size());
    for (const Trs& b : t.leaves) {
      check(trs_ok(b), "piece " + t.name + " has a leaf rim transform that is not a similarity");
      write_trs(w, b);
    }
    w.varint(t.quad_tile_type.size());
    for (std::size_t q = 0; q < t.quad_tile_type.size(); q += 8) {
      std::uint8_t bits = 0;
      for (std::size_t b = 0; b < 8 && q + b < t.quad_tile_type.size(); ++b)
        if (t.quad_tile_type[q + b] == 2) bits |= std::uint8_t(1u << b);
      w.u8(bits);
    }
  }
  w.varint(s.trees.size());
  for (const RmbPlacedTree& tree : s.trees) {
    check(trs_ok(tree.placement), "a tree placement that is not a similarity");
    write_trs(w, tree.placement);
    w.varint(tree.tile_seed);
    check(!tree.pieces.empty(), "a tree without pieces");
    w.varint(tree.pieces.size());
    for (std::size_t i = 0; i < tree.pieces.size(); ++i) {
      const RmbPlacedPiece& p = tree.pieces[i];
      check(p.type < s.types.size(), "a piece type out of range");
      const RmbStreamType& type = s.types[p.type];
      check(p.joints.empty() || p.joints.size() == rmb_joint_count(type),
            "a piece whose joint poses do not match its type");
      w.varint(std::uint64_t(p.type) << 1 | (p.joints.empty() ? 0 : 1));
      if (i == 0) {
        check(p.parent == kRmbNoParent, "the first piece of a tree has a parent");
      } else {
        check(p.parent < i, "a piece before its parent, or without one");
        check(p.leaf < s.types[tree.pieces[p.parent].type].leaves.size() && p.twist < kRmbTwists,
              "a leaf rim or twist out of range");
        w.varint(i - p.parent);
        w.varint(std::uint64_t(p.leaf) * kRmbTwists + p.twist);
      }
      for (const RmbJointPose& j : p.joints) write_joint(w, j);
    }
  }
}

RmbPieceStream read_rmb_piece_stream(Reader& r) {
  RmbPieceStream s;
  s.set = r.str("piece set", kMaxName);
  s.tiles_per_type[0] = std::uint16_t(r.bounded("type-1 tiles", 0xffff));
  s.tiles_per_type[1] = std::uint16_t(r.bounded("type-2 tiles", 0xffff));
  for (Quat& q : s.twists) {
    const std::size_t at = r.pos();
    q.w = r.f64("twist rw");
    q.z = r.f64("twist rz");
    if (!trs_ok(Trs{{0, 0, 0}, q, 1.0})) r.fail_at(at, "expected a finite twist rotation");
  }
  const std::size_t at_types = r.pos();
  const std::size_t types = r.count("piece types", kRmbMaxStreamTypes, 3);
  if (types == 0) r.fail_at(at_types, "expected at least one piece type");
  for (std::size_t i = 0; i < types; ++i) {
    r.heading("piece type " + std::to_string(i));
    RmbStreamType t;
    t.name = r.str("name", kMaxName);
    const std::size_t leaves = r.count("leaf rims", kRmbMaxStreamLeaves, 64);
    for (std::size_t l = 0; l < leaves; ++l)
      t.leaves.push_back(read_trs(r, "a leaf rim transform"));
    const std::size_t quads = r.bounded("base quads", kRmbMaxStreamQuads);
    if ((quads + 7) / 8 > r.left())
      r.fail("expected " + std::to_string((quads + 7) / 8) + " bytes of quad tile types");
    t.quad_tile_type.resize(quads);
    for (std::size_t q = 0; q < quads; q += 8) {
      const std::uint8_t bits = r.u8("tile types (bit set: fork)");
      for (std::size_t b = 0; b < 8 && q + b < quads; ++b)
        t.quad_tile_type[q + b] = (bits >> b) & 1 ? 2 : 1;
    }
    s.types.push_back(std::move(t));
  }
  const std::size_t trees = r.count("trees", 0xffffffffu, 67);
  for (std::size_t k = 0; k < trees; ++k) {
    r.heading("tree " + std::to_string(k));
    RmbPlacedTree tree;
    tree.placement = read_trs(r, "a tree placement");
    tree.tile_seed = r.varint("tile seed");
    const std::size_t at_count = r.pos();
    const std::size_t pieces = r.count("pieces", 0xffffffffu, 1);
    if (pieces == 0) r.fail_at(at_count, "expected at least one piece");
    tree.pieces.reserve(pieces);
    for (std::size_t i = 0; i < pieces; ++i) {
      RmbPlacedPiece p;
      const std::size_t at = r.pos();
      const std::uint64_t head = r.varint("type << 1 | posed");
      if ((head >> 1) >= s.types.size()) {
        r.fail_at(at, "expected a piece type < " + std::to_string(s.types.size()) + ", found " +
                          std::to_string(head >> 1));
      }
      p.type = std::uint32_t(head >> 1);
      if (r.tracing()) r.explain(s.types[p.type].name + ((head & 1) ? ", posed" : ""));
      if (i > 0) {
        const std::size_t pat = r.pos();
        const std::uint64_t back = r.varint("parent back");
        if (back == 0 || back > i) {
          r.fail_at(pat, "expected a parent 1.." + std::to_string(i) + " pieces back, found " +
                             std::to_string(back));
        }
        p.parent = std::uint32_t(i - back);
        const RmbStreamType& pt = s.types[tree.pieces[p.parent].type];
        const std::size_t lat = r.pos();
        const std::uint64_t rim = r.varint("leaf * 6 + twist");
        if (rim / kRmbTwists >= pt.leaves.size()) {
          r.fail_at(lat, "expected a leaf rim < " + std::to_string(pt.leaves.size()) + " of " +
                             pt.name + ", found " + std::to_string(rim / kRmbTwists));
        }
        p.leaf = std::uint32_t(rim / kRmbTwists);
        p.twist = std::uint8_t(rim % kRmbTwists);
      }
      if (head & 1) {
        const std::size_t joints = rmb_joint_count(s.types[p.type]);
        for (std::size_t j = 0; j < joints; ++j) p.joints.push_back(read_joint(r));
      }
      tree.pieces.push_back(std::move(p));
    }
    s.trees.push_back(std::move(tree));
  }
  return s;
}

std::size_t rmb_piece_stream_tree_bytes(const RmbPieceStream& stream) {
  RmbPieceStream header = stream;
  header.trees.clear();
  Writer all, head;
  write_rmb_piece_stream(all, stream);
  write_rmb_piece_stream(head, header);
  return all.size() - head.size();
}

}  // namespace ramus
