// How the mesh commands write assets engines load as they are: glTF from every bundled tree is
// y up with its base at the origin; --lod-files writes one file per level; OBJ and PLY follow
// --up (default y for OBJ, z for PLY); a georeferenced scan's mesh keeps its UTM offset outside
// the float vertices; options that do not apply are errors.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "formats/skeleton_json.h"
#include "tests/backends/glb_reader.h"

namespace {

namespace fs = std::filesystem;
using cli_test::run_ramus;
using cli_test::slurp;
using ramus::Vec3;
using ramus::testing::item;

std::string tree_example(const std::string& name) {
  return std::string(RAMUS_SOURCE_DIR) + "/examples/trees/" + name + ".ramus";
}

// Bounds of the OBJ's `v` lines.
void obj_bounds(const std::string& text, Vec3& lo, Vec3& hi) {
  lo = {1e30, 1e30, 1e30};
  hi = {-1e30, -1e30, -1e30};
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream v(line.substr(2));
    Vec3 p;
    v >> p.x >> p.y >> p.z;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
}

}  // namespace

TEST_CASE("glTF of every bundled tree stands up along +Y with its base at the origin",
          "[cli][gltf][axes]") {
  cli_test::TempDir dir;
  for (const char* name : {"broadleaf", "conifer", "weeping"}) {
    const fs::path out = dir.path / (std::string(name) + ".glb");
    REQUIRE(run_ramus({"-q", "build", tree_example(name), "-o", out.string()}).status == 0);
    const auto g = ramus::testing::read_glb(slurp(out));
    const int pos = ramus::testing::attribute_accessor(g, 0, 0, "POSITION");
    const Vec3 lo = accessor_bound(g, pos, "min"), hi = accessor_bound(g, pos, "max");
    const Vec3 size = hi - lo;
    INFO(name << ": size " << size.x << " x " << size.y << " x " << size.z);
    CHECK(size.y > size.x);  // tallest along +Y
    CHECK(size.y > size.z);
    CHECK(hi.y > 0.9 * size.y);
    // The trunk's base is at the ground plane (weeping whips may hang lower): the lowest vertex
    // near the vertical axis.
    double base = 1e30;
    for (const ramus::Vec3f& p : read_vec3(g, pos)) {
      if (std::hypot(p.x, p.z) < 0.01 * size.y) base = std::min(base, double(p.y));
    }
    CHECK(base == Approx(0).margin(1e-3 * size.y));
    CHECK(std::abs(lo.x + hi.x) / 2 < 0.25 * size.y);  // and the crown around the vertical axis
    CHECK(std::abs(lo.z + hi.z) / 2 < 0.25 * size.y);
    CHECK(item(g.at("nodes"), 0).find("translation") == nullptr);
  }
}

TEST_CASE("ramus build --lod-files writes one file per level", "[cli][build][lod]") {
  cli_test::TempDir dir;
  const std::string src = tree_example("conifer");
  for (const char* ext : {".glb", ".obj", ".ply"}) {
    const fs::path out = dir.path / (std::string("tree") + ext);
    const auto r = run_ramus({"-q", "build", src, "-o", out.string(), "--lod", "2", "--lod-files"});
    INFO(r.out);
    REQUIRE(r.status == 0);
    CHECK_FALSE(fs::exists(out));
    for (int k = 0; k <= 2; ++k) {
      const fs::path level = dir.path / ("tree_LOD" + std::to_string(k) + ext);
      REQUIRE(fs::exists(level));
      if (std::string(ext) == ".glb") {
        const auto g = ramus::testing::read_glb(slurp(level));
        CHECK(g.at("meshes").items.size() == 1);
        CHECK(item(g.at("meshes"), 0).find("name")->text == "conifer_LOD" + std::to_string(k));
        CHECK(g.json.find("extensionsUsed") == nullptr);
      }
    }
    CHECK_FALSE(fs::exists(dir.path / (std::string("tree_LOD3") + ext)));
  }
  // The levels get coarser: each file is smaller than the one before.
  CHECK(fs::file_size(dir.path / "tree_LOD1.glb") < fs::file_size(dir.path / "tree_LOD0.glb"));
  CHECK(fs::file_size(dir.path / "tree_LOD2.glb") < fs::file_size(dir.path / "tree_LOD1.glb"));
}

