// The placed-pieces block of the C API (runtime/ramus_runtime.h): an .rmb written by `ramus
// build --target binary --placed-pieces` expands, with the runtime alone, to the very bytes of
// the instance buffer `ramus build --target pieces --instance-buffer` writes for the same
// arguments -- for assembled trees (rest poses), posed copies (turned joints) and a tree fitted
// to a grown skeleton (moved joints). Malformed images give NULL and a message, never a crash.
#include <catch2/catch.hpp>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "runtime/ramus_runtime.h"
#include "tests/cli/cli_runner.h"

namespace {

using cli_test::run_ramus;
using cli_test::slurp;
using cli_test::TempDir;
using PiecesPtr = std::unique_ptr<ramus_pieces, decltype(&ramus_free_pieces)>;

PiecesPtr expand(const std::string& image, std::string* message = nullptr) {
  char err[512] = "unset";
  PiecesPtr p(ramus_pieces_expand(image.data(), image.size(), err, sizeof err), &ramus_free_pieces);
  if (message) *message = err;
  return p;
}

// Builds `example` both ways with `extra` arguments and returns (rmb, instance buffer).
std::pair<std::string, std::string> build_both(const TempDir& dir, const std::string& example,
                                               const std::vector<std::string>& extra) {
  const std::string file = std::string(RAMUS_SOURCE_DIR) + "/examples/pieces/" + example;
  const std::string rmb = (dir.path / "t.rmb").string(), bin = (dir.path / "t.bin").string();
  std::vector<std::string> a = {"build", file, "--target", "binary", "--placed-pieces", "-o", rmb};
  a.insert(a.end(), extra.begin(), extra.end());
  const auto r1 = run_ramus(a);
  INFO(r1.out);
  REQUIRE(r1.status == 0);
  std::vector<std::string> b = {
      "build", file, "--target", "pieces", "-o", (dir.path / "t.glb").string(), "--instance-buffer",
      bin};
  b.insert(b.end(), extra.begin(), extra.end());
  const auto r2 = run_ramus(b);
  INFO(r2.out);
  REQUIRE(r2.status == 0);
  return {slurp(rmb), slurp(bin)};
}

}  // namespace

TEST_CASE("the runtime expands an .rmb's placed pieces to the pieces build's instance buffer",
          "[runtime][pieces]") {
  TempDir dir;
  struct Case {
    const char* example;
    std::vector<std::string> extra;
  };
  const std::vector<Case> cases = {
      {"almond.ramus", {}},
      {"almond.ramus", {"--poses", "3", "--seed", "7"}},  // turned joints
      {"orchard.ramus", {"--seed", "3"}},
      {"grown.ramus", {}},  // fitted: moved joints
      {"broadleaf_pieces.ramus", {"-n", "4"}},
  };
  for (const Case& c : cases) {
    INFO(c.example << " " << c.extra.size() << " extra arguments");
    const auto [rmb, bin] = build_both(dir, c.example, c.extra);
    std::string message;
    const PiecesPtr p = expand(rmb, &message);
    INFO(message);
    REQUIRE(p);
    size_t n = 0;
    const void* bytes = ramus_pieces_instance_buffer(p.get(), &n);
    REQUIRE(n == bin.size());
    REQUIRE(std::memcmp(bytes, bin.data(), n) == 0);
    // The arrays are the file's sections.
    std::uint32_t header[12];
    std::memcpy(header, bin.data(), sizeof header);
    REQUIRE(ramus_pieces_type_count(p.get()) == header[3]);
    REQUIRE(ramus_pieces_tree_count(p.get()) == header[4]);
    REQUIRE(ramus_pieces_instance_count(p.get()) == header[5]);
    REQUIRE(ramus_pieces_bone_count(p.get()) == header[6]);
    REQUIRE(ramus_pieces_tile_count(p.get()) == header[7]);
    REQUIRE(std::memcmp(ramus_pieces_ranges(p.get()), bin.data() + header[8], 8 * header[3]) == 0);
    REQUIRE(std::memcmp(ramus_pieces_bones(p.get()), bin.data() + header[9], 64 * header[6]) == 0);
    REQUIRE(std::memcmp(ramus_pieces_instances(p.get()), bin.data() + header[10], 16 * header[5]) ==
            0);
    REQUIRE(std::memcmp(ramus_pieces_tiles(p.get()), bin.data() + header[11], 2 * header[7]) == 0);
    REQUIRE(ramus_pieces_type_name(p.get(), 0) != nullptr);
    REQUIRE(ramus_pieces_type_name(p.get(), header[3]) == nullptr);
  }
}

TEST_CASE("ramus_pieces_expand refuses bad images with a message, never a crash",
          "[runtime][pieces]") {
  TempDir dir;
  const std::string rmb = build_both(dir, "almond.ramus", {"--poses", "2"}).first;
  std::string message;
  // Every truncation, and every byte flipped (checksum and all): NULL with a message, or, for
  // a flip the format cannot tell (none here: the CRC-32 covers every byte), a valid expansion.
  for (std::size_t n = 0; n < rmb.size(); ++n) {
    REQUIRE_FALSE(expand(rmb.substr(0, n), &message));
    REQUIRE(!message.empty());
  }
  for (std::size_t i = 0; i < rmb.size(); ++i) {
    std::string bad = rmb;
    bad[i] = char(bad[i] ^ 0x5a);
    REQUIRE_FALSE(expand(bad, &message));
    REQUIRE(message.find("byte") != std::string::npos);
  }
  REQUIRE_FALSE(ramus_pieces_expand(nullptr, 4, nullptr, 0));
  // An .rmb without placed pieces.
  const std::string file = std::string(RAMUS_SOURCE_DIR) + "/examples/pieces/almond.ramus";
  const std::string plain = (dir.path / "plain.rmb").string();
  REQUIRE(run_ramus({"build", file, "--target", "binary", "-o", plain}).status == 0);
  REQUIRE_FALSE(expand(slurp(plain), &message));
  REQUIRE(message.find("no placed pieces") != std::string::npos);
  // Null handles are safe to ask.
  REQUIRE(ramus_pieces_instance_count(nullptr) == 0);
  size_t n = 7;
  REQUIRE(ramus_pieces_instance_buffer(nullptr, &n) == nullptr);
  REQUIRE(n == 0);
  ramus_free_pieces(nullptr);
}
