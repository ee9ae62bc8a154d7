// `ramus enhance`: super-resolution of a scan written as voxel centres, reproducible by seed.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.h"

namespace {

using cli_test::slurp;
using Result = cli_test::CliResult;

Result run(const std::string& args) { return cli_test::run_ramus_shell(args); }

}  // namespace

TEST_CASE("enhance cli: writes the enhanced voxel centres and the same seed gives the same file",
          "[cli][wavelet]") {
  std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/rtwig_cloud.txt";
  if (!std::filesystem::exists(scan)) {
    WARN("skipped: " << scan << " is missing");
    return;
  }
  std::string dir = std::string(RAMUS_BINARY_DIR) + "/enhance_cli_test";
  std::filesystem::create_directories(dir);
  Result a = run("-q enhance " + scan + " -o " + dir + "/a.xyz --grid 16 --seed 5");
  REQUIRE(a.status == 0);
  CHECK(a.out.find("-> 32^3 enhanced") != std::string::npos);
  CHECK(a.out.find("upsampled: IoU") != std::string::npos);
  Result b = run("-q enhance " + scan + " -o " + dir + "/b.xyz --grid 16 --seed 5");
  REQUIRE(b.status == 0);
  std::string fa = slurp(dir + "/a.xyz");
  CHECK(fa == slurp(dir + "/b.xyz"));
  // One line per enhanced voxel after the header comment, as many as the summary says.
  std::size_t lines = 0;
  for (char c : fa) lines += c == '\n';
  std::size_t at = a.out.find("enhanced (");
  REQUIRE(at != std::string::npos);
  CHECK(lines - 1 == std::stoul(a.out.substr(at + 10)));
  Result c = run("-q enhance " + scan + " -o " + dir + "/c.xyz --grid 16 --seed 6");
  CHECK(c.status == 0);
  CHECK(slurp(dir + "/c.xyz") != fa);
}

TEST_CASE("enhance cli: bad arguments are errors", "[cli][wavelet]") {
  std::string dir = std::string(RAMUS_BINARY_DIR) + "/enhance_cli_test";
  std::filesystem::create_directories(dir);
  std::string one = dir + "/one.xyz";
  std::ofstream(one) << "1 2 3\n4 5 6\n";
  CHECK(run("enhance " + one + " -o " + dir + "/x.obj").status == 1);
  CHECK(run("enhance " + one + " -o " + dir + "/x.ply --grid 2").status == 1);
  CHECK(run("enhance " + one + " -o " + dir + "/x.ply --classes 4").status == 1);
  Result ok = run("-q enhance " + one + " -o " + dir + "/x.ply --grid 8");
  CHECK(ok.status == 0);  // two points: a sparse grid, but a valid result
  CHECK(run("enhance").status == 2);
}
