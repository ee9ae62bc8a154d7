// Blender's and Godot 3's own glTF importers load the demo tree upright
// (scripts/check-engines.sh). Runs only where Debian's blender, godot3 and xvfb-run are
// installed (scripts/install-deps.sh installs them); elsewhere the test says it was skipped.
#include <catch2/catch.hpp>

#include "tests/assets/three_runner.h"

using namespace assets_test;

TEST_CASE("Blender and Godot load the demo tree upright", "[assets][engines]") {
  for (const char* exe : {"/usr/bin/blender", "/usr/bin/godot3", "/usr/bin/xvfb-run"}) {
    if (!fs::exists(exe)) {
      WARN("skipped: " << exe << " is not installed (scripts/install-deps.sh installs it)");
      return;
    }
  }
  std::string out;
  const int code =
      run_shell("RAMUS_NO_INSTALL=1 bash " +
                    cli_test::shell_quote(RAMUS_SOURCE_DIR "/scripts/check-engines.sh") + " " +
                    cli_test::shell_quote(RAMUS_EXE),
                out);
  INFO(out);
  CHECK(code == 0);
  CHECK(out.find("blender: ") != std::string::npos);
  CHECK(out.find("godot: ") != std::string::npos);
}
