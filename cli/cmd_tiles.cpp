// ramus tiles [EXEMPLAR...] -o TILESET.png [--edges K] [--tile T] [--seed S] [--joins PICTURE]
// A bark tile set whose edges match (docs/textures.md; Burkus, Karpati & Szecsi 5.2): K^4 tiles
// in a K^2 x K^2 atlas, stitched from the exemplar pictures by image quilting's minimum-error
// cuts. Without exemplars it uses the bundled procedural bark, which gives the default set that
// `ramus build` puts on meshes.
#include <filesystem>
#include <memory>

#include "backends/texture/image.h"
#include "backends/texture/tile_set.h"
#include "cli/command.h"
#include "cli/output_path.h"
#include "core/atomic_file.h"

namespace ramus::cli {
namespace {

struct TilesArgs {
  std::vector<std::string> exemplars;
  std::string output;
  std::string joins;
  texture::TileSetOptions options;
};

CLI::Validator png_output() {
  return CLI::Validator(
      [](const std::string& p) -> std::string {
        return std::filesystem::path(p).extension() == ".png" ? "" : "the output must end in .png";
      },
      "FILE", "png");
}

int run_tiles(const TilesArgs& a, const GlobalOptions& global) {
  std::vector<texture::Image> exemplars;
  try {
    for (const std::string& path : a.exemplars) exemplars.push_back(texture::read_image(path));
  } catch (const texture::ImageError& e) {
    throw UserError(e.what());
  }
  if (exemplars.empty()) exemplars.push_back(texture::bundled_bark_exemplar());
  texture::TileSet set;
  try {
    set = texture::build_tile_set(exemplars, a.options);
  } catch (const std::invalid_argument& e) {
    throw UserError(e.what());
  }
  try {
    write_file_atomically(a.output, texture::encode_png(set.atlas));
    if (!a.joins.empty()) {
      // Beside the set: the same tiles joined along straight lines (the seams the cuts avoid),
      // then the set itself with the cut paths drawn.
      texture::TileSetOptions straight = a.options;
      straight.straight_joins = true;
      const texture::TileSet plain = texture::build_tile_set(exemplars, straight);
      const texture::Image marked = texture::highlight_joins(set);
      const int gap = 16;
      texture::Image both(2 * marked.width + gap, marked.height);
      std::fill(both.rgb.begin(), both.rgb.end(), std::uint8_t(255));
      both.paste(plain.atlas, 0, 0);
      both.paste(marked, marked.width + gap, 0);
      write_file_atomically(a.joins, texture::encode_png(both));
    }
  } catch (const WriteError& e) {
    throw UserError(e.what());
  }
  if (!global.quiet) {
    std::fprintf(stderr, "ramus: wrote %s (%d tiles of %d px, %d edge colours)\n", a.output.c_str(),
                 set.count(), set.tile, set.edges);
  }
  return 0;
}

}  // namespace

void add_tiles(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<TilesArgs>();
  CLI::App* sub = app.add_subcommand(
      "tiles", "build a bark tile set with matching edges from exemplar pictures (image quilting)");
  sub->add_option("exemplars", args->exemplars,
                  "exemplar pictures (.png .jpg ...), each at least one tile large; none: the "
                  "bundled procedural bark")
      ->check(CLI::ExistingFile);
  output_path(sub->add_option("-o,--output", args->output, "the tile set atlas (.png)"))
      ->required()
      ->check(png_output());
  sub->add_option("--edges", args->options.edges,
                  "edge colours per direction K (1, 2 or 4): K^4 tiles in a K^2 x K^2 atlas "
                  "(default 2)");
  sub->add_option("--tile", args->options.tile,
                  "tile side in pixels, a power of two from 32 to 2048 (default 256)");
  sub->add_option("--seed", args->options.seed, "seed of the patch choices (default 1)");
  output_path(sub->add_option("--joins", args->joins,
                              "also write a picture (.png): the set joined along straight lines "
                              "beside the set with its cuts drawn"))
      ->check(png_output());
  sub->callback(
      [args, &global, &run] { run = [args, &global] { return run_tiles(*args, global); }; });
}

}  // namespace ramus::cli
