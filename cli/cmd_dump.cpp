// ramus dump FILE.rmb
// Prints a binary grammar field by field (docs/binary-format.md): offset, the bytes in hex,
// the field and its value, with a heading line per section and record. On a damaged file it
// prints what it could read, then the error with the byte offset (exit 1).
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/read_file.h"
#include "formats/rmb/rmb.h"

namespace ramus::cli {

namespace {

int run_dump(const std::string& path) {
  const std::string file = read_file_bytes(path);
  std::string bytes;  // what the listing shows: the file, or a zstd file's plain image
  try {
    bytes = rmb_uncompressed(file);
  } catch (const RmbError& e) {
    throw UserError(path + ": " + e.what());
  }
  if (bytes.size() != file.size() || bytes != file) {
    std::printf(
        "-- zstd: the %zu bytes after the header decompress to %zu; the listing is of "
        "that plain image\n",
        file.size() - 12, bytes.size() - 12);
  }
  std::vector<rmb::TraceEntry> trace;
  RmbDecodeOptions options;
  options.verify_checksum = bytes == file;  // an image's CRC-32 was checked over the file
  try {
    decode_rmb(bytes, options, &trace);
  } catch (const RmbError& e) {
    std::fputs(format_rmb_trace(bytes, trace).c_str(), stdout);
    std::fflush(stdout);
    throw UserError(path + ": " + e.what());
  }
  std::fputs(format_rmb_trace(bytes, trace).c_str(), stdout);
  std::printf("%zu bytes\n", file.size());
  return 0;
}

}  // namespace

void add_dump(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  auto path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand("dump", "print a binary grammar (.rmb) field by field");
  sub->add_option("file", *path, "the .rmb file")->required();
  sub->callback([path, &run] { run = [path] { return run_dump(*path); }; });
}

}  // namespace ramus::cli
