// The WebAssembly runtime (runtime/wasm/) grows and meshes, inside headless Chromium, the trees
// of the native build: the example page (examples/runtime/web/) fetches each .rmb, grows it with
// ramus_runtime.wasm, meshes it and draws it with three.js; grow_in_chromium.mjs
// (tests/runtime/browser/) reports what the page made.
//
// What must be equal: the triangles the page meshed and three.js drew and the count in the
// .glb `ramus build` writes from the same .rmb and seed; node and organ counts, parents, every
// part's vertex count and index array (the native runtime's, whose arrays are the .glb's:
// test_grow_mesh_example.cpp); and a truncated image must give the runtime's "byte N: ...".
// What may differ in the last bits: the numbers. The module's math library is emscripten's
// (musl's sin, cos, atan2, ...), which rounds some arguments the other way from glibc's
// (docs/runtime.md, "In the browser"); the skeleton's doubles must agree within 1e-12 and the
// mesh's floats within 1e-6 of the largest magnitude of their array.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "core/skeleton.h"
#include "formats/rmb/rmb_codec.h"
#include "grammar/loader.h"
#include "runtime/ramus_runtime.h"
#include "tests/assets/three_runner.h"

namespace {

namespace fs = std::filesystem;
using cli_test::shell_quote;
using nlohmann::json;

#ifdef RAMUS_WASM_BUILT
constexpr bool kWasmBuilt = true;
#else
constexpr bool kWasmBuilt = false;
#endif

struct Case {
  std::string example;  // below examples/
  std::uint64_t seed;   // 0: the grammar's own
};

// The values whose little-endian bytes grow_in_chromium.mjs wrote as hex.
template <typename T>
std::vector<T> from_hex(const std::string& hex) {
  const auto nibble = [](char c) { return c <= '9' ? c - '0' : c - 'a' + 10; };
  std::vector<unsigned char> bytes(hex.size() / 2);
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] = static_cast<unsigned char>(nibble(hex[2 * i]) << 4 | nibble(hex[2 * i + 1]));
  }
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));  // no null
  return out;
}

// Checks that `got` has the values of `want`, each within tolerance x the largest magnitude
// in `want` (at least 1); says how many differ at all.
template <typename T>
void require_close(const std::string& what, const std::vector<T>& want, const std::vector<T>& got,
                   double tolerance) {
  INFO(what);
  REQUIRE(got.size() == want.size());
  double scale = 1, largest = 0;
  std::size_t differ = 0, worst = 0;
  for (std::size_t i = 0; i < want.size(); ++i) {
    scale = std::max(scale, std::fabs(double(want[i])));
    const double d = std::fabs(double(want[i]) - double(got[i]));
    if (want[i] != got[i]) ++differ;
    if (d > largest) largest = d, worst = i;
  }
  INFO(differ << " of " << want.size() << " values differ; the largest difference is " << largest
              << " at " << worst << " (scale " << scale << ")");
  CHECK(largest <= tolerance * scale);
}

template <typename T>
std::vector<T> array_of(const T* data, std::size_t n) {
  return data ? std::vector<T>(data, data + n) : std::vector<T>{};
}

// Compares level 0 of the page's mesh with the native runtime's (`ramus build`'s defaults).
void require_same_mesh(const std::string& rmb, std::uint64_t seed, const json& parts) {
  const std::string bytes = cli_test::slurp(rmb);
  std::unique_ptr<ramus_grammar, decltype(&ramus_free_grammar)> g(
      ramus_load(bytes.data(), bytes.size(), nullptr, 0), ramus_free_grammar);
  REQUIRE(g);
  std::unique_ptr<ramus_skeleton, decltype(&ramus_free_skeleton)> s(
      ramus_grow(g.get(), -1, seed, nullptr, 0), ramus_free_skeleton);
  REQUIRE(s);
  std::unique_ptr<ramus_mesh, decltype(&ramus_free_mesh)> m(
      ramus_mesh_build(s.get(), nullptr, nullptr, 0), ramus_free_mesh);
  REQUIRE(m);
  REQUIRE(parts.size() == 3);
  for (int part : {RAMUS_PART_BARK, RAMUS_PART_LEAVES, RAMUS_PART_SURFACES}) {
    INFO("part " << part);
    const std::size_t n = ramus_mesh_vertex_count(m.get(), 0, part);
    const std::size_t k = ramus_mesh_index_count(m.get(), 0, part);
    const json& p = parts[std::size_t(part)];
    REQUIRE(p.is_null() == (n == 0));
    if (n == 0) continue;
    CHECK(p["indices"].get<std::vector<std::uint32_t>>() ==
          array_of(ramus_mesh_indices(m.get(), 0, part), k));
    require_close("positions", array_of(ramus_mesh_positions(m.get(), 0, part), 3 * n),
                  from_hex<float>(p["positions"]), 1e-6);
    require_close("normals", array_of(ramus_mesh_normals(m.get(), 0, part), 3 * n),
                  from_hex<float>(p["normals"]), 1e-6);
    require_close("uvs", array_of(ramus_mesh_uvs(m.get(), 0, part), 2 * n),
                  from_hex<float>(p["uvs"]), 1e-6);
  }
}

