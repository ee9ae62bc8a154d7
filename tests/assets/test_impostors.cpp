// 2.5D foliage impostors in the `ramus view` page (Burkus 6, cli/view_impostors.cpp), run in
// headless Chromium by tests/assets/view_impostors.js on the demo tree: the impostors draw its
// foliage with at most a tenth of the leaf cards' triangles, their offscreen pictures are
// rendered again when the view turns (and only then) and differ between two views, they cover
// the screen where the leaf cards do, and their per-texel depth hides and shows branches as the
// cards do. Frame times are printed, not checked (software
// rendering; bench numbers belong in the report).
#include <catch2/catch.hpp>

#include "tests/assets/three_runner.h"

using namespace assets_test;

namespace {

bool run_impostors(const fs::path& page, Numbers& r) {
  return run_page_driver("view_impostors.js", page, r);
}

}  // namespace

TEST_CASE("the view page draws the demo tree's foliage as re-rendered 2.5D impostors",
          "[assets][view][impostors]") {
  cli_test::TempDir dir;
  const fs::path page = dir.path / "broadleaf.html";
  ramus_ok({"view", example("trees/broadleaf.ramus"), "-o", page.string()});
  Numbers r;
  if (!run_impostors(page, r)) return;
  for (const auto& [k, v] : r) INFO(k << " " << v);
  CHECK(r.at("networkRequests") == 0);
  CHECK(r.at("impostorMode") == 1);  // ?foliage=impostors
  REQUIRE(r.at("clouds") >= 2);
  CHECK(r.at("impostorTriangles") == 2 * r.at("clouds"));
  CHECK(r.at("impostorTriangles") * 10 <= r.at("cardTriangles"));
  // The frame itself: bark plus quads against bark plus cards.
  CHECK(r.at("frameTrianglesImpostors") + r.at("cardTriangles") - r.at("impostorTriangles") ==
        r.at("frameTrianglesCards"));
  // Re-rendered on view change, only beyond the threshold, and the pictures follow the view.
  CHECK(r.at("refreshesSmallTurn") == 0);
  CHECK(r.at("refreshesFirstFrame") >= 4);  // the per-frame budget, the most turned first
  CHECK(r.at("refreshesFirstFrame") < r.at("clouds"));
  CHECK(r.at("settleFrames") >= 2);
  CHECK(r.at("refreshesBigTurn") == r.at("clouds"));
  CHECK(r.at("picturesChanged") == r.at("clouds"));
  CHECK(r.at("pictureChange") > 0.2);
  CHECK(r.at("pictureReturn") < 0.01);
  CHECK(r.at("screenChange") > 0.2);
  // The impostors stand where the leaves are, and their depth comes from their pictures: where
  // it decides between branch and leaf, it agrees with the leaf cards more often than the
  // quads' flat depth does.
  CHECK(r.at("coverageIoU") > 0.7);
  CHECK(r.at("depthChanged") > 0.005);
  CHECK(r.at("depthAgrees") > r.at("flatAgrees") + 0.1);
  WARN("ms/frame (software WebGL): cards "
       << r.at("msCardsStill") << ", impostors " << r.at("msImpostorsStill") << " still, "
       << r.at("msImpostorsTurning") << " turning 5 degrees a frame");
}
