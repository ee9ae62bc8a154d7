// Limits that fail with a message (issue 22 point 5, docs/robustness.md): each limit, hit from the
// command line, stops with exit 1, names what was exceeded (and the option that raises it), and
// leaves no output behind.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using cli_test::run_ramus;

// A doubling grammar: after n steps the string holds 2^n modules.
constexpr const char* kDoubling = "lsystem t { axiom A; A -> F A A; }\n";

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("limits: the memory of the derivation: --max-memory", "[cli][limits]") {
  cli_test::TempDir dir;
  const std::string f = dir.write("doubling.ramus", kDoubling).string();
  const auto r = run_ramus({"derive", f, "-n", "20", "--max-memory", "1M", "--print"});
  CHECK(r.status == 1);
  CHECK(has(r.out, "memory limit of 1.05 MB (--max-memory)"));
  CHECK(has(r.out, "step "));
  CHECK_FALSE(has(r.out, "FAA"));  // nothing of the string was printed
  // The same from `build`: no output file.
  const fs::path glb = dir.path / "tree.glb";
  const auto b = run_ramus({"build", f, "-n", "20", "--max-memory", "1M", "-o", glb.string()});
  CHECK(b.status == 1);
  CHECK(has(b.out, "--max-memory"));
  CHECK_FALSE(fs::exists(glb));
  // Under the limit the same grammar derives.
  CHECK(run_ramus({"derive", f, "-n", "8", "--max-memory", "1M", "--print"}).status == 0);
  // A size that is not one is an option error, not a silent default.
  CHECK(run_ramus({"derive", f, "--max-memory", "lots"}).status != 0);
}

TEST_CASE("limits: the modules of the derivation: --max-modules and no output", "[cli][limits]") {
  cli_test::TempDir dir;
  const std::string f = dir.write("doubling.ramus", kDoubling).string();
  const fs::path glb = dir.path / "tree.glb";
  const auto b = run_ramus({"build", f, "-n", "12", "--max-modules", "1000", "-o", glb.string()});
  CHECK(b.status == 1);
  CHECK(has(b.out, "more than the limit of 1000 (--max-modules)"));
  CHECK_FALSE(fs::exists(glb));
}

TEST_CASE("limits: the nesting of the parser: 128 levels of brackets", "[cli][limits]") {
  cli_test::TempDir dir;
  std::string deep = "lsystem t { axiom ";
  for (int i = 0; i < 200; ++i) deep += "[F";
  for (int i = 0; i < 200; ++i) deep += "]";
  deep += "; }\n";
  const std::string f = dir.write("deep.ramus", deep).string();
  const auto c = run_ramus({"check", f});
  CHECK(c.status == 1);
  CHECK(has(c.out, "nested deeper than 128 levels"));
  const fs::path glb = dir.path / "deep.glb";
  CHECK(run_ramus({"build", f, "-o", glb.string()}).status == 1);
  CHECK_FALSE(fs::exists(glb));
}

TEST_CASE("limits: .rmb file size and decompressed size", "[cli][limits]") {
  cli_test::TempDir dir;
  // A zstd frame of 2 KiB that claims 65 MiB of content (a decompression bomb): refused from
  // the frame header, before anything is allocated.
  const std::string bomb =
      std::string(RAMUS_SOURCE_DIR) + "/tests/fuzz/corpus/decode_rmb/zstd_bomb_65mib.rmb";
  const fs::path out = dir.path / "bomb.ramus";
  const auto d = run_ramus({"decompile", bomb, "-o", out.string()});
  CHECK(d.status == 1);
  CHECK(has(d.out, "expected zstd content of at most"));
  CHECK(has(d.out, "found 68157440"));
  CHECK_FALSE(fs::exists(out));
  // A file over 64 MiB is refused whatever it holds.
  const fs::path big = dir.path / "big.rmb";
  {
    std::ofstream o(big, std::ios::binary);
    o << "RMB\x1a";
    o.seekp((std::streamoff(64) << 20) + 16);
    o.put('\0');
  }
  const auto b = run_ramus({"decompile", big.string(), "-o", out.string()});
  CHECK(b.status == 1);
  CHECK(has(b.out, "expected a file of at most 64 MiB"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("limits: the size of any input file: --max-file-size", "[cli][limits]") {
  cli_test::TempDir dir;
  const std::string grammar = dir.write("doubling.ramus", kDoubling).string();
  std::string xyz;
  for (int i = 0; i < 200; ++i) xyz += std::to_string(i * 0.01) + " 0 " + std::to_string(i) + "\n";
  const std::string scan = dir.write("scan.xyz", xyz).string();
  const fs::path glb = dir.path / "tree.glb", json = dir.path / "skeleton.json";
  // A grammar over the limit: refused before it is parsed, no output.
  const auto g = run_ramus({"--max-file-size", "16", "build", grammar, "-o", glb.string()});
  CHECK(g.status == 1);
  CHECK(has(g.out, "more than the limit of 16 (--max-file-size)"));
  CHECK_FALSE(fs::exists(glb));
  // A scan over the limit, with K as the unit.
  const auto s = run_ramus({"--max-file-size", "1K", "reconstruct", scan, "-o", json.string()});
  CHECK(s.status == 1);
  CHECK(has(s.out, "scan.xyz"));
  CHECK(has(s.out, "more than the limit of 1024 (--max-file-size)"));
  CHECK_FALSE(fs::exists(json));
  // A binary grammar over the limit.
  const fs::path rmb = dir.path / "t.rmb";
  REQUIRE(run_ramus({"build", grammar, "--target", "binary", "-o", rmb.string()}).status == 0);
  const auto b = run_ramus({"--max-file-size", "8", "derive", rmb.string()});
  CHECK(b.status == 1);
  CHECK(has(b.out, "--max-file-size"));
  // Under the limit the same files are read.
  CHECK(run_ramus({"--max-file-size", "1M", "build", grammar, "-n", "3", "-o", glb.string()})
            .status == 0);
  CHECK(run_ramus({"--max-file-size", "1M", "inspect", scan}).status == 0);
}

TEST_CASE("limits: the points of a scan: --max-points", "[cli][limits]") {
  cli_test::TempDir dir;
  std::string xyz;
  for (int i = 0; i < 200; ++i) xyz += std::to_string(i * 0.01) + " 0 " + std::to_string(i) + "\n";
  const std::string scan = dir.write("scan.xyz", xyz).string();
  const fs::path json = dir.path / "skeleton.json";
  const auto r = run_ramus({"--max-points", "150", "reconstruct", scan, "-o", json.string()});
  CHECK(r.status == 1);
  CHECK(has(r.out, "scan.xyz"));
  CHECK(has(r.out, "more than 150 points (--max-points)"));
  CHECK_FALSE(fs::exists(json));
  CHECK(run_ramus({"--max-points", "150", "inspect", scan}).status == 1);
  CHECK(run_ramus({"--max-points", "200", "inspect", scan}).status == 0);
  // The limit counts the points kept after thinning: 5 m cubes leave a few dozen.
  CHECK(run_ramus({"--max-points", "150", "tile", scan, "-o", (dir.path / "tiles").string(),
                   "--size", "100", "--buffer", "5", "--thin", "5"})
            .status == 0);
  CHECK(run_ramus({"--max-points", "0", "inspect", scan}).status != 0);  // not a limit
}
