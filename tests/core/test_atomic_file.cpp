#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"

namespace fs = std::filesystem;

TEST_CASE("atomic_file: writes whole files and leaves nothing on failure", "[io]") {
  fs::path dir = fs::temp_directory_path() / "ramus_atomic_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string target = (dir / "out.txt").string();

  ramus::write_file_atomically(target, std::string_view("hello"));
  std::ifstream in(target);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str() == "hello");

  // A writer that fails halfway: the old file stays, no temporary is left behind.
  CHECK_THROWS(ramus::write_file_atomically(target, [](std::ostream& out) {
    out << "partial";
    throw std::runtime_error("boom");
  }));
  std::ifstream again(target);
  std::stringstream ss2;
  ss2 << again.rdbuf();
  CHECK(ss2.str() == "hello");
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);

  CHECK_THROWS_AS(ramus::write_file_atomically((dir / "missing" / "x").string(), std::string_view("x")),
                  ramus::WriteError);
  fs::remove_all(dir);
}
