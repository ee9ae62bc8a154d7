// `ramus build FILE --target pieces` end to end: every encoding and option on a grammar and on
// the bundled examples/pieces/*.ramus, each output through the Khronos glTF-Validator, same
// bytes on a second run, and clear errors for what the user got wrong.
#include <set>

#include "tests/cli/cli_runner.h"
#include "tests/pieces/output_fixture.h"

using namespace cli_test;

namespace {

std::vector<fs::path> bundled_examples() {
  std::vector<fs::path> out;
  const fs::path dir = fs::path(RAMUS_SOURCE_DIR) / "examples" / "pieces";
  if (fs::is_directory(dir)) {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".ramus") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("ramus build --target pieces writes every encoding, the instance buffer and a preview",
          "[pieces][cli]") {
  TempDir tmp;
  const fs::path g = tmp.write("almond.ramus", output_test::kAlmond);
  const std::string file = g.string(), dir = tmp.path.string();
  struct Run {
    std::vector<std::string> extra;
    std::string out;
  };
  const std::vector<Run> runs = {
      {{}, "canonical.glb"},
      {{"--flatten", "--wind"}, "flatten.glb"},
      {{"--gpu-instancing", "--instance-buffer", dir + "/forest.bin"}, "instanced.glb"},
      {{"--poses", "4", "--wind", "--lod", "2", "--preview", dir + "/forest.png"}, "posed.glb"},
      {{"--seed", "9"}, "text.gltf"},
  };
  std::vector<fs::path> written;
  for (const Run& r : runs) {
    std::vector<std::string> args{"build", file, "--target", "pieces", "-o", dir + "/" + r.out};
    args.insert(args.end(), r.extra.begin(), r.extra.end());
    const CliResult res = run_ramus(args);
    INFO(res.out);
    REQUIRE(res.status == 0);
    CHECK(res.out.find("pieces") != std::string::npos);
    written.push_back(tmp.path / r.out);
  }
  CHECK(fs::exists(tmp.path / "text.bin"));
  CHECK(fs::exists(tmp.path / "forest.json"));
  CHECK(slurp(tmp.path / "forest.bin").substr(0, 4) == "RPIB");
  CHECK(slurp(tmp.path / "forest.json").find("\"meshes\": \"instanced.glb\"") != std::string::npos);
  CHECK(slurp(tmp.path / "forest.png").substr(1, 3) == "PNG");
  std::string out;
  CHECK(output_test::validate(written, out) == 0);
  INFO(out);
  CHECK(out.find("errors") != std::string::npos);
  // Same input, same bytes.
  const std::string again = dir + "/again.glb";
  REQUIRE(run_ramus({"build", file, "--target", "pieces", "-o", again}).status == 0);
  CHECK(slurp(again) == slurp(tmp.path / "canonical.glb"));
}

TEST_CASE("ramus build --target pieces on the bundled piece examples gives valid files",
          "[pieces][cli]") {
  const std::vector<fs::path> examples = bundled_examples();
  INFO("examples/pieces/*.ramus");
  REQUIRE_FALSE(examples.empty());
  TempDir tmp;
  std::vector<fs::path> written;
  for (const fs::path& ex : examples) {
    for (const char* mode : {"", "--flatten", "--gpu-instancing"}) {
      const fs::path out =
          tmp.path / (ex.stem().string() + (*mode ? std::string(mode + 2) : "canonical") + ".glb");
      std::vector<std::string> args{"build", ex.string(),  "--target", "pieces",
                                    "-o",    out.string(), "--poses",  "2"};
      if (*mode) args.push_back(mode);
      const CliResult r = run_ramus(args);
      INFO(ex.string() << " " << mode << "\n" << r.out);
      REQUIRE(r.status == 0);
      written.push_back(out);
    }
  }
  std::string out;
  const int code = output_test::validate(written, out);
  INFO(out);
  CHECK(code == 0);
}

TEST_CASE("ramus build --target pieces reports user errors clearly", "[pieces][cli]") {
  TempDir tmp;
  const std::string file = tmp.write("almond.ramus", output_test::kAlmond).string();
  const std::string dir = tmp.path.string();
  CliResult r = run_ramus({"build", file, "--target", "pieces", "-o", dir + "/a.obj"});
  CHECK(r.status == 1);
  CHECK(r.out.find(".glb or .gltf") != std::string::npos);
  r = run_ramus({"build", file, "--target", "pieces", "-o", dir + "/a.glb", "--lod", "7"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--lod 7") != std::string::npos);
  r = run_ramus(
      {"build", file, "--target", "pieces", "-o", dir + "/a.glb", "--flatten", "--gpu-instancing"});
  CHECK(r.status == 2);
  CHECK_FALSE(fs::exists(tmp.path / "a.glb"));
  r = run_ramus(
      {"build", file, "--target", "pieces", "-o", dir + "/a.glb", "--preview", dir + "/p.jpg"});
  CHECK(r.status == 1);
  CHECK(r.out.find("--preview") != std::string::npos);
  const std::string bad =
      tmp.write("bad.ramus", "pieces p {\n  piece I = tube(length: );\n}\n").string();
  r = run_ramus({"build", bad, "--target", "pieces", "-o", dir + "/b.glb"});
  CHECK(r.status == 1);
  CHECK(r.out.find("bad.ramus:2:") != std::string::npos);
  CHECK_FALSE(fs::exists(tmp.path / "b.glb"));
}
