// `ramus infer --method skeleton` and `ramus compare` end to end: a real scan, a grammar, a
// skeleton file, bad input.
#include <catch2/catch.hpp>
#include <filesystem>

#include "../cli/cli_runner.h"
#include "skeleton_fixtures.h"

using cli_test::run_ramus;
using cli_test::slurp;

namespace {

std::string data(const std::string& name) {
  return std::string(RAMUS_SHARED_DIR) + "/data/" + name;
}

}  // namespace

TEST_CASE("infer skeleton cli: a real scan gives a grammar that checks and is formatted",
          "[skeleton_infer]") {
  const std::string out = skeleton_test::scratch("adtree_tree1.ramus").string();
  const auto r = run_ramus({"infer", data("adtree_tree1.xyz"), "-o", out, "--method", "skeleton"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("productions") != std::string::npos);
  CHECK(run_ramus({"check", out}).status == 0);
  CHECK(run_ramus({"fmt", "--check", out}).status == 0);
  const std::string text = slurp(out);
  std::string messages;
  CHECK(skeleton_test::grammar_checks(text, messages));
  // It grows a tree.
  const ramus::Skeleton grown = skeleton_test::grow_text("adtree_regrown.ramus", text, 2);
  CHECK(grown.size() > 10);
  // Deterministic: the same input and seed write the same bytes.
  const std::string again = skeleton_test::scratch("adtree_tree1_again.ramus").string();
  REQUIRE(
      run_ramus({"infer", data("adtree_tree1.xyz"), "-o", again, "--method", "skeleton"}).status ==
      0);
  CHECK(slurp(again) == text);
}

TEST_CASE("infer skeleton cli: options, merge, and bad input", "[skeleton_infer]") {
  const std::string grammar = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/conifer.ramus";
  const std::string out = skeleton_test::scratch("conifer_inferred.ramus").string();
  auto r = run_ramus({"infer", grammar, "-o", out, "--method", "skeleton", "--model", "clustered",
                      "--max-rules", "6", "--clusters", "3", "--merge", "10,15"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("merged branches") != std::string::npos);
  CHECK(run_ramus({"check", out}).status == 0);
  // Bad --merge text, a one-node skeleton, an unreadable input, a malformed skeleton file.
  r = run_ramus({"infer", grammar, "-o", out, "--method", "skeleton", "--merge", "ten"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--merge") != std::string::npos);
  const std::string one = skeleton_test::write_temp(
      "one_node.json",
      R"({"format": "ramus-skeleton", "version": 1, "nodes": [{"position": [0, 0, 0], "parent": -1, "radius": 0.1}]})");
  r = run_ramus({"infer", one, "-o", out, "--method", "skeleton"});
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK(r.out.find("error") != std::string::npos);
  r = run_ramus({"infer", "/nonexistent/x.json", "-o", out, "--method", "skeleton"});
  CHECK(r.status == 1);
  // The options of the other model are errors, before the input is read or reconstructed.
  const std::string never = skeleton_test::scratch("never_written.ramus").string();
  std::filesystem::remove(never);
  r = run_ramus(
      {"infer", data("adtree_tree1.xyz"), "-o", never, "--method", "skeleton", "--max-rules", "5"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--max-rules applies to --model clustered only") != std::string::npos);
  CHECK(r.out.find("reconstructed") == std::string::npos);
  r = run_ramus({"infer", grammar, "-o", never, "--method", "skeleton", "--model", "clustered",
                 "--limb-share", "0.1"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--limb-share applies to --model scaffold only") != std::string::npos);
  CHECK(!std::filesystem::exists(never));
  const std::string bad = skeleton_test::write_temp("bad.json", "{\"format\": ");
  r = run_ramus({"infer", bad, "-o", out, "--method", "skeleton"});
  CHECK(r.status == 1);
}

TEST_CASE("compare cli: prints a KS distance per distribution", "[skeleton_infer]") {
  const std::string grammar = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/broadleaf.ramus";
  auto r = run_ramus({"compare", grammar, grammar, "--seeds", "3"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  for (const char* m : {"branch length", "branching angle", "azimuth", "radius ratio",
                        "branch order", "total length", "crown extent", "height"}) {
    CHECK(r.out.find(m) != std::string::npos);
  }
  // The same source against itself: every distance is 0.
  CHECK(r.out.find("largest KS 0.0000") != std::string::npos);
  // A scan against a grammar.
  r = run_ramus({"compare", data("adtree_tree1.xyz"), grammar, "--seeds", "2"});
  CHECK(r.status == 0);
  r = run_ramus({"compare", "/nonexistent.json", grammar});
  CHECK(r.status == 1);
}

TEST_CASE("infer skeleton cli: reconstruction options, the written skeleton and compare",
          "[skeleton_infer]") {
  // The flood fill reconstructs the scan; the skeleton the grammar comes from is written too,
  // and `compare` reconstructs the scan the same way, so it reads the same skeleton.
  const std::string out = skeleton_test::scratch("rtwig_flood.ramus").string();
  const std::string skel = skeleton_test::scratch("rtwig_flood.json").string();
  auto r = run_ramus({"infer", data("rtwig_cloud.txt"), "-o", out, "--method", "skeleton",
                      "--reconstruct", "flood", "--write-skeleton", skel});
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("reconstructed (flood)") != std::string::npos);
  CHECK(r.out.find("elasticity") != std::string::npos);
  CHECK(run_ramus({"check", out}).status == 0);
  const auto from_json = run_ramus({"compare", skel, out, "--seeds", "3"});
  const auto from_scan = run_ramus(
      {"compare", data("rtwig_cloud.txt"), out, "--seeds", "3", "--reconstruct", "flood"});
  REQUIRE(from_json.status == 0);
  REQUIRE(from_scan.status == 0);
  // The same A side: identical tables (the progress line goes to stderr, merged in `out`).
  auto table = [](const std::string& s) { return s.substr(s.find("\nmeasure ") + 1); };
  CHECK(table(from_json.out) == table(from_scan.out));
  // The skeleton file regrows the same grammar as the scan it came from.
  const std::string out2 = skeleton_test::scratch("rtwig_flood_json.ramus").string();
  REQUIRE(run_ramus({"infer", skel, "-o", out2, "--method", "skeleton"}).status == 0);
  const std::string a = slurp(out), b = slurp(out2);
  CHECK(a.substr(a.find('\n')) == b.substr(b.find('\n')));  // the header names the input
  // --voxel reaches the BSG reconstruction; bad values are usage errors.
  CHECK(run_ramus({"infer", data("rtwig_cloud.txt"), "-o", out, "--method", "skeleton", "--voxel",
                   "0.02", "--model", "clustered", "--calibrate", "1"})
            .status == 0);
  CHECK(run_ramus({"infer", data("rtwig_cloud.txt"), "-o", out, "--method", "skeleton",
                   "--reconstruct", "poisson"})
            .status != 0);
  CHECK(run_ramus({"compare", data("rtwig_cloud.txt"), out, "--voxel", "-1"}).status != 0);
  // --no-tropism writes no elasticity.
  REQUIRE(run_ramus({"infer", std::string(RAMUS_SOURCE_DIR) + "/examples/trees/conifer.ramus", "-o",
                     out, "--method", "skeleton", "--no-tropism"})
              .status == 0);
  CHECK(slurp(out).find("elasticity") == std::string::npos);
}
