#include "cli/build_binary.h"

#include <cstdio>
#include <filesystem>

#include "backends/pieces/pieces.h"
#include "cli/build_pieces.h"
#include "cli/grow_args.h"
#include "cli/read_file.h"
#include "core/atomic_file.h"
#include "formats/rmb/rmb.h"
#include "grammar/check.h"
#include "grammar/loader.h"

namespace ramus::cli {

void add_binary_build_options(CLI::App* sub, BinaryBuildArgs& args) {
  sub->add_option("--tolerance", args.tolerance,
                  "--target binary: store reals quantized within this absolute tolerance "
                  "(lossy; default: exact)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--zstd", args.zstd, "--target binary: compress the sections with zstd");
  sub->add_flag("--strip", args.strip,
                "--target binary: leave out source locations and production texts (errors "
                "then name productions by index)");
  sub->add_option("--rmb-version", args.version,
                  "--target binary: the format version to write (default 2; 1 for older readers)")
      ->check(CLI::Range(1, 2));
  sub->add_flag("--placed-pieces", args.placed_pieces,
                "--target binary: also store the tree the pieces block builds (--pieces, "
                "--poses, --seed) as placed pieces the runtime expands to the instance buffer");
  sub->add_flag("--mesh-paths", args.mesh_paths,
                "--target binary: store mesh(\"file\") pieces as their paths instead of "
                "embedding the files");
}

namespace {

bool has_decl_of(const ast::File& f, auto pick) {
  for (const ast::Decl& d : f.decls) {
    if (pick(d)) return true;
  }
  return false;
}

// A file of pieces blocks alone has no lsystem block to lower: it is checked, and its .rmb
// carries the empty, unnamed grammar (rmb_has_lsystem). nullopt: lower the lsystem block.
std::optional<bool> check_pieces_only(const Program& program, const SourceManager& sm,
                                      DiagnosticSink& diags) {
  if (diags.has_errors() || program.files.empty()) return std::nullopt;
  const auto is_lsystem = [](const ast::Decl& d) {
    return std::holds_alternative<ast::LSystem>(d);
  };
  const auto is_pieces = [](const ast::Decl& d) { return std::holds_alternative<ast::Pieces>(d); };
  for (const ast::File& f : program.files) {
    if (has_decl_of(f, is_lsystem)) return std::nullopt;
  }
  if (!has_decl_of(program.files[0], is_pieces)) return std::nullopt;
  check_program(program, sm, diags);
  print_diagnostics(sm, diags);
  return !diags.has_errors();
}

// The placed-pieces stream --placed-pieces asks for: the same forest `--target pieces` builds
// with these arguments. --pieces and --poses say which tree, so without the flag they are
// mistakes.
std::optional<RmbPieceStream> placed_stream(const GrowArgs& a, const BinaryBuildArgs& binary,
                                            const PiecesBuildArgs& pieces) {
  if (!binary.placed_pieces) {
    if (!pieces.block.empty())
      throw UserError("--pieces with --target binary needs --placed-pieces");
    if (pieces.poses != 1) throw UserError("--poses with --target binary needs --placed-pieces");
    return RmbPieceStream{};
  }
  std::optional<GrownPieces> grown = grow_pieces(a, pieces);
  if (!grown) return std::nullopt;
  return std::move(grown->stream);
}

RmbEncodeOptions encode_options(const BinaryBuildArgs& binary) {
  RmbEncodeOptions options;
  options.tolerance = binary.tolerance;
  options.zstd = binary.zstd;
  options.strip = binary.strip;
  options.version = binary.version;
  return options;
}

void report(const std::string& output, const std::string& bytes, const ir::Grammar& g,
            std::size_t piece_sets, bool quiet) {
  if (quiet) return;
  std::fprintf(stderr,
               "ramus: wrote %s (%zu bytes: %zu symbols, %zu productions, %zu pieces blocks)\n",
               output.c_str(), bytes.size(), g.symbols.size(), g.productions.size(), piece_sets);
}

// An .rmb in, an .rmb out: everything it holds (lsystem, piece sets, voxel tables) re-encoded
// with this build's options (--zstd, --strip, --tolerance, --rmb-version), -n and --seed stored
// as the new defaults.
int rebuild_binary(const GrowArgs& a, const BinaryBuildArgs& binary, const PiecesBuildArgs& pieces,
                   const std::string& output, bool quiet) {
  if (!a.defines.empty()) {
    throw UserError("-D/--define needs the grammar's source; " + a.file +
                    " is a compiled binary grammar");
  }
  if (!a.system.empty()) throw UserError("--system does not apply to an .rmb input");
  if (binary.mesh_paths) {
    throw UserError("--mesh-paths applies to a grammar's mesh files; " + a.file +
                    " already holds its pieces as compiled");
  }
  // Without --placed-pieces, the stream the file holds (if any) goes along unchanged.
  const std::optional<RmbPieceStream> placed = placed_stream(a, binary, pieces);
  if (!placed) return 1;
  std::string bytes;
  try {
    RmbContents c = decode_rmb_contents(read_file_bytes(a.file));
    if (a.steps) c.grammar.settings.derive = *a.steps;
    if (a.seed) c.grammar.settings.seed = *a.seed;
    if (binary.placed_pieces) c.placed = *placed;
    bytes = encode_rmb(c.grammar, c.voxels, c.pieces, c.placed, encode_options(binary));
    write_file_atomically(output, bytes);
    report(output, bytes, c.grammar, c.pieces.sets.size(), quiet);
  } catch (const RmbError& e) {
    throw UserError(a.file + ": " + e.what());
  }
  return 0;
}

}  // namespace

int build_binary(const GrowArgs& a, const BinaryBuildArgs& binary,
                 const PiecesBuildArgs& pieces_args, const std::string& output, bool quiet) {
  if (std::filesystem::path(output).extension() != ".rmb") {
    throw UserError("--target binary writes an .rmb file, not " + output);
  }
  if (is_binary_grammar(a.file)) return rebuild_binary(a, binary, pieces_args, output, quiet);
  const std::optional<RmbPieceStream> placed = placed_stream(a, binary, pieces_args);
  if (!placed) return 1;
  SourceManager sm;
  DiagnosticSink diags;
  const Program program = load_program(a.file, sm, diags);
  std::optional<ir::Grammar> lowered;
  if (const std::optional<bool> ok = check_pieces_only(program, sm, diags)) {
    if (!*ok) return 1;
    lowered = ir::make_grammar("");
  } else {
    // A file whose lsystem is imported for a pieces block's `skeleton` stores that lsystem.
    GrowArgs args = a;
    if (args.system.empty() && !program.files.empty()) {
      args.system = pieces::pieces_skeleton_system(program, "");
      // A binary holds one lsystem: blocks fitted to different ones cannot all be stored, and
      // reading the file back would fit them to the wrong tree.
      for (const ast::Decl& d : program.files[0].decls) {
        const auto* p = std::get_if<ast::Pieces>(&d);
        if (!p) continue;
        const std::string other = pieces::pieces_skeleton_system(program, p->name.name);
        if (!other.empty() && other != args.system) {
          throw UserError(a.file + ": pieces " + p->name.name + " takes its skeleton from " +
                          other + ", another block from " + args.system +
                          "; an .rmb holds one lsystem, so write one binary per skeleton");
        }
      }
    }
    lowered = lower_for_cli(args);
    if (!lowered) return 1;
    if (a.steps) lowered->settings.derive = *a.steps;
    // The same bytes from any working directory and any checkout (formats/rmb/rmb_paths.h).
    make_locations_portable(*lowered, a.file, default_stdlib_dirs());
  }
  const ir::Grammar& g = *lowered;
  const RmbEncodeOptions options = encode_options(binary);
  // The pieces blocks (section 10) and voxels blocks (section 11) of the root file go along.
  RmbPiecesOptions pieces_options;
  pieces_options.defines = to_grow_options(a).defines;
  pieces_options.mesh_paths = binary.mesh_paths;
  std::vector<RmbVoxelTable> voxels;
  RmbPieces pieces;
  std::string bytes;
  try {
    if (!program.files.empty()) {
      voxels = voxel_tables_of(program.files[0], g);
      pieces = piece_sets_of(program, a.file, pieces_options);
    }
    bytes = encode_rmb(g, voxels, pieces, *placed, options);
  } catch (const RmbError& e) {
    throw UserError(a.file + ": " + e.what());
  }
  write_file_atomically(output, bytes);
  report(output, bytes, g, pieces.sets.size(), quiet);
  return 0;
}

}  // namespace ramus::cli
