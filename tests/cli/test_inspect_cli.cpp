// `ramus inspect`: what it prints for real scans, and positioned errors for bad ones.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
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
    std::string tmpl = (fs::temp_directory_path() / "ramus_inspect_XXXXXX").string();
    path = mkdtemp(tmpl.data());
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path / name, std::ios::binary) << bytes;
    return path / name;
  }
};

Result inspect(const TempDir& dir, const std::string& scan) {
  std::string cmd = quote(RAMUS_EXE) + " inspect " + quote(scan);
  fs::path out = dir.path / "stdout.txt", err = dir.path / "stderr.txt";
  cmd += " >" + quote(out.string()) + " 2>" + quote(err.string());
  int raw = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::string shared(const std::string& f) { return std::string(RAMUS_SHARED_DIR) + "/data/" + f; }

}  // namespace

TEST_CASE("inspect: the UTM-scale LAS scan", "[cli][inspect]") {
  TempDir dir;
  Result r = inspect(dir, shared("pytlidar_tree_1.las"));
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("format:   las (LAS 1.4, point format 6, 30-byte records)\n") !=
        std::string::npos);
  CHECK(r.out.find("points:   90,239\n") != std::string::npos);
  CHECK(r.out.find("extent:   12.713 x 18.212 x 12.884\n") != std::string::npos);
  CHECK(r.out.find("offset:   1176142 2857167 7\n") != std::string::npos);
  CHECK(r.out.find("channels: positions, intensity\n") != std::string::npos);
  CHECK(r.out.find("scanner:  not given\n") != std::string::npos);
}

TEST_CASE("inspect: a PCD with normals and a viewpoint and skipped NaN points", "[cli][inspect]") {
  TempDir dir;
  fs::path scan = dir.write("cloud.pcd",
                            "FIELDS x y z normal_x normal_y normal_z\nSIZE 4 4 4 4 4 4\n"
                            "TYPE F F F F F F\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 1 2 3 1 0 0 0\n"
                            "DATA ascii\n0 0 0 0 0 1\nnan nan nan 0 0 1\n2 4 6 0 1 0\n");
  Result r = inspect(dir, scan.string());
  CHECK(r.status == 0);
  CHECK(r.out.find("points:   2 (1 skipped: non-finite coordinates)\n") != std::string::npos);
  CHECK(r.out.find("bounds:   min 0.000 0.000 0.000\n          max 2.000 4.000 6.000\n") !=
        std::string::npos);
  CHECK(r.out.find("channels: positions, normals\n") != std::string::npos);
  CHECK(r.out.find("scanner:  1.000 2.000 3.000\n") != std::string::npos);
}

TEST_CASE("inspect: LAZ scans are decompressed and described", "[cli][inspect][laz]") {
  TempDir dir;
  Result laz = inspect(dir, shared("treels_spruce.laz"));
  CHECK(laz.status == 0);
  CHECK(laz.out.find("format:   las (LAZ 1.2, point format 0, 20-byte records, chunks "
                     "(compressor 2), point10 v2, 50000-point chunks)\n") != std::string::npos);
  CHECK(laz.out.find("points:   83,392\n") != std::string::npos);
}

TEST_CASE("inspect: unreadable scans exit 1 with the reader's positioned message",
          "[cli][inspect]") {
  TempDir dir;
  fs::path bad = dir.write("bad.xyz", "1 2 3\n4 5 six\n");
  Result r = inspect(dir, bad.string());
  CHECK(r.status == 1);
  CHECK(r.err == "ramus: error: " + bad.string() +
                     ": line 2: expected a number in column 3 (z), found 'six'\n");

  fs::path empty = dir.write("empty.ply", "");
  CHECK(inspect(dir, empty.string()).err ==
        "ramus: error: " + empty.string() + ": the file is empty\n");
  CHECK(inspect(dir, (dir.path / "missing.las").string()).status == 1);
}
