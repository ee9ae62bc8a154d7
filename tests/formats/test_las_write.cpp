// LAS 1.4 / LAZ writing (formats/las_file.h): coordinates survive at the written scale, the
// channels and extra bytes come back, the same cloud gives the same bytes.
#include <catch2/catch.hpp>
#include <cstring>

#include "format_test_util.h"
#include "formats/las_file.h"
#include "formats/point_cloud_io.h"

using namespace ramus;

namespace {

double worst_distance(const PointCloud& a, const PointCloud& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, distance(a.world(i), b.world(i)));
  return worst;
}

}  // namespace

TEST_CASE("las write: treels_spruce and pytlidar_tree_1 survive LAS and LAZ at 0.1 mm",
          "[las][write][real]") {
  for (const char* name : {"treels_spruce.laz", "pytlidar_tree_1.las"}) {
    INFO(name);
    const PointCloud in = read_point_cloud(test::shared_data(name));
    for (bool compressed : {false, true}) {
      LasWriteOptions o;
      o.compressed = compressed;
      const std::string bytes = point_cloud_to_las(in, o);
      CHECK(bytes == point_cloud_to_las(in, o));  // deterministic
      ReadReport report;
      const PointCloud back = read_point_cloud_bytes(bytes, Format::kLas, "w.las", {}, &report);
      CHECK(report.variant.find(compressed ? "LAZ 1.4, point format 6"
                                           : "LAS 1.4, point format 6") == 0);
      REQUIRE(back.size() == in.size());
      // Half the 0.1 mm grid per axis, plus float resolution of the recentred positions.
      CHECK(worst_distance(in, back) < 0.5e-4 * std::sqrt(3.0) + 1e-5);
      CHECK(back.classification == in.classification);
      CHECK(back.intensity == in.intensity);
    }
  }
}

TEST_CASE("las write: extra bytes are described and written per point", "[las][write]") {
  PointCloud c;
  c.offset = {1000, 2000, 0};
  for (int i = 0; i < 300; ++i) c.positions.push_back(Vec3f(i * 0.01f, -i * 0.02f, i * 0.003f));
  LasWriteOptions o;
  std::vector<std::uint8_t> flag;
  std::vector<float> score;
  for (int i = 0; i < 300; ++i) {
    flag.push_back(std::uint8_t(i % 3 == 0));
    score.push_back(float(i) / 300);
  }
  o.extra.push_back({"wood", "1 wood, 0 leaf", flag, {}});
  o.extra.push_back({"leaf_score", "leaf likelihood", {}, score});
  for (bool compressed : {false, true}) {
    o.compressed = compressed;
    std::string las = point_cloud_to_las(c, o);
    if (compressed) las = decompress_laz(las, "w.laz");
    std::uint32_t offset;
    std::memcpy(&offset, las.data() + 96, 4);
    CHECK(las[104] == 6);
    CHECK(las.substr(375 + 2, 9) == "LASF_Spec");  // the Extra Bytes VLR, record 4
    CHECK(las.find("leaf_score") < offset);
    for (int i = 0; i < 300; ++i) {
      const char* r = las.data() + offset + 35 * i;
      CHECK(std::uint8_t(r[30]) == flag[i]);
      float f;
      std::memcpy(&f, r + 31, 4);
      CHECK(f == score[i]);
    }
  }
  o.extra[0].u8.pop_back();
  CHECK_THROWS_AS(point_cloud_to_las(c, o), std::invalid_argument);
}
