// `ramus compare` prints the envelope IoU and the tree shape (cli/compare_shape.cpp) and draws
// --picture (cli/compare_picture.cpp); options that do not apply are errors.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "../cli/cli_runner.h"

using namespace cli_test;

namespace {

std::string data(const std::string& name) {
  return (fs::path(RAMUS_SHARED_DIR) / "data" / name).string();
}

const std::string kGrammar = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/conifer.ramus";

// The numbers of the row whose label starts the line.
std::vector<double> row(const std::string& out, const std::string& label) {
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(label + " ", 0) != 0) continue;
    std::istringstream fields(line.substr(label.size()));
    std::vector<double> v;
    std::string f;
    while (fields >> f) v.push_back(f == "n/a" ? -1e9 : std::stod(f));
    return v;
  }
  return {};
}

}  // namespace

TEST_CASE("compare shape cli: a scan against a grammar prints IoU and shape per seed", "[shape]") {
  if (!fs::exists(data("rtwig_cloud.txt"))) return;  // the shared data is not in every checkout
  TempDir tmp;
  const fs::path png = tmp.path / "cmp.png";
  const CliResult r = run_ramus_split(tmp.path, {"compare", data("rtwig_cloud.txt"), kGrammar,
                                                 "--seeds", "3", "--picture", png.string()});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("envelope IoU and tree shape against A = scan rtwig_cloud.txt") !=
        std::string::npos);
  // The reconstruction and each seed: IoU, pieces, largest-piece share, axis-locked share,
  // height ratio, lean, lean difference.
  for (const std::string label : {"A reconstruction", "B seed 1", "B seed 2", "B seed 3"}) {
    INFO(label);
    const std::vector<double> v = row(r.out, label);
    REQUIRE(v.size() == 7);
    for (int i : {0, 2, 3}) {
      CHECK(v[std::size_t(i)] >= 0.0);
      CHECK(v[std::size_t(i)] <= 1.0);
    }
    CHECK(v[1] >= 1);
    CHECK(v[4] > 0);
  }
  // The reconstruction covers its own scan well (measured 0.81).
  CHECK(row(r.out, "A reconstruction")[0] > 0.7);
  double median = -1, recon = -1;
  const auto at = r.out.find("envelope IoU: B median ");
  REQUIRE(at != std::string::npos);
  REQUIRE(std::sscanf(r.out.c_str() + at,
                      "envelope IoU: B median %lf over 3 trees vs A "
                      "reconstruction %lf",
                      &median, &recon) == 2);
  CHECK(median >= 0.0);
  CHECK(median <= 1.0);
  CHECK(recon == row(r.out, "A reconstruction")[0]);
  // The branch statistics are still there, after the shape part.
  CHECK(r.out.find("measure") > at);
  CHECK(r.out.find("largest KS") != std::string::npos);
  // The picture: a PNG (signature, then the IHDR of 5 columns of 320 by 2 rows of 400).
  const std::string bytes = slurp(png);
  REQUIRE(bytes.size() > 1000);
  CHECK(bytes.substr(1, 3) == "PNG");
  auto be32 = [&](std::size_t o) {
    return (unsigned(std::uint8_t(bytes[o])) << 24) | (unsigned(std::uint8_t(bytes[o + 1])) << 16) |
           (unsigned(std::uint8_t(bytes[o + 2])) << 8) | unsigned(std::uint8_t(bytes[o + 3]));
  };
  CHECK(be32(16) == 5 * 320);
  CHECK(be32(20) == 2 * 400);
  // Same input, same bytes.
  const fs::path png2 = tmp.path / "cmp2.png";
  const CliResult again = run_ramus_split(tmp.path, {"compare", data("rtwig_cloud.txt"), kGrammar,
                                                     "--seeds", "3", "--picture", png2.string()});
  CHECK(again.out == r.out);
  CHECK(slurp(png2) == bytes);
  // --picture-also adds a second grammar's first 3 trees (8 columns); the printed measures are
  // still those of B.
  const fs::path png3 = tmp.path / "cmp3.png";
  const CliResult also =
      run_ramus_split(tmp.path, {"compare", data("rtwig_cloud.txt"), kGrammar, "--seeds", "3",
                                 "--picture", png3.string(), "--picture-also",
                                 std::string(RAMUS_SOURCE_DIR) + "/examples/trees/conifer.ramus"});
  INFO(also.err);
  REQUIRE(also.status == 0);
  CHECK(also.out == r.out);
  const std::string bytes3 = slurp(png3);
  REQUIRE(bytes3.size() > 1000);
  const unsigned width3 =
      (unsigned(std::uint8_t(bytes3[16])) << 24) | (unsigned(std::uint8_t(bytes3[17])) << 16) |
      (unsigned(std::uint8_t(bytes3[18])) << 8) | unsigned(std::uint8_t(bytes3[19]));
  CHECK(width3 == 8 * 320);
}

