// The WebAssembly runtime (runtime/wasm/) grows, inside headless Chromium, the same trees as
// the native pipeline: the example page (examples/runtime/web/) fetches each .rmb, grows it
// with ramus_runtime.wasm and draws it with three.js; tests/runtime/browser/grow_in_chromium.mjs
// reports what it grew, and every node and organ must equal grow_file's (the engine behind
// `ramus build`) bit for bit, for the grammar's seed and another one.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "core/skeleton.h"
#include "formats/rmb/rmb_codec.h"
#include "grammar/loader.h"

namespace {

namespace fs = std::filesystem;

#ifdef RAMUS_WASM_BUILT
constexpr bool kWasmBuilt = true;
#else
constexpr bool kWasmBuilt = false;
#endif

struct Case {
  std::string example;  // below examples/
  std::uint64_t seed;   // 0: the grammar's own
};

// The little-endian bytes of the doubles as hex, the spelling grow_in_chromium.mjs uses.
std::string hex(const std::vector<double>& values) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (double v : values) {
    unsigned char b[8];
    std::memcpy(b, &v, 8);
    for (unsigned char c : b) {
      out += digits[c >> 4];
      out += digits[c & 15];
    }
  }
  return out;
}

// Where two hex strings of doubles first differ, as "item I" (stride doubles per item).
std::string first_difference(const std::string& want, const std::string& got, int stride) {
  std::size_t i = 0;
  while (i < want.size() && i < got.size() && want[i] == got[i]) ++i;
  return "item " + std::to_string(i / 16 / stride);
}

int run_shell(const std::string& cmd, std::string& out) {
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return -1;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  const int raw = pclose(pipe);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

TEST_CASE("WebAssembly: Chromium grows the skeletons of the native pipeline", "[runtime][wasm]") {
  // The demo tree (`make demo`) with its seed and a seed above 2^53 (JavaScript passes seeds
  // as BigInts), a tree with organs, a deterministic and a branching ABOP figure.
  const std::vector<Case> cases = {{"trees/broadleaf.ramus", 0},
                                   {"trees/broadleaf.ramus", 0xfedcba9876543210ull},
                                   {"trees/weeping.ramus", 0},
                                   {"abop/fig1_24a.ramus", 0},
                                   {"abop/fig2_8a_ternary.ramus", 7}};
  if (!kWasmBuilt) {
    WARN("skipped: configured with -DRAMUS_BUILD_WASM=OFF");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("ramus_wasm_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::vector<ramus::Skeleton> want;
  std::string args;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = std::string(RAMUS_SOURCE_DIR) + "/examples/" + cases[i].example;
    ramus::SourceManager sm;
    ramus::DiagnosticSink diags;
    const ramus::ir::Grammar g = ramus::lower_file(path, {}, sm, diags);
    const fs::path rmb = dir / (std::to_string(i) + ".rmb");
    std::ofstream(rmb, std::ios::binary) << ramus::encode_rmb(g);
    ramus::GrowOptions o;
    o.seed = cases[i].seed ? cases[i].seed : g.settings.seed;
    want.push_back(ramus::grow_file(path, o, sm, diags));
    args += " " + quote(rmb.string() + "#seed=" + std::to_string(*o.seed));
  }
  std::string out;
  const int code =
      run_shell("node " + quote(RAMUS_SOURCE_DIR "/tests/runtime/browser/grow_in_chromium.mjs") +
                    " " + quote(RAMUS_BINARY_DIR) + args,
                out);
  fs::remove_all(dir);
  if (code == 77) {
    WARN("skipped: " << out);
    return;
  }
  INFO(out.substr(0, 4000));
  REQUIRE(code == 0);
  std::vector<nlohmann::json> got;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("{\"file\"", 0) == 0) got.push_back(nlohmann::json::parse(line));
  }
  REQUIRE(got.size() == cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const ramus::Skeleton& s = want[i];
    const nlohmann::json& r = got[i];
    INFO(cases[i].example << " seed " << r["file"].get<std::string>());
    std::vector<double> positions, radii, organ_positions, organ_sizes;
    std::vector<std::int64_t> parents;
    for (const ramus::SkeletonNode& n : s.nodes) {
      positions.insert(positions.end(), {n.position.x, n.position.y, n.position.z});
      radii.push_back(n.radius);
      parents.push_back(n.parent == ramus::kNoParent ? -1 : std::int64_t(n.parent));
    }
    for (const ramus::OrganAnchor& o : s.organs) {
      organ_positions.insert(organ_positions.end(), {o.position.x, o.position.y, o.position.z});
      organ_sizes.push_back(o.size);
    }
    REQUIRE(r["nodes"].get<std::size_t>() == s.nodes.size());
    REQUIRE(r["organs"].get<std::size_t>() == s.organs.size());
    const auto same = [](const std::string& want_hex, const nlohmann::json& got_hex, int stride) {
      const std::string g = got_hex.get<std::string>();
      INFO("first difference at " << first_difference(want_hex, g, stride));
      CHECK(g == want_hex);
    };
    same(hex(positions), r["positions"], 3);
    same(hex(radii), r["radii"], 1);
    same(hex(organ_positions), r["organPositions"], 3);
    same(hex(organ_sizes), r["organSizes"], 1);
    CHECK(r["parents"].get<std::vector<std::int64_t>>() == parents);
    // Drawn: the page rendered segments and organs over part of its picture.
    CHECK(r["drawCalls"].get<int>() >= 1);
    CHECK(r["drawnPixels"].get<int>() > 0);
    CHECK(r["drawnPixels"].get<int>() < r["pixels"].get<int>());
  }
}
