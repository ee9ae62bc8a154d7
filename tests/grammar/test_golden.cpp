// Golden tests (tests/golden/): one file per diagnostic code with the expected rendering,
// files with several mistakes, and formatter inputs with their expected output.
// RAMUS_UPDATE_GOLDENS=1 rewrites the expected files from what the code produces now (review
// the diff). The suite fails when some diagnostic code has no golden file.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "grammar/check.h"
#include "grammar/format.h"
#include "grammar/loader.h"
#include "grammar/parser.h"

using namespace ramus;
namespace fs = std::filesystem;

namespace {

const fs::path kGolden = fs::path(RAMUS_SOURCE_DIR) / "tests" / "golden";

bool updating() {
  const char* v = std::getenv("RAMUS_UPDATE_GOLDENS");
  return v && std::string(v) == "1";
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// What `ramus check FILE` prints, with paths relative to the source tree so the expected text
// does not depend on where the tree is.
std::string check_output(const fs::path& path, std::set<std::string>* codes = nullptr) {
  SourceManager sm;
  DiagnosticSink sink;
  Program program = load_program(path.string(), sm, sink);
  if (!program.files.empty()) check_program(program, sm, sink);
  sink.sort();
  if (codes) {
    for (const Diagnostic& d : sink.all()) codes->insert(info(d.code).id);
  }
  std::string text = render_text(sm, sink.all());
  const std::string prefix = std::string(RAMUS_SOURCE_DIR) + "/";
  for (std::size_t p = text.find(prefix); p != std::string::npos; p = text.find(prefix, p)) {
    text.erase(p, prefix.size());
  }
  return text;
}

// Compares `actual` with the expected file, or rewrites it when updating.
void expect_golden(const fs::path& expected, const std::string& actual) {
  INFO("golden file: " << expected.string());
  if (updating()) {
    write_file_atomically(expected.string(), actual);
    return;
  }
  REQUIRE(fs::exists(expected));
  CHECK(read(expected) == actual);
}

std::vector<fs::path> inputs(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".ramus") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("golden: every diagnostic code has a golden file that produces it", "[golden]") {
  const fs::path dir = kGolden / "diagnostics";
  for (const DiagCodeInfo& code : all_diag_codes()) {
    const fs::path input = dir / (std::string(code.id) + ".ramus");
    INFO("diagnostic code " << code.id << " (" << code.summary << ") needs " << input.string());
    REQUIRE(fs::exists(input));
    std::set<std::string> seen;
    std::string out = check_output(input, &seen);
    CHECK(seen.count(code.id) == 1);
    expect_golden(fs::path(input).replace_extension(".err"), out);
  }
}

TEST_CASE("golden: no golden file names a code that does not exist", "[golden]") {
  std::set<std::string> ids;
  for (const DiagCodeInfo& code : all_diag_codes()) ids.insert(code.id);
  for (const fs::path& p : inputs(kGolden / "diagnostics")) {
    INFO(p.string());
    CHECK(ids.count(p.stem().string()) == 1);
  }
}

TEST_CASE("golden: files with several mistakes report each at its place", "[golden]") {
  std::vector<fs::path> files = inputs(kGolden / "multi");
  REQUIRE_FALSE(files.empty());
  for (const fs::path& p : files) {
    expect_golden(fs::path(p).replace_extension(".err"), check_output(p));
  }
}

TEST_CASE("golden: formatter outputs", "[golden]") {
  std::vector<fs::path> files = inputs(kGolden / "fmt");
  REQUIRE_FALSE(files.empty());
  for (const fs::path& p : files) {
    INFO(p.string());
    SourceManager sm;
    DiagnosticSink sink;
    std::uint32_t id = sm.add(p.string(), read(p));
    ast::File file = parse(sm, id, sink);
    INFO(render_text(sm, sink.all()));
    REQUIRE_FALSE(sink.has_errors());
    expect_golden(fs::path(p).replace_extension(".out"), format_file(file, sm));
  }
}
