// `ramus build` and `ramus preview` end to end: every bundled example that draws a plant becomes
// a .glb the Khronos glTF-Validator accepts with 0 errors and 0 warnings, outputs are
// byte-identical across runs, and bad invocations fail with a clear message and the right code.
#include <sys/wait.h>

#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

using cli_test::slurp;
using Run = cli_test::CliResult;

// stdout and stderr together.
Run run(const std::string& args) { return cli_test::run_ramus_shell(args); }

fs::path scratch() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "build-cli";
  fs::create_directories(dir);
  return dir;
}

std::string example(const char* rel) { return std::string(RAMUS_SOURCE_DIR) + "/examples/" + rel; }

}  // namespace

TEST_CASE("ramus build turns every example into a valid glb", "[cli][build]") {
  std::string files;
  int built = 0;
  for (const auto& dir : {"abop", "trees"}) {
    for (const auto& entry : fs::directory_iterator(example(dir))) {
      if (entry.path().extension() != ".ramus") continue;
      const fs::path out = scratch() / (entry.path().stem().string() + ".glb");
      const Run r = run("--quiet build \"" + entry.path().string() + "\" -o \"" + out.string() +
                        "\" --lod 1");
      if (r.status != 0 && r.out.find("no geometry") != std::string::npos) continue;  // not a plant
      INFO(entry.path() << "\n" << r.out);
      REQUIRE(r.status == 0);
      files += " \"" + out.string() + "\"";
      ++built;
    }
  }
  CHECK(built >= 20);
  const std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/gltf/validate.js\"" + files + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe);
  std::string out;
  std::array<char, 512> buf;
  while (fgets(buf.data(), int(buf.size()), pipe)) out += buf.data();
  const int st = pclose(pipe);
  INFO(out);
  CHECK((WIFEXITED(st) && WEXITSTATUS(st) == 0));
}

TEST_CASE("ramus build writes gltf, obj and ply, byte-identical across runs", "[cli][build]") {
  const std::string src = example("abop/fig2_6a_monopodial.ramus");
  for (const char* ext : {".glb", ".gltf", ".obj", ".ply"}) {
    const fs::path out = scratch() / (std::string("mono") + ext);
    REQUIRE(run("build \"" + src + "\" -o \"" + out.string() + "\" --seed 3").status == 0);
    const std::string first = slurp(out);
    REQUIRE(run("build \"" + src + "\" -o \"" + out.string() + "\" --seed 3").status == 0);
    CHECK(slurp(out) == first);
    CHECK(first.size() > 1000);
  }
  CHECK(fs::exists(scratch() / "mono.bin"));
  CHECK(fs::exists(scratch() / "mono.mtl"));
}

TEST_CASE("ramus build options change the mesh", "[cli][build]") {
  const std::string src = example("abop/fig2_6a_monopodial.ramus");
  const fs::path a = scratch() / "pipe.glb", b = scratch() / "plain.glb";
  REQUIRE(run("build \"" + src + "\" -o \"" + a.string() + "\" --pipe-exponent 2.5").status == 0);
  REQUIRE(run("build \"" + src + "\" -o \"" + b.string() + "\"").status == 0);
  CHECK(slurp(a) != slurp(b));
  const Run r =
      run("build \"" + src + "\" -o \"" + (scratch() / "lod.glb").string() + "\" --lod 2");
  REQUIRE(r.status == 0);
  const std::string glb = slurp(scratch() / "lod.glb");
  CHECK(glb.find("fig2_6a_monopodial_LOD2") != std::string::npos);
}

TEST_CASE("ramus build and preview reject bad invocations clearly", "[cli][build]") {
  const std::string src = example("abop/fig2_6a_monopodial.ramus");
  Run r = run("build \"" + src + "\" -o x.glb --target voxels");
  CHECK(r.status == 2);
  // pieces is a target, but this grammar has no pieces block: an input error, not usage.
  r = run("build \"" + src + "\" -o x.glb --target pieces");
  CHECK(r.status == 1);
  CHECK((r.out + r.err).find("pieces") != std::string::npos);
  r = run("build \"" + src + "\" -o x.fbx");
  CHECK(r.status == 2);
  CHECK(r.out.find(".glb") != std::string::npos);
  r = run("build \"" + src + "\" -o /nonexistent-ramus-dir/x.glb");
  CHECK(r.status == 1);
  CHECK(r.out.find("/nonexistent-ramus-dir/x.glb") != std::string::npos);
  CHECK_FALSE(fs::exists("/nonexistent-ramus-dir/x.glb"));
  r = run("build /nonexistent-ramus-dir/g.ramus -o x.glb");
  CHECK(r.status == 1);
  r = run("preview \"" + src + "\" -o x.png --size 12by9");
  CHECK(r.status == 1);
  CHECK(r.out.find("--size") != std::string::npos);
  r = run("preview \"" + src + "\" -o x.jpg");
  CHECK(r.status == 2);
}

TEST_CASE("ramus preview writes PNG and SVG pictures", "[cli][preview]") {
  const std::string src = example("abop/fig2_6a_monopodial.ramus");
  const fs::path png = scratch() / "mono.png", svg = scratch() / "mono.svg";
  REQUIRE(run("preview \"" + src + "\" -o \"" + png.string() + "\" --size 320x200").status == 0);
  const std::string bytes = slurp(png);
  REQUIRE(bytes.size() > 24);
  CHECK(bytes.substr(1, 3) == "PNG");
  // IHDR width and height, big-endian at offsets 16 and 20.
  auto be32 = [&](std::size_t at) {
    return (unsigned(std::uint8_t(bytes[at])) << 24) |
           (unsigned(std::uint8_t(bytes[at + 1])) << 16) |
           (unsigned(std::uint8_t(bytes[at + 2])) << 8) | unsigned(std::uint8_t(bytes[at + 3]));
  };
  CHECK(be32(16) == 320);
  CHECK(be32(20) == 200);
  REQUIRE(run("preview \"" + src + "\" -o \"" + svg.string() + "\"").status == 0);
  CHECK(slurp(svg).find("<polygon") != std::string::npos);
}
