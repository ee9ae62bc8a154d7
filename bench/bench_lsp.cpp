// How fast `ramus lsp` answers on the bundled grammars (issue 20: "within 50 ms"), measured as
// an editor sees it: round trips over stdio with the built executable, from writing a request
// to reading its response. For every example under examples/: didOpen and a full didChange
// (until their diagnostics arrive), hover and definition at the start of every word, completion
// on every line, formatting and the outline. Prints per method: count, median, 99th
// percentile and maximum in milliseconds.
//   bench_lsp build/release/ramus [examples]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "lsp/uri.h"
#include "tests/lsp/lsp_session.h"

namespace fs = std::filesystem;
using lsp_test::json;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Every place a word or turtle symbol starts: (line, character); the examples are ASCII.
std::vector<std::pair<int, int>> word_starts(const std::string& text) {
  std::vector<std::pair<int, int>> out;
  int line = 0, col = 0;
  char prev = ' ';
  for (char c : text) {
    if (c == '\n') {
      ++line;
      col = 0;
      prev = ' ';
      continue;
    }
    bool word = std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    bool prev_word = std::isalnum(static_cast<unsigned char>(prev)) || prev == '_';
    if ((word && !prev_word) ||
        std::string_view("+-&^\\/|$[]!'~%").find(c) != std::string_view::npos)
      out.push_back({line, col});
    prev = c;
    ++col;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_lsp RAMUS_EXE [EXAMPLES_DIR]\n");
    return 2;
  }
  const fs::path examples = argc > 2 ? argv[2] : "examples";
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(examples)) {
    if (e.path().extension() == ".ramus") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());

  lsp_test::LspSession s{std::string(argv[1])};
  s.request(0, "initialize", {{"capabilities", json::object()}});
  s.response(0);
  s.notify("initialized");
  std::map<std::string, std::vector<double>> times;
  std::map<std::string, std::pair<double, std::string>> worst;  // method -> (ms, file)
  std::map<std::string, int> errors;                            // error responses: none expected
  std::size_t items = 0;  // completion items, to show the answers are real
  int id = 1;
  auto record = [&](const std::string& method, double ms, const fs::path& f) {
    times[method].push_back(ms);
    if (ms > worst[method].first) worst[method] = {ms, f.string()};
  };
  auto timed = [&](const std::string& method, json params, const fs::path& f) {
    auto t0 = Clock::now();
    s.request(id, "textDocument/" + method, std::move(params));
    json r = s.response(id++);
    record(method, ms_since(t0), f);
    if (r.contains("error") && errors[method]++ == 0)
      std::fprintf(stderr, "%s: %s\n", method.c_str(), r.dump().c_str());
    if (method == "completion") items += r["result"].size();
  };
  for (const fs::path& f : files) {
    const std::string text = slurp(f);
    const std::string uri = ramus::lsp::uri_of_path(fs::absolute(f).lexically_normal().string());
    const json doc = {{"uri", uri}};
    auto t0 = Clock::now();
    s.notify("textDocument/didOpen",
             {{"textDocument",
               {{"uri", uri}, {"languageId", "ramus"}, {"version", 1}, {"text", text}}}});
    s.diagnostics(uri);
    record("didOpen -> diagnostics", ms_since(t0), f);
    t0 = Clock::now();
    s.notify("textDocument/didChange", {{"textDocument", {{"uri", uri}, {"version", 2}}},
                                        {"contentChanges", {{{"text", text + "\n"}}}}});
    s.diagnostics(uri);
    record("didChange -> diagnostics", ms_since(t0), f);
    int lines = 0;
    for (const auto& [line, col] : word_starts(text)) {
      json pos = {{"line", line}, {"character", col}};
      timed("hover", {{"textDocument", doc}, {"position", pos}}, f);
      timed("definition", {{"textDocument", doc}, {"position", pos}}, f);
      if (line >= lines) {
        timed("completion", {{"textDocument", doc}, {"position", pos}}, f);
        lines = line + 1;
      }
    }
    timed("formatting",
          {{"textDocument", doc}, {"options", {{"tabSize", 2}, {"insertSpaces", true}}}}, f);
    timed("documentSymbol", {{"textDocument", doc}}, f);
    s.notify("textDocument/didClose", {{"textDocument", doc}});
    s.diagnostics(uri);
  }
  s.request(id, "shutdown", nullptr);
  s.response(id);
  s.notify("exit");
  s.wait_exit();

  std::printf("ramus lsp over stdio, %zu grammars under %s (ms per round trip)\n", files.size(),
              examples.string().c_str());
  std::printf("%-26s %7s %7s %8s %8s %8s  %s\n", "method", "count", "errors", "median", "p99",
              "max", "slowest file");
  for (auto& [method, v] : times) {
    std::sort(v.begin(), v.end());
    auto q = [&](double p) { return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))]; };
    std::printf("%-26s %7zu %7d %8.3f %8.3f %8.3f  %s\n", method.c_str(), v.size(), errors[method],
                q(0.5), q(0.99), v.back(), worst[method].second.c_str());
  }
  std::printf("completion items returned: %zu\n", items);
  return 0;
}
