// LAZ reading: our own LASzip decoder (formats/laz/) against the bundled treels_spruce.laz and
// against laz-perf (npm, the LASzip decoder of PDAL's authors in WebAssembly) as an oracle,
// which runs only where node and tools/node_modules/laz-perf are installed.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "format_test_util.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
namespace fs = std::filesystem;

namespace {

std::string shared_data(const std::string& name) {
  return std::string(RAMUS_SHARED_DIR) + "/data/" + name;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

fs::path scratch() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "laz";
  fs::create_directories(dir);
  return dir;
}

bool oracle_available() {
  return fs::exists(fs::path(RAMUS_SOURCE_DIR) / "tools/node_modules/laz-perf") &&
         std::system("node --version >/dev/null 2>&1") == 0;
}

// The oracle's uncompressed LAS file of `laz` (written to `out`); empty when it failed.
std::string oracle_decompress(const fs::path& laz, const fs::path& out) {
  const std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/formats/laz/laz_oracle.js\" \"" +
                          laz.string() + "\" \"" + out.string() + "\"";
  if (std::system(cmd.c_str()) != 0) return {};
  return slurp(out);
}

}  // namespace

TEST_CASE("laz: treels_spruce.laz reads all 83,392 points of point format 0", "[laz][real]") {
  ReadReport report;
  PointCloud c = read_point_cloud(shared_data("treels_spruce.laz"), {}, &report);
  CHECK(c.size() == 83392);
  CHECK(report.variant.find("LAZ 1.2, point format 0") == 0);
  CHECK(report.variant.find("point10 v2") != std::string::npos);
  // SOURCES.md: a 2.5 x 2.5 x 16.9 m column.
  Vec3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c.world(i)[k]);
      hi[k] = std::max(hi[k], c.world(i)[k]);
    }
  }
  CHECK(hi.x - lo.x == Approx(2.49).margin(0.01));
  CHECK(hi.z - lo.z == Approx(16.94).margin(0.01));
}

TEST_CASE("laz: treels_spruce.laz decodes to exactly the records laz-perf decodes",
          "[laz][real][oracle]") {
  if (!oracle_available()) {
    WARN("node or tools/node_modules/laz-perf missing: the oracle comparison is skipped");
    return;
  }
  const fs::path laz = shared_data("treels_spruce.laz");
  const std::string want = oracle_decompress(laz, scratch() / "spruce_oracle.las");
  REQUIRE(!want.empty());
  const std::string ours = decompress_laz(slurp(laz), laz.string());
  REQUIRE(ours.size() == want.size());
  CHECK(ours == want);  // header, VLRs and all 83,392 records byte for byte

  // And the uncompressed twin reads to the same cloud, coordinate for coordinate.
  PointCloud a = read_point_cloud(laz.string());
  PointCloud b = read_point_cloud_bytes(want, Format::kLas, "twin.las");
  REQUIRE(a.size() == 83392);
  REQUIRE(b.size() == a.size());
  CHECK(a.offset == b.offset);
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, distance(a.world(i), b.world(i)));
  CHECK(worst == 0);
}
