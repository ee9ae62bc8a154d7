// A real engine loads the outputs: three.js (npm three) inside Debian's headless Chromium
// (driven by npm playwright-core, software WebGL) loads the canonical, flattened and
// gpu-instancing files, renders each once, and the counts of skinned meshes, bones, skins,
// instanced meshes, draw calls and drawn pixels must be the ones the forest implies
// (tests/pieces/browser/load_in_three.js). The test is skipped, with the reason, only when
// Chromium cannot run on this machine (the script's exit code 77).
#include <map>
#include <set>
#include <sstream>

#include "backends/pieces/gltf_pieces.h"
#include "backends/pieces/output_layout.h"
#include "tests/cli/cli_runner.h"
#include "tests/pieces/output_fixture.h"

using namespace ramus;
using namespace ramus::pieces;
using namespace output_test;

namespace {

// Runs the loader on `files`; false (after a warning) when Chromium cannot run here.
bool load_in_three(const std::vector<fs::path>& files,
                   std::vector<std::map<std::string, double>>& results) {
  std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/pieces/browser/load_in_three.js\"";
  for (const fs::path& f : files) cmd += " \"" + f.string() + "\"";
  std::string out;
  const int code = run(cmd, out);
  if (code == 77) {
    WARN("skipped: " << out);
    return false;
  }
  INFO(out);
  REQUIRE(code == 0);
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("{\"file\"", 0) == 0) results.push_back(cli_test::json_line_numbers(line));
  REQUIRE(results.size() == files.size());
  return true;
}

// "(2 trees, 110 pieces, 276 bones)" from ramus build's report.
std::array<double, 3> reported_counts(const std::string& out) {
  std::array<double, 3> n{-1, -1, -1};
  const std::size_t at = out.find(" trees, ");
  REQUIRE(at != std::string::npos);
  std::size_t open = out.rfind('(', at);
  REQUIRE(std::sscanf(out.c_str() + open, "(%lf trees, %lf pieces, %lf bones)", &n[0], &n[1],
                      &n[2]) == 3);
  return n;
}

}  // namespace

TEST_CASE("three.js loads the bundled piece examples with the expected skins and bones",
          "[pieces][browser]") {
  const fs::path src = fs::path(RAMUS_SOURCE_DIR) / "examples" / "pieces";
  std::vector<fs::path> examples;
  if (fs::is_directory(src))
    for (const auto& e : fs::directory_iterator(src))
      if (e.path().extension() == ".ramus") examples.push_back(e.path());
  std::sort(examples.begin(), examples.end());
  REQUIRE_FALSE(examples.empty());
  cli_test::TempDir tmp;
  std::vector<fs::path> files;
  std::vector<std::array<double, 3>> counts;
  for (const fs::path& ex : examples) {
    for (const char* mode : {"canonical", "flatten"}) {
      const fs::path out = tmp.path / (ex.stem().string() + "_" + mode + ".glb");
      std::vector<std::string> args{"build", ex.string(),  "--target", "pieces",
                                    "-o",    out.string(), "--poses",  "2"};
      if (std::string(mode) == "flatten") args.push_back("--flatten");
      const cli_test::CliResult r = cli_test::run_ramus(args);
      INFO(r.out);
      REQUIRE(r.status == 0);
      files.push_back(out);
      counts.push_back(reported_counts(r.out));
    }
  }
  std::vector<std::map<std::string, double>> results;
  if (!load_in_three(files, results)) return;
  for (std::size_t i = 0; i < files.size(); ++i) {
    INFO(files[i].string());
    const bool flat = i % 2 == 1;
    const auto& r = results[i];
    // The pieces, and the leaves at the branch tips with their own skin.
    CHECK(r.at("skinnedMeshes") == (flat ? 1 : counts[i][1]) + 1);
    CHECK(r.at("skins") == (flat ? 1 : counts[i][1]) + 1);
    CHECK(r.at("alphaTestedPrimitives") == 1);
    CHECK(r.at("bones") == counts[i][2]);
    CHECK(r.at("drawnPixels") > 0.002 * r.at("pixels"));
  }
}

TEST_CASE("three.js in headless Chromium loads the canonical, flattened and instanced files",
          "[pieces][browser]") {
  const fs::path dir = scratch("browser");
  const PieceSet set = lower_set();
  pieces::AssembleOptions ao;
  ao.seed = 13;
  // Two copies close together, so that the picture's width is mostly trees.
  const Forest f = pose_copies(set, assemble(set, ao), 2, 13, 6.0);
  const PiecesLayout layout = layout_forest(set, f);
  std::set<std::uint32_t> types;
  for (const auto& inst : layout.instances) types.insert(inst.type);
  const fs::path canonical = dir / "canonical.glb", flat = dir / "flatten.glb",
                 instanced = dir / "instanced.glb";
  PiecesGltfOptions o;
  o.wind = true;
  write_pieces_gltf(set, f, o, canonical.string());
  o.encoding = GltfEncoding::kFlatten;
  write_pieces_gltf(set, f, o, flat.string());
  o.encoding = GltfEncoding::kGpuInstancing;
  o.wind = false;
  write_pieces_gltf(set, f, o, instanced.string());

  std::string out;
  const int code =
      run("node \"" RAMUS_SOURCE_DIR "/tests/pieces/browser/load_in_three.js\" \"" +
              canonical.string() + "\" \"" + flat.string() + "\" \"" + instanced.string() + "\"",
          out);
  if (code == 77) {
    WARN("skipped: " << out);
    return;
  }
  INFO(out);
  REQUIRE(code == 0);
  std::vector<std::map<std::string, double>> results;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("{\"file\"", 0) == 0) results.push_back(cli_test::json_line_numbers(line));
  REQUIRE(results.size() == 3);
  const double pieces = double(piece_count(f)), bones = double(bone_count(f));

  // Each file also has the leaves: one mesh (skinned to the branch tips but in gpu-instancing).
  const auto& c = results[0];  // one SkinnedMesh and one skeleton per placed piece
  CHECK(c.at("skinnedMeshes") == pieces + 1);
  CHECK(c.at("skins") == pieces + 1);
  CHECK(c.at("bones") == bones);
  CHECK(c.at("drawCalls") == pieces + 1);
  const auto& fl = results[1];  // every piece in one skinned mesh: one draw call
  CHECK(fl.at("skinnedMeshes") == 2);
  CHECK(fl.at("skins") == 2);
  CHECK(fl.at("bones") == bones);
  CHECK(fl.at("drawCalls") == 2);
  CHECK(fl.at("triangles") == c.at("triangles"));
  const auto& in = results[2];  // one instanced draw call per piece type
  CHECK(in.at("skinnedMeshes") == 0);
  CHECK(in.at("instancedMeshes") == double(types.size()));
  CHECK(in.at("instances") == pieces);
  CHECK(in.at("drawCalls") == double(types.size()) + 1);
  CHECK(in.at("triangles") == c.at("triangles"));
  // The trees are in the picture: a real share of the pixels, not all of them.
  for (const auto& r : results) {
    CHECK(r.at("drawnPixels") > 0.01 * r.at("pixels"));
    CHECK(r.at("drawnPixels") < 0.9 * r.at("pixels"));
  }
  // Canonical and flattened are the same posed trees: nearly the same pixels.
  CHECK(std::abs(c.at("drawnPixels") - fl.at("drawnPixels")) < 0.02 * c.at("drawnPixels") + 20);
}
