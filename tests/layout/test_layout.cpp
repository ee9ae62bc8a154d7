// The layout of the source tree (docs/design.md, Stages): every include points down the order
// of the stages, no include loops between files or between implementations, no stage folder holds
// more than 35 % of the code, no source file is over 700 lines, every stage has its README.
// The build already refuses an include that points up (cmake/RamusLibrary.cmake gives each
// stage an include root with only the stages below it); this test names every offence at once
// and covers what the compiler cannot see: loops between units and sizes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = RAMUS_SOURCE_DIR;

// What each stage folder may include besides itself.
const std::map<std::string, std::set<std::string>> kMayUse = {
    {"core", {}},
    {"grammar", {"core"}},
    {"compiler", {"core", "grammar"}},
    {"formats", {"core", "grammar", "compiler"}},
    {"reconstruct", {"core"}},
    {"infer", {"core", "grammar", "compiler", "reconstruct"}},
    {"mesh", {"core"}},
    {"backends", {"core", "mesh", "grammar", "compiler", "formats"}},
    {"runtime", {"core", "mesh", "grammar", "compiler", "formats"}},
    {"lsp", {"core", "grammar"}},
    {"cli",
     {"core", "mesh", "grammar", "compiler", "formats", "reconstruct", "infer", "backends", "lsp"}},
};

bool is_source(const fs::path& p) {
  const std::string e = p.extension().string();
  return e == ".h" || e == ".cpp" || e == ".c" || e == ".def";
}

std::vector<fs::path> sources_under(const std::string& folder) {
  std::vector<fs::path> out;
  if (!fs::exists(kRoot / folder)) return out;
  for (const auto& e : fs::recursive_directory_iterator(kRoot / folder)) {
    if (e.is_regular_file() && is_source(e.path()) &&
        e.path().string().find("node_modules") == std::string::npos)
      out.push_back(fs::relative(e.path(), kRoot));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> lines_of(const fs::path& relative) {
  std::ifstream in(kRoot / relative);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The project includes of a file: "stage/..." paths.
std::vector<std::string> includes_of(const fs::path& relative) {
  static const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)")re");
  std::vector<std::string> out;
  for (const std::string& line : lines_of(relative)) {
    std::smatch m;
    if (std::regex_search(line, m, include)) out.push_back(m[1]);
  }
  return out;
}

std::string stage_of(const std::string& path) { return path.substr(0, path.find('/')); }

std::string lines_joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

// A unit is a header and its implementation: "formats/rmb/rmb_decompile".
std::string unit_of(const std::string& path) {
  return (fs::path(path).parent_path() / fs::path(path).stem()).string();
}

}  // namespace

TEST_CASE("every include points down the order of the stages") {
  std::vector<std::string> offences;
  for (const auto& [stage, allowed] : kMayUse) {
    for (const fs::path& file : sources_under(stage)) {
      for (const std::string& inc : includes_of(file)) {
        const std::string target = stage_of(inc);
        if (!kMayUse.count(target) && target != "tests") continue;  // a system or local header
        if (target != stage && !allowed.count(target))
          offences.push_back(file.string() + " includes " + inc);
      }
    }
  }
  INFO(lines_joined(offences));
  CHECK(offences.empty());
}

namespace {

// The loops of a directed graph, each as "a -> b -> ... -> a" (depth-first search: a grey node
// met again closes a loop).
std::vector<std::string> loops_of(const std::map<std::string, std::set<std::string>>& edges) {
  std::map<std::string, int> colour;  // 0 white, 1 grey, 2 black
  std::vector<std::string> path, loops;
  std::function<void(const std::string&)> visit = [&](const std::string& u) {
    colour[u] = 1;
    path.push_back(u);
    if (auto it = edges.find(u); it != edges.end()) {
      for (const std::string& v : it->second) {
        if (colour[v] == 1) {
          std::string loop;
          for (auto p = std::find(path.begin(), path.end(), v); p != path.end(); ++p)
            loop += *p + " -> ";
          loops.push_back(loop + v);
        } else if (colour[v] == 0) {
          visit(v);
        }
      }
    }
    path.pop_back();
    colour[u] = 2;
  };
  for (const auto& [u, _] : edges)
    if (colour[u] == 0) visit(u);
  return loops;
}

}  // namespace

