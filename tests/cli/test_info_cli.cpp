// `ramus info`: the .rmb version this build writes and reads comes from the codec, and with a
// file argument the version its header really holds.
#include <catch2/catch.hpp>
#include <string>

#include "cli_runner.h"

using cli_test::run_ramus;

TEST_CASE("ramus info prints the .rmb versions of the codec", "[cli][info]") {
  const auto r = run_ramus({"info"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find(".rmb version 2 written, versions 1-2 read") != std::string::npos);
  CHECK(r.out.find("version 1 (docs") == std::string::npos);
}

TEST_CASE("ramus info FILE.rmb prints the version in the file's header", "[cli][info]") {
  cli_test::TempDir dir;
  const std::string src = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/conifer.ramus";
  for (const char* version : {"1", "2"}) {
    const std::string out = (dir.path / (std::string("v") + version + ".rmb")).string();
    REQUIRE(
        run_ramus({"-q", "build", src, "--target", "binary", "-o", out, "--rmb-version", version})
            .status == 0);
    const auto r = run_ramus({"info", out});
    INFO(r.out);
    REQUIRE(r.status == 0);
    CHECK(r.out.find(".rmb version " + std::string(version) + ", flags 0x0000") !=
          std::string::npos);
  }
  const auto z = run_ramus({"-q", "build", src, "--target", "binary", "-o",
                            (dir.path / "z.rmb").string(), "--zstd", "--strip"});
  REQUIRE(z.status == 0);
  const auto r = run_ramus({"info", (dir.path / "z.rmb").string()});
  CHECK(r.out.find(".rmb version 2, flags 0x0006 zstd stripped") != std::string::npos);
  const auto bad = run_ramus({"info", src});
  CHECK(bad.status == 1);
  CHECK(bad.out.find("not an .rmb file") != std::string::npos);
}
