// Running the `ramus` executable (RAMUS_EXE) from the CLI tests: its exit code and what it
// printed, plus the temporary files the tests feed it. The namespace is not ramus:: because the
// tests call their runner `ramus(...)`, which would clash with a namespace of that name.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

struct CliResult {
  int status = -1;  // the exit code; -1 when it did not exit normally or could not be started
  std::string out;  // stdout, or stdout and stderr together for the runs that merge them
  std::string err;  // stderr, for run_ramus_split only
};

// Single quotes for /bin/sh, so arguments with spaces or quotes pass through unchanged.
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// The whole file as bytes ("" when it cannot be read).
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Writes `text` to `path`, creating its folder; returns the path.
inline fs::path write_text(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

inline int exit_code(int raw) { return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1; }

// Runs `ramus ARGS`, where ARGS is shell text (quote file names yourself), with stdout and stderr
// together in `out`.
inline CliResult run_ramus_shell(const std::string& args) {
  const std::string cmd = shell_quote(RAMUS_EXE) + " " + args + " 2>&1";
  CliResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) r.out.append(buf, n);
  r.status = exit_code(pclose(pipe));
  return r;
}

// The same with one argument per element, each quoted.
inline CliResult run_ramus(const std::vector<std::string>& args) {
  std::string text;
  for (const std::string& a : args) text += " " + shell_quote(a);
  return run_ramus_shell(text);
}

// Runs `ramus ARGS` with stdout and stderr apart (in `out` and `err`); they pass through files
// in `scratch`.
inline CliResult run_ramus_split(const fs::path& scratch, const std::vector<std::string>& args) {
  std::string cmd = shell_quote(RAMUS_EXE);
  for (const std::string& a : args) cmd += " " + shell_quote(a);
  const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  cmd += " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
  CliResult r;
  r.status = exit_code(std::system(cmd.c_str()));
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// A temporary directory for one test case, removed at the end.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "ramus_cli_XXXXXX").string();
    path = mkdtemp(tmpl.data());
  }
  ~TempDir() { fs::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  fs::path write(const std::string& name, const std::string& text) const {
    return write_text(path / name, text);
  }
};

// The numbers of one JSON line {"file":"...","key":number,...} that the browser checks print
// (string values are skipped).
inline std::map<std::string, double> json_line_numbers(const std::string& line) {
  std::map<std::string, double> out;
  std::size_t at = 0;
  while ((at = line.find('"', at)) != std::string::npos) {
    const std::size_t end = line.find('"', at + 1);
    if (end == std::string::npos) break;
    const std::string key = line.substr(at + 1, end - at - 1);
    at = end + 1;
    if (at + 1 < line.size() && line[at] == ':' && line[at + 1] != '"')
      out[key] = std::strtod(line.c_str() + at + 1, nullptr);
  }
  return out;
}

}  // namespace cli_test
