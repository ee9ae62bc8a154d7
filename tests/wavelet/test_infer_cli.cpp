// `ramus infer --method wavelet` end to end: every readable scan of ../shared/data gives a grammar
// that `ramus check` accepts, `ramus fmt --check` leaves alone and `ramus build` turns into a glTF
// the Khronos validator accepts; bad input exits 1 with a message.
#include <catch2/catch.hpp>
#include <filesystem>

#include "../cli/cli_runner.h"

using namespace cli_test;

namespace {

std::string data(const char* name) { return std::string(RAMUS_SHARED_DIR) + "/data/" + name; }

bool validates(const std::string& files, std::string& out) {
  const std::string cmd = "node \"" RAMUS_SOURCE_DIR "/tests/gltf/validate.js\"" + files + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return false;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe)) out += buf;
  const int st = pclose(pipe);
  return WIFEXITED(st) && WEXITSTATUS(st) == 0;
}

}  // namespace

TEST_CASE("infer on every readable real scan writes a grammar that checks and builds",
          "[infer][cli]") {
  TempDir dir;
  std::string glbs;
  int done = 0;
  for (const char* name : {"adtree_tree1.xyz", "adtree_ahn3_delft.xyz", "plantscan3d_A3B4.asc",
                           "pytlidar_tree_1.las", "rtwig_cloud.txt"}) {
    if (!fs::exists(data(name))) {
      WARN("skipped: " << data(name) << " is missing");
      continue;
    }
    INFO(name);
    const fs::path out = dir.path / (std::string(name) + ".ramus");
    const CliResult r =
        run_ramus({"infer", data(name), "-o", out.string(), "--method", "wavelet", "--grid", "64"});
    INFO(r.out);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("compression: lossless") != std::string::npos);
    CHECK(r.out.find("L-rules: ") != std::string::npos);
    CHECK(r.out.find("voxel rules: ") != std::string::npos);
    CHECK(r.out.find("spanning trees") != std::string::npos);
    const std::string text = slurp(out);
    CHECK(text.find("voxels ") != std::string::npos);
    CHECK(text.find("lsystem ") != std::string::npos);
    CHECK(text.find("  axiom ") != std::string::npos);
    CHECK(text.find("select nearest(sin(e) * sin(a), sin(e) * cos(a), cos(e), l / s);") !=
          std::string::npos);
    const CliResult check = run_ramus({"check", out.string()});
    INFO(check.out);
    CHECK(check.status == 0);
    CHECK(run_ramus({"fmt", "--check", out.string()}).status == 0);
    const fs::path glb = dir.path / (std::string(name) + ".glb");
    const CliResult build = run_ramus({"--quiet", "build", out.string(), "-o", glb.string()});
    INFO(build.out);
    CHECK(build.status == 0);
    glbs += " \"" + glb.string() + "\"";
    ++done;
  }
  if (done == 0) return;
  std::string out;
  INFO(out);
  CHECK(validates(glbs, out));
}

TEST_CASE("infer options: grid, axiom level, offset, scanner, same input same bytes",
          "[infer][cli]") {
  const std::string scan = data("rtwig_cloud.txt");
  if (!fs::exists(scan)) {
    WARN("skipped: " << scan << " is missing");
    return;
  }
  TempDir dir;
  const std::string a = (dir.path / "a.ramus").string(), b = (dir.path / "b.ramus").string();
  const std::vector<std::string> common = {"infer",    scan,    "--method",      "wavelet",
                                           "--grid",   "32",    "--axiom-level", "3",
                                           "--offset", "exact", "--scanner",     "10,0,1"};
  auto with_output = [&](const std::string& out) {
    std::vector<std::string> args = common;
    args.push_back("-o");
    args.push_back(out);
    return run_ramus(args);
  };
  const CliResult r = with_output(a);
  INFO(r.out);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("axiom: dyad 3") != std::string::npos);
  CHECK(r.out.find("32^3 grid") != std::string::npos);
  CHECK(r.out.find("warning") == std::string::npos);  // the scanner was given
  REQUIRE(with_output(b).status == 0);
  CHECK(slurp(a) == slurp(b));
  CHECK(slurp(a).find("offset exact") != std::string::npos);
  CHECK(run_ramus({"check", a}).status == 0);
  // -q: the same file, nothing printed.
  const std::string c = (dir.path / "c.ramus").string();
  std::vector<std::string> quiet = {"-q"};
  quiet.insert(quiet.end(), common.begin(), common.end());
  quiet.push_back("-o");
  quiet.push_back(c);
  const CliResult q = run_ramus(quiet);
  REQUIRE(q.status == 0);
  CHECK(q.out.empty());
  CHECK(slurp(c) == slurp(a));
}

TEST_CASE("infer reports bad input and bad options with exit 1", "[infer][cli]") {
  TempDir dir;
  const std::string out = (dir.path / "o.ramus").string();
  const fs::path one = dir.write("one.xyz", "1 2 3\n");
  std::string same_text;
  for (int i = 0; i < 500; ++i) same_text += "1 2 3\n";
  const fs::path same = dir.write("same.xyz", same_text);
  const fs::path tree = dir.write("tree.xyz", "0 0 0\n0 0 1\n0.5 0 1.5\n-0.5 0 1.5\n0 0 2\n");
  struct Case {
    std::vector<std::string> args;
    const char* message;
  };
  const std::vector<Case> cases = {
      {{"infer", one.string(), "-o", out, "--method", "wavelet"}, "the scan has 1 point(s)"},
      {{"infer", same.string(), "-o", out, "--method", "wavelet"}, "no height"},
      {{"infer", tree.string(), "-o", out, "--method", "wavelet", "--grid", "100"}, "--grid"},
      {{"infer", tree.string(), "-o", out, "--method", "wavelet", "--grid", "1024"},
       "from 4 to 256"},
      {{"infer", tree.string(), "-o", out, "--method", "wavelet", "--axiom-level", "7"},
       "--axiom-level"},
      {{"infer", tree.string(), "-o", out, "--method", "wavelet", "--scanner", "1,2"}, "scanner"},
      {{"infer", (dir.path / "missing.xyz").string(), "-o", out, "--method", "wavelet"},
       "missing.xyz"},
  };
  // A word CLI11 rejects itself is a usage error (exit 2).
  const CliResult usage =
      run_ramus({"infer", tree.string(), "-o", out, "--method", "wavelet", "--offset", "shifted"});
  CHECK(usage.status == 2);
  CHECK(usage.out.find("--offset") != std::string::npos);
  for (const Case& c : cases) {
    const CliResult r = run_ramus(c.args);
    INFO(c.args[1] << " -> " << r.out);
    CHECK(r.status == 1);
    CHECK(r.out.find(c.message) != std::string::npos);
    CHECK_FALSE(fs::exists(out));  // nothing written on an error
  }
}
