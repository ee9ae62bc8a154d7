// ABOP conformance: the examples of examples/abop/ derived by the `ramus` executable must match
// the numbers of tests/expected/abop.tsv and the words of tests/expected/abop_strings.tsv.
//
// The expected files are written by tests/tools/abop_oracle.py, an independent rewriter that
// types every L-system in from the book (Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of
// Plants, 1990) and cross-checks itself with Parikh vectors, recurrences and closed forms; see
// its header for how each number is computed. Three properties are checked here directly:
// the invariant length = (5 #F - 3) / 2 of the stochastic fig. 1.27 (and its seeding), the
// lattice path of the 3D Hilbert curve (fig. 1.10), and a clean `ramus check` of every example
// and stdlib file.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

using Run = cli_test::CliResult;

// Runs `ramus ARGS` and returns its exit status and output (stdout and stderr together).
Run ramus(const std::vector<std::string>& args) { return cli_test::run_ramus(args); }

std::string source_path(const std::string& rel) {
  return std::string(RAMUS_SOURCE_DIR) + "/" + rel;
}

// Reads a tab-separated file, skipping '#' comments and blank lines.
std::vector<std::vector<std::string>> read_tsv(const std::string& rel) {
  std::ifstream in(source_path(rel));
  REQUIRE(in.good());
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cols;
    std::stringstream ss(line);
    std::string col;
    while (std::getline(ss, col, '\t')) cols.push_back(col);
    rows.push_back(cols);
  }
  return rows;
}

// The --stats output: `length N`, `count SYM N`, `sum SYM.K V`, `steps N`, `time T s`.
struct Stats {
  bool has_length = false, has_steps = false;
  long long length = -1, steps = -1;
  std::map<std::string, long long> counts;
  std::map<std::string, double> sums;  // key "F.0"
};

Stats parse_stats(const std::string& text) {
  Stats s;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "length") {
      s.has_length = bool(ls >> s.length);
    } else if (key == "steps") {
      s.has_steps = bool(ls >> s.steps);
    } else if (key == "count") {
      std::string sym;
      long long n = 0;
      if (ls >> sym >> n) s.counts[sym] = n;
    } else if (key == "sum") {
      std::string what;
      double v = 0;
      if (ls >> what >> v) s.sums[what] = v;
    }
  }
  return s;
}

long long count_of(const Stats& s, const std::string& sym) {
  auto it = s.counts.find(sym);
  return it == s.counts.end() ? 0 : it->second;
}

std::string without_space(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (!std::isspace(static_cast<unsigned char>(c))) r += c;
  }
  return r;
}

// Checks every row of abop.tsv whose file name contains `part`; returns how many it checked.
// The first row of a file is at the file's own `derive N`, so it runs without -n.
int check_rows(const std::string& part) {
  int checked = 0;
  std::set<std::string> seen;
  for (const auto& row : read_tsv("tests/expected/abop.tsv")) {
    REQUIRE(row.size() == 5);
    const std::string& file = row[0];
    if (file.find(part) == std::string::npos || row[2].find('F') != std::string::npos) continue;
    const bool first = seen.insert(file).second;
    std::vector<std::string> args = {"derive", source_path(file), "--stats"};
    if (!first) args.insert(args.end(), {"-n", row[1]});
    Run run = ramus(args);
    INFO("ramus derive " << file << (first ? "" : " -n " + row[1]) << " --stats\n" << run.out);
    REQUIRE(run.status == 0);
    Stats s = parse_stats(run.out);
    REQUIRE(s.has_length);
    CHECK(s.length == std::stoll(row[2]));
    CHECK(count_of(s, "F") == std::stoll(row[3]));
    REQUIRE(s.has_steps);
    CHECK(s.steps == std::stoll(row[1]));
    if (row[4] != "-") {
      int f_sums = 0;
      for (const auto& [key, value] : s.sums) {
        if (key.rfind("F.", 0) != 0) continue;
        ++f_sums;
        double want = std::stod(row[4]);
        CHECK(std::abs(value - want) <= 1e-9 * std::max(1.0, std::abs(want)));
      }
      CHECK(f_sums == 1);  // F has one parameter in every ABOP example
    }
    ++checked;
  }
  return checked;
}

}  // namespace

