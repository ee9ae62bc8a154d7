// `ramus fmt`: rewriting in place, --check, and files with errors left untouched.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

using cli_test::slurp;
using cli_test::TempDir;
using Result = cli_test::CliResult;

Result ramus(const TempDir& dir, const std::vector<std::string>& args) {
  return cli_test::run_ramus_split(dir.path, args);
}

const char* kMessy = "lsystem s{axiom F;F->F[+F]F; // keep me\n}\n";
const char* kTidy = "lsystem s {\n  axiom F;\n  F -> F[+F]F;  // keep me\n}\n";

}  // namespace

TEST_CASE("fmt cli: rewrites a file in place and then leaves it alone", "[cli][fmt]") {
  TempDir dir;
  fs::path f = dir.write("a.ramus", kMessy);
  Result r = ramus(dir, {"fmt", f.string()});
  CHECK(r.status == 0);
  CHECK(slurp(f) == kTidy);
  Result again = ramus(dir, {"fmt", "--check", f.string()});
  CHECK(again.status == 0);
  CHECK(again.out.empty());
}

TEST_CASE("fmt cli: --check names the files that would change and writes nothing", "[cli][fmt]") {
  TempDir dir;
  fs::path messy = dir.write("messy.ramus", kMessy);
  fs::path tidy = dir.write("tidy.ramus", kTidy);
  Result r = ramus(dir, {"fmt", "--check", messy.string(), tidy.string()});
  CHECK(r.status == 1);
  CHECK(r.out == messy.string() + "\n");
  CHECK(slurp(messy) == kMessy);
  CHECK(ramus(dir, {"fmt", "--check", tidy.string()}).status == 0);
}

TEST_CASE("fmt cli: a file with syntax errors is reported and left untouched", "[cli][fmt]") {
  TempDir dir;
  const std::string broken = "lsystem s{axiom F;F->F[+F;\n";
  fs::path bad = dir.write("bad.ramus", broken);
  fs::path good = dir.write("good.ramus", kMessy);
  Result r = ramus(dir, {"fmt", bad.string(), good.string()});
  CHECK(r.status == 1);
  CHECK(r.err.find("error[E0003]") != std::string::npos);
  CHECK(slurp(bad) == broken);
  CHECK(slurp(good) == kTidy);  // the other files are still formatted
  CHECK(ramus(dir, {"fmt", (dir.path / "missing.ramus").string()}).status == 1);
  CHECK(ramus(dir, {"fmt"}).status == 2);
}

TEST_CASE("fmt cli: the examples are formatted", "[cli][fmt]") {
  TempDir dir;
  std::vector<std::string> args = {"fmt", "--check"};
  for (const auto& e : fs::recursive_directory_iterator(fs::path(RAMUS_SOURCE_DIR) / "examples")) {
    if (e.path().extension() == ".ramus") args.push_back(e.path().string());
  }
  REQUIRE(args.size() > 2);
  Result r = ramus(dir, args);
  INFO(r.out << r.err);
  CHECK(r.status == 0);
}
