// An .rmb goes wherever a grammar goes (cli/grow_args.h): every example built with
// `--target binary` derives the same string as its source for the same seed, and the commands
// that grow a tree read it; options that need the source are errors.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

cli_test::CliResult ramus(const std::vector<std::string>& args) {
  return cli_test::run_ramus(args);
}

fs::path temp_dir() {
  const fs::path dir = fs::path(RAMUS_BINARY_DIR) / "rmb_everywhere";
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("rmb: every example derives the same string from its .rmb", "[cli][rmb]") {
  int compared = 0;
  for (const auto& entry :
       fs::recursive_directory_iterator(fs::path(RAMUS_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".ramus") continue;
    const std::string src = entry.path().string();
    const std::string bin = (temp_dir() / (entry.path().stem().string() + ".rmb")).string();
    INFO(src);
    REQUIRE(ramus({"-q", "build", src, "--target", "binary", "-o", bin}).status == 0);
    const auto text = ramus({"derive", src, "--print", "-n", "3", "--seed", "5"});
    if (text.status != 0) continue;  // pieces blocks only: no lsystem of its own to derive
    const auto binary = ramus({"derive", bin, "--print", "-n", "3", "--seed", "5"});
    REQUIRE(binary.status == 0);
    CHECK(binary.out == text.out);
    const auto own = ramus({"derive", bin, "--stats"});
    REQUIRE(own.status == 0);
    CHECK(own.out.substr(0, own.out.find("time")) ==
          ramus({"derive", src, "--stats"}).out.substr(0, own.out.find("time")));
    ++compared;
  }
  CHECK(compared >= 29);
}

TEST_CASE("rmb: build, scan and compare read an .rmb, -D and --system are refused", "[cli][rmb]") {
  const std::string src =
      std::string(RAMUS_SOURCE_DIR) + "/examples/abop/fig5_5_cordate_leaf.ramus";
  const fs::path dir = temp_dir();
  // Named as its source: a mesh and its node are named after the input file's stem.
  const std::string bin = (dir / "fig5_5_cordate_leaf.rmb").string();
  REQUIRE(ramus({"-q", "build", src, "--target", "binary", "-o", bin}).status == 0);
  // The same mesh from the binary as from the source.
  REQUIRE(ramus({"-q", "build", src, "-o", (dir / "a.glb").string()}).status == 0);
  REQUIRE(ramus({"-q", "build", bin, "-o", (dir / "b.glb").string()}).status == 0);
  CHECK(slurp(dir / "a.glb") == slurp(dir / "b.glb"));
  // Re-encoded with other options, still the same grammar.
  REQUIRE(
      ramus({"-q", "build", bin, "--target", "binary", "--strip", "-o", (dir / "s.rmb").string()})
          .status == 0);
  CHECK(ramus({"derive", (dir / "s.rmb").string(), "--print"}).out ==
        ramus({"derive", src, "--print"}).out);
  CHECK(ramus({"-q", "scan", bin, "-o", (dir / "s.xyz").string()}).status == 0);
  const auto cmp = ramus({"compare", src, bin, "--seeds", "2"});
  CHECK(cmp.status == 0);
  CHECK(cmp.out.find("largest KS 0.0000") != std::string::npos);
  const auto d = ramus({"derive", bin, "-D", "x=1"});
  CHECK(d.status == 1);
  CHECK(d.out.find("-D/--define needs the grammar's source") != std::string::npos);
  const auto s = ramus({"derive", bin, "--system", "other"});
  CHECK(s.status == 1);
  CHECK(s.out.find("holds the lsystem 'fig5_5_cordate_leaf' only") != std::string::npos);
  const auto p = ramus({"build", bin, "--target", "pieces", "-o", (dir / "p.glb").string()});
  CHECK(p.status == 1);
  CHECK(p.out.find("holds no pieces block") != std::string::npos);  // tests/cli/test_rmb_pieces_cli
}

TEST_CASE("pieces: a pieces block fitted to an imported lsystem by its skeleton line",
          "[cli][pieces]") {
  const std::string src = std::string(RAMUS_SOURCE_DIR) + "/examples/pieces/broadleaf_pieces.ramus";
  const fs::path dir = temp_dir();
  const auto r = ramus({"build", src, "--target", "pieces", "-o", (dir / "bp.glb").string()});
  INFO(r.out);
  REQUIRE(r.status == 0);
  // As many pieces as the broadleaf's skeleton has internodes and forks: far more than the three
  // declared, so the tree was fitted, not assembled from rules (the block has none).
  const std::size_t at = r.out.find("1 trees, ");
  REQUIRE(at != std::string::npos);
  CHECK(std::stoul(r.out.substr(at + 9)) > 1000);
  // Another lsystem by --system than the one the block names is refused.
  const auto clash = ramus(
      {"build", src, "--target", "pieces", "--system", "conifer", "-o", (dir / "c.glb").string()});
  CHECK(clash.status == 1);
}