TEST_CASE("compare shape cli: a grammar against itself gives IoU 1 for every seed", "[shape]") {
  TempDir tmp;
  const CliResult r = run_ramus_split(tmp.path, {"compare", kGrammar, kGrammar, "--seeds", "2"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(row(r.out, "B seed 1 vs A seed 1")[0] == 1.0);
  CHECK(row(r.out, "B seed 2 vs A seed 2")[0] == 1.0);
  CHECK(row(r.out, "B seed 1 vs A seed 1")[4] == 1.0);  // height ratio
  CHECK(r.out.find("envelope IoU: B median 1.0000 over 2 trees\n") != std::string::npos);
}

TEST_CASE("compare shape cli: options that do not apply and bad input are errors", "[shape]") {
  TempDir tmp;
  const fs::path skel = tmp.path / "tree.json";
  REQUIRE(run_ramus({"derive", kGrammar, "--skeleton", skel.string()}).status == 0);
  // Two skeleton files: nothing for --picture to draw but skeletons, nothing to grow.
  CliResult r = run_ramus(
      {"compare", skel.string(), skel.string(), "--picture", (tmp.path / "x.png").string()});
  CHECK(r.status == 1);
  CHECK(r.out.find("--picture") != std::string::npos);
  CHECK(!fs::exists(tmp.path / "x.png"));
  r = run_ramus({"compare", skel.string(), skel.string(), "--seeds", "3"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--seeds") != std::string::npos);
  r = run_ramus({"compare", skel.string(), kGrammar, "--reconstruct", "flood"});
  CHECK(r.status == 1);
  CHECK(r.out.find("neither source is a scan") != std::string::npos);
  r = run_ramus({"compare", skel.string(), kGrammar, "--picture", (tmp.path / "x.jpg").string()});
  CHECK(r.status == 1);
  // --picture-also without --picture, or naming a scan.
  r = run_ramus({"compare", skel.string(), kGrammar, "--picture-also", kGrammar});
  CHECK(r.status == 1);
  CHECK(r.out.find("no --picture") != std::string::npos);
  r = run_ramus({"compare", skel.string(), kGrammar, "--picture", (tmp.path / "y.png").string(),
                 "--picture-also", data("rtwig_cloud.txt")});
  CHECK(r.status == 1);
  CHECK(!fs::exists(tmp.path / "y.png"));
  // A skeleton against itself: IoU 1; without --seeds or scan options nothing is refused.
  r = run_ramus({"compare", skel.string(), skel.string()});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(row(r.out, "B skeleton")[0] == 1.0);
  // A scan without height.
  const fs::path flat = tmp.write("flat.xyz", "0 0 1\n1 0 1\n0 1 1\n1 1 1\n");
  r = run_ramus({"compare", flat.string(), kGrammar, "--seeds", "1"});
  CHECK(r.status == 1);
  r = run_ramus({"compare", "/nonexistent/scan.xyz", kGrammar});
  CHECK(r.status == 1);
}