TEST_CASE("no header of the stages includes itself through others") {
  std::map<std::string, std::set<std::string>> edges;  // file -> files it includes
  for (const auto& [stage, allowed] : kMayUse) {
    for (const fs::path& file : sources_under(stage)) {
      edges[file.string()];
      for (const std::string& inc : includes_of(file))
        if (fs::exists(kRoot / inc)) edges[file.string()].insert(inc);
    }
  }
  const std::vector<std::string> loops = loops_of(edges);
  INFO(lines_joined(loops));
  CHECK(loops.empty());
}

TEST_CASE("no two implementations depend on each other, directly or through others") {
  // a -> b when a.cpp includes b.h: the code of a calls b. A loop means that no unit of it can
  // be understood, tested or moved without the others (formats/rmb/rmb_decompile.cpp and
  // rmb_pieces_ast.cpp once called each other; the number they shared is now a unit below both).
  std::map<std::string, std::set<std::string>> edges;
  for (const auto& [stage, allowed] : kMayUse) {
    for (const fs::path& file : sources_under(stage)) {
      if (file.extension() != ".cpp") continue;
      const std::string from = unit_of(file.string());
      edges[from];
      for (const std::string& inc : includes_of(file)) {
        if (!fs::exists(kRoot / inc)) continue;
        const std::string to = unit_of(inc);
        if (to != from) edges[from].insert(to);
      }
    }
  }
  const std::vector<std::string> loops = loops_of(edges);
  INFO(lines_joined(loops));
  CHECK(loops.empty());
}

TEST_CASE("no folder holds more than 35 percent of the code outside the tests") {
  std::map<std::string, std::size_t> lines;
  std::size_t total = 0;
  for (const auto& entry : fs::directory_iterator(kRoot)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || name == "tests" || name == "build" || name[0] == '.') continue;
    for (const fs::path& file : sources_under(name)) {
      lines[name] += lines_of(file).size();
      total += lines_of(file).size();
    }
  }
  REQUIRE(total > 0);
  for (const auto& [folder, n] : lines) {
    INFO(folder << " holds " << n << " of " << total << " lines");
    CHECK(double(n) <= 0.35 * double(total));
  }
}

TEST_CASE("no source file is over 700 lines") {
  for (const auto& entry : fs::directory_iterator(kRoot)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || name == "build" || name[0] == '.') continue;
    for (const fs::path& file : sources_under(name)) {
      INFO(file.string());
      CHECK(lines_of(file).size() <= 700);
    }
  }
}

TEST_CASE("every stage folder says its job, what it may include and its entry headers") {
  for (const auto& [stage, allowed] : kMayUse) {
    INFO(stage);
    const fs::path readme = kRoot / stage / "README.md";
    REQUIRE(fs::exists(readme));
    std::ifstream in(readme);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str().find("May use:") != std::string::npos);
    CHECK(text.str().find("Entry headers:") != std::string::npos);
  }
}

// ctest registers each Catch2 test case by its name, and a name with ';' is split in two (a CMake
// list): neither half names a test case, so the test ran nothing and passed.
TEST_CASE("no test case name holds a semicolon") {
  const std::regex test_case(R"(TEST_CASE\(\s*"([^"]*)\")");
  for (const fs::path& file : sources_under("tests")) {
    for (const std::string& line : lines_of(file)) {
      std::smatch m;
      if (!std::regex_search(line, m, test_case)) continue;
      INFO(file.string() << ": " << m[1].str());
      CHECK(m[1].str().find(';') == std::string::npos);
    }
  }
}
