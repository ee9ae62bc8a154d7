// `ramus compress`: a Table I row for a scan, and clear errors for bad input.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.h"

namespace {

using Result = cli_test::CliResult;

Result run(const std::string& args) { return cli_test::run_ramus_shell(args); }

}  // namespace

TEST_CASE("compress cli: prints a Table I row for a scan", "[cli][wavelet]") {
  std::string scan = std::string(RAMUS_SHARED_DIR) + "/data/adtree_tree1.xyz";
  if (!std::filesystem::exists(scan)) {
    WARN("skipped: " << scan << " is missing");
    return;
  }
  Result r = run("compress " + scan + " --grid 32 --gamma 0.2");
  CHECK(r.status == 0);
  CHECK(r.out.find("| file | points | grid |") != std::string::npos);
  CHECK(r.out.find("| adtree_tree1.xyz | 11855 | 32^3 |") != std::string::npos);
  CHECK(r.out.find("warning: no scanner position") != std::string::npos);
  Result q = run("-q compress " + scan + " --grid 32 --no-header --scanner 0,0,0");
  CHECK(q.status == 0);
  CHECK(q.out.find("| file |") == std::string::npos);
  CHECK(q.out.find("warning") == std::string::npos);
}

TEST_CASE("compress cli: bad grids and scanners and files are errors", "[cli][wavelet]") {
  std::string dir = std::string(RAMUS_BINARY_DIR) + "/compress_cli_test";
  std::filesystem::create_directories(dir);
  std::string one = dir + "/one.xyz";
  std::ofstream(one) << "1 2 3\n";
  Result r = run("compress " + one + " --grid 8 --no-header");
  CHECK(r.status == 0);  // a single point is one voxel: nothing to compress, but no crash
  CHECK(r.out.find("| one.xyz | 1 | 8^3 | 1 |") != std::string::npos);
  CHECK(run("compress " + one + " --grid 48").status == 1);
  CHECK(run("compress " + one + " --grid 48").out.find("not a power of two") != std::string::npos);
  CHECK(run("compress " + one + " --scanner 1,x,3").status == 1);
  CHECK(run("compress " + one + " --grid 1024").status == 1);  // larger than the 512^3 limit
  CHECK(run("compress " + dir + "/missing.xyz").status == 1);
  CHECK(run("compress " + one + " --values counts").status == 2);
}