// The triangles of every primitive of a .glb: the index accessors' counts / 3.
std::size_t glb_triangles(const fs::path& glb) {
  const std::string bytes = cli_test::slurp(glb);
  REQUIRE(bytes.size() > 20);
  REQUIRE(bytes.compare(0, 4, "glTF") == 0);
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  REQUIRE(bytes.compare(16, 4, "JSON") == 0);
  const json gltf = json::parse(bytes.substr(20, json_length));
  std::size_t indices = 0;
  for (const json& mesh : gltf["meshes"]) {
    for (const json& prim : mesh["primitives"]) {
      indices += gltf["accessors"][prim["indices"].get<std::size_t>()]["count"].get<std::size_t>();
    }
  }
  return indices / 3;
}

}  // namespace

TEST_CASE("WebAssembly: Chromium grows and meshes the trees of the native build",
          "[runtime][wasm]") {
  if (!kWasmBuilt) {
    WARN("skipped: configured with -DRAMUS_BUILD_WASM=OFF");
    return;
  }
  // The demo tree (`make demo`), a tree that draws random numbers with a seed above 2^53
  // (JavaScript passes seeds as BigInts), an ABOP figure with polygon leaves and a branching one.
  const std::vector<Case> cases = {{"trees/broadleaf.ramus", 0},
                                   {"trees/weeping.ramus", 0xfedcba9876543210ull},
                                   {"abop/fig5_5_cordate_leaf.ramus", 0},
                                   {"abop/fig2_8a_ternary.ramus", 7}};
  const fs::path dir = fs::temp_directory_path() / ("ramus_wasm_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<ramus::Skeleton> want;
  std::vector<std::size_t> want_triangles;
  std::vector<std::uint64_t> seeds;
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
    seeds.push_back(*o.seed);
    want.push_back(ramus::grow_file(path, o, sm, diags));
    const fs::path glb = dir / (std::to_string(i) + ".glb");
    assets_test::ramus_ok(
        {"build", rmb.string(), "--seed", std::to_string(*o.seed), "-o", glb.string()});
    want_triangles.push_back(glb_triangles(glb));
    args += " " + shell_quote(rmb.string() + "#seed=" + std::to_string(*o.seed));
  }
  // And a truncated image: the page shows the runtime's message, thrown as a RamusError.
  const std::string whole = cli_test::slurp(dir / "0.rmb");
  const fs::path truncated = dir / "truncated.rmb";
  std::ofstream(truncated, std::ios::binary) << whole.substr(0, whole.size() / 2);
  args += " " + shell_quote(truncated.string());
  std::string out;
  const int code = assets_test::run_shell(
      "node " + shell_quote(RAMUS_SOURCE_DIR "/tests/runtime/browser/grow_in_chromium.mjs") + " " +
          shell_quote(RAMUS_BINARY_DIR) + args,
      out);
  if (code == 77) {
    fs::remove_all(dir);
    WARN("skipped: " << out);
    return;
  }
  INFO(out.substr(0, 4000));
  REQUIRE(code == 0);
  std::vector<json> got;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("{\"file\"", 0) == 0) got.push_back(json::parse(line));
  }
  REQUIRE(got.size() == cases.size() + 1);
  REQUIRE(got.back().contains("error"));
  CHECK(got.back()["error"].get<std::string>().rfind("byte ", 0) == 0);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const ramus::Skeleton& s = want[i];
    const json& r = got[i];
    INFO(cases[i].example << " with seed " << seeds[i]);
    REQUIRE_FALSE(r.contains("error"));
    // The acceptance: the page meshed and drew the triangles of `ramus build`'s .glb.
    CHECK(want_triangles[i] > 0);
    CHECK(r["meshTriangles"].get<std::size_t>() == want_triangles[i]);
    CHECK(r["triangles"].get<std::size_t>() == want_triangles[i]);
    CHECK(r["drawnPixels"].get<int>() > 0);
    CHECK(r["drawnPixels"].get<int>() < r["pixels"].get<int>());
    // The skeleton: the same topology, the same numbers up to the last bits.
    REQUIRE(r["nodes"].get<std::size_t>() == s.nodes.size());
    REQUIRE(r["organs"].get<std::size_t>() == s.organs.size());
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
    CHECK(r["parents"].get<std::vector<std::int64_t>>() == parents);
    require_close("node positions", positions, from_hex<double>(r["positions"]), 1e-12);
    require_close("radii", radii, from_hex<double>(r["radii"]), 1e-12);
    require_close("organ positions", organ_positions, from_hex<double>(r["organPositions"]), 1e-12);
    require_close("organ sizes", organ_sizes, from_hex<double>(r["organSizes"]), 1e-12);
    require_same_mesh((dir / (std::to_string(i) + ".rmb")).string(), seeds[i], r["parts"]);
  }
  fs::remove_all(dir);
}
