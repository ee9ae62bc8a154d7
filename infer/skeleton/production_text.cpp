#include "infer/skeleton/production_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "grammar/diagnostic.h"
#include "grammar/format.h"
#include "grammar/parser.h"
#include "grammar/source.h"
#include "infer/skeleton/infer_error.h"

namespace ramus::skeleton_infer {

// `clamp(normal(m, s), lo, hi)`, or the mean alone when the spread is nil.
std::string draw(const Fitted& f) {
  if (f.sd < 1e-6 || f.max - f.min < 1e-9) return grammar_number(f.mean);
  return "clamp(normal(" + grammar_number(f.mean) + ", " + grammar_number(f.sd) + "), " +
         grammar_number(f.min) + ", " + grammar_number(f.max) + ")";
}

// A log-normal ratio: exp of the clamped normal of the logarithms, or the constant ratio. A
// length ratio with a slope has its mean depend on the parent's log-length (regression).
std::string draw_ratio(const Fitted& f, const char* parent) {
  if (f.regression()) {
    const std::string mean = grammar_number(f.mean - f.slope * f.centre) + " + " +
                             grammar_number(f.slope) + " * log(max(" + parent + ", 1e-9))";
    return "exp(clamp(normal(" + mean + ", " + grammar_number(std::max(f.sd, 1e-6)) + "), " +
           grammar_number(f.min) + ", " + grammar_number(f.max) + "))";
  }
  if (f.atoms) {
    // Two exact ratios: floor(uniform(0, 1) + p) is 1 with probability p.
    const double r0 = std::exp(f.atom0), r1 = std::exp(f.atom1);
    if (f.atom_p <= 0 || std::abs(r1 - r0) < 1e-9) return grammar_number(r0);
    return "(" + grammar_number(r0) + " + " + grammar_number(r1 - r0) +
           " * floor(uniform(0, 1) + " + grammar_number(f.atom_p) + "))";
  }
  if (f.sd < 1e-6 || f.max - f.min < 1e-9) return grammar_number(std::exp(f.mean));
  return "exp(" + draw(f) + ")";
}

std::string draw_angle(const FittedAngle& f) {
  if (f.uniform) return "uniform(0, 360)";
  if (f.sd < 1e-6) return grammar_number(f.mean);
  return "normal(" + grammar_number(f.mean) + ", " + grammar_number(f.sd) + ")";
}

// The turtle turns of one child: level the frame, roll by phi, pitch down by theta.
std::string turn(const ChildDistribution& c) {
  return "$/(" + draw_angle(c.phi) + ")&(" + draw(c.theta) + ")";
}

// How an internode of length `len` is drawn. A reconstructed internode is a bent chain whose
// chord is shorter than its path (tortuosity tau = chord / path, 0.36 to 0.92 on the bundled
// scans); drawn straight with its path length, a regrown tree spreads up to 3.5 times wider.
// With tau < 1 it is drawn as two halves kinked by +-psi, psi = acos(tau), in a plane of random
// roll: the path length stays `len`, the chord becomes tau * len, and the heading at the end is
// the heading at the start (the pitches cancel; the roll is reset by the `$` of every child).
// Below kMinKink (tortuosity above cos 10 degrees = 0.985) an internode is drawn straight:
// the chord changes by under 1.5 percent, and the straight form keeps the grammar plain.

// The axiom may not draw random numbers: it kinks in the plane of roll 0.
std::string segment(double kink_degrees, const std::string& len, bool random_roll) {
  if (kink_degrees < kMinKink) return "F(" + len + ")";
  const std::string k = grammar_number(kink_degrees);
  return (random_roll ? "/(uniform(0, 360))&(" : "&(") + k + ")F(" + len + " * 0.5)&(-" +
         grammar_number(2 * kink_degrees) + ")F(" + len + " * 0.5)&(" + k + ")";
}

std::string child(const ChildDistribution& d, const LengthRange& range, const std::string& rest) {
  return turn(d) + "N(clamp(l * " + draw_ratio(d.log_a, "l") + ", " + grammar_number(range.min) +
         ", " + grammar_number(range.max) + "), w * " + draw_ratio(d.log_b, "w") + ", " + rest +
         ")";
}

// `lateral_budget`: the axis budget drawn for a lateral child, empty without axis budgets (the
// module then has no parameter r); the continuation gets what is left of r after this internode.
// With `tips`, the cluster is a last branch node (RuleGroup::last): its continuation is the
// axis's tip and is drawn as one, of the length left, kept within the observed tip lengths.
std::string alternative(const RuleCluster& c, const LengthRange& range, double kink,
                        const std::string& lateral_budget, const LengthRange* tips) {
  const bool budget = !lateral_budget.empty();
  std::string s = "!(w)" + segment(kink, "l");
  for (std::size_t j = 1; j < c.children.size(); ++j) {
    s += "[" +
         child(c.children[j], range,
               "o + 1, 0, d + 1" + (budget ? ", " + lateral_budget : std::string())) +
         "]";
  }
  if (c.children.empty()) return s;
  if (tips != nullptr && budget) {
    const ChildDistribution& t = c.children[0];
    return s + turn(t) + "!(w * " + draw_ratio(t.log_b, "w") + ")" +
           segment(kink, "clamp(r - l, " + grammar_number(tips->min) + ", " +
                             grammar_number(tips->max) + ")");
  }
  return s + child(c.children[0], range, budget ? "o, i + 1, d + 1, r - l" : "o, i + 1, d + 1");
}

// The draw of a lateral axis's length budget (AxisBudget), its log moved by `shift`.
std::string budget_draw(const AxisBudget& b, double shift) {
  std::string mean = grammar_number(b.c0 + shift);
  if (b.cl != 0) mean += " + " + grammar_number(b.cl) + " * log(max(l, 1e-9))";
  if (b.cw != 0) mean += " + " + grammar_number(b.cw) + " * log(max(w, 1e-9))";
  if (b.cd != 0) mean += " + " + grammar_number(b.cd) + " * d";
  const std::string lo = grammar_number(b.lo + shift), hi = grammar_number(b.hi + shift);
  if (b.sd < 1e-6 && b.cl == 0 && b.cw == 0 && b.cd == 0)  // one length: written as it is
    return grammar_number(std::exp(std::clamp(b.c0 + shift, b.lo + shift, b.hi + shift)));
  if (b.sd < 1e-6) return "exp(clamp(" + mean + ", " + lo + ", " + hi + "))";
  return "exp(clamp(normal(" + mean + ", " + grammar_number(b.sd) + "), " + lo + ", " + hi + "))";
}

// The draw of a lateral's budget: the mixture of LateralBudget, by one uniform draw. The shift
// moves only the branching axes: a single internode's length is observed as it is, while how far
// the axes branch is what the calibration corrects.
std::string budget_draw(const LateralBudget& b, double shift) {
  if (b.p_single <= 0) return budget_draw(b.branching, shift);
  if (b.p_single >= 1) return budget_draw(b.single, 0);
  return "(uniform(0, 1) < " + grammar_number(b.p_single) + " ? " + budget_draw(b.single, 0) +
         " : " + budget_draw(b.branching, shift) + ")";
}

// Where an axis ends. The budget r counts the internode of length l itself; T is the median
// length of the order's tips. The tip takes what is left of r (the fallback draws F(r)), so an
// axis is as long as its budget and its last internode as long as the input's tips, which
// differ from the inner internodes: a weeping tree's axes end in whips 5 times their parent's
// length, a conifer's in a twig, a pruned scan's in a cut. Each guard sits halfway between the
// two budgets it tells apart, so that the spread of the drawn lengths tips neither way:
//  - the internode carries more than a tip when r > l / 2 + T, halfway between r = T (it is
//    the tip) and r = l + T (one tip follows);
//  - with the last branch nodes of the axes grouped apart (RuleGroup::last), the other branch
//    nodes apply when r > (1 + next / 2) l + T, halfway between r = l + T and r = l + next l + T
//    (another internode of about `next` times l follows, `next` the median ratio of the order's
//    branching continuations), and the last ones below that.
std::string carries_guard(double tip) { return " && r > 0.5 * l + " + grammar_number(tip); }
std::string branching_guard(double next, double tip) {
  return " && r > " + grammar_number(1 + next / 2) + " * l + " + grammar_number(tip);
}

// AxisEnds::shared: an internode of length l continues its axis while the budget r leaves more
// than half of a next internode of l times `next`: r > l (1 + next / 2). `next` is the lower
// quartile of the order's continuation ratios, not the median: an order whose axes end in a
// long shoot (a weeping tree's whip, 6 times its parent) has ratios far above 1 in many of its
// continuations, and a threshold set by them would end its ordinary axes early.
std::string continue_guard(double next) {
  return " && r > " + grammar_number(1 + next / 2) + " * l";
}

// Observed frequencies as decimals with six places that sum to exactly 1 (largest remainder),
// as the checker requires of a stochastic production.
std::vector<std::string> probabilities(const std::vector<std::size_t>& counts) {
  constexpr std::int64_t kScale = 1'000'000;
  std::size_t total = 0;
  for (std::size_t c : counts) total += c;
  std::vector<std::int64_t> parts(counts.size());
  std::vector<std::pair<double, std::size_t>> remainders;
  std::int64_t used = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const double exact = double(counts[i]) * double(kScale) / double(total);
    parts[i] = std::int64_t(std::floor(exact));
    used += parts[i];
    remainders.push_back({exact - double(parts[i]), i});
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  for (std::size_t k = 0; used < kScale; ++k, ++used)
    ++parts[remainders[k % remainders.size()].second];
  std::vector<std::string> out;
  for (std::int64_t p : parts) {
    if (p == kScale) {
      out.push_back("1");
      continue;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "0.%06lld", static_cast<long long>(p));
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    out.push_back(s);
  }
  return out;
}

std::string grammar_number(double v) {
  if (!std::isfinite(v)) return "0";
  if (std::abs(v) < 1e-9) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  std::string s = buf;
  // "%g" may write "1e+02"; the language reads "1e+02" too, but fixed notation reads better.
  if (s.find('e') != std::string::npos && std::abs(v) >= 1e-4 && std::abs(v) < 1e15) {
    std::snprintf(buf, sizeof buf, "%.6f", v);
    s = buf;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  return s;
}

std::string canonical_layout(const std::string& text) {
  SourceManager sources;
  DiagnosticSink sink;
  const std::uint32_t id = sources.add("inferred.ramus", text);
  const ast::File file = parse(sources, id, sink);
  if (sink.has_errors()) throw InferError("internal error: the inferred grammar does not parse");
  return format_file(file, sources);
}

}  // namespace ramus::skeleton_infer
