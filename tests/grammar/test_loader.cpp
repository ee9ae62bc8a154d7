// The loader: relative and stdlib imports, each file once, missing imports, cycles, unreadable
// files, and the stdlib search path.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "grammar/loader.h"

using namespace ramus;
namespace fs = std::filesystem;

namespace {

// A fresh folder of .ramus files for one test.
struct TempTree {
  fs::path root;
  explicit TempTree(const std::string& name) {
    root = fs::temp_directory_path() / ("ramus_loader_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~TempTree() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  std::string write(const std::string& rel, const std::string& text) const {
    fs::path p = root / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
};

std::string codes(const SourceManager& sm, const DiagnosticSink& diags) {
  std::string out;
  for (const Diagnostic& d : diags.all()) {
    LineCol lc = sm.line_col(d.span.file, d.span.begin);
    out += (out.empty() ? "" : " ") + fs::path(sm.name(d.span.file)).filename().string() + ":" +
           info(d.code).id + "@" + std::to_string(lc.line) + ":" + std::to_string(lc.column);
  }
  return out;
}

std::string file_name(const SourceManager& sm, const Program& p, std::uint32_t i) {
  return fs::path(sm.name(p.files.at(i).file_id)).filename().string();
}

}  // namespace

TEST_CASE("loader: relative and stdlib imports, each file loaded once", "[loader]") {
  TempTree t("diamond");
  std::string root =
      t.write("main.ramus",
              "import \"parts/a.ramus\";\nimport \"parts/b.ramus\";\nimport trees.oak;\n"
              "const x = 1;\n");
  t.write("parts/a.ramus", "import \"c.ramus\";\nconst a = 1;\n");
  t.write("parts/b.ramus", "import \"../parts/c.ramus\";\nimport \"c.ramus\";\n");
  t.write("parts/c.ramus", "const c = 3;\n");
  t.write("lib/trees/oak.ramus", "import \"../../parts/c.ramus\";\nmodule Oak;\n");
  SourceManager sm;
  DiagnosticSink diags;
  LoadOptions opts;
  opts.stdlib_dirs = {(t.root / "nowhere").string(), (t.root / "lib").string()};
  Program p = load_program(root, sm, diags, opts);
  INFO(render_text(sm, diags.all()));
  CHECK(diags.all().empty());
  REQUIRE(p.files.size() == 5);
  REQUIRE(p.imports.size() == 5);
  CHECK(file_name(sm, p, 0) == "main.ramus");
  CHECK(file_name(sm, p, 1) == "a.ramus");
  CHECK(file_name(sm, p, 2) == "c.ramus");
  CHECK(file_name(sm, p, 3) == "b.ramus");
  CHECK(file_name(sm, p, 4) == "oak.ramus");
  CHECK(p.imports[0] == std::vector<std::uint32_t>{1, 3, 4});
  CHECK(p.imports[1] == std::vector<std::uint32_t>{2});
  CHECK(p.imports[2].empty());
  CHECK(p.imports[3] == std::vector<std::uint32_t>{2});
  CHECK(p.imports[4] == std::vector<std::uint32_t>{2});
  CHECK(p.files[2].decls.size() == 1);
}

TEST_CASE("loader: missing imports are E0601 at the import", "[loader]") {
  TempTree t("missing");
  std::string root =
      t.write("main.ramus", "const a = 1;\nimport \"nope.ramus\";\n  import no.such.module;\n");
  SourceManager sm;
  DiagnosticSink diags;
  LoadOptions opts;
  opts.stdlib_dirs = {t.root.string()};
  Program p = load_program(root, sm, diags, opts);
  CHECK(codes(sm, diags) == "main.ramus:E0601@2:1 main.ramus:E0601@3:3");
  CHECK(diags.all()[0].message == "cannot find imported file 'nope.ramus'");
  CHECK(diags.all()[1].message ==
        "cannot find module 'no.such.module' (no/such/module.ramus) in the standard library");
  CHECK(sm.slice(diags.all()[1].span) == "import no.such.module;");
  CHECK(p.files.size() == 1);
}

TEST_CASE("loader: import cycles are E0602 and do not loop", "[loader]") {
  TempTree t("cycle");
  std::string root = t.write("a.ramus", "import \"b.ramus\";\n");
  t.write("b.ramus", "const x = 1;\nimport \"c.ramus\";\n");
  t.write("c.ramus", "import \"a.ramus\";\nimport \"c.ramus\";\n");
  SourceManager sm;
  DiagnosticSink diags;
  Program p = load_program(root, sm, diags);
  CHECK(codes(sm, diags) == "c.ramus:E0602@1:1 c.ramus:E0602@2:1");
  CHECK(diags.all()[0].message.find("import cycle: ") == 0);
  CHECK(diags.all()[0].message.find("a.ramus -> ") != std::string::npos);
  REQUIRE(p.files.size() == 3);
  CHECK(p.imports[0] == std::vector<std::uint32_t>{1});
  CHECK(p.imports[1] == std::vector<std::uint32_t>{2});
  CHECK(p.imports[2].empty());
}

TEST_CASE("loader: an unreadable root is E0001 and an empty program", "[loader]") {
  TempTree t("unreadable");
  SourceManager sm;
  DiagnosticSink diags;
  Program p = load_program((t.root / "absent.ramus").string(), sm, diags);
  REQUIRE(diags.all().size() == 1);
  CHECK(diags.all()[0].code == DiagCode::FileUnreadable);
  CHECK(p.files.empty());
  CHECK(render_text(sm, diags.all()).find("absent.ramus:1:1: error[E0001]: cannot read file") !=
        std::string::npos);
  DiagnosticSink d2;
  Program q = load_program(t.root.string(), sm, d2);  // a directory
  REQUIRE(d2.all().size() == 1);
  CHECK(d2.all()[0].message.find("is a directory") != std::string::npos);
  CHECK(q.files.empty());
}

TEST_CASE("loader: text in memory imports relative to its name", "[loader]") {
  TempTree t("text");
  t.write("sub/x.ramus", "const x = 1;\n");
  SourceManager sm;
  DiagnosticSink diags;
  Program p = load_program_text((t.root / "virtual.ramus").string(),
                                "import \"sub/x.ramus\";\nconst y = x;\n", sm, diags);
  INFO(render_text(sm, diags.all()));
  CHECK(diags.all().empty());
  REQUIRE(p.files.size() == 2);
  CHECK(p.imports[0] == std::vector<std::uint32_t>{1});
  // Syntax errors of imported files are reported in those files.
  t.write("sub/bad.ramus", "const = 1;\n");
  DiagnosticSink d2;
  Program q =
      load_program_text((t.root / "v2.ramus").string(), "import \"sub/bad.ramus\";", sm, d2);
  CHECK(codes(sm, d2) == "bad.ramus:E0003@1:7");
  CHECK(q.files.size() == 2);
}

TEST_CASE("loader: the stdlib search path", "[loader]") {
  const char* old = std::getenv("RAMUS_STDLIB");
  std::string saved = old ? old : "";
  ::setenv("RAMUS_STDLIB", "/one:/two::", 1);
  CHECK(default_stdlib_dirs() == std::vector<std::string>{"/one", "/two"});
  ::unsetenv("RAMUS_STDLIB");
  std::vector<std::string> dirs = default_stdlib_dirs();
  REQUIRE(!dirs.empty());
  CHECK(fs::equivalent(dirs[0], fs::path(RAMUS_SOURCE_DIR) / "stdlib"));
  if (old) ::setenv("RAMUS_STDLIB", saved.c_str(), 1);
  // The project's own stdlib loads through the default path.
  SourceManager sm;
  DiagnosticSink diags;
  Program p = load_program_text("t.ramus", "import abop;\n", sm, diags);
  INFO(render_text(sm, diags.all()));
  CHECK(diags.all().empty());
  CHECK(p.files.size() >= 2);
}
