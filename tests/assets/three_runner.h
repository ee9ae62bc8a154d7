// Runs tests/pieces/browser/load_in_three.js (three.js in headless Chromium) on files and reads
// its JSON lines, and runs the Khronos validator (tests/gltf/validate.js); for the asset tests.
#pragma once

#include <catch2/catch.hpp>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace assets_test {

namespace fs = std::filesystem;
using Numbers = std::map<std::string, double>;

// Runs a shell command; returns its exit code with stdout and stderr in `out`.
inline int run_shell(const std::string& cmd, std::string& out) {
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return -1;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  return cli_test::exit_code(pclose(pipe));
}

// Runs a page driver of tests/assets (`node SCRIPT PAGE`) on a page written by `ramus view` and
// reads the JSON line it prints (it starts with {"file"); false (after a warning) when Chromium
// cannot run on this machine.
inline bool run_page_driver(const char* script, const fs::path& page, Numbers& r) {
  std::string out;
  const int code = run_shell(
      "node " + cli_test::shell_quote(std::string(RAMUS_SOURCE_DIR "/tests/assets/") + script) +
          " " + cli_test::shell_quote(page.string()),
      out);
  if (code == 77) {
    WARN("skipped: " << out);
    return false;
  }
  INFO(out);
  REQUIRE(code == 0);
  const std::size_t at = out.find("{\"file\"");
  REQUIRE(at != std::string::npos);
  r = cli_test::json_line_numbers(out.substr(at, out.find('\n', at) - at));
  return true;
}

// One result per file; false (after a warning) when Chromium cannot run on this machine.
inline bool load_in_three(const std::vector<fs::path>& files, std::vector<Numbers>& results) {
  std::string cmd =
      "node " + cli_test::shell_quote(RAMUS_SOURCE_DIR "/tests/pieces/browser/load_in_three.js");
  for (const fs::path& f : files) cmd += " " + cli_test::shell_quote(f.string());
  std::string out;
  const int code = run_shell(cmd, out);
  if (code == 77) {
    WARN("skipped: " << out);
    return false;
  }
  INFO(out);
  REQUIRE(code == 0);
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("{\"file\"", 0) == 0) results.push_back(cli_test::json_line_numbers(line));
  REQUIRE(results.size() == files.size());
  return true;
}

// The Khronos validator's verdict: true when every file has 0 errors and 0 warnings.
inline bool validates(const std::vector<fs::path>& files, std::string& out) {
  std::string cmd = "node " + cli_test::shell_quote(RAMUS_SOURCE_DIR "/tests/gltf/validate.js");
  for (const fs::path& f : files) cmd += " " + cli_test::shell_quote(f.string());
  return run_shell(cmd, out) == 0;
}

// `ramus ARGS` must succeed.
inline void ramus_ok(const std::vector<std::string>& args) {
  const cli_test::CliResult r = cli_test::run_ramus(args);
  INFO(r.out);
  REQUIRE(r.status == 0);
}

inline std::string example(const std::string& path) {
  return std::string(RAMUS_SOURCE_DIR) + "/examples/" + path;
}

}  // namespace assets_test
