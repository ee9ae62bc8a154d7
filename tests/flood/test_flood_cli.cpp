// `ramus reconstruct --method flood` and `--merge ALPHA,BETA`, and parse_merge_angles.
#include <catch2/catch.hpp>

#include "../cli/cli_runner.h"
#include "formats/point_cloud_io.h"
#include "formats/skeleton_json.h"
#include "reconstruct/merge/merge_angles.h"
#include "tests/flood/flood_fixtures.h"

using namespace cli_test;

namespace {

// A trunk with a fork, written as .xyz.
fs::path write_fork(const TempDir& dir) {
  ramus::PointCloud c;
  const ramus::Vec3 fork{0, 0, 2};
  ramus::test::add_cylinder(c, {0, 0, 0}, fork, 0.06, 15000, false, 1);
  ramus::test::add_cylinder(c, fork, fork + ramus::Vec3{-0.6, 0, 1.2}, 0.04, 8000, false, 2);
  ramus::test::add_cylinder(c, fork, fork + ramus::Vec3{0.6, 0, 1.2}, 0.04, 8000, false, 3);
  const fs::path p = dir.path / "fork.xyz";
  ramus::write_point_cloud_xyz(p.string(), c);
  return p;
}

}  // namespace

TEST_CASE("flood cli: --method flood writes a skeleton and a mesh", "[flood][cli]") {
  TempDir dir;
  const fs::path scan = write_fork(dir);
  const fs::path json = dir.path / "fork.json", glb = dir.path / "fork.glb";
  const CliResult r =
      run_ramus({"reconstruct", scan.string(), "-o", json.string(), "--method", "flood"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  const ramus::Skeleton s = ramus::read_skeleton_json(json.string());
  CHECK(s.size() > 10);
  CHECK(s.validate().empty());
  CHECK(s.organs.empty());  // the flood method synthesizes no leaves
  const CliResult m =
      run_ramus({"reconstruct", scan.string(), "-o", glb.string(), "--method", "flood"});
  CHECK(m.status == 0);
  CHECK(fs::file_size(glb) > 1000);
  // The same input gives byte-identical output.
  const fs::path again = dir.path / "again.json";
  REQUIRE(
      run_ramus({"reconstruct", scan.string(), "-o", again.string(), "--method", "flood"}).status ==
      0);
  CHECK(slurp(again) == slurp(json));
}

TEST_CASE("flood cli: --merge reduces nodes and reports the counts", "[flood][cli]") {
  TempDir dir;
  const fs::path scan = write_fork(dir);
  const fs::path plain = dir.path / "plain.json", merged = dir.path / "merged.json";
  REQUIRE(
      run_ramus({"reconstruct", scan.string(), "-o", plain.string(), "--method", "flood"}).status ==
      0);
  const CliResult r = run_ramus({"reconstruct", scan.string(), "-o", merged.string(), "--method",
                                 "flood", "--merge", "10,15"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("merged branches:") != std::string::npos);
  const ramus::Skeleton a = ramus::read_skeleton_json(plain.string());
  const ramus::Skeleton b = ramus::read_skeleton_json(merged.string());
  CHECK(double(b.size()) < 0.7 * double(a.size()));
  CHECK(b.size() >= 4);  // root, fork and two tips at least
  CHECK(b.validate().empty());
}

TEST_CASE("flood cli: bad --method and --merge values are usage errors", "[flood][cli]") {
  TempDir dir;
  const fs::path scan = write_fork(dir);
  const fs::path out = (dir.path / "x.json");
  for (const char* bad : {"10", "a,b", "10,-5", "10,200", ",", "10,15,20"}) {
    const CliResult r =
        run_ramus({"reconstruct", scan.string(), "-o", out.string(), "--merge", bad});
    INFO(bad << ": " << r.out);
    CHECK(r.status != 0);
    CHECK(r.out.find("--merge") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  const CliResult m =
      run_ramus({"reconstruct", scan.string(), "-o", out.string(), "--method", "voxels"});
  CHECK(m.status != 0);
  CHECK(m.out.find("method") != std::string::npos);
  const fs::path empty = dir.write("empty.xyz", "");
  const CliResult e =
      run_ramus({"reconstruct", empty.string(), "-o", out.string(), "--method", "flood"});
  CHECK(e.status == 1);
  CHECK(e.out.find("empty.xyz") != std::string::npos);
}

TEST_CASE("flood cli: merge angle parsing", "[flood][merge]") {
  const auto o = ramus::merge::parse_merge_angles("12.5,0");
  CHECK(o.alpha_deg == 12.5);
  CHECK(o.beta_deg == 0);
  CHECK_THROWS_WITH(ramus::merge::parse_merge_angles("12"), Catch::Contains("ALPHA,BETA"));
  CHECK_THROWS_WITH(ramus::merge::parse_merge_angles("x,1"), Catch::Contains("alpha"));
  CHECK_THROWS_WITH(ramus::merge::parse_merge_angles("1,nan"), Catch::Contains("beta"));
  CHECK_THROWS(ramus::merge::parse_merge_angles("1,2,3"));
}