TEST_CASE("ramus build OBJ and PLY follow --up", "[cli][build][axes]") {
  cli_test::TempDir dir;
  const std::string src = tree_example("conifer");
  struct Case {
    const char* file;
    std::vector<std::string> up;
    char axis;
  };
  for (const Case& c : {Case{"default.obj", {}, 'y'}, Case{"y.obj", {"--up", "y"}, 'y'},
                        Case{"z.obj", {"--up", "z"}, 'z'}, Case{"default.ply", {}, 'z'},
                        Case{"y.ply", {"--up", "y"}, 'y'}, Case{"z.ply", {"--up", "z"}, 'z'}}) {
    const fs::path out = dir.path / c.file;
    std::vector<std::string> args{"-q", "build", src, "-o", out.string()};
    args.insert(args.end(), c.up.begin(), c.up.end());
    REQUIRE(run_ramus(args).status == 0);
    const std::string text = slurp(out);
    const std::string header = text.substr(
        0,
        text.find(std::string(c.file).find(".ply") != std::string::npos ? "end_header" : "mtllib"));
    INFO(c.file << "\n" << header);
    CHECK(header.find(std::string(c.axis == 'y' ? "up y\n" : "up z\n")) != std::string::npos);
    CHECK(header.find("origin 0 0 0\n") != std::string::npos);
    if (std::string(c.file).find(".obj") != std::string::npos) {
      Vec3 lo, hi;
      obj_bounds(text, lo, hi);
      const int up = c.axis == 'y' ? 1 : 2, other = c.axis == 'y' ? 2 : 1;
      CHECK(hi[up] - lo[up] > hi[other] - lo[other]);
      CHECK(std::abs(lo[up]) < 0.02 * (hi[up] - lo[up]));
    }
  }
  // The defaults are y up for OBJ and z up for PLY.
  auto without_mtllib = [](std::string text) {
    const std::size_t at = text.find("mtllib ");
    return text.erase(at, text.find('\n', at) - at);
  };
  CHECK(without_mtllib(slurp(dir.path / "default.obj")) ==
        without_mtllib(slurp(dir.path / "y.obj")));
  CHECK(slurp(dir.path / "default.ply") == slurp(dir.path / "z.ply"));
}

TEST_CASE("options that do not apply to the output are errors", "[cli][build][axes]") {
  cli_test::TempDir dir;
  const std::string src = tree_example("conifer");
  const std::string glb = (dir.path / "t.glb").string();
  auto fails = [&](std::vector<std::string> args, const char* message) {
    const auto r = run_ramus(args);
    INFO(r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find(message) != std::string::npos);
  };
  fails({"build", src, "-o", glb, "--up", "y"}, "--up applies to .obj and .ply meshes only");
  fails({"build", src, "-o", glb, "--lod-files"}, "--lod-files needs --lod N");
  fails({"build", src, "-o", (dir.path / "t.rmb").string(), "--target", "binary", "--up", "z"},
        "--up applies to --target mesh only");
  fails({"build", src, "-o", (dir.path / "t.rmb").string(), "--target", "binary", "--lod-files"},
        "--lod-files applies to --target mesh only");
  fails({"reconstruct", std::string(RAMUS_SHARED_DIR) + "/data/pytlidar_tree_1.las", "-o",
         (dir.path / "t.json").string(), "--up", "z"},
        "--up applies to .obj and .ply meshes only");
  fails({"propagate", src, "-n", "1", "-o", (dir.path / "p").string(), "--up", "y"},
        "--up applies to .obj and .ply meshes only");
  CHECK_FALSE(fs::exists(glb));
  CHECK_FALSE(fs::exists(dir.path / "p"));
}

TEST_CASE("a reconstruction from a UTM scan keeps its offset outside the float vertices",
          "[cli][reconstruct][axes]") {
  cli_test::TempDir dir;
  const std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/pytlidar_tree_1.las";
  const fs::path glb = dir.path / "t.glb", json = dir.path / "t.json", obj = dir.path / "t.obj";
  REQUIRE(run_ramus({"-q", "reconstruct", scan, "-o", glb.string()}).status == 0);
  REQUIRE(run_ramus({"-q", "reconstruct", scan, "-o", json.string()}).status == 0);
  REQUIRE(run_ramus({"-q", "reconstruct", scan, "-o", obj.string(), "--up", "z"}).status == 0);
  const auto g = ramus::testing::read_glb(slurp(glb));
  const auto* t = item(g.at("nodes"), 0).find("translation");
  REQUIRE(t != nullptr);
  const Vec3 offset{t->items[0].number, t->items[1].number, t->items[2].number};
  CHECK(std::abs(offset.x) > 1e6);  // easting
  CHECK(std::abs(offset.z) > 1e6);  // northing, as -z of y up
  const int pos = ramus::testing::attribute_accessor(g, 0, 0, "POSITION");
  const Vec3 lo = accessor_bound(g, pos, "min"), hi = accessor_bound(g, pos, "max");
  for (int k = 0; k < 3; ++k) CHECK(std::max(std::abs(lo[k]), std::abs(hi[k])) < 100);
  // The skeleton JSON keeps the world doubles; the mesh, put back at its offset, encloses them.
  const ramus::Skeleton s = ramus::read_skeleton_json(json.string());
  Vec3 slo, shi;
  s.bounds(slo, shi);
  const Vec3 world_lo{offset.x + lo.x, -(offset.z + hi.z), offset.y + lo.y};  // back to z up
  const Vec3 world_hi{offset.x + hi.x, -(offset.z + lo.z), offset.y + hi.y};
  for (int k = 0; k < 3; ++k) {
    CHECK(world_lo[k] <= slo[k] + 1e-3);
    CHECK(world_hi[k] >= shi[k] - 1e-3);
    CHECK(world_hi[k] - world_lo[k] < shi[k] - slo[k] + 2.0);  // within the thickest radius
  }
  // The OBJ records the same origin, z up, for the reader to add.
  const std::string text = slurp(obj);
  std::ostringstream origin;
  origin.precision(17);
  origin << "# origin " << offset.x << " " << -offset.z << " " << offset.y << "\n";
  CHECK(text.find(origin.str()) != std::string::npos);
}
