// Every glTF these tests write goes through the Khronos glTF-Validator (tests/gltf/validate.js,
// npm gltf-validator in tools/) and must have 0 errors and 0 warnings; a deliberately broken file
// must fail, so the gate is known to work.
#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "backends/mesh/gltf_writer.h"
#include "core/atomic_file.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;
using namespace ramus::mesh;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "gltf";
  fs::create_directories(dir);
  return dir;
}

// Runs the validator; returns its exit code and appends its output to `out`.
int validate(const std::vector<fs::path>& files, std::string& out) {
  std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/gltf/validate.js\"";
  for (const auto& f : files) cmd += " \"" + f.string() + "\"";
  cmd += " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  REQUIRE(pipe);
  std::array<char, 512> buf;
  while (fgets(buf.data(), int(buf.size()), pipe.get())) out += buf.data();
  const int status = pclose(pipe.release());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<TreeMesh> tree(std::uint64_t seed, std::size_t nodes, int lods, LeafStyle style) {
  MeshOptions o;
  o.lod_count = lods;
  o.leaf_style = style;
  o.pipe_exponent = seed % 2 ? 2.0 : 0.0;
  return build_tree_lods(testing::synthetic_tree(seed, nodes), o);
}

}  // namespace

TEST_CASE("written glTF files pass the Khronos validator with no errors or warnings", "[gltf]") {
  const fs::path dir = scratch();
  std::vector<fs::path> files;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto lods = tree(seed, 200 * seed, 1 + int(seed % 4),
                           seed % 2 ? LeafStyle::kQuad : LeafStyle::kCrossed);
    const fs::path glb = dir / ("tree" + std::to_string(seed) + ".glb");
    const fs::path gltf = dir / ("tree " + std::to_string(seed) + ".gltf");  // a space in the name
    write_gltf(lods, glb.string());
    write_gltf(lods, gltf.string());
    files.push_back(glb);
    files.push_back(gltf);
  }
  // Bark only (no organs), and a tree large enough for 32-bit indices.
  Skeleton bare = testing::synthetic_tree(11, 300);
  bare.organs.clear();
  write_gltf({build_tree_mesh(bare, {})}, (dir / "bare.glb").string());
  files.push_back(dir / "bare.glb");
  write_gltf(tree(12, 20000, 2, LeafStyle::kQuad), (dir / "large.glb").string());
  files.push_back(dir / "large.glb");
  // A georeferenced tree: translated root and level nodes (MSFT_lod with 3 levels).
  Skeleton geo = testing::synthetic_tree(13, 400);
  for (SkeletonNode& n : geo.nodes) n.position += Vec3{1180000.37, 2860000.81, 312.4};
  for (OrganAnchor& a : geo.organs) a.position += Vec3{1180000.37, 2860000.81, 312.4};
  MeshOptions geo_options;
  geo_options.lod_count = 3;
  write_gltf(build_tree_lods(geo, geo_options), (dir / "geo.glb").string());
  files.push_back(dir / "geo.glb");
  // The wind skin and its animation, alone and compressed (Draco, meshopt), as .glb and .gltf;
  // also on the georeferenced tree, whose root joints then carry the local origin.
  MeshOptions wind_options;
  wind_options.wind = true;
  wind_options.lod_count = 3;
  const auto windy = build_tree_lods(testing::synthetic_tree(14, 600), wind_options);
  for (const auto& [name, how] :
       {std::pair{"wind", GltfCompression::kNone}, std::pair{"draco", GltfCompression::kDraco},
        std::pair{"meshopt", GltfCompression::kMeshopt}}) {
    for (const char* ext : {".glb", ".gltf"}) {
      const fs::path f = dir / (std::string(name) + ext);
      write_gltf(windy, f.string(), how);
      files.push_back(f);
    }
  }
  write_gltf(build_tree_lods(geo, wind_options), (dir / "geo_wind.glb").string());
  files.push_back(dir / "geo_wind.glb");
  // Polygon organs (ABOP's `{ . }`) sway with the node they grew on, as leaf cards do.
  Skeleton polygons = testing::synthetic_tree(16, 600);
  REQUIRE(!polygons.organs.empty());
  for (OrganAnchor& a : polygons.organs) {
    const Vec3 p = a.position;
    a.vertices = {p, p + Vec3{0.05, 0, 0.02}, p + Vec3{0.06, 0.03, 0.05}, p + Vec3{0, 0.02, 0.04}};
  }
  const auto windy_polygons = build_tree_lods(polygons, wind_options);
  REQUIRE(windy_polygons.front().surfaces.triangle_count() > 0);
  write_gltf(windy_polygons, (dir / "polygons_wind.glb").string());
  files.push_back(dir / "polygons_wind.glb");
  write_gltf(tree(15, 800, 2, LeafStyle::kCrossed), (dir / "plain_draco.glb").string(),
             GltfCompression::kDraco);
  files.push_back(dir / "plain_draco.glb");
  std::string out;
  const int code = validate(files, out);
  INFO(out);
  CHECK(code == 0);
  CHECK(out.find("0 errors, 0 warnings") != std::string::npos);
}

