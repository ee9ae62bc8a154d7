#include "infer/skeleton/grown_trees.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "compiler/derive.h"
#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "compiler/turtle.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"
#include "infer/skeleton/infer_error.h"

namespace ramus::skeleton_infer {

// Grows `text` with seeds 1..n and hands every tree to `use`; false when a growth goes over
// kMaxCalibrationModules (far too long).
bool grow_seeds(const std::string& text, int seeds, const std::function<void(const Skeleton&)>& use) {
  for (int k = 1; k <= seeds; ++k) {
    GrowOptions o;
    o.seed = std::uint64_t(k);
    SourceManager sources;
    DiagnosticSink sink;
    try {
      const ir::Grammar g = lower_text("inferred.ramus", text, o, sources, sink);
      DeriveOptions d;
      d.max_modules = kMaxCalibrationModules;
      TurtleOptions t;
      t.seed = g.settings.seed;
      t.steps = g.settings.derive;
      use(interpret(g, derive(g, d), t));
    } catch (const DeriveError&) {
      return false;
    } catch (const std::exception& e) {
      throw InferError(std::string("internal error: the inferred grammar does not grow: ") +
                       e.what());
    }
  }
  return true;
}

// Mean total length of trees grown from `text` with seeds 1..n.
double mean_grown_length(const std::string& text, int seeds) {
  double sum = 0;
  if (!grow_seeds(text, seeds, [&](const Skeleton& s) { sum += s.total_length(); }))
    return std::numeric_limits<double>::infinity();
  return sum / double(seeds);
}

// Calibration against the input: the intercept shift of every tip hazard for which the trees the
// grammar grows have, over `seeds` seeds, the input tree's total length. Without it
// the regrown length is off by up to 3x: the hazard is fitted per internode, but the regrown tree
// compounds its errors (ratios drawn independently, tips of a scan hidden by occlusion). The
// mean length falls as the shift grows (more tips), so the shift is found by bisection on
// [-kMaxShift, kMaxShift] in the log of the length ratio.
double calibrate_tip_shift(const std::function<std::string(double)>& write, double target,
                           int seeds) {
  constexpr double kMaxShift = 30;
  constexpr int kSteps = 12;
  if (!(target > 0)) return 0;
  auto error = [&](double shift) {
    const double grown = mean_grown_length(write(shift), seeds);
    return std::log(std::max(grown, 1e-12) / target);
  };
  double lo = -kMaxShift, hi = kMaxShift;
  if (error(lo) <= 0) return lo;  // even with fewer tips the grammar grows too little
  if (error(hi) >= 0) return hi;
  for (int it = 0; it < kSteps; ++it) {
    const double mid = (lo + hi) / 2;
    (error(mid) > 0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

double grown_distance(const std::string& text, const Distributions& input, int seeds) {
  Distributions grown;
  if (!grow_seeds(text, seeds, [&](const Skeleton& s) { measure(s, grown); }))
    return std::numeric_limits<double>::infinity();
  if (input.trees == 0 || grown.trees == 0) return std::numeric_limits<double>::infinity();
  double distance = 0;
  for (const MeasureComparison& c : compare(input, grown)) {
    switch (c.measure) {
      case Measure::BranchLength:
      case Measure::BranchingAngle:
      case Measure::BranchOrder:
        distance += c.ks;
        break;
      case Measure::TotalLength:
      case Measure::CrownExtent:
      case Measure::Height:
        distance += std::abs(std::log(std::max(c.mean_b, 1e-12) / std::max(c.mean_a, 1e-12)));
        break;
      default:
        break;
    }
  }
  return distance;
}

double grown_distance(const std::string& text, const Skeleton& skeleton, int seeds) {
  Distributions input;
  measure(skeleton, input);
  return grown_distance(text, input, seeds);
}

}  // namespace ramus::skeleton_infer
