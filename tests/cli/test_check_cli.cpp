// `ramus check`: exit codes, text and JSON diagnostics, -D, on temporary files.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

using cli_test::TempDir;
using Result = cli_test::CliResult;

Result ramus(const TempDir& dir, const std::vector<std::string>& args) {
  return cli_test::run_ramus_split(dir.path, args);
}

const char* kClean = "lsystem s {\n  derive 2;\n  axiom F;\n  F -> F[+F]F;\n}\n";

}  // namespace

TEST_CASE("check cli: a clean file exits 0 and prints nothing", "[cli][check]") {
  TempDir dir;
  Result r = ramus(dir, {"check", dir.write("ok.ramus", kClean).string()});
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.empty());
}

TEST_CASE("check cli: errors exit 1 with file:line:col and caret and notes", "[cli][check]") {
  TempDir dir;
  fs::path f =
      dir.write("bad.ramus", "const a = 1;\nconst a = 2;\nlsystem s {\n  axiom A(a, b);\n}\n");
  Result r = ramus(dir, {"check", f.string()});
  CHECK(r.status == 1);
  CHECK(r.err.find(f.string() + ":2:7: error[E0103]: constant 'a' is defined twice") !=
        std::string::npos);
  CHECK(r.err.find(f.string() + ":4:14: error[E0104]: unknown name 'b'") != std::string::npos);
  CHECK(r.err.find("first defined here") != std::string::npos);
  CHECK(r.err.find("^") != std::string::npos);
}

TEST_CASE("check cli: warnings alone exit 0", "[cli][check]") {
  TempDir dir;
  fs::path f = dir.write("warn.ramus", std::string("const unused = 1;\n") + kClean);
  Result r = ramus(dir, {"check", f.string()});
  CHECK(r.status == 0);
  CHECK(r.err.find("warning[W0001]") != std::string::npos);
}

TEST_CASE("check cli: --diagnostics=json prints one document on stdout", "[cli][check]") {
  TempDir dir;
  fs::path f = dir.write("bad.ramus", "lsystem s {\n  derive -1;\n  axiom F;\n}\n");
  Result r = ramus(dir, {"check", "--diagnostics=json", f.string()});
  CHECK(r.status == 1);
  REQUIRE(r.out.rfind("{\"diagnostics\":[", 0) == 0);
  CHECK(r.out.find("\"code\":\"E0301\"") != std::string::npos);
  CHECK(r.out.find("\"line\":2") != std::string::npos);
  CHECK(r.out.find("\"column\":10") != std::string::npos);
  Result clean =
      ramus(dir, {"check", "--diagnostics=json", dir.write("ok.ramus", kClean).string()});
  CHECK(clean.status == 0);
  CHECK(clean.out.find("{\"diagnostics\":[]") == 0);
}

TEST_CASE("check cli: several files each with its own mistakes", "[cli][check]") {
  TempDir dir;
  fs::path a = dir.write("a.ramus", "lsystem s { axiom S_1; }\n");
  fs::path b = dir.write("b.ramus", kClean);
  fs::path c = dir.write("c.ramus", "voxels v { classes 2; 1 -> [0 0 0 0 0 0 0]; }\n");
  Result r = ramus(dir, {"check", a.string(), b.string(), c.string()});
  CHECK(r.status == 1);
  CHECK(r.err.find(a.string() + ":1:19: error[E0101]") != std::string::npos);
  CHECK(r.err.find(c.string() + ":1:23: error[E0501]") != std::string::npos);
  CHECK(r.err.find(b.string()) == std::string::npos);
}

TEST_CASE("check cli: -D overrides a param and must name one", "[cli][check]") {
  TempDir dir;
  fs::path f = dir.write(
      "p.ramus", "param n = 2;\nconst k = 1;\nlsystem s {\n  derive n * k;\n  axiom F;\n}\n");
  CHECK(ramus(dir, {"check", f.string(), "-D", "n=5"}).status == 0);
  Result neg = ramus(dir, {"check", f.string(), "-D", "n=-1"});
  CHECK(neg.status == 1);
  CHECK(neg.err.find("E0301") != std::string::npos);
  Result konst = ramus(dir, {"check", f.string(), "-D", "k=3"});
  CHECK(konst.status == 1);
  CHECK(konst.err.find("'k' is a const") != std::string::npos);
  Result unknown = ramus(dir, {"check", f.string(), "-D", "zz=3"});
  CHECK(unknown.status == 1);
  CHECK(unknown.err.find("no param named 'zz'") != std::string::npos);
  CHECK(ramus(dir, {"check", f.string(), "-D", "n"}).status == 2);
  CHECK(ramus(dir, {"check", f.string(), "-D", "n=abc"}).status == 2);
}

TEST_CASE("check cli: usage errors exit 2 and unreadable files 1", "[cli][check]") {
  TempDir dir;
  CHECK(ramus(dir, {"check"}).status == 2);
  CHECK(ramus(dir, {"check", "--diagnostics=xml", dir.write("ok.ramus", kClean).string()}).status ==
        2);
  Result missing = ramus(dir, {"check", (dir.path / "missing.ramus").string()});
  CHECK(missing.status == 1);
  CHECK(missing.err.find("E0001") != std::string::npos);
  Result binary =
      ramus(dir, {"check", dir.write("bin.ramus", std::string("\0\1\2\3", 4)).string()});
  CHECK(binary.status == 1);
  CHECK(binary.err.find("E0002") != std::string::npos);
}

TEST_CASE("check cli: the five mistakes of the golden file are all reported", "[cli][check]") {
  TempDir dir;
  fs::path f = fs::path(RAMUS_SOURCE_DIR) / "tests/golden/multi/five_mistakes.ramus";
  Result r = ramus(dir, {"check", f.string()});
  CHECK(r.status == 1);
  for (const char* code : {"E0104", "E0102", "E0207", "E0003", "E0108"}) {
    INFO(code);
    CHECK(r.err.find(std::string("error[") + code + "]") != std::string::npos);
  }
}
