// Writes that cannot half-happen (issue 22 point 7, core/atomic_file.h): `ramus build` killed
// with SIGKILL while it writes its output leaves the old output intact and no temporary file in
// the output folder. The test watches the process's open files (/proc/PID/fd) and kills it the
// moment it holds a file of the output folder open, so the kill lands inside the write.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;

// Whether process `pid` has a file of `dir` open (a write in progress: ramus keeps no other file
// of the output folder open).
bool writing_into(pid_t pid, const fs::path& dir) {
  std::error_code ec;
  const std::string prefix = fs::canonical(dir).string() + "/";
  for (const auto& e : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
    const fs::path target = fs::read_symlink(e.path(), ec);
    if (!ec && target.string().rfind(prefix, 0) == 0) return true;
  }
  return false;
}

// A complete binary glTF: its header's length is the file's size.
bool whole_glb(const std::string& bytes) {
  if (bytes.size() < 12 || bytes.compare(0, 4, "glTF") != 0) return false;
  const auto byte = [&](std::size_t i) { return std::uint32_t(std::uint8_t(bytes[i])); };
  const std::uint32_t length = byte(8) | byte(9) << 8 | byte(10) << 16 | byte(11) << 24;
  return length == bytes.size();
}

std::vector<std::string> folder_listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE(
    "atomic write: build killed by SIGKILL while writing leaves the old output and no temporary",
    "[cli][atomic]") {
  cli_test::TempDir dir;
  const fs::path out_dir = dir.path / "out";
  fs::create_directories(out_dir);
  const fs::path glb = out_dir / "tree.glb";
  const std::string old = "the old output";
  cli_test::write_text(glb, old);
  const std::string grammar = std::string(RAMUS_SOURCE_DIR) + "/examples/trees/broadleaf.ramus";
  int killed_while_writing = 0;
  for (int attempt = 0; attempt < 20 && killed_while_writing < 3; ++attempt) {
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      std::freopen("/dev/null", "w", stderr);
      execl(RAMUS_EXE, "ramus", "build", grammar.c_str(), "--seed", std::to_string(attempt).c_str(),
            "-o", glb.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    bool killed = false;
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0) {
      if (writing_into(pid, out_dir)) {
        kill(pid, SIGKILL);
        killed = true;
        waitpid(pid, &status, 0);
        break;
      }
    }
    if (killed && WIFSIGNALED(status)) {
      // The kill follows the poll that saw the file open; on a busy machine the write can
      // finish in between. Either way nothing is half-written: the old output, or the whole new
      // one. Only kills that found the old output and no other file count as landing inside a
      // write. A kill in the commit's few microseconds, after the file was complete and linked
      // under its temporary name but before the rename (core/atomic_file.cpp), leaves that name
      // holding the whole new output beside the old one: no longer a kill inside the write.
      const std::string now = cli_test::slurp(glb);
      CHECK((now == old || whole_glb(now)));
      std::vector<std::string> listing = folder_listing(out_dir);
      std::sort(listing.begin(), listing.end());
      const bool in_commit = now == old && listing.size() == 2 && listing[0] == "tree.glb" &&
                             listing[1].rfind("tree.glb.tmp", 0) == 0 &&
                             listing[1].size() == std::string("tree.glb.tmp").size() + 8 &&
                             whole_glb(cli_test::slurp(out_dir / listing[1]));
      if (in_commit) {
        fs::remove(out_dir / listing[1]);
        continue;
      }
      CHECK(listing == std::vector<std::string>{"tree.glb"});
      if (now == old) {
        ++killed_while_writing;
      } else {
        cli_test::write_text(glb, old);
      }
    } else {
      // The write finished before the poll saw it: the new output is whole; start again from
      // the old one.
      CHECK(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == 0);
      CHECK(cli_test::slurp(glb).substr(0, 4) == "glTF");
      CHECK(folder_listing(out_dir) == std::vector<std::string>{"tree.glb"});
      cli_test::write_text(glb, old);
    }
  }
  CHECK(killed_while_writing >= 1);
}
