// `ramus build --target binary` stores source locations that depend on the grammar alone
// (formats/rmb/rmb_paths.h): the same bytes from any working directory and from a copy of the
// tree at another path, with stdlib imports named stdlib/...
#include <catch2/catch.hpp>
#include <string>

#include "../cli/cli_runner.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_paths.h"

using namespace cli_test;

namespace {

const fs::path kSource = RAMUS_SOURCE_DIR;

// Runs ramus in `cwd` with extra environment text (e.g. "RAMUS_STDLIB=...").
CliResult ramus_in(const fs::path& cwd, const std::string& env, const std::string& args) {
  const std::string cmd = "cd " + shell_quote(cwd.string()) + " && " + env + " " +
                          shell_quote(RAMUS_EXE) + " " + args + " 2>&1";
  CliResult r;
  r.status = exit_code(std::system(cmd.c_str()));
  return r;
}

}  // namespace

TEST_CASE("binary: build gives the same bytes from any working directory", "[binary]") {
  TempDir tmp;
  for (const char* example : {"examples/trees/broadleaf.ramus", "examples/abop/fig1_24a.ramus"}) {
    INFO(example);
    const fs::path a = tmp.path / "a.rmb", b = tmp.path / "b.rmb", c = tmp.path / "c.rmb";
    // From the source tree with a relative path, from the grammar's folder, from elsewhere.
    REQUIRE(ramus_in(kSource, "",
                     "-q build " + shell_quote(example) + " --target binary -o " +
                         shell_quote(a.string()))
                .status == 0);
    const fs::path file = kSource / example;
    REQUIRE(ramus_in(file.parent_path(), "",
                     "-q build " + shell_quote(file.filename().string()) + " --target binary -o " +
                         shell_quote(b.string()))
                .status == 0);
    REQUIRE(ramus_in("/", "",
                     "-q build " + shell_quote(file.string()) + " --target binary -o " +
                         shell_quote(c.string()))
                .status == 0);
    const std::string bytes = slurp(a);
    REQUIRE(!bytes.empty());
    CHECK(slurp(b) == bytes);
    CHECK(slurp(c) == bytes);
    // No path outside the grammar's folder is stored.
    CHECK(bytes.find(kSource.string()) == std::string::npos);
    CHECK(bytes.find("examples/") == std::string::npos);
  }
}

TEST_CASE("binary: build gives the same bytes from a copy of the tree elsewhere", "[binary]") {
  TempDir tmp;
  const fs::path copy = tmp.path / "another checkout";
  fs::create_directories(copy / "examples");
  fs::copy(kSource / "examples", copy / "examples", fs::copy_options::recursive);
  fs::copy(kSource / "stdlib", copy / "stdlib", fs::copy_options::recursive);
  const fs::path a = tmp.path / "a.rmb", b = tmp.path / "b.rmb";
  const std::string example = "examples/trees/conifer.ramus";
  REQUIRE(ramus_in(kSource, "",
                   "-q build " + example + " --target binary -o " + shell_quote(a.string()))
              .status == 0);
  REQUIRE(ramus_in(copy, "RAMUS_STDLIB=" + shell_quote((copy / "stdlib").string()),
                   "-q build " + example + " --target binary -o " + shell_quote(b.string()))
              .status == 0);
  const std::string bytes = slurp(a);
  CHECK(slurp(b) == bytes);
  for (const std::string& loc : ramus::decode_rmb(bytes).locations) {
    CHECK(loc.rfind("conifer.ramus:", 0) == 0);
  }
}

TEST_CASE("binary: a block from a stdlib import is stored as stdlib/...", "[binary]") {
  TempDir tmp;
  tmp.write("lib/demo/sys.ramus", "lsystem demo {\n  axiom A(1);\n  A(x) -> A(x + 1);\n}\n");
  tmp.write("g/main.ramus", "import demo.sys;\n");
  const fs::path out = tmp.path / "demo.rmb";
  REQUIRE(
      ramus_in(tmp.path / "g", "RAMUS_STDLIB=" + shell_quote((tmp.path / "lib").string()),
               "-q build main.ramus --system demo --target binary -o " + shell_quote(out.string()))
          .status == 0);
  const ramus::ir::Grammar g = ramus::decode_rmb(slurp(out));
  REQUIRE(!g.locations.empty());
  for (const std::string& loc : g.locations) {
    CHECK(loc.rfind("stdlib/demo/sys.ramus:", 0) == 0);
  }
}

TEST_CASE("binary: portable names of files inside and outside the grammar folder", "[binary]") {
  using ramus::portable_source_name;
  TempDir tmp;
  tmp.write("g/main.ramus", "");
  tmp.write("g/parts/leaf.ramus", "");
  tmp.write("shared/common.ramus", "");
  tmp.write("lib/trees/oak.ramus", "");
  const std::string root = (tmp.path / "g/main.ramus").string();
  const std::vector<std::string> lib = {(tmp.path / "lib").string()};
  CHECK(portable_source_name(root, root, lib) == "main.ramus");
  CHECK(portable_source_name((tmp.path / "g/./parts/../parts/leaf.ramus").string(), root, lib) ==
        "parts/leaf.ramus");
  CHECK(portable_source_name((tmp.path / "shared/common.ramus").string(), root, lib) ==
        "../shared/common.ramus");
  CHECK(portable_source_name((tmp.path / "lib/trees/oak.ramus").string(), root, lib) ==
        "stdlib/trees/oak.ramus");
  CHECK(portable_source_name("<stdin>", root, lib) == "<stdin>");
}
