// `ramus fmt`: rewriting in place, --check, and files with errors left untouched.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Result {
  int status = -1;
  std::string out, err;
};

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "ramus_fmt_XXXXXX").string();
    path = mkdtemp(tmpl.data());
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return path / name;
  }
};

Result ramus(const TempDir& dir, const std::vector<std::string>& args) {
  std::string cmd = quote(RAMUS_EXE);
  for (const std::string& a : args) cmd += " " + quote(a);
  fs::path out = dir.path / "stdout.txt", err = dir.path / "stderr.txt";
  cmd += " >" + quote(out.string()) + " 2>" + quote(err.string());
  int raw = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

const char* kMessy = "lsystem s{axiom F;F->F[+F]F; // keep me\n}\n";
const char* kTidy = "lsystem s {\n  axiom F;\n  F -> F[+F]F;  // keep me\n}\n";

}  // namespace

TEST_CASE("fmt cli: rewrites a file in place, then leaves it alone", "[cli][fmt]") {
  TempDir dir;
  fs::path f = dir.write("a.ramus", kMessy);
  Result r = ramus(dir, {"fmt", f.string()});
  CHECK(r.status == 0);
  CHECK(slurp(f) == kTidy);
  Result again = ramus(dir, {"fmt", "--check", f.string()});
  CHECK(again.status == 0);
  CHECK(again.out.empty());
}

TEST_CASE("fmt cli: --check names the files that would change and writes nothing", "[cli][fmt]") {
  TempDir dir;
  fs::path messy = dir.write("messy.ramus", kMessy);
  fs::path tidy = dir.write("tidy.ramus", kTidy);
  Result r = ramus(dir, {"fmt", "--check", messy.string(), tidy.string()});
  CHECK(r.status == 1);
  CHECK(r.out == messy.string() + "\n");
  CHECK(slurp(messy) == kMessy);
  CHECK(ramus(dir, {"fmt", "--check", tidy.string()}).status == 0);
}

TEST_CASE("fmt cli: a file with syntax errors is reported and left untouched", "[cli][fmt]") {
  TempDir dir;
  const std::string broken = "lsystem s{axiom F;F->F[+F;\n";
  fs::path bad = dir.write("bad.ramus", broken);
  fs::path good = dir.write("good.ramus", kMessy);
  Result r = ramus(dir, {"fmt", bad.string(), good.string()});
  CHECK(r.status == 1);
  CHECK(r.err.find("error[E0003]") != std::string::npos);
  CHECK(slurp(bad) == broken);
  CHECK(slurp(good) == kTidy);  // the other files are still formatted
  CHECK(ramus(dir, {"fmt", (dir.path / "missing.ramus").string()}).status == 1);
  CHECK(ramus(dir, {"fmt"}).status == 2);
}

TEST_CASE("fmt cli: the examples are formatted", "[cli][fmt]") {
  TempDir dir;
  std::vector<std::string> args = {"fmt", "--check"};
  for (const auto& e : fs::recursive_directory_iterator(fs::path(RAMUS_SOURCE_DIR) / "examples")) {
    if (e.path().extension() == ".ramus") args.push_back(e.path().string());
  }
  REQUIRE(args.size() > 2);
  Result r = ramus(dir, args);
  INFO(r.out << r.err);
  CHECK(r.status == 0);
}
