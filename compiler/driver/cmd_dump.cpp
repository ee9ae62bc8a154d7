// ramus dump FILE.rmb
// Prints a binary grammar field by field (docs/binary-format.md): offset, the bytes in hex,
// the field and its value, with a heading line per section and record. On a damaged file it
// prints what it could read, then the error with the byte offset (exit 1).
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "compiler/driver/command.h"
#include "compiler/rmb_codec.h"

namespace ramus::cli {

namespace {

std::string read_binary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError("cannot open " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int run_dump(const std::string& path) {
  const std::string bytes = read_binary(path);
  std::vector<rmb::TraceEntry> trace;
  try {
    decode_rmb(bytes, RmbDecodeOptions{}, &trace);
  } catch (const RmbError& e) {
    std::fputs(format_rmb_trace(bytes, trace).c_str(), stdout);
    std::fflush(stdout);
    throw UserError(path + ": " + e.what());
  }
  std::fputs(format_rmb_trace(bytes, trace).c_str(), stdout);
  std::printf("%zu bytes\n", bytes.size());
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
