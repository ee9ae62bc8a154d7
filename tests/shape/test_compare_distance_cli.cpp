// `ramus compare A B --within D,...`: the share of B's skeleton within each distance of reference
// A's and of A's within it of B's (cli/compare_distance.cpp), on skeletons whose answer is known.
#include <catch2/catch.hpp>
#include <cstdio>
#include <sstream>

#include "../cli/cli_runner.h"

using namespace cli_test;

namespace {

// A 3 m trunk with one 1.41 m branch leaving it at 1 m, in the x-z plane; `dy` moves the whole
// tree across that plane, `branch` false leaves the branch out.
std::string tree_json(double dy, bool branch) {
  struct Node {
    double x, y, z;
    int parent;
  };
  std::vector<Node> nodes = {{0, 0, 0, -1}, {0, 0, 1, 0}, {0, 0, 2, 1}, {0, 0, 3, 2}};
  if (branch) nodes.push_back({0.5, 0, 1.5, 1}), nodes.push_back({1, 0, 2, 4});
  std::ostringstream out;
  out << "{\"format\": \"ramus-skeleton\", \"version\": 1, \"nodes\": [";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    out << (i ? ", " : "") << "{\"position\": [" << nodes[i].x << ", " << nodes[i].y + dy << ", "
        << nodes[i].z << "], \"radius\": 0.05, \"parent\": " << nodes[i].parent << "}";
  }
  out << "]}";
  return out.str();
}

struct Row {
  double within = -1, precision = -1, recall = -1;
};

// The row of the distance table for `within`, as printed.
Row row_for(const std::string& out, const std::string& within) {
  std::istringstream in(out.substr(out.find("skeleton B against reference A")));
  std::string line;
  while (std::getline(in, line)) {
    Row r;
    if (line.rfind(within + " ", 0) == 0 &&
        std::sscanf(line.c_str(), "%lf %lf %lf", &r.within, &r.precision, &r.recall) == 3)
      return r;
  }
  return {};
}

// `ramus compare A B --within WITHIN` on two skeleton files written into `tmp`.
CliResult compare_within(const TempDir& tmp, const std::string& a_json, const std::string& b_json,
                         const std::string& within) {
  const fs::path a = tmp.write("a.json", a_json), b = tmp.write("b.json", b_json);
  return run_ramus_split(tmp.path, {"compare", a.string(), b.string(), "--within", within});
}

}  // namespace

TEST_CASE("compare distance cli: a skeleton 7 cm beside its reference", "[shape]") {
  TempDir tmp;
  const CliResult r = compare_within(tmp, tree_json(0, true), tree_json(0.07, true), "0.1,0.05");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  // Every sample of either is 7 cm from the other's (sampled every 1 cm, a fifth of 5 cm).
  CHECK(r.out.find("sampled every 0.01") != std::string::npos);
  const Row near = row_for(r.out, "0.05"), far = row_for(r.out, "0.1");
  CHECK(near.precision == 0);
  CHECK(near.recall == 0);
  CHECK(far.precision == 1);
  CHECK(far.recall == 1);
  // Ascending, whatever the order given, and before the branch statistics.
  CHECK(r.out.find("\n0.05 ") < r.out.find("\n0.1 "));
  CHECK(r.out.find("skeleton B against reference A") < r.out.find("largest KS"));
  CHECK(r.out.find("length: A 4.414, B 4.414 (B / A 1.0000); tips: A 2, B 2") != std::string::npos);
}

TEST_CASE("compare distance cli: a skeleton missing a branch of its reference", "[shape]") {
  TempDir tmp;
  const CliResult r = compare_within(tmp, tree_json(0, true), tree_json(0, false), "0.05");
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const Row row = row_for(r.out, "0.05");
  // All of B lies on A; of A, the trunk (303 of 447 samples) and the branch's first 5 cm (6).
  CHECK(row.precision == 1);
  CHECK(row.recall == Approx(309.0 / 447.0).margin(0.005));
  CHECK(r.out.find("length: A 4.414, B 3 (B / A 0.6796); tips: A 2, B 1") != std::string::npos);
  // The converse: B as the reference.
  const CliResult c = compare_within(tmp, tree_json(0, false), tree_json(0, true), "0.05");
  REQUIRE(c.status == 0);
  CHECK(row_for(c.out, "0.05").recall == 1);
  CHECK(row_for(c.out, "0.05").precision == Approx(309.0 / 447.0).margin(0.005));
}

TEST_CASE("compare distance cli: a reconstruction against itself, and what does not apply",
          "[shape]") {
  TempDir tmp;
  const fs::path a = tmp.write("a.json", tree_json(0, true));
  const std::string grammar = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/conifer.ramus";
  // A grammar's grown trees are not the reference tree.
  CliResult r = run_ramus({"compare", a.string(), grammar, "--within", "0.1"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--within measures a skeleton against a reference skeleton") !=
        std::string::npos);
  // Distances must be positive numbers.
  CHECK(run_ramus({"compare", a.string(), a.string(), "--within", "0"}).status != 0);
  CHECK(run_ramus({"compare", a.string(), a.string(), "--within", "-0.1"}).status != 0);
  CHECK(run_ramus({"compare", a.string(), a.string(), "--within", "x"}).status != 0);
  // A scan's reconstruction written to a file and read again lies on itself.
  const fs::path scan = fs::path(RAMUS_SHARED_DIR) / "data" / "rtwig_cloud.txt";
  if (!fs::exists(scan)) return;  // the shared data is not in every checkout
  const fs::path rec = tmp.path / "rec.json";
  REQUIRE(run_ramus({"reconstruct", scan.string(), "-o", rec.string()}).status == 0);
  r = run_ramus_split(tmp.path, {"compare", rec.string(), scan.string(), "--within", "0.01"});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK(row_for(r.out, "0.01").precision == 1);
  CHECK(row_for(r.out, "0.01").recall == 1);
}
