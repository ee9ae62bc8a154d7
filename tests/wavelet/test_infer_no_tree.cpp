// `ramus infer --method wavelet` on a scan that holds no tree (a tilted plane, a handful of
// points, every point at one height) exits 1 with a message naming what is missing and writes
// no file.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "../cli/cli_runner.h"
#include "core/rng.h"

using namespace cli_test;

namespace {

std::string xyz(const std::vector<std::array<double, 3>>& points) {
  std::ostringstream out;
  out.precision(9);
  for (const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  return out.str();
}

void refused(const std::string& what, const std::vector<std::array<double, 3>>& points,
             const std::string& message) {
  INFO(what);
  TempDir dir;
  const fs::path scan = write_text(dir.path / "scan.xyz", xyz(points));
  const fs::path out = dir.path / "out.ramus";
  const CliResult r =
      run_ramus({"infer", scan.string(), "-o", out.string(), "--method", "wavelet"});
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK(r.out.find(message) != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

}  // namespace

TEST_CASE("infer wavelet: a scan without a tree is refused with what is missing",
          "[infer][cli][wavelet]") {
  ramus::Rng rng(5);
  std::vector<std::array<double, 3>> plane, flat, few;
  for (int i = 0; i < 3000; ++i) {
    const double u = rng.uniform(0, 4), v = rng.uniform(0, 4);
    plane.push_back({u, v * std::cos(0.6), v * std::sin(0.6)});  // a slope rising 2.3 m
    flat.push_back({u, v, 1.5});
  }
  for (int i = 0; i < 6; ++i) few.push_back({rng.uniform(0, 1), rng.uniform(0, 1), 0.3 * i});
  refused("a tilted plane", plane, "the points lie on one plane");
  refused("all points at one height", flat, "no height");
  refused("a few points", few, "the scan has 6 point(s)");
}
