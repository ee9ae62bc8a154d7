// The engine-ready instance buffer read back by an independent reader written from
// docs/instance-buffer.md alone (byte offsets, little-endian), checked against the forest:
// header, draw ranges per piece type, skinning matrices, instance records, tiles; a CPU
// skinning shader fed only the buffer puts the vertices where the back end does, in the y-up
// frame of the glTF piece meshes it skins.
#include <cstring>

#include "core/up_axis.h"
#include "backends/pieces/output_instance_buffer.h"
#include "core/atomic_file.h"
#include "tests/pieces/output_fixture.h"

using namespace ramus;
using namespace ramus::pieces;
using namespace output_test;

namespace {

// The reader: what docs/instance-buffer.md describes, nothing else.
struct ReadBuffer {
  std::uint32_t version = 0, header_bytes = 0, types = 0, trees = 0, instances = 0, bones = 0,
                tiles = 0, ranges_at = 0, bones_at = 0, instances_at = 0, tiles_at = 0;
  struct Range {
    std::uint32_t first, count;
  };
  struct Instance {
    std::uint32_t bone_offset, tile_offset, tree;
    std::uint16_t type, joints;
  };
  std::vector<Range> ranges;
  std::vector<std::array<float, 16>> matrices;
  std::vector<Instance> records;
  std::vector<std::uint16_t> tile_slices;
};

std::uint32_t u32(const std::string& b, std::size_t at) {
  REQUIRE(at + 4 <= b.size());
  return std::uint32_t(std::uint8_t(b[at])) | std::uint32_t(std::uint8_t(b[at + 1])) << 8 |
         std::uint32_t(std::uint8_t(b[at + 2])) << 16 |
         std::uint32_t(std::uint8_t(b[at + 3])) << 24;
}
std::uint16_t u16(const std::string& b, std::size_t at) {
  REQUIRE(at + 2 <= b.size());
  return std::uint16_t(std::uint8_t(b[at]) | std::uint8_t(b[at + 1]) << 8);
}
float f32(const std::string& b, std::size_t at) {
  const std::uint32_t u = u32(b, at);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

ReadBuffer read_buffer(const std::string& b) {
  ReadBuffer r;
  REQUIRE(b.size() >= 48);
  REQUIRE(b.substr(0, 4) == "RPIB");
  std::uint32_t* fields[] = {&r.version,   &r.header_bytes, &r.types,   &r.trees,
                             &r.instances, &r.bones,        &r.tiles,   &r.ranges_at,
                             &r.bones_at,  &r.instances_at, &r.tiles_at};
  for (std::size_t i = 0; i < std::size(fields); ++i) *fields[i] = u32(b, 4 + 4 * i);
  REQUIRE(r.version == 1);
  REQUIRE(r.header_bytes == 48);
  REQUIRE(r.ranges_at == 48);
  REQUIRE(r.bones_at % 16 == 0);
  REQUIRE(r.bones_at >= r.ranges_at + 8 * r.types);
  REQUIRE(r.instances_at == r.bones_at + 64 * r.bones);
  REQUIRE(r.tiles_at == r.instances_at + 16 * r.instances);
  REQUIRE(b.size() == (r.tiles_at + 2 * r.tiles + 3) / 4 * 4);
  for (std::uint32_t t = 0; t < r.types; ++t)
    r.ranges.push_back({u32(b, r.ranges_at + 8 * t), u32(b, r.ranges_at + 8 * t + 4)});
  for (std::uint32_t g = 0; g < r.bones; ++g) {
    std::array<float, 16> m;
    for (int k = 0; k < 16; ++k) m[k] = f32(b, r.bones_at + 64 * g + 4 * k);
    r.matrices.push_back(m);
  }
  for (std::uint32_t i = 0; i < r.instances; ++i) {
    const std::size_t at = r.instances_at + 16 * i;
    r.records.push_back(
        {u32(b, at), u32(b, at + 4), u32(b, at + 8), u16(b, at + 12), u16(b, at + 14)});
  }
  for (std::uint32_t i = 0; i < r.tiles; ++i) r.tile_slices.push_back(u16(b, r.tiles_at + 2 * i));
  return r;
}

Vec3 apply(const std::array<float, 16>& m, const Vec3& p) {
  return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
          m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
          m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

}  // namespace

TEST_CASE("instance buffer: header, draw ranges, instances and tiles as documented",
          "[pieces][instance-buffer]") {
  const PieceSet set = lower_set();
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const Forest f = forest(set, seed, int(seed));
    const InstanceBufferBytes bytes = encode_instance_buffer(set, f, "forest.bin", "forest.glb");
    const ReadBuffer r = read_buffer(bytes.binary);
    CHECK(r.types == set.types.size());
    CHECK(r.trees == f.trees.size());
    CHECK(r.instances == piece_count(f));
    CHECK(r.bones == bone_count(f));
    // Ranges tile the instance array in type order; every record in a range has that type.
    std::uint32_t next = 0;
    for (std::uint32_t t = 0; t < r.types; ++t) {
      if (r.ranges[t].count == 0) continue;
      CHECK(r.ranges[t].first == next);
      for (std::uint32_t i = r.ranges[t].first; i < r.ranges[t].first + r.ranges[t].count; ++i) {
        CHECK(r.records[i].type == t);
        CHECK(r.records[i].joints == set.types[t].joints.size());
      }
      next += r.ranges[t].count;
    }
    CHECK(next == r.instances);
    // Every placed piece appears once with its bone window and its tiles.
    std::vector<std::uint32_t> tree_base;
    std::uint32_t base = 0;
    for (const Tree& t : f.trees) {
      tree_base.push_back(base);
      base += std::uint32_t(t.bones.size());
    }
    std::size_t matched = 0;
    for (const auto& rec : r.records) {
      REQUIRE(rec.tree < f.trees.size());
      const Tree& tree = f.trees[rec.tree];
      REQUIRE(rec.bone_offset >= tree_base[rec.tree]);
      const std::uint32_t local = rec.bone_offset - tree_base[rec.tree];
      REQUIRE(local < tree.bones.size());
      const std::uint32_t piece = tree.bones[local].piece;
      const PlacedPiece& p = tree.pieces[piece];
      CHECK(p.bone_offset == local);
      CHECK(p.type == rec.type);
      REQUIRE(rec.tile_offset + p.tiles.size() <= r.tiles);
      for (std::size_t q = 0; q < p.tiles.size(); ++q)
        CHECK(r.tile_slices[rec.tile_offset + q] == p.tiles[q]);
      ++matched;
    }
    CHECK(matched == piece_count(f));
    // The manifest names the files and the sections at the same offsets.
    const std::string& j = bytes.manifest;
    CHECK(j.find("\"format\": \"ramus-pieces-instance-buffer\"") != std::string::npos);
    CHECK(j.find("\"binary\": \"forest.bin\"") != std::string::npos);
    CHECK(j.find("\"meshes\": \"forest.glb\"") != std::string::npos);
    CHECK(j.find("\"bones\": {\"offset\": " + std::to_string(r.bones_at)) != std::string::npos);
    CHECK(j.find("\"instances\": {\"offset\": " + std::to_string(r.instances_at)) !=
          std::string::npos);
    CHECK(j.find("\"tiles\": {\"offset\": " + std::to_string(r.tiles_at)) != std::string::npos);
    CHECK(j.find("\"bytes\": " + std::to_string(bytes.binary.size())) != std::string::npos);
  }
}

TEST_CASE("instance buffer: a skinning shader fed only the buffer reproduces the posed pieces",
          "[pieces][instance-buffer]") {
  const PieceSet set = lower_set();
  const Forest f = forest(set, 21, 3);
  const ReadBuffer r = read_buffer(encode_instance_buffer(set, f, "f.bin").binary);
  std::vector<std::uint32_t> tree_base;
  std::uint32_t base = 0;
  for (const Tree& t : f.trees) {
    tree_base.push_back(base);
    base += std::uint32_t(t.bones.size());
  }
  double worst = 0;
  for (const auto& rec : r.records) {
    const Tree& tree = f.trees[rec.tree];
    const std::uint32_t piece = tree.bones[rec.bone_offset - tree_base[rec.tree]].piece;
    const PieceMesh& mesh = set.types[rec.type].lods[0];
    const SkinnedPiece expect = skin_piece(set, tree, bone_world(tree, tree.pose), piece, 0);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      // Section 4.3: the instance's bone offset is added to the piece-local blend indices. The
      // vertex is the glTF file's, y up.
      const Vec3 vertex = mesh::z_up_to_y_up(mesh.positions[v]);
      Vec3 p{0, 0, 0};
      for (int s = 0; s < 4; ++s) {
        if (mesh.weights[v][s] == 0) continue;
        p += apply(r.matrices.at(rec.bone_offset + mesh.joints[v][s]), vertex) *
             double(mesh.weights[v][s]);
      }
      worst = std::max(worst, distance(p, mesh::z_up_to_y_up(expect.positions[v])));
    }
  }
  CHECK(worst < 1e-3 * set.rim_radius);
}

TEST_CASE("instance buffer: same bytes for the same forest, manifest beside the binary",
          "[pieces][instance-buffer]") {
  const PieceSet set = lower_set();
  const auto a = encode_instance_buffer(set, forest(set, 8, 2), "a.bin");
  const auto b = encode_instance_buffer(set, forest(set, 8, 2), "a.bin");
  CHECK(a.binary == b.binary);
  CHECK(a.manifest == b.manifest);
  const fs::path dir = scratch("instance-buffer");
  const std::string manifest =
      write_instance_buffer(set, forest(set, 8, 2), (dir / "forest.bin").string(), "forest.glb");
  CHECK(manifest == (dir / "forest.json").string());
  CHECK(fs::file_size(dir / "forest.bin") == a.binary.size());
  CHECK_THROWS_AS(write_instance_buffer(set, forest(set, 8, 1), "/nonexistent-ramus/x.bin"),
                  WriteError);
}
