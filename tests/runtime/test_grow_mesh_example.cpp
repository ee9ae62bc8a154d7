// The runtime's example program (examples/runtime/grow_mesh.c, a C program on ramus_runtime
// alone) grows and meshes every example grammar's .rmb into the arrays of the .glb that
// `ramus build` writes from the grammar itself: every attribute of every primitive of every level
// byte for byte (float32, the same bits), the indices value for value (the .glb stores them as
// 16-bit when they fit), and no array on one side that the other lacks.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "tests/backends/glb_reader.h"
#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using cli_test::shell_quote;
using ramus::testing::Glb;
using ramus::testing::item;
using ramus::testing::number;

std::vector<fs::path> example_grammars() {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(RAMUS_SOURCE_DIR) / "examples"))
    if (e.is_regular_file() && e.path().extension() == ".ramus") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

cli_test::CliResult run(const std::string& command) {
  cli_test::CliResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) r.out.append(buf, n);
  r.status = cli_test::exit_code(pclose(pipe));
  return r;
}

// The bytes an accessor covers (tightly packed, as the writers store them).
std::string accessor_bytes(const Glb& g, int accessor, std::size_t element_size) {
  const auto& a = item(g.at("accessors"), accessor);
  const auto& view = item(g.at("bufferViews"), int(a.find("bufferView")->number));
  const std::size_t at = std::size_t(number(view, "byteOffset", 0) + number(a, "byteOffset", 0));
  const std::size_t n = std::size_t(a.find("count")->number) * element_size;
  REQUIRE(at + n <= g.bin.size());
  return g.bin.substr(at, n);
}

// An index accessor's values, whatever their component type (5123 uint16, 5125 uint32).
std::vector<std::uint32_t> accessor_indices(const Glb& g, int accessor) {
  const int type = int(item(g.at("accessors"), accessor).find("componentType")->number);
  REQUIRE((type == 5123 || type == 5125));
  const std::string bytes = accessor_bytes(g, accessor, type == 5123 ? 2 : 4);
  std::vector<std::uint32_t> out(bytes.size() / (type == 5123 ? 2 : 4));
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (type == 5123) {
      std::uint16_t v;
      std::memcpy(&v, bytes.data() + 2 * i, 2);
      out[i] = v;
    } else {
      std::memcpy(&out[i], bytes.data() + 4 * i, 4);
    }
  }
  return out;
}

// Compares the arrays grow_mesh wrote into `dir` with the .glb; returns how many it compared.
std::size_t compare_with_glb(const Glb& g, const fs::path& dir) {
  const std::size_t float_size[] = {3, 3, 2, 4, 4};
  const char* const attributes[] = {"POSITION", "NORMAL", "TEXCOORD_0", "TANGENT", "_WIND"};
  std::set<std::string> expected;
  const auto& meshes = g.at("meshes").items;
  for (std::size_t lod = 0; lod < meshes.size(); ++lod) {
    for (const auto& prim : meshes[lod].find("primitives")->items) {
      const int material = int(prim.find("material")->number);
      const std::string part = item(g.at("materials"), material).find("name")->text;
      const std::string stem = "lod" + std::to_string(lod) + "_" + part + "_";
      INFO(stem);
      const auto* attrs = prim.find("attributes");
      for (std::size_t k = 0; k < 5; ++k) {
        const auto* a = attrs->find(attributes[k]);
        if (a == nullptr) continue;
        const std::string file = stem + attributes[k] + ".bin";
        INFO(file);
        expected.insert(file);
        REQUIRE(fs::exists(dir / file));
        const std::string want = accessor_bytes(g, int(a->number), 4 * float_size[k]);
        const std::string got = cli_test::slurp(dir / file);
        REQUIRE(got.size() == want.size());
        CHECK(got == want);
      }
      const std::string file = stem + "indices.bin";
      expected.insert(file);
      const std::vector<std::uint32_t> want =
          accessor_indices(g, int(prim.find("indices")->number));
      const std::string got = cli_test::slurp(dir / file);
      REQUIRE(got.size() == 4 * want.size());
      CHECK(std::memcmp(got.data(), want.data(), got.size()) == 0);
    }
  }
  std::set<std::string> written;
  for (const auto& e : fs::directory_iterator(dir)) written.insert(e.path().filename().string());
  CHECK(written == expected);
  return expected.size();
}

}  // namespace