TEST_CASE("abop: every row of the expected table belongs to a tested example", "[abop]") {
  const std::vector<std::string> groups = {"fig1_24",   "fig1_25",   "fig1_27", "fig1_31",
                                           "hilbert3d", "param_p42", "fig2_6",  "fig2_8",
                                           "fig5_5",    "ch5_lily"};
  auto rows = read_tsv("tests/expected/abop.tsv");
  REQUIRE(rows.size() > 100);
  for (const auto& row : rows) {
    INFO(row[0]);
    bool found = false;
    for (const auto& g : groups) found = found || row[0].find(g) != std::string::npos;
    CHECK(found);
    CHECK(fs::exists(source_path(row[0])));
  }
}

TEST_CASE("abop: fig 1.24a-f bracketed OL-systems", "[abop]") { CHECK(check_rows("fig1_24") > 0); }

TEST_CASE("abop: fig 1.25 three-dimensional bush", "[abop]") { CHECK(check_rows("fig1_25") > 0); }

TEST_CASE("abop: fig 1.31a-e context-sensitive with ignore sets", "[abop]") {
  CHECK(check_rows("fig1_31") > 0);
}

TEST_CASE("abop: p. 42 parametric example counts", "[abop]") { CHECK(check_rows("param_p42") > 0); }

TEST_CASE("abop: fig 2.6a-d monopodial trees with F length sums", "[abop]") {
  CHECK(check_rows("fig2_6") > 0);
}

TEST_CASE("abop: fig 2.8a-d ternary trees with tropism and F length sums", "[abop]") {
  CHECK(check_rows("fig2_8") > 0);
}

TEST_CASE("abop: 3D Hilbert curve counts", "[abop]") { CHECK(check_rows("hilbert3d") > 0); }

TEST_CASE("abop: fig 5.5 cordate leaf and the lily of the valley (polygons) counts", "[abop]") {
  CHECK(check_rows("fig5_5") > 0);
  CHECK(check_rows("ch5_lily") > 0);
}

TEST_CASE("abop: polygon symbols { . } G counted exactly", "[abop]") {
  int checked = 0;
  for (const auto& row : read_tsv("tests/expected/abop_polygons.tsv")) {
    REQUIRE(row.size() == 6);
    Run run = ramus({"derive", source_path(row[0]), "-n", row[1], "--stats"});
    INFO("ramus derive " << row[0] << " -n " << row[1] << " --stats\n" << run.out);
    REQUIRE(run.status == 0);
    const Stats s = parse_stats(run.out);
    CHECK(count_of(s, "{") == std::stoll(row[2]));
    CHECK(count_of(s, ".") == std::stoll(row[3]));
    CHECK(count_of(s, "}") == std::stoll(row[4]));
    CHECK(count_of(s, "G") == std::stoll(row[5]));
    ++checked;
  }
  CHECK(checked >= 15);
}

TEST_CASE("abop: whole words of short derivations including p. 42", "[abop]") {
  int checked = 0;
  for (const auto& row : read_tsv("tests/expected/abop_strings.tsv")) {
    REQUIRE(row.size() == 3);
    Run run = ramus({"derive", source_path(row[0]), "-n", row[1], "--print"});
    INFO("ramus derive " << row[0] << " -n " << row[1] << " --print\n" << run.out);
    REQUIRE(run.status == 0);
    CHECK(without_space(run.out) == row[2]);
    ++checked;
  }
  CHECK(checked > 0);
}

