// ramus decompile FILE.rmb [-o FILE.ramus]
// Turns a binary grammar back into .ramus text (docs/binary-format.md, Decompiling): verified
// first like every .rmb, then rebuilt by formats/rmb/rmb_decompile.h. The text is in the canonical
// layout (`ramus fmt` leaves it unchanged) and derives the same string for the same seed.
// Without -o it goes to stdout. The mesh files a piece set embeds (docs/binary-format.md,
// section 10) are written beside the -o file under their stored names, which the text's
// mesh("...") pieces name; an existing file of that name with other contents is not replaced.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/output_path.h"
#include "cli/read_file.h"
#include "core/atomic_file.h"
#include "formats/rmb/rmb.h"

namespace ramus::cli {

namespace {

struct DecompileArgs {
  std::string file;
  std::string output;
};

// The embedded mesh files, next to the decompiled grammar.
void write_meshes(const RmbPieces& pieces, const std::string& output, bool quiet) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(output).parent_path();
  for (const RmbMeshFile& m : pieces.meshes) {
    const fs::path path = dir / m.name;  // a plain name (rmb_mesh_name_ok): stays in dir
    std::error_code ec;
    if (fs::exists(path, ec)) {
      if (read_file_bytes(path.string()) == m.bytes) continue;
      throw UserError("not replacing " + path.string() +
                      ": the grammar embeds another file of that name; decompile into another "
                      "folder");
    }
    write_file_atomically(path.string(), m.bytes);
    if (!quiet) {
      std::fprintf(stderr, "ramus: wrote %s (%zu bytes)\n", path.string().c_str(), m.bytes.size());
    }
  }
}

int run_decompile(const DecompileArgs& a, bool quiet) {
  const std::string bytes = read_file_bytes(a.file);
  std::string text;
  RmbContents contents;
  try {
    contents = decode_rmb_contents(bytes);
    text = decompile(contents);
  } catch (const RmbError& e) {
    throw UserError(a.file + ": " + e.what());
  } catch (const DecompileError& e) {
    throw UserError(a.file + ": cannot decompile: " + e.what());
  }
  const std::string left_out = decompile_left_out(contents);
  if (!left_out.empty() && !quiet) std::fprintf(stderr, "ramus: note: %s\n", left_out.c_str());
  if (a.output.empty() || a.output == "-") {
    if (!contents.pieces.meshes.empty()) {
      throw UserError(a.file +
                      ": it embeds mesh files, which are written beside the grammar: give "
                      "-o FILE.ramus");
    }
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
  }
  write_meshes(contents.pieces, a.output, quiet);
  write_file_atomically(a.output, text);
  if (!quiet) std::fprintf(stderr, "ramus: wrote %s (%zu bytes)\n", a.output.c_str(), text.size());
  return 0;
}

}  // namespace

void add_decompile(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<DecompileArgs>();
  CLI::App* sub =
      app.add_subcommand("decompile", "turn a binary grammar (.rmb) back into .ramus text");
  sub->add_option("file", args->file, "the .rmb file")->required();
  output_path(
      sub->add_option("-o,--output", args->output, "the .ramus file to write (default: stdout)"));
  sub->callback([args, &global, &run] {
    run = [args, &global] { return run_decompile(*args, global.quiet); };
  });
}

}  // namespace ramus::cli
