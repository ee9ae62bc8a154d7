// Golden test of the annotated dump `ramus dump FILE.rmb` prints (tests/golden/rmb/). The
// grammar is lowered under its file name, as `ramus build` stores it from any directory, so the
// locations in the file do not depend on where the tree is.
// RAMUS_UPDATE_GOLDENS=1 rewrites the expected files (review the diff).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "formats/rmb/rmb_codec.h"
#include "rmb_test_util.h"

using namespace ramus;

namespace {

std::string read(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string dump_of(const std::string& relative) {
  SourceManager sm;
  DiagnosticSink diags;
  const std::string text = read(std::string(RAMUS_SOURCE_DIR) + "/" + relative);
  // Named as `ramus build` stores it: relative to the grammar's own folder (formats/rmb/rmb_paths.h).
  const std::string name = relative.substr(relative.rfind('/') + 1);
  const ir::Grammar g = lower_text(name, text, GrowOptions{}, sm, diags);
  const std::string bytes = encode_rmb(g);
  std::vector<rmb::TraceEntry> trace;
  decode_rmb(bytes, RmbDecodeOptions{}, &trace);
  return format_rmb_trace(bytes, trace) + std::to_string(bytes.size()) + " bytes\n";
}

}  // namespace

TEST_CASE("rmb: the dump of a small example matches its golden file", "[rmb]") {
  for (const char* name : {"fig1_24a", "param_p42"}) {
    const std::string expected_path =
        std::string(RAMUS_SOURCE_DIR) + "/tests/golden/rmb/" + name + ".rmb.txt";
    const std::string actual = dump_of(std::string("examples/abop/") + name + ".ramus");
    INFO("golden file: " << expected_path);
    const char* update = std::getenv("RAMUS_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
      write_file_atomically(expected_path, actual);
      continue;
    }
    CHECK(actual == read(expected_path));
  }
}

TEST_CASE("rmb: the dump accounts for every byte of the file", "[rmb]") {
  const ir::Grammar g = test::lower_example("examples/trees/broadleaf.ramus");
  const std::string bytes = encode_rmb(g);
  std::vector<rmb::TraceEntry> trace;
  decode_rmb(bytes, RmbDecodeOptions{}, &trace);
  std::size_t next = 0;  // fields tile the file: each starts where the previous ended
  for (const rmb::TraceEntry& e : trace) {
    if (e.size == 0) continue;
    CHECK(e.offset == next);
    next = e.offset + e.size;
  }
  CHECK(next == bytes.size());
}