TEST_CASE("abop: fig 1.27 stochastic length invariant for several seeds", "[abop]") {
  const std::string file = source_path("examples/abop/fig1_27.ramus");
  for (const char* seed : {"1", "2", "3", "17", "12345"}) {
    for (const char* steps : {"1", "3", "5", "6"}) {
      Run run = ramus({"derive", file, "--stats", "--seed", seed, "-n", steps});
      INFO("seed " << seed << " steps " << steps << "\n" << run.out);
      REQUIRE(run.status == 0);
      Stats s = parse_stats(run.out);
      REQUIRE(s.has_length);
      long long f = count_of(s, "F");
      CHECK(2 * s.length == 5 * f - 3);
      // every F makes 3 or 5 F per step
      CHECK(f >= std::pow(3, std::stoi(steps)));
      CHECK(f <= std::pow(5, std::stoi(steps)));
    }
  }
}

TEST_CASE("abop: fig 1.27 same seed same word and different seeds different words", "[abop]") {
  const std::string file = source_path("examples/abop/fig1_27.ramus");
  auto word = [&](const char* seed) {
    Run run = ramus({"derive", file, "--print", "--seed", seed});
    INFO(run.out);
    REQUIRE(run.status == 0);
    return without_space(run.out);
  };
  const std::string a = word("1");
  CHECK(a.size() > 100);
  CHECK(word("1") == a);
  CHECK(word("2") != a);
  CHECK(word("3") != a);
  // without --seed the file's own `seed 1` is used
  Run run = ramus({"derive", file, "--print"});
  REQUIRE(run.status == 0);
  CHECK(without_space(run.out) == a);
}

