// The GLB container check (backends/mesh/gltf_container.h, glb_layout_error): what ramus writes
// passes, and every way a header or chunk can lie about the bytes is refused with the byte where
// it lies, before tinygltf copies a chunk past the end of the file (found by fuzz_piece_gltf).
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "backends/mesh/gltf_container.h"
#include "backends/mesh/gltf_writer.h"
#include "backends/mesh/mesh_reader.h"
#include "backends/pieces/piece_build.h"
#include "tests/mesh/synthetic_tree.h"

using namespace ramus;

namespace {

namespace fs = std::filesystem;

void put32(std::string& s, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s += char((v >> (8 * k)) & 0xFF);
}

// A GLB from its chunks (type, data), with the header's length set to the bytes' size.
std::string glb(const std::vector<std::pair<std::uint32_t, std::string>>& chunks) {
  std::string s = "glTF";
  put32(s, 2);
  put32(s, 0);
  for (const auto& [type, data] : chunks) {
    put32(s, std::uint32_t(data.size()));
    put32(s, type);
    s += data;
  }
  const std::uint32_t n = std::uint32_t(s.size());
  for (int k = 0; k < 4; ++k) s[std::size_t(8 + k)] = char((n >> (8 * k)) & 0xFF);
  return s;
}

constexpr std::uint32_t kJson = 0x4E4F534Au, kBin = 0x004E4942u;
const std::string kText = R"({"asset":{"version":"2.0"}}     )";  // 32 bytes, space-padded

std::string error_of(const std::string& bytes) {
  return mesh::glb_layout_error(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

}  // namespace

TEST_CASE("glb layout: what ramus writes and well-formed containers pass", "[gltf][glb]") {
  REQUIRE(kText.size() == 32);
  CHECK(error_of(glb({{kJson, kText}})).empty());
  CHECK(error_of(glb({{kJson, kText}, {kBin, std::string(8, '\0')}})).empty());
  // An unknown chunk after them is allowed (glTF 2.0: clients ignore it).
  CHECK(error_of(glb({{kJson, kText}, {kBin, "abcd"}, {0x12345678u, "wxyz"}})).empty());
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "test-output" / "glb-layout";
  fs::create_directories(dir);
  mesh::write_gltf({mesh::build_tree_mesh(testing::synthetic_tree(3, 200), {})},
                   (dir / "tree.glb").string());
  std::ifstream in(dir / "tree.glb", std::ios::binary);
  const std::string written{std::istreambuf_iterator<char>(in), {}};
  CHECK(error_of(written).empty());
}

TEST_CASE("glb layout: a header or chunk that lies about the bytes names the byte", "[gltf][glb]") {
  const std::string good = glb({{kJson, kText}, {kBin, std::string(8, '\0')}});
  struct Case {
    std::string bytes, expected;
  };
  std::string version = good;
  version[4] = 1;
  std::string longer = good;
  longer[8] = char(good.size() + 4);
  std::string past_end = good;
  past_end[20 + kText.size()] = 64;  // the BIN chunk claims 64 bytes; 8 follow
  const std::vector<Case> cases{
      {"glT", "byte 3: the file ends inside the 12-byte GLB header"},
      {"glTX" + good.substr(4), "byte 0: expected the GLB magic"},
      {version, "byte 4: expected GLB version 2, found 1"},
      {longer, "byte 8: the header gives a length of"},
      {glb({}), "byte 12: expected the JSON chunk"},
      {glb({{kBin, "abcd"}}), "byte 16: expected the JSON chunk first"},
      {glb({{kJson, kText}, {kJson, kText}}), "byte 56: a second JSON chunk"},
      {glb({{kJson, kText}, {0x12345678u, "wxyz"}, {kBin, "abcd"}}),
       "byte 68: a BIN chunk that is not the second"},
      {glb({{kJson, kText.substr(0, 30)}}), "byte 12: a chunk length of 30 bytes, not a multiple"},
      {past_end, "byte 52: a chunk of 64 bytes, past the end of the file (8 bytes left)"},
      {good.substr(0, 16), "byte 12: the file ends inside a chunk header"},
  };
  for (const Case& c : cases) {
    std::string bytes = c.bytes;
    // Cut files keep a header length that matches, so the chunk checks are what refuses them.
    if (bytes.size() >= 12 && c.expected.rfind("byte 8:", 0) != 0 &&
        bytes.compare(0, 4, "glTF") == 0)
      for (int k = 0; k < 4; ++k)
        bytes[std::size_t(8 + k)] = char((bytes.size() >> (8 * k)) & 0xFF);
    INFO(c.expected);
    CHECK(error_of(bytes).rfind(c.expected, 0) == 0);
  }
}

TEST_CASE("glb layout: the mesh and piece readers refuse a lying GLB before reading it",
          "[gltf][glb]") {
  // The input fuzz_piece_gltf found: a JSON chunk of 997 bytes (not aligned), after which
  // tinygltf took a BIN chunk length from the JSON's last bytes and copied past the file's end.
  const fs::path file = fs::path(RAMUS_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "piece_gltf" /
                        "regress_unaligned_json_chunk.glb";
  REQUIRE(fs::exists(file));
  try {
    mesh::read_mesh_file(file.string());
    FAIL("no error");
  } catch (const mesh::MeshError& e) {
    CHECK(std::string(e.what()).find("cannot read the glTF file: byte 12: a chunk length of 997") !=
          std::string::npos);
  }
  try {
    pieces::draft_mesh_file("p", file.string());
    FAIL("no error");
  } catch (const pieces::PiecesError& e) {
    CHECK(std::string(e.what()).find("cannot read the glTF file: byte 12") != std::string::npos);
  }
}
