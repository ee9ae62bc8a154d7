// `ramus scan` and `ramus reconstruct` end to end: every output kind, --trees, bad input files,
// and the scanner's options (stations, noise, density, ground truth, determinism).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <sstream>

#include "../cli/cli_runner.h"

using namespace cli_test;

namespace {

const std::string kBroadleaf = RAMUS_SOURCE_DIR "/examples/trees/broadleaf.ramus";

// A small, fast scan of the broadleaf example from two stations.
fs::path small_scan(const TempDir& dir, const std::string& name = "scan.ply") {
  const fs::path out = dir.path / name;
  const CliResult r = run_ramus({"scan", kBroadleaf, "-o", out.string(), "--from", "0,-20,0.2",
                                 "--from", "20,0,0.2", "--noise", "0.005", "--density", "600"});
  INFO(r.out);
  REQUIRE(r.status == 0);
  return out;
}

// Number of "parent": -1 entries in skeleton JSON: one per tree.
std::size_t roots_in(const std::string& json) {
  std::size_t n = 0;
  for (std::size_t at = json.find("\"parent\": -1"); at != std::string::npos;
       at = json.find("\"parent\": -1", at + 1)) {
    ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("ramus scan: stations, noise and density shape the cloud, truth is written",
          "[reconstruct_cli]") {
  TempDir dir;
  const fs::path one = dir.path / "one.xyz", two = dir.path / "two.xyz", dense = dir.path / "d.xyz";
  const fs::path truth = dir.path / "truth.json";
  REQUIRE(run_ramus({"scan", kBroadleaf, "-o", one.string(), "--from", "0,-20,0.2", "--density",
                     "300", "--truth", truth.string()})
              .status == 0);
  REQUIRE(run_ramus({"scan", kBroadleaf, "-o", two.string(), "--from", "0,-20,0.2", "--from",
                     "0,20,0.2", "--density", "300"})
              .status == 0);
  REQUIRE(run_ramus({"scan", kBroadleaf, "-o", dense.string(), "--from", "0,-20,0.2", "--density",
                     "1200"})
              .status == 0);
  auto lines = [](const fs::path& p) {
    const std::string s = slurp(p);
    return std::size_t(std::count(s.begin(), s.end(), '\n'));
  };
  const std::size_t n1 = lines(one), n2 = lines(two), nd = lines(dense);
  INFO(n1 << " " << n2 << " " << nd);
  CHECK(n1 > 1000);
  // A second station sees the other side: clearly more points, not a copy.
  CHECK(n2 > n1 * 3 / 2);
  // Four times the density: about four times the points.
  CHECK(nd > 3 * n1);
  CHECK(nd < 5 * n1);
  const std::string t = slurp(truth);
  CHECK(t.find("ramus-skeleton") != std::string::npos);
  CHECK(roots_in(t) == 1);
}

TEST_CASE("ramus scan: the same seed gives identical bytes", "[reconstruct_cli]") {
  TempDir dir;
  auto scan = [&](const std::string& name, const std::string& seed) {
    const fs::path out = dir.path / name;
    REQUIRE(run_ramus({"scan", kBroadleaf, "-o", out.string(), "--density", "300", "--noise",
                       "0.01", "--seed", seed})
                .status == 0);
    return slurp(out);
  };
  const std::string a = scan("a.ply", "5"), b = scan("b.ply", "5"), c = scan("c.ply", "6");
  CHECK(a.size() > 1000);
  CHECK(a == b);
  CHECK(a != c);
}

TEST_CASE("ramus scan: bad stations and options are user errors", "[reconstruct_cli]") {
  TempDir dir;
  const std::string out = (dir.path / "x.ply").string();
  CliResult r = run_ramus({"scan", kBroadleaf, "-o", out, "--from", "1,2"});
  CHECK(r.status == 1);
  CHECK(r.out.find("x,y,z") != std::string::npos);
  r = run_ramus({"scan", kBroadleaf, "-o", out, "--noise", "-1"});
  CHECK(r.status != 0);
  r = run_ramus({"scan", kBroadleaf, "-o", (dir.path / "x.obj").string()});
  CHECK(r.status != 0);
  // A range resolution parts echoes of a beam of some width; a registration error shifts the
  // stations after the first.
  r = run_ramus({"scan", kBroadleaf, "-o", out, "--range-resolution", "0.8"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--beam-divergence") != std::string::npos);
  r = run_ramus({"scan", kBroadleaf, "-o", out, "--registration-error", "0.01"});
  CHECK(r.status == 1);
  CHECK(r.out.find("two or more --from") != std::string::npos);
  r = run_ramus({"scan", kBroadleaf, "-o", out, "--beam-divergence", "-0.3"});
  CHECK(r.status != 0);
}

TEST_CASE("ramus scan: a wide beam adds mixed points, reconstruct ignores them as stray",
          "[reconstruct_cli]") {
  TempDir dir;
  const std::string plain = (dir.path / "plain.xyz").string();
  const std::string beam = (dir.path / "beam.xyz").string();
  const std::vector<std::string> common{"--from",  "0,-20,0.2", "--from",    "20,0,0.2",
                                        "--noise", "0.005",     "--density", "600"};
  std::vector<std::string> a{"scan", kBroadleaf, "-o", plain};
  a.insert(a.end(), common.begin(), common.end());
  REQUIRE(run_ramus(a).status == 0);
  std::vector<std::string> b{"scan", kBroadleaf, "-o", beam};
  for (const char* arg :
       {"--beam-divergence", "0.3", "--beam-diameter", "0.002", "--registration-error", "0.003"})
    b.push_back(arg);
  b.insert(b.end(), common.begin(), common.end());
  REQUIRE(run_ramus(b).status == 0);
  CHECK(slurp(plain) != slurp(beam));
  const std::string out = (dir.path / "t.json").string();
  CliResult r = run_ramus({"reconstruct", beam, "-o", out});
  INFO(r.out);
  CHECK(r.status == 0);
  CHECK(r.out.find("stray point(s)") != std::string::npos);
  r = run_ramus({"reconstruct", beam, "-o", out, "--keep-stray"});
  CHECK(r.status == 0);
  CHECK(r.out.find("stray point(s)") == std::string::npos);
  // The flood fill ignores them too.
  r = run_ramus({"reconstruct", beam, "-o", out, "--method", "flood"});
  CHECK(r.status == 0);
  CHECK(r.out.find("stray point(s)") != std::string::npos);
  r = run_ramus({"reconstruct", beam, "-o", out, "--method", "flood", "--keep-stray"});
  CHECK(r.status == 0);
  CHECK(r.out.find("stray point(s)") == std::string::npos);
  // The cluster size: the note says it, a larger one takes at least the points a smaller one
  // does, 1 (the default) leaves the neighbour test alone, and it has no meaning with
  // --keep-stray.
  const auto ignored = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args{"reconstruct", beam, "-o", out};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliResult c = run_ramus(args);
    INFO(c.out);
    CHECK(c.status == 0);
    const std::size_t at = c.out.find("ignored ");
    return at == std::string::npos ? 0L : std::stol(c.out.substr(at + 8));
  };
  r = run_ramus({"reconstruct", beam, "-o", out, "--stray-cluster", "5"});
  CHECK(r.out.find("or in a cluster of fewer than 5 points") != std::string::npos);
  const long alone = ignored({"--stray-cluster", "1"});
  const long by_default = ignored({});
  const long five = ignored({"--stray-cluster", "5"});
  const long twelve = ignored({"--stray-cluster", "12"});
  CHECK(alone > 0);
  CHECK(by_default == alone);
  CHECK(five >= alone);
  CHECK(twelve > alone);
  CHECK(twelve >= five);
  r = run_ramus({"reconstruct", beam, "-o", out});
  CHECK(r.out.find("cluster") == std::string::npos);
  r = run_ramus({"reconstruct", beam, "-o", out, "--stray-cluster", "-1"});
  CHECK(r.status != 0);
  CHECK(r.out.find("--stray-cluster") != std::string::npos);
  r = run_ramus({"reconstruct", beam, "-o", out, "--keep-stray", "--stray-cluster", "3"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--stray-cluster does not apply with --keep-stray") != std::string::npos);
}

TEST_CASE("ramus reconstruct: every output kind from one scan", "[reconstruct_cli]") {
  TempDir dir;
  const fs::path scan = small_scan(dir);
  for (const std::string ext : {".glb", ".obj", ".ply", ".json"}) {
    const fs::path out = dir.path / ("tree" + ext);
    const CliResult r = run_ramus({"reconstruct", scan.string(), "-o", out.string()});
    INFO(ext << ": " << r.out);
    REQUIRE(r.status == 0);
    const std::string bytes = slurp(out);
    REQUIRE(bytes.size() > 200);
    if (ext == ".glb") CHECK(bytes.compare(0, 4, "glTF") == 0);
    if (ext == ".obj") CHECK(bytes.find("\nf ") != std::string::npos);
    if (ext == ".ply") CHECK(bytes.compare(0, 3, "ply") == 0);
    if (ext == ".json") CHECK(roots_in(bytes) == 1);  // one tree in a one-tree scan
  }
}

TEST_CASE("ramus reconstruct: --trees one keeps one of several trees", "[reconstruct_cli]") {
  TempDir dir;
  // Two copies of one scan, 30 m apart: two trees.
  const fs::path a = small_scan(dir, "a.xyz");
  std::string text = slurp(a), shifted;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    double x, y, z;
    if (std::sscanf(line.c_str(), "%lf %lf %lf", &x, &y, &z) == 3) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f\n", x + 30, y, z);
      shifted += buf;
    }
  }
  const fs::path both = dir.write("both.xyz", text + shifted);
  const fs::path all = dir.path / "all.json", one = dir.path / "one.json";
  REQUIRE(run_ramus({"reconstruct", both.string(), "-o", all.string(), "--trees", "all"}).status ==
          0);
  REQUIRE(run_ramus({"reconstruct", both.string(), "-o", one.string(), "--trees", "one"}).status ==
          0);
  CHECK(roots_in(slurp(all)) == 2);
  CHECK(roots_in(slurp(one)) == 1);
  CHECK(run_ramus({"reconstruct", both.string(), "-o", one.string(), "--trees", "some"}).status !=
        0);
}

TEST_CASE("ramus reconstruct: bad scans give clear errors, never a crash", "[reconstruct_cli]") {
  TempDir dir;
  std::string plane, dup, box;
  for (int i = 0; i < 3000; ++i) {
    plane += std::to_string(i % 61 * 0.1) + " " + std::to_string(i / 61 * 0.1) + " 0\n";
    dup += "1 1 1\n";
  }
  // A closed box (a building, 10 x 6 x 8 m, with a roof) standing on a ground plane.
  for (int i = 0; i < 200; ++i) {
    for (int k = 0; k < 100; ++k) {
      const double u = i / 200.0, v = k / 100.0;
      char buf[256];
      std::snprintf(buf, sizeof buf, "%f 0 %f\n%f 6 %f\n0 %f %f\n10 %f %f\n%f %f 8\n%f %f 0\n",
                    10 * u, 8 * v, 10 * u, 8 * v, 6 * u, 8 * v, 6 * u, 8 * v, 10 * u, 6 * v,
                    -5 + 20 * u, -5 + 16 * v);
      box += buf;
    }
  }
  struct Case {
    std::string name, text, message;
  };
  const std::vector<Case> cases = {
      {"empty.xyz", "", "empty"},          {"nan.xyz", "nan nan nan\n1 2 3\n", "finite"},
      {"single.xyz", "1 2 3\n", "finite"}, {"plane.xyz", plane, "terrain"},
      {"duplicates.xyz", dup, "coincide"}, {"building.xyz", box, "no tree base"},
  };
  for (const Case& c : cases) {
    const fs::path in = dir.write(c.name, c.text);
    const fs::path out = dir.path / (c.name + ".glb");
    const CliResult r = run_ramus({"reconstruct", in.string(), "-o", out.string()});
    INFO(c.name << ": " << r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find(c.message) != std::string::npos);
    CHECK(r.out.find(c.name) != std::string::npos);  // the message names the file
    CHECK_FALSE(fs::exists(out));
  }
}
