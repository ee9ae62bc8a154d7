#include "infer/skeleton/scaffold_grammar.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "compiler/turtle_frame.h"
#include "infer/skeleton/infer_error.h"
#include "infer/skeleton/production_text.h"

namespace ramus::skeleton_infer {

namespace {

constexpr double kDeg = 57.29577951308232;

// Turns below this (degrees) are not written: the frame stays as it is, which also keeps a
// vertical heading's frame (where `$` does nothing) the one the turtle has.
constexpr double kMinTurn = 0.05;

// The polyline of a scaffold internode keeps its bends to within this share of the tree's
// height, and no drawn segment is longer than kMaxSegment of it.
constexpr double kSimplify = 0.01;
constexpr double kMaxSegment = 0.2;

// The first piece of a trunk whose root has several internodes, shared by them (a share of the
// height).
constexpr double kSharedFoot = 0.001;

// A cap on the derivation steps (see infer_scaffold_grammar).
constexpr int kMaxSteps = 400;

// Douglas-Peucker: the indices of `p` kept so that no dropped point is farther than `tol` from
// the polyline of the kept ones.
void simplify(const std::vector<Vec3>& p, std::size_t a, std::size_t b, double tol,
              std::vector<char>& keep) {
  if (b <= a + 1) return;
  const Vec3 d = p[b] - p[a];
  const double len = length(d);
  double worst = -1;
  std::size_t at = a;
  for (std::size_t k = a + 1; k < b; ++k) {
    const Vec3 v = p[k] - p[a];
    const double dist = len > 1e-12 ? length(cross(v, d)) / len : length(v);
    if (dist > worst) worst = dist, at = k;
  }
  if (worst <= tol) return;
  keep[at] = 1;
  simplify(p, a, at, tol, keep);
  simplify(p, at, b, tol, keep);
}

class AxiomWriter {
 public:
  AxiomWriter(const Skeleton& sk, const BranchRules& rules, const Scaffold& s, double height,
              const Vec3& tropism, double elasticity, double branch_angle)
      : sk_(sk),
        rules_(rules),
        s_(s),
        height_(height),
        tropism_(tropism),
        e_(elasticity),
        branch_angle_(branch_angle) {}

  std::string write() {
    const std::uint32_t trunk = s_.roots.front();
    width_ = 2 * sk_.nodes[rules_.internodes[trunk].start].radius;
    if (s_.roots.size() > 1) {
      // Several internodes leave the root. The turtle gives a branch that starts with `[` a
      // root node of its own, so a first short piece of the trunk gives them one node to share
      // (one tree, not several touching ones).
      const Internode& in = rules_.internodes[trunk];
      turn_to(in.direction);
      set_width(2 * sk_.nodes[in.start].radius);
      out_ += "F(" + grammar_number(kSharedFoot * height_) + ")";
      frame_.bend(tropism_, e_);
      for (std::size_t k = 1; k < s_.roots.size(); ++k) branch(s_.roots[k]);
    }
    axis(trunk);
    return out_;
  }
  std::size_t segments() const { return segments_; }
  std::size_t buds() const { return buds_; }
  double max_bud_budget() const { return max_bud_budget_; }

 private:
  // The turn that takes the turtle's heading to `d`, applied to the frame as the turtle will
  // apply the written numbers.
  //
  // The first turn of a branch is written as a multiple of branch_angle, so that
  // `-D branch_angle=...` opens or closes every branch and bud at once, in proportion (a shift
  // by the difference instead turned the narrowest branches past their parent's heading).
  void turn_to(const Vec3& d) {
    const bool opening = opening_;
    opening_ = false;
    const double c = std::clamp(dot(frame_.h, d), -1.0, 1.0);
    if (!opening && std::acos(c) * kDeg < kMinTurn) return;
    frame_.level();
    const Vec3 w = d - frame_.h * c;
    double phi = std::atan2(-dot(w, frame_.l), -dot(w, frame_.u)) * kDeg;
    if (phi < 0) phi += 360;
    const std::string phi_text = grammar_number(phi);
    const double theta = std::atan2(length(w), c) * kDeg;
    out_ += "$";
    if (phi_text != "0" && phi_text != "360") {
      out_ += "/(" + phi_text + ")";
      rotate_pair(frame_.l, frame_.u, -std::stod(phi_text));
      frame_.orthonormalize();
    }
    double written = 0;
    if (opening && branch_angle_ > 0) {
      const std::string factor = grammar_number(theta / branch_angle_);
      out_ += "&(" + factor + " * branch_angle)";
      written = std::stod(factor) * branch_angle_;
    } else {
      const std::string theta_text = grammar_number(theta);
      out_ += "&(" + theta_text + ")";
      written = std::stod(theta_text);
    }
    rotate_pair(frame_.h, frame_.u, -written);
    frame_.orthonormalize();
  }