TEST_CASE("grow_mesh writes the arrays of ramus build's glb for every example", "[runtime]") {
  const std::string ramus = shell_quote(RAMUS_EXE), grow_mesh = shell_quote(RAMUS_GROW_MESH_EXE);
  cli_test::TempDir tmp;
  const std::vector<fs::path> grammars = example_grammars();
  REQUIRE(grammars.size() >= 30);
  std::size_t compared = 0, skipped = 0;
  for (const fs::path& grammar : grammars) {
    const std::string name = grammar.stem().string();
    INFO(grammar.string());
    // Levels of detail for the trees; for the rest one level, with the options the runtime maps.
    const bool tree = grammar.parent_path().filename() == "trees";
    const std::string options = tree ? " --lod 2"
                                : name == "fig1_25"
                                    ? " --leaves crossed --leaf-scale 1.5 --pipe-exponent 2"
                                    : "";
    const fs::path rmb = tmp.path / (name + ".rmb"), glb = tmp.path / (name + ".glb");
    const fs::path dir = tmp.path / name;
    fs::create_directories(dir);
    const std::string g = shell_quote(grammar.string());
    const auto binary =
        run(ramus + " -q build " + g + " --target binary -o " + shell_quote(rmb.string()));
    REQUIRE(binary.status == 0);
    const auto mesh = run(ramus + " -q build " + g + options + " -o " + shell_quote(glb.string()));
    const auto grown = run(grow_mesh + " " + shell_quote(rmb.string()) + " " +
                           shell_quote(dir.string()) + options);
    INFO(mesh.out);
    INFO(grown.out);
    REQUIRE(grown.status == 0);
    if (mesh.status != 0 && mesh.out.find("no lsystem block") != std::string::npos) {
      // Pieces only, or an lsystem that comes from an import: `ramus build` makes no mesh of it
      // (the .rmb holds the imported block, which the runtime grows), so there is nothing to
      // compare with.
      ++skipped;
      continue;
    }
    if (mesh.status != 0) {
      // A string without anything to draw: `ramus build` has no .glb to write and the runtime
      // meshes nothing.
      REQUIRE(mesh.out.find("no geometry") != std::string::npos);
      CHECK(grown.out.find("LOD0 0 vertices 0 triangles") != std::string::npos);
      CHECK(fs::is_empty(dir));
      ++skipped;
      continue;
    }
    compared += compare_with_glb(ramus::testing::read_glb(cli_test::slurp(glb)), dir);
  }
  CHECK(skipped <= 4);
  CHECK(compared > 4 * (grammars.size() - skipped));
}

TEST_CASE("grow_mesh rejects bad input with a message", "[runtime]") {
  const std::string grow_mesh = shell_quote(RAMUS_GROW_MESH_EXE);
  cli_test::TempDir tmp;
  const fs::path corpus = fs::path(RAMUS_SOURCE_DIR) / "tests/fuzz/corpus/decode_rmb";
  auto r = run(grow_mesh + " " + shell_quote((corpus / "truncated.rmb").string()));
  CHECK(r.status == 1);
  CHECK(r.out.find("byte ") != std::string::npos);
  r = run(grow_mesh + " " + shell_quote((tmp.path / "missing.rmb").string()));
  CHECK(r.status == 1);
  CHECK(r.out.find("No such file") != std::string::npos);
  r = run(grow_mesh + " " + shell_quote((corpus / "fig1_24a.rmb").string()) + " --lod 9");
  CHECK(r.status == 1);
  CHECK(r.out.find("--lod") != std::string::npos);
  r = run(grow_mesh + " " + shell_quote((corpus / "fig1_24a.rmb").string()) + " " +
          shell_quote((tmp.path / "no/such/dir").string()));
  CHECK(r.status == 1);
  CHECK(r.out.find("no/such/dir") != std::string::npos);
}
