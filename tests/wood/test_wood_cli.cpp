// `ramus classify` and `ramus reconstruct --leaves-in-scan` end to end: the PLY with the `wood`
// property reads back, the wood-only file, determinism, bad input and options.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <sstream>

#include "../cli/cli_runner.h"
#include "formats/point_cloud_io.h"

using namespace cli_test;

namespace {

const std::string kBroadleaf = RAMUS_SOURCE_DIR "/examples/trees/broadleaf.ramus";

// A leafy scan of the broadleaf example from one station, at the density of the measurements
// in docs/wood-separation.md (the scale of the features follows the point spacing).
fs::path leafy_scan(const TempDir& dir) {
  const fs::path out = dir.path / "leafy.ply";
  const CliResult r = run_ramus({"scan", kBroadleaf, "-o", out.string(), "--leaves", "--noise",
                                 "0.005", "--density", "3000"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  return out;
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("ramus classify: every point with a wood property, and the wood points alone",
          "[wood_cli]") {
  TempDir dir;
  const fs::path scan = leafy_scan(dir);
  const fs::path split = dir.path / "split.ply", wood = dir.path / "wood.ply";
  const CliResult r = run_ramus(
      {"classify", scan.string(), "-o", split.string(), "--wood", wood.string(), "--ascii"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("leaf") != std::string::npos);
  const std::string text = slurp(split);
  REQUIRE(text.find("property uchar wood\n") != std::string::npos);
  CHECK(text.find("property float leaf_score\n") != std::string::npos);
  // The readers ignore the extra properties: the split reads back as the scan's points.
  const ramus::PointCloud in = ramus::read_point_cloud(scan.string());
  const ramus::PointCloud all = ramus::read_point_cloud(split.string());
  const ramus::PointCloud w = ramus::read_point_cloud(wood.string());
  CHECK(all.size() == in.size());
  // Count the points whose wood column (the fourth) is 1.
  std::size_t wood_rows = 0, rows = 0;
  std::istringstream lines(text.substr(text.find("end_header\n") + 11));
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream f(line);
    double x, y, z;
    int flag;
    float score;
    REQUIRE(static_cast<bool>(f >> x >> y >> z >> flag >> score));
    CHECK((flag == 0 || flag == 1));
    wood_rows += flag == 1, ++rows;
  }
  CHECK(rows == in.size());
  CHECK(wood_rows == w.size());
  CHECK(w.size() < in.size() / 2);  // most of a leafy broadleaf scan is foliage
  CHECK(w.size() > in.size() / 20);
}

TEST_CASE("ramus classify: the same scan gives the same bytes", "[wood_cli]") {
  TempDir dir;
  const fs::path scan = leafy_scan(dir);
  const fs::path a = dir.path / "a.ply", b = dir.path / "b.ply";
  REQUIRE(run_ramus({"classify", scan.string(), "-o", a.string()}).status == 0);
  REQUIRE(run_ramus({"classify", scan.string(), "-o", b.string()}).status == 0);
  CHECK(slurp(a) == slurp(b));
  CHECK(!slurp(a).empty());
}

TEST_CASE("ramus classify: bad input and options are clear errors", "[wood_cli]") {
  TempDir dir;
  const fs::path out = dir.path / "o.ply";
  CliResult r = run_ramus({"classify", (dir.path / "missing.ply").string(), "-o", out.string()});
  CHECK(r.status == 1);
  const fs::path empty = dir.write("empty.xyz", "");
  r = run_ramus({"classify", empty.string(), "-o", out.string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("error") != std::string::npos);
  const fs::path one = dir.write("one.xyz", "1 2 3\n");
  r = run_ramus({"classify", one.string(), "-o", out.string()});
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(r.out.find("too few points") != std::string::npos);
  r = run_ramus({"classify", one.string(), "-o", (dir.path / "o.obj").string()});
  CHECK(r.status == 2);
  r = run_ramus({"classify", one.string(), "-o", out.string(), "--scale", "-1"});
  CHECK(r.status == 2);
  CHECK(!fs::exists(dir.path / "o.obj"));
}

TEST_CASE("ramus reconstruct --leaves-in-scan: remove and auto drop the foliage, keep does not",
          "[wood_cli]") {
  TempDir dir;
  const fs::path scan = leafy_scan(dir);
  const fs::path keep = dir.path / "keep.json", removed = dir.path / "removed.json",
                 automatic = dir.path / "auto.json";
  CliResult r = run_ramus({"reconstruct", scan.string(), "-o", keep.string(), "--leaves-in-scan",
                           "keep", "--no-leaves"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("wood/leaf separation") == std::string::npos);
  r = run_ramus({"reconstruct", scan.string(), "-o", removed.string(), "--leaves-in-scan", "remove",
                 "--no-leaves"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("classified leaf") != std::string::npos);
  CHECK(r.out.find(": removed") != std::string::npos);
  r = run_ramus({"reconstruct", scan.string(), "-o", automatic.string(), "--leaves-in-scan", "auto",
                 "--no-leaves"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("foliage found: removed") != std::string::npos);
  // One tree each; the foliage no longer grows skeleton nodes.
  CHECK(count_of(slurp(removed), "\"parent\": -1") == 1);
  CHECK(slurp(automatic) == slurp(removed));
  CHECK(count_of(slurp(removed), "\"parent\"") < count_of(slurp(keep), "\"parent\""));
  r = run_ramus({"reconstruct", scan.string(), "-o", keep.string(), "--leaves-in-scan", "some"});
  CHECK(r.status == 2);
}

TEST_CASE("ramus reconstruct: auto keeps a bark-only scan whole", "[wood_cli]") {
  TempDir dir;
  const fs::path scan = dir.path / "bark.ply";
  REQUIRE(run_ramus({"scan", kBroadleaf, "-o", scan.string(), "--density", "600"}).status == 0);
  const CliResult r = run_ramus({"reconstruct", scan.string(), "-o", (dir.path / "t.json").string(),
                                 "--leaves-in-scan", "auto", "--no-leaves"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("removed") == std::string::npos);
  CHECK(r.out.find("all points kept") != std::string::npos);
}

TEST_CASE("ramus classify: LAS and LAZ outputs carry wood and leaf_score as extra bytes",
          "[wood_cli][laz]") {
  TempDir dir;
  const fs::path scan = leafy_scan(dir);
  const fs::path las = dir.path / "split.las", laz = dir.path / "split.laz",
                 wood = dir.path / "wood.laz", ply = dir.path / "split.ply";
  REQUIRE(
      run_ramus({"classify", scan.string(), "-o", las.string(), "--wood", wood.string()}).status ==
      0);
  REQUIRE(run_ramus({"classify", scan.string(), "-o", laz.string()}).status == 0);
  REQUIRE(run_ramus({"classify", scan.string(), "-o", ply.string()}).status == 0);
  const ramus::PointCloud in = ramus::read_point_cloud(scan.string());
  ramus::ReadReport report;
  const ramus::PointCloud a = ramus::read_point_cloud(las.string(), {}, &report);
  CHECK(report.variant == "LAS 1.4, point format 6, 35-byte records (5 extra bytes)");
  const ramus::PointCloud b = ramus::read_point_cloud(laz.string(), {}, &report);
  CHECK(report.variant.find("LAZ 1.4, point format 6, 35-byte records (5 extra bytes), layered") ==
        0);
  REQUIRE(a.size() == in.size());
  REQUIRE(b.size() == in.size());
  double worst = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    worst = std::max({worst, ramus::distance(a.world(i), in.world(i)),
                      ramus::distance(b.world(i), in.world(i))});
  }
  CHECK(worst <= 0.5e-4 * std::sqrt(3.0) + 1e-9);  // 0.1 mm grid
  // The wood flags: byte 30 of each format-6 record; as many as the PLY's wood points.
  const std::string bytes = slurp(las), text = slurp(ply);
  std::uint32_t offset;
  std::memcpy(&offset, bytes.data() + 96, 4);
  std::size_t wood_points = 0;
  for (std::size_t i = 0; i < a.size(); ++i) wood_points += bytes[offset + 35 * i + 30] == 1;
  CHECK(bytes.find("wood") < offset);  // named in the Extra Bytes VLR
  CHECK(bytes.find("leaf_score") < offset);
  CHECK(ramus::read_point_cloud(wood.string()).size() == wood_points);
  CHECK(wood_points > 0);
  CHECK(wood_points < a.size());

  const CliResult r = run_ramus({"classify", scan.string(), "-o", las.string(), "--ascii"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--ascii applies to PLY outputs only") != std::string::npos);
}