namespace {

// The node positions of a skeleton file (docs/skeleton-format.md): every "position": [x, y, z]
// between the "nodes" key and the "organs" key, in file order. A scan rather than a JSON
// parser, so this test needs nothing but the executable.
std::vector<std::array<double, 3>> skeleton_positions(const std::string& file_text) {
  std::vector<std::array<double, 3>> out;
  const std::size_t nodes = file_text.find("\"nodes\"");
  if (nodes == std::string::npos) return out;
  const std::string json = file_text.substr(nodes, file_text.find("\"organs\"", nodes) - nodes);
  const std::string key = "\"position\"";
  for (std::size_t at = json.find(key); at != std::string::npos; at = json.find(key, at + 1)) {
    std::size_t open = json.find('[', at);
    if (open == std::string::npos) break;
    std::array<double, 3> p{};
    const char* c = json.c_str() + open + 1;
    for (int k = 0; k < 3; ++k) {
      char* end = nullptr;
      p[k] = std::strtod(c, &end);
      c = end;
      while (*c == ',' || std::isspace(static_cast<unsigned char>(*c))) ++c;
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace

TEST_CASE("abop: 3D Hilbert curve path visits every lattice point of its box once", "[abop]") {
  const std::string file = source_path("examples/abop/hilbert3d.ramus");
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "abop_conformance";
  fs::create_directories(dir);
  for (int n = 1; n <= 3; ++n) {
    const std::string out = (dir / ("hilbert" + std::to_string(n) + ".json")).string();
    Run run = ramus({"derive", file, "-n", std::to_string(n), "--skeleton", out});
    INFO("n = " << n << "\n" << run.out);
    REQUIRE(run.status == 0);
    std::ifstream in(out);
    REQUIRE(in.good());
    std::stringstream text;
    text << in.rdbuf();
    auto points = skeleton_positions(text.str());
    const long long cells = 1LL << (3 * n);  // 8^n
    REQUIRE(points.size() >= std::size_t(cells));
    std::set<std::tuple<long long, long long, long long>> visited;
    std::array<long long, 3> lo{}, hi{};
    for (std::size_t i = 0; i < points.size(); ++i) {
      std::array<long long, 3> r{};
      for (int k = 0; k < 3; ++k) {
        r[k] = std::llround(points[i][k]);
        CHECK(std::abs(points[i][k] - double(r[k])) < 1e-6);
        lo[k] = i == 0 ? r[k] : std::min(lo[k], r[k]);
        hi[k] = i == 0 ? r[k] : std::max(hi[k], r[k]);
      }
      visited.insert({r[0], r[1], r[2]});
    }
    CHECK(visited.size() == std::size_t(cells));
    for (int k = 0; k < 3; ++k) CHECK(hi[k] - lo[k] == (1LL << n) - 1);
  }
}

TEST_CASE("abop: ramus check reports no errors on every example and stdlib file", "[abop]") {
  int files = 0;
  for (const char* folder : {"examples", "stdlib"}) {
    for (const auto& entry : fs::recursive_directory_iterator(source_path(folder))) {
      if (entry.path().extension() != ".ramus") continue;
      Run run = ramus({"check", entry.path().string()});
      INFO("ramus check " << entry.path().string() << "\n" << run.out);
      CHECK(run.status == 0);
      CHECK(run.out.find("error") == std::string::npos);
      ++files;
    }
  }
  CHECK(files >= 24);
}

namespace {

// How many organs of a skeleton file are polygons, and how many vertices they have in all.
std::pair<int, int> polygon_organs(const std::string& file_text) {
  int polygons = 0, vertices = 0;
  const std::string key = "\"vertices\": [";
  for (std::size_t at = file_text.find(key); at != std::string::npos;
       at = file_text.find(key, at + 1)) {
    ++polygons;
    const std::size_t end = file_text.find("]]", at);
    for (std::size_t v = file_text.find('[', at + key.size()); v != std::string::npos && v < end;
         v = file_text.find('[', v + 1)) {
      ++vertices;
    }
  }
  return {polygons, vertices};
}

}  // namespace

TEST_CASE("abop: the turtle's polygons of fig 5.5 and the lily of the valley", "[abop]") {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "abop_conformance";
  fs::create_directories(dir);
  auto skeleton = [&](const std::string& example, const std::string& steps) {
    const std::string out = (dir / (example + steps + ".json")).string();
    Run run = ramus({"derive", source_path("examples/abop/" + example + ".ramus"), "-n", steps,
                     "--skeleton", out});
    INFO(run.out);
    REQUIRE(run.status == 0);
    std::ifstream in(out);
    std::stringstream text;
    text << in.rdbuf();
    return polygon_organs(text.str());
  };
  // Cordate leaf after n steps: n polygons `{.].C.}` a side, each a triangle (a point of the
  // inner axis, the branch point, the point the outer axis C has grown to) except the two
  // youngest, whose axes have not grown yet: two of their vertices coincide, no surface.
  for (int n : {3, 10, 20}) {
    const auto [polygons, vertices] = skeleton("fig5_5_cordate_leaf", std::to_string(n));
    CHECK(polygons == 2 * n - 4);
    CHECK(vertices == 3 * (2 * n - 4));
  }
  // Lily: each of the 5 petals has n nested polygons, quads between the A and B axes, except the
  // innermost, whose A and B points both sit at the base: a triangle.
  for (int n : {2, 5}) {
    const auto [polygons, vertices] = skeleton("ch5_lily_of_the_valley", std::to_string(n));
    CHECK(polygons == 5 * n);
    CHECK(vertices == 5 * (4 * n - 1));
  }
}

TEST_CASE("abop: ramus check exits 1 on a closing bracket that closes no branch", "[abop]") {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "abop_conformance";
  fs::create_directories(dir);
  const std::string bad = (dir / "stray_pop.ramus").string();
  {
    std::ofstream f(bad);
    f << "lsystem stray { derive 2; axiom F; F -> F[+F]]F[-F; }\n";
  }
  Run check = ramus({"check", bad});
  CHECK(check.status == 1);
  CHECK(check.out.find(":1:46: error[E0309]: ']' closes no branch") != std::string::npos);
  CHECK(check.out.find("error[E0309]: '[' opens a branch that is never closed") !=
        std::string::npos);
}
