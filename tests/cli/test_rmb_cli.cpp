// `ramus build --target binary` and `ramus dump`: the dump of a built example matches its golden
// file (tests/golden/rmb/), and damaged files fail with exit code 1 and the byte offset.
#include <sys/wait.h>

#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Result {
  int status = -1;
  std::string out;
};

// Runs ramus from the source tree, so grammar paths (and the locations stored) are relative.
Result ramus(const std::string& args, bool merge_stderr = true) {
  const std::string cmd = std::string("cd '") + RAMUS_SOURCE_DIR + "' && '" + RAMUS_EXE + "' " +
                          args + (merge_stderr ? " 2>&1" : " 2>/dev/null");
  Result r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

fs::path temp_dir() {
  const fs::path dir = fs::temp_directory_path() / "ramus_test_rmb_cli";
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("rmb cli: build --target binary then dump matches the golden file", "[cli][rmb]") {
  const fs::path out = temp_dir() / "fig1_24a.rmb";
  Result b =
      ramus("-q build examples/abop/fig1_24a.ramus --target binary -o '" + out.string() + "'");
  REQUIRE(b.status == 0);
  CHECK(fs::file_size(out) < 1024);
  Result d = ramus("dump '" + out.string() + "'", false);
  CHECK(d.status == 0);
  CHECK(d.out == read(fs::path(RAMUS_SOURCE_DIR) / "tests/golden/rmb/fig1_24a.rmb.txt"));
}

TEST_CASE("rmb cli: a damaged file is an error with the byte offset", "[cli][rmb]") {
  const fs::path out = temp_dir() / "damaged.rmb";
  REQUIRE(ramus("-q build examples/abop/param_p42.ramus --target binary -o '" + out.string() + "'")
              .status == 0);
  std::string bytes = read(out);
  bytes.resize(bytes.size() / 2);
  std::ofstream(out, std::ios::binary) << bytes;
  Result d = ramus("dump '" + out.string() + "'");
  CHECK(d.status == 1);
  CHECK(d.out.find("ramus: error: ") != std::string::npos);
  CHECK(d.out.find(": byte ") != std::string::npos);
  CHECK(d.out.find("CRC-32") != std::string::npos);
}

TEST_CASE("rmb cli: targets and output extensions must agree", "[cli][rmb]") {
  const fs::path dir = temp_dir();
  CHECK(ramus("build examples/abop/fig1_24a.ramus --target binary -o '" + (dir / "x.glb").string() +
              "'")
            .status == 1);
  CHECK(ramus("build examples/abop/fig1_24a.ramus -o '" + (dir / "x.rmb").string() + "'").status ==
        1);
  CHECK(ramus("dump '" + (dir / "missing.rmb").string() + "'").status == 1);
}
