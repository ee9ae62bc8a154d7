// `ramus build --wind`: the glTF carries a skin along the branch chains and a looping animation
// that engines play without custom code. three.js (headless Chromium) plays it: at a quarter
// period the top of the tree has moved and the trunk's base has not; with --lod 2 it still draws
// one level; the file validates with 0 errors and 0 warnings, compressed or not. Options that
// mean nothing for the output are errors.
#include <catch2/catch.hpp>

#include "tests/assets/three_runner.h"

using namespace assets_test;

TEST_CASE("the wind animation sways the tips and keeps the trunk base still", "[assets][wind]") {
  cli_test::TempDir dir;
  std::vector<fs::path> files;
  for (const char* compress : {"", "draco", "meshopt"}) {
    const fs::path out = dir.path / ("broadleaf_wind_" + std::string(compress) + ".glb");
    std::vector<std::string> args{
        "build", example("trees/broadleaf.ramus"), "-o", out.string(), "--lod", "2", "--wind"};
    if (*compress) args.insert(args.end(), {"--compress", compress});
    ramus_ok(args);
    files.push_back(out);
  }
  const fs::path gltf = dir.path / "conifer_wind.gltf";
  ramus_ok({"build", example("trees/conifer.ramus"), "-o", gltf.string(), "--wind"});
  files.push_back(gltf);
  std::string report;
  CHECK(validates(files, report));
  INFO(report);
  std::vector<Numbers> results;
  if (!load_in_three(files, results)) return;
  for (std::size_t i = 0; i < files.size(); ++i) {
    INFO(files[i].string());
    const Numbers& r = results[i];
    const double height = r.at("maxY") - r.at("minY");
    CHECK(r.at("animations") == 1);
    CHECK(r.at("skinnedMeshes") == 2);  // bark and leaves of one level, both skinned
    CHECK(r.at("meshes") == 2);
    CHECK(r.at("period") >= 2.0);
    CHECK(r.at("tipMove") > 0.005 * height);      // the top sways visibly ...
    CHECK(r.at("tipMove") < 0.1 * height);        // ... but stays a tree
    CHECK(r.at("baseMove") < 1e-4 * height);      // the trunk's base does not move
    CHECK(height > r.at("maxX") - r.at("minX"));  // and it stands upright
  }
}

TEST_CASE("options that do not apply to a mesh build are errors", "[assets][cli]") {
  cli_test::TempDir dir;
  const std::string src = example("trees/conifer.ramus");
  auto fails = [&](std::vector<std::string> args, const std::string& message) {
    const cli_test::CliResult r = cli_test::run_ramus(args);
    INFO(r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find(message) != std::string::npos);
  };
  const std::string obj = (dir.path / "t.obj").string(), ply = (dir.path / "t.ply").string();
  const std::string glb = (dir.path / "t.glb").string();
  fails({"build", src, "-o", obj, "--wind"}, "--wind needs a glTF output");
  fails({"build", src, "-o", ply, "--compress", "draco"}, "--compress needs a glTF output");
  fails({"build", src, "-o", glb, "--flatten"}, "--flatten applies to --target pieces only");
  fails({"build", src, "-o", glb, "--poses", "3"},
        "--poses applies to --target pieces and binary only");
  fails({"build", src, "-o", glb, "--zstd"}, "--zstd applies to --target binary only");
  fails({"build", src, "-o", (dir.path / "t.rmb").string(), "--target", "binary", "--wind"},
        "--wind applies to --target mesh and pieces only");
  fails({"build", example("pieces/almond.ramus"), "-o", glb, "--target", "pieces", "--compress",
         "meshopt"},
        "--compress applies to --target mesh only");
  CHECK_FALSE(fs::exists(obj));
  CHECK_FALSE(fs::exists(ply));
  CHECK_FALSE(fs::exists(glb));
}