TEST_CASE("the validator gate rejects a broken file", "[gltf]") {
  const fs::path dir = scratch();
  const fs::path gltf = dir / "broken.gltf";
  write_gltf(tree(3, 300, 1, LeafStyle::kQuad), gltf.string());
  const fs::path bin = dir / "broken.bin";
  std::string bytes = slurp(bin);
  bytes.resize(bytes.size() / 2);  // the buffer is now shorter than its byteLength
  write_file_atomically(bin.string(), bytes);
  std::string out;
  CHECK(validate({gltf}, out) == 1);
  INFO(out);
  CHECK(out.find("error") != std::string::npos);
}

TEST_CASE("glTF layout: nodes, LOD meshes, materials and the wind attribute", "[gltf]") {
  const auto bytes = encode_gltf(tree(5, 500, 3, LeafStyle::kQuad), false, "t.bin");
  const std::string& json = bytes.main;
  CHECK(json.find("\"generator\":\"ramus\"") != std::string::npos);
  for (const char* s : {"\"tree_LOD0\"", "\"tree_LOD1\"", "\"tree_LOD2\"", "\"_WIND\"",
                        "\"alphaMode\":\"MASK\"", "\"name\":\"bark\"", "\"name\":\"leaf\"",
                        "\"uri\":\"t.bin\"", "\"target\":34962", "\"target\":34963"}) {
    CHECK(json.find(s) != std::string::npos);
  }
  CHECK(json.find("COLOR_0") == std::string::npos);
  CHECK(bytes.bin.size() % 4 == 0);
}

TEST_CASE("glTF output is byte-identical for the same input", "[gltf]") {
  const auto a = encode_gltf(tree(9, 800, 2, LeafStyle::kCrossed), true);
  const auto b = encode_gltf(tree(9, 800, 2, LeafStyle::kCrossed), true);
  CHECK(a.main == b.main);
  CHECK(a.main.substr(0, 4) == "glTF");
}

TEST_CASE("unwritable glTF paths give a clear error and leave no file", "[gltf]") {
  const auto lods = tree(2, 100, 1, LeafStyle::kQuad);
  const std::string path = "/nonexistent-ramus-dir/out.glb";
  REQUIRE_THROWS_AS(write_gltf(lods, path), WriteError);
  CHECK_FALSE(fs::exists(path));
  CHECK_THROWS_AS(write_gltf(lods, (scratch() / "x.fbx").string()), MeshError);
  CHECK_THROWS_WITH(write_gltf({build_tree_mesh(Skeleton{}, {})}, (scratch() / "e.glb").string()),
                    Catch::Contains("no geometry"));
  CHECK_FALSE(fs::exists(scratch() / "e.glb"));
}
