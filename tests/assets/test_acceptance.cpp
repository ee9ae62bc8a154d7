// Issue 17's acceptance sweep: every example grammar (examples/abop, examples/trees, and the
// pieces examples that grow a tree) and the reconstruction of every bundled scan (/work/shared/
// data) written as .glb validates with 0 errors and 0 warnings, and three.js (headless Chromium)
// places it exactly where ramus's own z-up mesh is: its world box is the box of the same mesh
// written as a z-up OBJ (plus the OBJ's recorded origin) turned to y up, within 1 cm. So every
// tree stands on +Y with its base at the origin, or at the recorded offset for a georeferenced
// reconstruction. A scan ramus cannot read yet (LAZ) is reported and left out.
#include <catch2/catch.hpp>
#include <fstream>

#include "tests/assets/three_runner.h"

using namespace assets_test;

namespace {

struct ObjBox {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  double origin[3] = {0, 0, 0};
};

// The bounds of an OBJ's vertices and its "# origin X Y Z" (z up: written with --up z).
ObjBox obj_box(const fs::path& obj) {
  ObjBox b;
  std::ifstream in(obj);
  for (std::string line; std::getline(in, line);) {
    double v[3];
    if (std::sscanf(line.c_str(), "# origin %lf %lf %lf", &v[0], &v[1], &v[2]) == 3) {
      for (int k = 0; k < 3; ++k) b.origin[k] = v[k];
    } else if (std::sscanf(line.c_str(), "v %lf %lf %lf", &v[0], &v[1], &v[2]) == 3) {
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], v[k]);
        b.hi[k] = std::max(b.hi[k], v[k]);
      }
    }
  }
  return b;
}

struct Case {
  std::string name;
  fs::path glb, obj;
  bool tree;  // a tree (not an ABOP plane figure or space-filling curve): must be tallest in y
};

}  // namespace

TEST_CASE("every example and reconstruction validates and loads upright where ramus put it",
          "[assets][acceptance]") {
  cli_test::TempDir dir;
  std::vector<Case> cases;
  std::vector<fs::path> grammars;
  for (const char* folder : {"abop", "trees", "pieces"})
    for (const auto& e : fs::directory_iterator(example(folder)))
      if (e.path().extension() == ".ramus") grammars.push_back(e.path());
  std::sort(grammars.begin(), grammars.end());
  for (const fs::path& g : grammars) {
    Case c{g.parent_path().filename().string() + "_" + g.stem().string(),
           {},
           {},
           g.parent_path().filename() != "abop"};
    c.glb = dir.path / (c.name + ".glb");
    c.obj = dir.path / (c.name + ".obj");
    const cli_test::CliResult r = cli_test::run_ramus({"build", g.string(), "-o", c.glb.string()});
    // A pieces example without an lsystem block grows no tree: it is built with --target pieces
    // (tests/pieces).
    if (r.status != 0 && g.parent_path().filename() == "pieces") continue;
    // ABOP's p. 42 example rewrites symbols that draw nothing: there is no mesh to write.
    if (r.status != 0 && r.out.find("the tree has no geometry") != std::string::npos) continue;
    INFO(r.out);
    REQUIRE(r.status == 0);
    ramus_ok({"build", g.string(), "-o", c.obj.string(), "--up", "z"});
    cases.push_back(c);
  }
  const fs::path data = fs::path(RAMUS_SHARED_DIR) / "data";
  std::vector<fs::path> scans;
  for (const auto& e : fs::directory_iterator(data))
    if (e.path().extension() != ".md") scans.push_back(e.path());
  std::sort(scans.begin(), scans.end());
  for (const fs::path& s : scans) {
    Case c{"scan_" + s.filename().string(), {}, {}, true};
    c.glb = dir.path / (c.name + ".glb");
    c.obj = dir.path / (c.name + ".obj");
    const cli_test::CliResult r =
        cli_test::run_ramus({"-q", "reconstruct", s.string(), "-o", c.glb.string()});
    if (r.status != 0 && r.out.find("LAZ-compressed") != std::string::npos) {
      WARN(s.filename().string() << " left out: " << r.out);
      continue;
    }
    INFO(r.out);
    REQUIRE(r.status == 0);
    ramus_ok({"-q", "reconstruct", s.string(), "-o", c.obj.string(), "--up", "z"});
    cases.push_back(c);
  }
  std::vector<fs::path> files;
  for (const Case& c : cases) files.push_back(c.glb);
  std::string report;
  CHECK(validates(files, report));
  INFO(report);
  std::vector<Numbers> results;
  if (!load_in_three(files, results)) return;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    INFO(cases[i].name);
    const Numbers& r = results[i];
    const ObjBox b = obj_box(cases[i].obj);
    // z up -> y up: (x, y, z) -> (x, z, -y), the origin added in double precision.
    const double ox = b.origin[0], oy = b.origin[1], oz = b.origin[2];
    CHECK(std::abs(r.at("minX") - (ox + b.lo[0])) < 0.01);
    CHECK(std::abs(r.at("maxX") - (ox + b.hi[0])) < 0.01);
    CHECK(std::abs(r.at("minY") - (oz + b.lo[2])) < 0.01);
    CHECK(std::abs(r.at("maxY") - (oz + b.hi[2])) < 0.01);
    CHECK(std::abs(r.at("minZ") + (oy + b.hi[1])) < 0.01);
    CHECK(std::abs(r.at("maxZ") + (oy + b.lo[1])) < 0.01);
    CHECK(r.at("drawnPixels") > 0);
    if (!cases[i].tree) continue;
    const double height = r.at("maxY") - r.at("minY");
    CHECK(height > r.at("maxX") - r.at("minX"));
    CHECK(height > r.at("maxZ") - r.at("minZ"));
    // The base: a grammar tree's trunk starts at the origin (the lowest point near it is
    // there). A reconstruction's base is where its scan has it: at the recorded offset for a
    // georeferenced one; the box comparison above places it within 1 cm.
    INFO("root " << r.at("rootX") << " " << r.at("rootY") << " " << r.at("rootZ") << " foot "
                 << r.at("footY") << " minY " << r.at("minY"));
    const bool scan = cases[i].name.rfind("scan_", 0) == 0;
    if (!scan) CHECK(std::abs(r.at("footY")) < 0.01);
    if (!scan) CHECK(r.at("rootY") == 0);
  }
}