  // A width never above the one the branch started from (radii of reconstructions can grow).
  void set_width(double w) {
    const std::string text = grammar_number(std::min(w, width_));
    const double v = std::stod(text);
    if (v > 0 && text != width_text_) {
      out_ += "!(" + text + ")";
      width_text_ = text;
      width_ = v;
    }
  }

  void segment(const Vec3& from, const Vec3& to, double radius) {
    const Vec3 d = to - from;
    const double len = length(d);
    if (len < 1e-9) return;
    const int pieces = std::max(1, int(std::ceil(len / (kMaxSegment * height_))));
    for (int k = 0; k < pieces; ++k) {
      turn_to(d / len);
      set_width(2 * radius);
      out_ += "F(" + grammar_number(len / pieces) + ")";
      frame_.bend(tropism_, e_);
      ++segments_;
    }
  }

  // The node chain of internode i, simplified.
  void internode(std::uint32_t i) {
    const Internode& in = rules_.internodes[i];
    std::vector<std::uint32_t> chain;
    for (std::uint32_t k = in.end; k != in.start && k != kNoParent; k = sk_.nodes[k].parent)
      chain.push_back(k);
    chain.push_back(in.start);
    std::reverse(chain.begin(), chain.end());
    std::vector<Vec3> p;
    for (std::uint32_t k : chain) p.push_back(sk_.nodes[k].position);
    std::vector<char> keep(p.size(), 0);
    keep.front() = keep.back() = 1;
    simplify(p, 0, p.size() - 1, kSimplify * height_, keep);
    std::size_t last = 0;
    for (std::size_t k = 1; k < p.size(); ++k) {
      if (!keep[k]) continue;
      segment(p[last], p[k], sk_.nodes[chain[last]].radius);
      last = k;
    }
  }

  // A bud: a fine shoot the rules grow, with its measured first internode and width and the
  // length of all it carries.
  void bud(std::uint32_t c) {
    const Internode& in = rules_.internodes[c];
    turn_to(in.direction);
    const double w = std::min(2 * in.radius, width_);
    const double budget = std::max(s_.carried[c], in.chord);
    out_ += "A(" + grammar_number(std::max(in.chord, 1e-4)) + ", " + grammar_number(w) + ", " +
            grammar_number(budget) + ", 1)";
    max_bud_budget_ = std::max(max_bud_budget_, budget);
    ++buds_;
  }

  void branch(std::uint32_t c) {
    const TurtleFrame frame = frame_;
    const double width = width_;
    const std::string width_text = width_text_;
    out_ += "[";
    opening_ = true;
    if (s_.in_scaffold[c]) {
      axis(c);
    } else {
      bud(c);
    }
    out_ += "]";
    frame_ = frame;
    width_ = width;
    width_text_ = width_text;
  }

  void axis(std::uint32_t first) {
    for (std::uint32_t i = first; i != kNone; i = s_.continuation[i]) {
      internode(i);
      const NodeRule& r = rules_.rules[i];
      for (const ChildRule* c = rules_.begin(r); c != rules_.end(r); ++c)
        if (c->internode != s_.continuation[i]) branch(c->internode);
    }
  }

