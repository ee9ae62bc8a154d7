// `ramus build --compress draco|meshopt`: the demo tree (broadleaf, --lod 2, as `make demo`
// writes it) compressed validates with 0 errors and 0 warnings, three.js loads it with its
// decoders and draws the same triangles within a centimetre of the uncompressed file, and Draco
// takes it to at most a sixth of its size.
#include <catch2/catch.hpp>

#include "tests/assets/three_runner.h"

using namespace assets_test;

TEST_CASE("Draco and meshopt files validate, load in three.js and shrink the demo tree",
          "[assets][compress]") {
  cli_test::TempDir dir;
  std::vector<fs::path> files;
  for (const char* compress : {"", "draco", "meshopt"}) {
    const fs::path out = dir.path / ("broadleaf_" + std::string(compress) + ".glb");
    std::vector<std::string> args{
        "build", example("trees/broadleaf.ramus"), "-o", out.string(), "--lod", "2"};
    if (*compress) args.insert(args.end(), {"--compress", compress});
    ramus_ok(args);
    files.push_back(out);
  }
  const fs::path gltf = dir.path / "weeping_meshopt.gltf";
  ramus_ok({"build", example("trees/weeping.ramus"), "-o", gltf.string(), "--compress", "meshopt"});
  const auto raw = double(fs::file_size(files[0]));
  const auto draco = double(fs::file_size(files[1])), meshopt = double(fs::file_size(files[2]));
  INFO("plain " << raw << " B, draco " << draco << " B, meshopt " << meshopt << " B");
  CHECK(draco <= raw / 6);
  CHECK(meshopt <= raw / 4);
  std::string report;
  CHECK(validates({files[0], files[1], files[2], gltf}, report));
  INFO(report);
  std::vector<Numbers> results;
  if (!load_in_three({files[0], files[1], files[2], gltf}, results)) return;
  for (std::size_t i = 1; i < 3; ++i) {
    INFO(files[i].string());
    CHECK(results[i].at("triangles") == results[0].at("triangles"));
    CHECK(results[i].at("meshes") == 2);
    for (const char* k : {"minX", "minY", "minZ", "maxX", "maxY", "maxZ"})
      CHECK(std::abs(results[i].at(k) - results[0].at(k)) < 0.01);
    CHECK(std::abs(results[i].at("drawnPixels") - results[0].at("drawnPixels")) <
          0.02 * results[0].at("drawnPixels"));
  }
  CHECK(results[3].at("drawnPixels") > 0);
}
