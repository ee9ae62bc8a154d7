// `ramus preview` of everything a user gets from ramus, end to end: a grammar and its .rmb, a
// skeleton JSON, the tree's .glb (with MSFT_lod), .gltf, .obj and .ply, the glb of a
// georeferenced reconstruction and scans. Each gives a PNG of the asked size whose two views
// show an upright tree (the drawn pixels taller than wide), the same bytes on every run, and
// the same picture whatever the mesh format or its up axis. Options that do not apply and
// broken files are errors (exit 1) that leave no picture behind.
#include <stb/stb_image.h>

#include <array>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

using cli_test::run_ramus;
using cli_test::slurp;

constexpr int kWidth = 400, kHeight = 300;

fs::path scratch() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "preview-inputs";
  fs::create_directories(dir);
  return dir;
}

std::string source(const char* rel) { return std::string(RAMUS_SOURCE_DIR) + "/" + rel; }
std::string shared(const char* rel) { return std::string(RAMUS_SHARED_DIR) + "/" + rel; }
std::string out(const char* name) { return (scratch() / name).string(); }

// Runs ramus and requires success.
void ok(const std::vector<std::string>& args) {
  const cli_test::CliResult r = run_ramus(args);
  INFO(r.out);
  REQUIRE(r.status == 0);
}

// The extent of the drawn pixels of one view: rows and columns holding any pixel that is not
// the background.
struct Extent {
  int columns = 0, rows = 0;
};

std::array<Extent, 2> view_extents(const std::string& png) {
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                            int(png.size()), &w, &h, &n, 3);
  REQUIRE(px != nullptr);
  CHECK(w == kWidth);
  CHECK(h == kHeight);
  std::array<std::vector<int>, 2> per_column{std::vector<int>(w), std::vector<int>(w)};
  std::array<std::vector<int>, 2> per_row{std::vector<int>(h), std::vector<int>(h)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (x == w / 2) continue;  // the rule between the views
      const unsigned char* p = px + (std::size_t(y) * w + x) * 3;
      if (p[0] >= 230 && p[1] >= 230 && p[2] >= 225) continue;  // background (245, 245, 240)
      const int v = x < w / 2 ? 0 : 1;
      ++per_column[v][x];
      ++per_row[v][y];
    }
  }
  stbi_image_free(px);
  std::array<Extent, 2> e;
  for (int v = 0; v < 2; ++v) {
    for (int c : per_column[v]) e[v].columns += c > 0;
    for (int r : per_row[v]) e[v].rows += r > 0;
  }
  return e;
}

// Draws `input` twice; checks the picture and that both runs wrote the same bytes. Returns them.
std::string check_upright(const std::string& input, const char* name) {
  INFO(input);
  const std::string a = out(name), b = out((std::string("again_") + name).c_str());
  const std::string size = std::to_string(kWidth) + "x" + std::to_string(kHeight);
  ok({"-q", "preview", input, "-o", a, "--size", size});
  ok({"-q", "preview", input, "-o", b, "--size", size});
  const std::string bytes = slurp(a);
  CHECK(bytes == slurp(b));
  for (const Extent& e : view_extents(bytes)) {
    CHECK(e.rows > kHeight / 2);  // not empty: fitted to the height
    CHECK(e.rows > e.columns);    // a tree stands: taller than wide
  }
  return bytes;
}

}  // namespace

TEST_CASE("preview draws a grammar's meshes in every format the same, upright", "[cli][preview]") {
  const std::string grammar = source("examples/trees/broadleaf.ramus");
  ok({"-q", "build", grammar, "-o", out("t.glb"), "--lod", "2"});
  ok({"-q", "build", grammar, "-o", out("t.gltf")});
  ok({"-q", "build", grammar, "-o", out("ty.obj")});
  ok({"-q", "build", grammar, "-o", out("tz.obj"), "--up", "z"});
  ok({"-q", "build", grammar, "-o", out("tz.ply")});
  ok({"-q", "build", grammar, "-o", out("ty.ply"), "--up", "y"});
  const std::string glb = check_upright(out("t.glb"), "glb.png");
  CHECK(check_upright(out("t.gltf"), "gltf.png") == glb);
  CHECK(check_upright(out("ty.obj"), "ty_obj.png") == glb);
  CHECK(check_upright(out("tz.obj"), "tz_obj.png") == glb);
  CHECK(check_upright(out("tz.ply"), "tz_ply.png") == glb);
  CHECK(check_upright(out("ty.ply"), "ty_ply.png") == glb);
  check_upright(grammar, "grammar.png");
}

TEST_CASE("preview grows an .rmb like its grammar and meshes a skeleton JSON", "[cli][preview]") {
  const std::string grammar = source("examples/trees/conifer.ramus");
  ok({"-q", "build", grammar, "--target", "binary", "-o", out("c.rmb")});
  ok({"-q", "derive", grammar, "--skeleton", out("c.json")});
  const std::string g = check_upright(grammar, "conifer.png");
  CHECK(check_upright(out("c.rmb"), "rmb.png") == g);
  CHECK(check_upright(out("c.json"), "json.png") == g);
  // The grow options work on an .rmb as on the grammar.
  ok({"-q", "preview", grammar, "-o", out("g7.png"), "--seed", "7", "-n", "4"});
  ok({"-q", "preview", out("c.rmb"), "-o", out("r7.png"), "--seed", "7", "-n", "4"});
  CHECK(slurp(out("g7.png")) == slurp(out("r7.png")));
}

