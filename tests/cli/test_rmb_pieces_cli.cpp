// `ramus build X.rmb --target pieces` (cli/build_pieces.cpp, cli/grow_args.h load_binary_pieces):
// the piece sets an .rmb stores, with the lsystem a block without attach rules is fitted to, give
// the same outputs byte for byte as the source -- the .glb, the instance buffer and its
// manifest, the preview -- for every example in examples/pieces/, also stripped and compressed;
// meshes embedded or kept as paths; options that need the source are errors.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"

using namespace cli_test;

namespace {

std::vector<fs::path> piece_examples() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(RAMUS_SOURCE_DIR) / "examples/pieces")) {
    if (e.path().extension() == ".ramus") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Builds pieces from `input` into dir/t.glb (+ options), with the instance buffer (dir/t.bin and
// its manifest) and a preview when asked; returns the exit code.
int build_pieces(const fs::path& input, const fs::path& dir, std::vector<std::string> options,
                 bool preview) {
  fs::create_directories(dir);
  std::vector<std::string> args{"-q",
                                "build",
                                input.string(),
                                "--target",
                                "pieces",
                                "-o",
                                (dir / "t.glb").string(),
                                "--instance-buffer",
                                (dir / "t.bin").string()};
  if (preview) {
    args.push_back("--preview");
    args.push_back((dir / "t.png").string());
  }
  args.insert(args.end(), options.begin(), options.end());
  return run_ramus(args).status;
}

}  // namespace

TEST_CASE("rmb: every pieces example builds the same pieces from its .rmb as from its source",
          "[cli][rmb][pieces]") {
  const std::vector<fs::path> examples = piece_examples();
  REQUIRE(examples.size() >= 4);
  for (const fs::path& src : examples) {
    for (const std::vector<std::string>& encode :
         {std::vector<std::string>{}, std::vector<std::string>{"--strip", "--zstd"}}) {
      TempDir tmp;
      const fs::path rmb = tmp.path / "g.rmb";
      std::vector<std::string> build{"-q",     "build", src.string(), "--target",
                                     "binary", "-o",    rmb.string()};
      build.insert(build.end(), encode.begin(), encode.end());
      REQUIRE(run_ramus(build).status == 0);
      // The default outputs, and other seeds, poses, encodings and the wind clip.
      for (const std::vector<std::string>& options :
           {std::vector<std::string>{},
            std::vector<std::string>{"--seed", "7", "--poses", "3", "--wind"},
            std::vector<std::string>{"--flatten", "--lod", "2"},
            std::vector<std::string>{"--gpu-instancing", "--seed", "3"}}) {
        INFO(src.filename().string()
             << (encode.empty() ? "" : " --strip --zstd") << " options " << options.size());
        const bool preview = options.empty() && encode.empty();
        const fs::path a = tmp.path / "src" / std::to_string(options.size());
        const fs::path b = tmp.path / "rmb" / std::to_string(options.size());
        REQUIRE(build_pieces(src, a, options, preview) == 0);
        REQUIRE(build_pieces(rmb, b, options, preview) == 0);
        const std::string glb = slurp(a / "t.glb");
        CHECK(glb.size() > 1000);
        CHECK(glb == slurp(b / "t.glb"));
        CHECK(slurp(a / "t.bin").size() > 100);
        CHECK(slurp(a / "t.bin") == slurp(b / "t.bin"));
        for (const auto& e : fs::directory_iterator(a)) {  // the manifest beside the buffer
          if (e.path().extension() != ".json") continue;
          CHECK(slurp(e.path()) == slurp(b / e.path().filename()));
        }
        if (preview) {
          CHECK(slurp(a / "t.png").size() > 1000);
          CHECK(slurp(a / "t.png") == slurp(b / "t.png"));
        }
      }
    }
  }
}

TEST_CASE("rmb: mesh pieces are built from the embedded file or found beside the .rmb",
          "[cli][rmb][pieces]") {
  const fs::path src = fs::path(RAMUS_SOURCE_DIR) / "examples/pieces/orchard.ramus";
  TempDir tmp;
  REQUIRE(build_pieces(src, tmp.path / "src", {}, false) == 0);
  const std::string glb = slurp(tmp.path / "src" / "t.glb");
  REQUIRE(glb.size() > 1000);

  // Embedded: the .rmb alone, in a folder without bent.obj.
  const fs::path embedded = tmp.path / "e" / "o.rmb";
  fs::create_directories(embedded.parent_path());
  REQUIRE(run_ramus({"-q", "build", src.string(), "--target", "binary", "-o", embedded.string()})
              .status == 0);
  REQUIRE(build_pieces(embedded, tmp.path / "e_out", {}, false) == 0);
  CHECK(slurp(tmp.path / "e_out" / "t.glb") == glb);
  CHECK(!fs::exists(tmp.path / "e" / "bent.obj"));  // nothing is written beside it

  // --mesh-paths: the path as written, relative to the .rmb.
  const fs::path paths = tmp.path / "p" / "o.rmb";
  fs::create_directories(paths.parent_path());
  REQUIRE(run_ramus({"-q", "build", src.string(), "--target", "binary", "--mesh-paths", "-o",
                     paths.string()})
              .status == 0);
  const CliResult missing = run_ramus(
      {"build", paths.string(), "--target", "pieces", "-o", (tmp.path / "m.glb").string()});
  CHECK(missing.status == 1);
  CHECK(missing.out.find("bent.obj: cannot read the piece file") != std::string::npos);
  CHECK(!fs::exists(tmp.path / "m.glb"));
  fs::copy_file(src.parent_path() / "bent.obj", paths.parent_path() / "bent.obj");
  REQUIRE(build_pieces(paths, tmp.path / "p_out", {}, false) == 0);
  CHECK(slurp(tmp.path / "p_out" / "t.glb") == glb);
}

TEST_CASE("rmb: pieces from an .rmb refuse what needs the source or is not stored",
          "[cli][rmb][pieces]") {
  const fs::path pieces_dir = fs::path(RAMUS_SOURCE_DIR) / "examples/pieces";
  TempDir tmp;
  const fs::path almond = tmp.path / "almond.rmb", grown = tmp.path / "grown.rmb",
                 leaf = tmp.path / "leaf.rmb";
  REQUIRE(run_ramus({"-q", "build", (pieces_dir / "almond.ramus").string(), "--target", "binary",
                     "-o", almond.string()})
              .status == 0);
  REQUIRE(run_ramus({"-q", "build", (pieces_dir / "grown.ramus").string(), "--target", "binary",
                     "-o", grown.string()})
              .status == 0);
  REQUIRE(run_ramus({"-q", "build",
                     std::string(RAMUS_SOURCE_DIR) + "/examples/abop/fig5_5_cordate_leaf.ramus",
                     "--target", "binary", "-o", leaf.string()})
              .status == 0);
  const std::string out = (tmp.path / "x.glb").string();
  const CliResult define =
      run_ramus({"build", almond.string(), "--target", "pieces", "-D", "x=1", "-o", out});
  CHECK(define.status == 1);
  CHECK(define.out.find("-D/--define needs the grammar's source") != std::string::npos);
  const CliResult none = run_ramus({"build", leaf.string(), "--target", "pieces", "-o", out});
  CHECK(none.status == 1);
  CHECK(none.out.find("holds no pieces block") != std::string::npos);
  const CliResult block =
      run_ramus({"build", almond.string(), "--target", "pieces", "--pieces", "oak", "-o", out});
  CHECK(block.status == 1);
  CHECK(block.out.find("no pieces block named 'oak'") != std::string::npos);
  const CliResult system =
      run_ramus({"build", grown.string(), "--target", "pieces", "--system", "other", "-o", out});
  CHECK(system.status == 1);
  CHECK(system.out.find("holds the lsystem 'sympodial' only") != std::string::npos);
  CHECK(!fs::exists(out));
  // -n and --seed reach the stored lsystem as they reach the source's.
  REQUIRE(build_pieces(pieces_dir / "grown.ramus", tmp.path / "a", {"-n", "3", "--seed", "9"},
                       false) == 0);
  REQUIRE(build_pieces(grown, tmp.path / "b", {"-n", "3", "--seed", "9"}, false) == 0);
  CHECK(slurp(tmp.path / "a" / "t.glb") == slurp(tmp.path / "b" / "t.glb"));
  REQUIRE(build_pieces(grown, tmp.path / "c", {}, false) == 0);
  CHECK(slurp(tmp.path / "a" / "t.glb") != slurp(tmp.path / "c" / "t.glb"));
}

TEST_CASE("rmb: a file whose pieces blocks fit different lsystems is refused as one binary",
          "[cli][rmb][pieces]") {
  const std::string trees = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/";
  TempDir tmp;
  const fs::path src = tmp.path / "two.ramus";
  write_text(src, "import \"" + trees + "broadleaf.ramus\";\nimport \"" + trees +
                      "conifer.ramus\";\n"
                      "pieces a {\n  piece I = tube(length: 4, taper: 0.9);\n"
                      "  piece Y = fork(angle: 30, taper: 0.8);\n  root I;\n"
                      "  skeleton broadleaf;\n}\n"
                      "pieces b {\n  piece I = tube(length: 4, taper: 0.9);\n"
                      "  piece Y = fork(angle: 30, taper: 0.8);\n  root I;\n"
                      "  skeleton conifer;\n}\n");
  const fs::path out = tmp.path / "two.rmb";
  const CliResult r = run_ramus({"build", src.string(), "--target", "binary", "-o", out.string()});
  INFO(r.out);
  CHECK(r.status == 1);
  CHECK(r.out.find("an .rmb holds one lsystem") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}
