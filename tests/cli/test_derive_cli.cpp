// `ramus derive`: the --print and --stats contracts, --skeleton, -D, and errors with exit code 1.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

using Result = cli_test::CliResult;

Result ramus_derive(const std::string& args) { return cli_test::run_ramus_shell("derive " + args); }

std::string write_temp(const std::string& name, const std::string& text) {
  return cli_test::write_text(fs::temp_directory_path() / "ramus_test_derive_cli" / name, text)
      .string();
}

}  // namespace

TEST_CASE("derive cli: --print writes ABOP notation with shortest numbers", "[cli][derive]") {
  const std::string f = write_temp(
      "tree.ramus", "param r = 2;\nlsystem t { axiom A(1); A(s) -> F(s) [ + A(s / r) ]; }\n");
  Result r = ramus_derive(f + " -n 2 --print");
  CHECK(r.status == 0);
  CHECK(r.out == "F(1)[+F(0.5)[+A(0.25)]]\n");
  Result d = ramus_derive(f + " -n 1 -D r=4");
  CHECK(d.out == "F(1)[+A(0.25)]\n");
}

TEST_CASE("derive cli: --stats follows its line contract", "[cli][derive]") {
  const std::string f = write_temp(
      "stats.ramus", "lsystem t { derive 3; axiom A(1); A(s) -> F(s) [ + A(s / 2) ] B A(s); }\n");
  Result r = ramus_derive(f + " --stats");
  REQUIRE(r.status == 0);
  // after 3 steps: 8 A; 7 each of F [ + ] B; F lengths 1 + (0.5 + 1) + (0.25 + 0.5 + 0.5 + 1)
  std::vector<std::string> lines;
  std::size_t b = 0;
  for (std::size_t e; (e = r.out.find('\n', b)) != std::string::npos; b = e + 1) {
    lines.push_back(r.out.substr(b, e - b));
  }
  REQUIRE(lines.size() == 10);
  CHECK(lines[0] == "length 43");
  CHECK(lines[1] == "count + 7");
  CHECK(lines[2] == "count A 8");
  CHECK(lines[3] == "count B 7");
  CHECK(lines[4] == "count F 7");
  CHECK(lines[5] == "count [ 7");
  CHECK(lines[6] == "count ] 7");
  CHECK(lines[7] == "sum F.0 4.75");
  CHECK(lines[8] == "steps 3");
  CHECK(lines[9].rfind("time ", 0) == 0);
  CHECK(lines[9].substr(lines[9].size() - 2) == " s");
}

TEST_CASE("derive cli: --skeleton writes a skeleton file", "[cli][derive]") {
  const std::string f = write_temp("sk.ramus", "lsystem t { axiom F [ + F ] F; }\n");
  const std::string out =
      (fs::temp_directory_path() / "ramus_test_derive_cli" / "sk.json").string();
  fs::remove(out);
  Result r = ramus_derive(f + " --skeleton '" + out + "'");
  CHECK(r.status == 0);
  std::ifstream in(out);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("ramus-skeleton") != std::string::npos);
  CHECK(text.find("\"parent\": 1") != std::string::npos);
}

TEST_CASE("derive cli: errors exit with 1 and say why", "[cli][derive]") {
  const std::string f = write_temp("run.ramus", "lsystem t { axiom A; A -> A A; }\n");
  Result r = ramus_derive(f + " -n 30 --max-modules 1000");
  CHECK(r.status == 1);
  CHECK(r.out.find("step 10") != std::string::npos);
  Result d = ramus_derive(f + " -D nope=1");
  CHECK(d.status == 1);
  CHECK(d.out.find("nope") != std::string::npos);
  const std::string z = write_temp("zero.ramus", "lsystem t { axiom A(0); A(x) -> A(1 / x); }\n");
  Result e = ramus_derive(z + " -n 1");
  CHECK(e.status == 1);
  CHECK(e.out.find("division by zero") != std::string::npos);
  CHECK(e.out.find("step 1") != std::string::npos);
}