  const Skeleton& sk_;
  const BranchRules& rules_;
  const Scaffold& s_;
  double height_;
  Vec3 tropism_;
  double e_;
  double branch_angle_;  // the param's value as written
  TurtleFrame frame_;
  bool opening_ = false;  // the next turn is a branch's first
  double width_ = 0;
  std::string width_text_;
  std::string out_;
  std::size_t segments_ = 0, buds_ = 0;
  double max_bud_budget_ = 0;
};

// The height of the chosen tree: vertical extent of its internodes' nodes; a flat tree is
// measured by its horizontal extent instead, so that the scale of the drawing is never zero.
double tree_scale(const Skeleton& sk, const BranchRules& rules, std::uint32_t tree_id,
                  double& height) {
  double zlo = 1e300, zhi = -1e300, xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
  for (const Internode& in : rules.internodes) {
    if (in.tree != tree_id) continue;
    for (std::uint32_t k = in.end; k != kNoParent; k = sk.nodes[k].parent) {
      const Vec3& p = sk.nodes[k].position;
      zlo = std::min(zlo, p.z), zhi = std::max(zhi, p.z);
      xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
      ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
      if (k == in.start) break;
    }
  }
  height = zhi - zlo;
  return std::max({height, xhi - xlo, yhi - ylo});
}

std::string param(const std::string& name, double value, const std::string& what) {
  return "param " + name + " = " + grammar_number(value) + ";  // " + what + "\n";
}

// The grammar around the axiom: header, params, settings and the productions of the shoots.
std::string grammar_text(const ScaffoldGrammarOptions& options, ScaffoldGrammar& out,
                         const std::string& axiom, double e) {
  {
    std::string t;
    t += "// Inferred by `ramus infer --method skeleton` from " +
         (options.source_name.empty() ? std::string("a skeleton") : options.source_name) + ": " +
         std::to_string(out.internodes) + " internodes.\n";
    t += "// The axiom is the tree's scaffold as measured: its trunk and " +
         std::to_string(out.scaffold_axes - 1) + " limbs carrying at least " +
         grammar_number(100 * options.scaffold.min_share) + " % of its length each (" +
         std::to_string(out.scaffold_segments) +
         " segments). Each A(l, w, b, s) on it is a shoot: its first internode l long and w wide, "
         "b the length of all it carries (its budget), s the side it turns to first; the "
         "productions grow the shoots from the "
         "params below.\n";
    const SpeciesParams& q = out.params;
    const struct {
      const char* name;
      double value;
      const char* what;
    } params[] = {
        {"branch_angle", q.branch_angle,
         "mean angle of a lateral shoot to its parent (degrees); every branch of the axiom turns "
         "by a multiple of it"},
        {"branch_angle_sd", q.branch_angle_sd, "its spread (degrees)"},
        {"kink_angle", q.kink_angle,
         "mean angle between successive internodes of a shoot (degrees)"},
        {"kink_angle_sd", q.kink_angle_sd, "its spread (degrees)"},
        {"lateral_side", q.lateral_side,
         "where around its parent a lateral turns: degrees from straight up (90: to the side, "
         "180: down)"},
        {"lateral_side_sd", q.lateral_side_sd, "its spread (degrees)"},
        {"kink_side", q.kink_side,
         "the same for a shoot's next internode, to the other side (degrees)"},
        {"kink_side_sd", q.kink_side_sd, "its spread (degrees)"},
        {"internode_length", q.internode_length, "mean length of a shoot's internodes (m)"},
        {"internode_length_sd", q.internode_length_sd, "its spread (m)"},
        {"continuation_width", q.continuation_width, "next internode's width / this one's"},
        {"lateral_width", q.lateral_width, "a lateral's width / its parent's"},
        {"lateral_share", q.lateral_share,
         "share of what a shoot has left that one of its laterals takes (by length)"},
    };
    for (const auto& p : params) t += param(p.name, p.value, p.what);
    // The first alternative of the shoot production takes what the others leave (below): its
    // share is not a param.
    const bool has_none = grammar_number(out.params.p_one + out.params.p_two) != "1";
    const bool has_one = grammar_number(out.params.p_one) != "0";
    const bool has_two = grammar_number(out.params.p_two) != "0";
    if (has_one && has_none)
      t += param("p_one_lateral", out.params.p_one,
                 "share of a shoot's internodes followed by one lateral");
    if (has_two && (has_none || has_one))
      t += param("p_two_laterals", out.params.p_two, "share followed by two laterals");
    t += param("min_internode", out.params.min_internode, "shortest drawn internode (m)");
    t += param("max_internode", out.params.max_internode, "longest drawn internode (m)");
    if (e != 0)
      t += param("gravitropism", e, "elasticity: how shoots bend towards the ground (ABOP 2.2)");
    t += "lsystem " + options.system_name + " {\n";
    t += "  derive " + std::to_string(out.steps) + ";\n";
    t += "  seed " + std::to_string(options.seed) + ";\n";
    if (e != 0) {
      t += std::string("  tropism 0, 0, ") + (out.params.elasticity < 0 ? "1" : "-1") + ";\n";
      t += "  elasticity gravitropism;\n";
    }
    t += "  axiom " + axiom + ";\n";
    if (out.buds == 0) {
      t += "  // Every limb is drawn as measured: no shoot is left to grow.\n}\n";
      out.productions = 0;
      return t;
    }
    const std::string length =
        "clamp(normal(internode_length, internode_length_sd), min_internode, max_internode)";
    // Each internode levels the turtle ($, ABOP 1.5: its left horizontal), so that "up" and
    // "to the side" mean what they say; s = +1 or -1 is the side, which alternates.
    auto next = [&](const std::string& budget) {
      return "/(180 - s * normal(kink_side, kink_side_sd))&(normal(kink_angle, kink_angle_sd))A(" +
             length + ", w * continuation_width, " + budget + ", -s)";
    };
    auto lateral = [&](const std::string& side) {
      return "[/(180 + " + side +
             " * normal(lateral_side, lateral_side_sd))&(normal(branch_angle, branch_angle_sd))A(" +
             length + ", w * lateral_width, (b - l) * lateral_share, 1)]";
    };
    // None, one or two laterals with their measured shares. A share that rounds to 0 is left
    // out (a probability must lie in (0, 1]); the first alternative takes what the others leave,
    // so the probabilities still sum to 1 when -D changes one of them.
    struct Alternative {
      std::string param;  // empty: 1 - the others
      std::string body;
    };
    std::vector<Alternative> alternatives;
    if (has_none) alternatives.push_back({"", "!(w)F(l)$" + next("b - l")});
    if (has_one)
      alternatives.push_back(
          {"p_one_lateral", "!(w)F(l)$" + lateral("s") + next("(b - l) * (1 - lateral_share)")});
    if (has_two)
      alternatives.push_back({"p_two_laterals", "!(w)F(l)$" + lateral("s") + lateral("-s") +
                                                    next("(b - l) * (1 - 2 * lateral_share)")});
    t += "  // A shoot with more than one and a half internodes of its budget left: an internode, "
         "no, one or two laterals that take their share of what is left, and the shoot goes on "
         "with the rest.\n";
    t += "  A(l, w, b, s) : b > 1.5 * l ->";
    for (std::size_t k = 0; k < alternatives.size(); ++k) {
      std::string prob = alternatives[k].param;
      if (alternatives.size() > 1 && k == 0) {
        prob = "1";
        for (std::size_t j = 1; j < alternatives.size(); ++j) prob += " - " + alternatives[j].param;
      }
      if (alternatives.size() == 1) prob.clear();
      t += std::string(k == 0 ? " " : "\n      | ") + (prob.empty() ? "" : "(" + prob + ") ") +
           alternatives[k].body;
    }
    t += ";\n";
    t += "  // The last internode of a shoot: the rest of its budget.\n";
    t += "  A(l, w, b, s) -> !(w)F(b);\n";
    t += "  // A shoot the derivation left unfinished: the rest of its budget, straight.\n";
    t += "  interpret A(l, w, b, s) -> !(w)F(b);\n";
    t += "}\n";
    out.productions = 3;
    return t;
  }
}

}  // namespace

ScaffoldGrammar infer_scaffold_grammar(const Skeleton& skeleton,
                                       const ScaffoldGrammarOptions& options) {
  const BranchRules rules = extract_branch_rules(skeleton);
  if (rules.internodes.empty())
    throw InferError("the skeleton has no segment (a single node or none): nothing to infer");
  ScaffoldGrammar out;
  const Scaffold scaffold = select_scaffold(rules, options.scaffold);
  const std::uint32_t tree_id = rules.internodes[rules.tree_first[scaffold.tree]].tree;
  const double scale = tree_scale(skeleton, rules, tree_id, out.height);
  if (!(scale > 0)) throw InferError("the tree has no extent: all its nodes are at one point");
  for (const Internode& in : rules.internodes) out.internodes += in.tree == tree_id ? 1 : 0;

  // Gravitropism (ABOP 2.2) as the clustered model fits it: one bend per drawn internode; the
  // shoots' angles are then measured from the bent heading. A fit on few pairs, or one that
  // explains almost none of the variance, is not written.
  constexpr std::size_t kMinTropismPairs = 10;
  constexpr double kMinTropismR2 = 0.02;
  BranchRules bent = rules;
  if (options.tropism) {
    out.tropism = fit_elasticity(rules, 1);
    if (out.tropism.pairs < kMinTropismPairs || out.tropism.r2 < kMinTropismR2 ||
        std::abs(out.tropism.elasticity) < 1e-4) {
      out.tropism.elasticity = 0;
    } else {
      measure_from_bent_heading(bent, out.tropism.elasticity, 1);
    }
  }
  out.params = fit_species_params(bent, scaffold, scale);
  SpeciesParams& p = out.params;
  p.elasticity = out.tropism.elasticity;
  const double e = std::stod(grammar_number(std::abs(p.elasticity)));
  const Vec3 tropism{0, 0, p.elasticity < 0 ? 1.0 : -1.0};

  AxiomWriter writer(skeleton, rules, scaffold, scale, tropism, e,
                     std::stod(grammar_number(p.branch_angle)));
  const std::string axiom = writer.write();
  out.scaffold_axes = scaffold.axes;
  out.scaffold_segments = writer.segments();
  out.buds = writer.buds();
  // Steps enough for every shoot to end by its productions: along any chain of a shoot and its
  // laterals the budget falls by at least the shortest internode a step (a lateral takes a share
  // below 1 of what its parent has left). The interpretation rule finishes what a cap leaves.
  out.steps =
      out.buds == 0
          ? 0
          : std::clamp(
                int(std::ceil(writer.max_bud_budget() / std::max(p.min_internode, 1e-9))) + 1,
                p.depth + 1, kMaxSteps);

  const std::string t = grammar_text(options, out, axiom, e);
  out.text = canonical_layout(t);
  return out;
}

}  // namespace ramus::skeleton_infer
