// Loading a program: the root file and its imports, depth first, each file parsed once.
// A file is "loading" while its own imports are resolved, so meeting it again then is a cycle.
#include "grammar/loader.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>

#include "core/input_file.h"
#include "grammar/parser.h"

#ifndef RAMUS_STDLIB_DIR
#define RAMUS_STDLIB_DIR ""
#endif

namespace ramus {

namespace fs = std::filesystem;

std::vector<std::string> default_stdlib_dirs() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("RAMUS_STDLIB"); env && *env) {
    std::stringstream ss(env);
    for (std::string d; std::getline(ss, d, ':');) {
      if (!d.empty()) dirs.push_back(d);
    }
    return dirs;
  }
  std::error_code ec;
  if (std::string built = RAMUS_STDLIB_DIR; !built.empty() && fs::is_directory(built, ec)) {
    dirs.push_back(built);
  }
  // An installed ramus: <prefix>/bin/ramus beside <prefix>/share/ramus/stdlib.
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path shared = exe.parent_path().parent_path() / "share" / "ramus" / "stdlib";
    if (fs::is_directory(shared, ec)) dirs.push_back(shared.string());
  }
  return dirs;
}

namespace {

// Reads a whole file (core/input_file.h: under --max-file-size); failure reported through `error`.
bool read_file(const fs::path& path, std::string& text, std::string& error) {
  return read_input_file(path, text, error);
}

class Loader {
 public:
  Loader(SourceManager& sm, DiagnosticSink& diags, const LoadOptions& options)
      : sm_(sm), diags_(diags), stdlib_(options.stdlib_dirs) {
    if (stdlib_.empty()) stdlib_ = default_stdlib_dirs();
  }

  // Adds a file that was read; parses it and, recursively, its imports. Returns its index.
  std::uint32_t add(std::string name, std::string text, const std::string& key) {
    std::uint32_t id = sm_.add(name, std::move(text));
    std::uint32_t index = std::uint32_t(program_.files.size());
    program_.files.push_back(parse(sm_, id, diags_));
    program_.imports.emplace_back();
    if (!key.empty()) by_key_[key] = index;
    loading_.push_back(index);
    resolve_imports(index, name);
    loading_.pop_back();
    return index;
  }

  Program take() { return std::move(program_); }

 private:
  void resolve_imports(std::uint32_t index, const std::string& importer) {
    // Copy the imports first: loading a file appends to program_.files.
    std::vector<ast::Import> imports;
    for (const ast::Decl& d : program_.files[index].decls) {
      if (const auto* im = std::get_if<ast::Import>(&d)) imports.push_back(*im);
    }
    for (const ast::Import& im : imports) {
      std::optional<std::uint32_t> target = resolve(im, importer);
      if (!target) continue;
      auto& list = program_.imports[index];
      if (std::find(list.begin(), list.end(), *target) == list.end()) list.push_back(*target);
    }
  }

  std::optional<fs::path> locate(const ast::Import& im, const std::string& importer) const {
    std::error_code ec;
    if (im.is_file) {
      fs::path p = fs::path(importer).parent_path() / im.path;
      if (fs::exists(p, ec)) return p.lexically_normal();
      return std::nullopt;
    }
    std::string rel = im.path;
    std::replace(rel.begin(), rel.end(), '.', '/');
    rel += ".ramus";
    for (const std::string& dir : stdlib_) {
      fs::path p = fs::path(dir) / rel;
      if (fs::exists(p, ec)) return p.lexically_normal();
    }
    return std::nullopt;
  }

  std::optional<std::uint32_t> resolve(const ast::Import& im, const std::string& importer) {
    std::optional<fs::path> path = locate(im, importer);
    if (!path) {
      if (im.is_file) {
        diags_.report(DiagCode::ImportNotFound, im.span,
                      "cannot find imported file '" + im.path + "'");
      } else {
        std::string rel = im.path;
        std::replace(rel.begin(), rel.end(), '.', '/');
        diags_.report(
            DiagCode::ImportNotFound, im.span,
            "cannot find module '" + im.path + "' (" + rel + ".ramus) in the standard library");
      }
      return std::nullopt;
    }
    std::error_code ec;
    fs::path canon = fs::weakly_canonical(*path, ec);
    std::string key = ec ? path->string() : canon.string();
    if (auto it = by_key_.find(key); it != by_key_.end()) {
      if (std::find(loading_.begin(), loading_.end(), it->second) != loading_.end()) {
        report_cycle(im, it->second);
        return std::nullopt;
      }
      return it->second;
    }
    std::string text, error;
    if (!read_file(*path, text, error)) {
      diags_.report(DiagCode::FileUnreadable, im.span,
                    "cannot read imported file '" + path->string() + "': " + error);
      return std::nullopt;
    }
    return add(path->string(), std::move(text), key);
  }

  void report_cycle(const ast::Import& im, std::uint32_t target) {
    // The chain from the file being imported again down to the importing file.
    std::string chain;
    bool on = false;
    for (std::uint32_t f : loading_) {
      on = on || f == target;
      if (on) chain += sm_.name(program_.files[f].file_id) + " -> ";
    }
    chain += sm_.name(program_.files[target].file_id);
    diags_.report(DiagCode::ImportCycle, im.span, "import cycle: " + chain);
  }

  SourceManager& sm_;
  DiagnosticSink& diags_;
  std::vector<std::string> stdlib_;
  Program program_;
  std::map<std::string, std::uint32_t> by_key_;  // canonical path -> file index
  std::vector<std::uint32_t> loading_;           // the files whose imports are being resolved
};

std::string key_of(const std::string& path) {
  std::error_code ec;
  fs::path canon = fs::weakly_canonical(path, ec);
  return ec ? path : canon.string();
}

}  // namespace

Program load_program(const std::string& path, SourceManager& sm, DiagnosticSink& diags,
                     const LoadOptions& options) {
  std::string text, error;
  if (!read_file(path, text, error)) {
    std::uint32_t id = sm.add(path, "");
    diags.report(DiagCode::FileUnreadable, SourceSpan{id, 0, 0},
                 "cannot read file '" + path + "': " + error);
    return {};
  }
  Loader loader(sm, diags, options);
  loader.add(path, std::move(text), key_of(path));
  return loader.take();
}

Program load_program_text(std::string name, std::string text, SourceManager& sm,
                          DiagnosticSink& diags, const LoadOptions& options) {
  Loader loader(sm, diags, options);
  // Text in memory has no path of its own; a file of the same name may still import it.
  std::error_code ec;
  std::string key = fs::exists(name, ec) ? key_of(name) : std::string();
  loader.add(std::move(name), std::move(text), key);
  return loader.take();
}

}  // namespace ramus