TEST_CASE("preview draws scans as points and a georeferenced reconstruction upright",
          "[cli][preview]") {
  ok({"-q", "scan", source("examples/trees/conifer.ramus"), "-o", out("s.ply")});
  check_upright(out("s.ply"), "scan_ply.png");
  check_upright(shared("data/adtree_tree1.xyz"), "scan_xyz.png");
  check_upright(shared("data/pytlidar_tree_1.las"), "scan_las.png");
  ok({"-q", "reconstruct", shared("data/pytlidar_tree_1.las"), "-o", out("r.glb")});
  ok({"-q", "reconstruct", shared("data/pytlidar_tree_1.las"), "-o", out("r.ply")});
  CHECK(check_upright(out("r.glb"), "r_glb.png") == check_upright(out("r.ply"), "r_ply.png"));
  ok({"-q", "preview", out("s.ply"), "-o", out("s.svg")});
  CHECK(slurp(out("s.svg")).find("<rect x=") != std::string::npos);
}

// The share of pixels of two same-size PNGs that differ by more than 24 in a channel.
double differing_share(const std::string& a, const std::string& b) {
  int w = 0, h = 0, n = 0, w2 = 0, h2 = 0;
  unsigned char* pa = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(a.data()),
                                            int(a.size()), &w, &h, &n, 3);
  unsigned char* pb = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(b.data()),
                                            int(b.size()), &w2, &h2, &n, 3);
  REQUIRE(pa != nullptr);
  REQUIRE(pb != nullptr);
  REQUIRE(w == w2);
  REQUIRE(h == h2);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(int(pa[3 * i + c]) - int(pb[3 * i + c])) > 24) {
        ++differ;
        break;
      }
    }
  }
  stbi_image_free(pa);
  stbi_image_free(pb);
  return double(differ) / double(std::size_t(w) * h);
}

TEST_CASE("preview skins a pieces glb, flattened or instanced, into the same tree",
          "[cli][preview]") {
  const std::string grammar = source("examples/pieces/almond.ramus");
  ok({"-q", "build", grammar, "--target", "pieces", "-o", out("p.glb")});
  ok({"-q", "build", grammar, "--target", "pieces", "-o", out("pf.glb"), "--flatten"});
  ok({"-q", "build", grammar, "--target", "pieces", "-o", out("pi.glb"), "--gpu-instancing"});
  for (const char* f : {"p", "pf", "pi"}) {
    ok({"-q", "preview", out((std::string(f) + ".glb").c_str()), "-o",
        out((std::string(f) + ".png").c_str()), "--size", "400x300"});
  }
  const std::string skinned = slurp(out("p.png"));
  const std::array<Extent, 2> e = view_extents(skinned);
  CHECK(e[0].rows > kHeight / 2);  // not empty
  // Unskinned, the canonical file would show its few piece meshes at their bind poses.
  CHECK(differing_share(skinned, slurp(out("pf.png"))) < 0.005);
  CHECK(differing_share(skinned, slurp(out("pi.png"))) < 0.005);
}

TEST_CASE("preview refuses options that do not apply and broken files, writing nothing",
          "[cli][preview]") {
  const std::string grammar = source("examples/trees/broadleaf.ramus");
  ok({"-q", "build", grammar, "-o", out("e.glb")});
  ok({"-q", "build", grammar, "-o", out("e.obj")});
  const std::string glb = slurp(out("e.glb"));
  cli_test::write_text(scratch() / "cut.glb", glb.substr(0, glb.size() / 3));
  cli_test::write_text(scratch() / "junk.obj", "this is not\nan OBJ file\n");
  cli_test::write_text(scratch() / "what.bin", "neither mesh nor scan\n");
  struct Case {
    std::vector<std::string> args;
    const char* says;
  };
  const std::string scan = shared("data/adtree_tree1.xyz");
  const std::vector<Case> cases = {
      {{out("e.glb"), "--seed", "3"}, "--seed applies to grammars only"},
      {{out("e.obj"), "-D", "a=1"}, "-D/--define applies to grammars only"},
      {{scan, "-n", "2"}, "-n/--steps applies to grammars only"},
      {{scan, "--pipe-exponent", "2"}, "--pipe-exponent applies to grammars and skeletons"},
      {{out("cut.glb")}, "cut.glb: cannot read the glTF file: byte 8: the header gives a length"},
      {{out("junk.obj")}, "junk.obj"},
      {{out("what.bin")}, "cannot tell what this is"},
      {{out("missing.glb")}, "missing.glb"},
  };
  for (const Case& c : cases) {
    const fs::path picture = scratch() / "refused.png";
    fs::remove(picture);
    std::vector<std::string> args = {"preview"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.insert(args.end(), {"-o", picture.string()});
    const cli_test::CliResult r = run_ramus(args);
    INFO(c.args.front() << "\n" << r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find(c.says) != std::string::npos);
    CHECK_FALSE(fs::exists(picture));
  }
}
