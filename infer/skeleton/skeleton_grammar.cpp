#include "infer/skeleton/skeleton_grammar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "infer/skeleton/fidelity.h"
#include "infer/skeleton/grown_trees.h"
#include "infer/skeleton/production_text.h"

namespace ramus::skeleton_infer {

namespace {

// Widths and lengths are logged as log(max(x, kTiny)), as the grammar writes them.
constexpr double kTiny = 1e-9;

// What the grammar needs to know about one order group besides its clusters.
struct OrderStats {
  std::size_t internodes = 0, tips = 0;
  std::uint32_t max_axis_index = 0;  // the last internode of every axis is a tip
  std::vector<TipSample> hazard;     // depth, log width, log length and tip of every internode
  std::vector<double> tip_lengths;   // of the order's tips
};

// The lower quartile of `v` (not empty).
double lower_quartile(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 4), v.end());
  return v[v.size() / 4];
}

// The median of `v` (not empty).
double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::size_t count_alternatives(const std::vector<RuleGroup>& groups) {
  std::size_t n = 1;  // the fallback production
  for (const RuleGroup& g : groups) n += g.clusters.size();
  return n;
}

// Meets the rule budget: fewer clusters in the group with the most, then drop the rarest
// branching groups (their weight goes to the rest of their order).
void fit_budget(const BranchRules& rules, std::vector<RuleGroup>& groups,
                const GrammarOptions& options) {
  const auto budget = std::size_t(std::max(options.max_rules, 2));
  while (count_alternatives(groups) > budget) {
    auto most = std::max_element(groups.begin(), groups.end(), [](const auto& x, const auto& y) {
      return x.clusters.size() < y.clusters.size();
    });
    if (most->clusters.size() > 1) {
      recluster_group(rules, *most, int(most->clusters.size()) - 1, options.cluster);
      continue;
    }
    auto rarest = groups.end();
    for (auto it = groups.begin(); it != groups.end(); ++it) {
      if (it->arity == 0) continue;
      if (rarest == groups.end() || it->count < rarest->count) rarest = it;
    }
    if (rarest == groups.end()) break;
    groups.erase(rarest);
  }
}

// With axis budgets the calibration's shift s (more tips as it grows) moves every log budget by
// -s / kBudgetShiftScale: at most a factor e^3 either way.
constexpr double kBudgetShiftScale = 10;

}  // namespace

InferredGrammar infer_grammar(const Skeleton& skeleton, const GrammarOptions& options) {
  const BranchRules rules = extract_branch_rules(skeleton);
  using AxisEnds = GrammarOptions::AxisEnds;
  if (!options.axis_budget || options.axis_ends != AxisEnds::automatic ||
      options.calibration_seeds <= 0 || rules.internodes.empty())
    return infer_grammar(rules, options);
  // Model selection by simulation: the two ways of ending axes suit different trees (the own
  // tips fit a tree whose axes end in long shoots, the shared lengths fit sparse scans whose
  // few tips say little), and what decides is how close the grown trees come to the input.
  GrammarOptions o = options;
  o.axis_ends = AxisEnds::own;
  InferredGrammar own = infer_grammar(rules, o);
  o.axis_ends = AxisEnds::shared;
  InferredGrammar shared = infer_grammar(rules, o);
  Distributions input;
  measure(skeleton, input);
  const double d_own = grown_distance(own.text, input, options.calibration_seeds);
  const double d_shared = grown_distance(shared.text, input, options.calibration_seeds);
  InferredGrammar& best = d_shared < d_own ? shared : own;
  best.distance_own = d_own;
  best.distance_shared = d_shared;
  return std::move(best);
}

InferredGrammar infer_grammar(const BranchRules& extracted, const GrammarOptions& given) {
  GrammarOptions options = given;
  // AxisEnds::own: a tip takes what is left of its budget, and the last branch nodes of the
  // axes are a production of their own (see carries_guard and branching_guard).
  const bool own = options.axis_budget && options.axis_ends != GrammarOptions::AxisEnds::shared;
  options.cluster.branching_child_lengths = own;
  options.cluster.split_last = own;
  if (extracted.internodes.empty()) {
    throw InferError("the skeleton has no segment (a single node or none): nothing to infer");
  }
  InferredGrammar out;
  out.axis_ends = own ? GrammarOptions::AxisEnds::own : GrammarOptions::AxisEnds::shared;
  // Tortuosity of the internodes, length-weighted: the kink angle of `segment`.
  double chords = 0, paths = 0;
  for (const Internode& in : extracted.internodes) chords += in.chord, paths += in.length;
  const double tortuosity = paths > 0 ? std::clamp(chords / paths, 0.0, 1.0) : 1.0;
  const double kink = std::acos(tortuosity) * 57.29577951308232;  // degrees
  out.tortuosity = tortuosity;
  // Tropism (ABOP 2.2, tropism_fit.h): the turtle bends after every F, so per internode once
  // when it is drawn straight and twice when kinked; the rules' angles are measured from the
  // bent heading. A fit on fewer than kMinTropismPairs pairs, or one that explains almost none
  // of the variance, is not written.
  constexpr std::size_t kMinTropismPairs = 10;
  constexpr double kMinTropismR2 = 0.02;
  const int bends = kink < kMinKink ? 1 : 2;
  std::optional<BranchRules> bent;
  if (options.tropism) {
    out.tropism = fit_elasticity(extracted, bends, &out.tropism_by_order);
    if (out.tropism.pairs < kMinTropismPairs || out.tropism.r2 < kMinTropismR2 ||
        std::abs(out.tropism.elasticity) < 1e-4) {
      out.tropism.elasticity = 0;
    } else {
      bent = extracted;
      measure_from_bent_heading(*bent, out.tropism.elasticity, bends);
    }
  }
  const BranchRules& rules = bent ? *bent : extracted;
  out.internodes = rules.internodes.size();
  for (const NodeRule& r : rules.rules) out.branch_nodes += r.child_count >= 2 ? 1 : 0;

  const int max_order = options.cluster.max_order;
  std::map<std::uint16_t, OrderStats> stats;
  std::uint16_t deepest_order = 0;
  std::uint32_t deepest = 0;
  for (const Internode& in : rules.internodes) {
    OrderStats& s = stats[std::uint16_t(std::min<int>(in.order, max_order))];
    ++s.internodes;
    const bool tip = rules.rules[&in - rules.internodes.data()].child_count == 0;
    s.tips += tip ? 1 : 0;
    if (tip) s.tip_lengths.push_back(in.length);
    s.hazard.push_back({double(in.depth), std::log(std::max(2 * in.radius, kTiny)), tip ? 1.0 : 0.0,
                        std::log(std::max(in.length, kTiny))});
    s.max_axis_index = std::max(s.max_axis_index, in.axis_index);
    deepest_order = std::max(deepest_order, in.order);
    deepest = std::max(deepest, in.depth);
  }
  LengthRange lengths{rules.internodes[0].length, rules.internodes[0].length};
  for (const Internode& in : rules.internodes) {
    lengths.min = std::min(lengths.min, in.length);
    lengths.max = std::max(lengths.max, in.length);
  }
  out.derive = int(deepest);  // the axiom draws depth 0; step k expands depth k
  out.groups = cluster_rules(rules, options.cluster);
  fit_budget(rules, out.groups, options);

  // The axiom: the first internode of the tree with the most length (when the root forks, the
  // one carrying the most length above it: a reconstructed root often has short side branches
  // beside the trunk), turned from the turtle's initial frame like the real trunk.
  std::size_t tree = 0;
  for (std::size_t t = 1; t < rules.tree_length.size(); ++t) {
    if (rules.tree_length[t] > rules.tree_length[tree]) tree = t;
  }
  std::vector<double> carried(rules.internodes.size(), 0.0);  // length of internode + subtree
  for (std::size_t i = rules.internodes.size(); i-- > 0;) {
    carried[i] += rules.internodes[i].length;
    std::uint32_t p = rules.internodes[i].parent;
    if (p != kNone && p < i) {
      carried[p] += carried[i];
    } else {
      // Parents are extracted before their children; walk up if one is not.
      for (; p != kNone; p = rules.internodes[p].parent) carried[p] += rules.internodes[i].length;
    }
  }
  std::uint32_t trunk = rules.tree_first[tree];
  for (std::uint32_t i = trunk;
       i < rules.internodes.size() &&
       rules.internodes[i].tree == rules.internodes[rules.tree_first[tree]].tree;
       ++i) {
    const Internode& in = rules.internodes[i];
    if (in.parent == kNone && carried[i] > carried[trunk]) trunk = i;
  }
  const Internode& t0 = rules.internodes[trunk];
  double theta0 = 0, phi0 = 0;
  angle_and_azimuth(Vec3{0, 0, 1}, t0.direction, theta0, phi0);

  // Termination per order group: the logistic hazard of depth, and of log width and log length
  // too when that model is better by the Bayesian information criterion (a tree grown with a
  // width threshold has its tips where w falls, one whose axes end in a long shoot where l
  // jumps; on a scan the radii are often too noisy to tell).
  std::map<std::uint16_t, TipHazard> hazards;
  for (const auto& [order, st] : stats) {
    // Depth always; width and length each when the BIC (2 ln L - p ln n) prefers them.
    const double ln_n = std::log(double(std::max<std::size_t>(st.hazard.size(), 1)));
    double best_score = -std::numeric_limits<double>::infinity();
    for (int model = 0; model < 4; ++model) {
      std::vector<TipSample> samples = st.hazard;
      for (TipSample& t : samples) {
        if ((model & 1) == 0) t.log_width = 0;
        if ((model & 2) == 0) t.log_length = 0;
      }
      const TipHazard h = fit_tip_hazard(samples);
      const double params = 2 + (model & 1) + ((model & 2) >> 1);
      const double score = 2 * h.log_likelihood - params * ln_n;
      if (score > best_score) best_score = score, hazards[order] = h;
    }
  }

  // Axis budgets: `remaining[i]` is the length of internode i and of all that continue its axis.
  // A lateral's sample pairs its axis length with the internode carrying it; groups by the
  // lateral's order, a group with fewer than kMinBudgetAxes axes uses the fit over all laterals.
  constexpr std::size_t kMinBudgetAxes = 8;
  const std::size_t n_in = rules.internodes.size();
  std::vector<double> remaining(n_in, 0.0);
  std::map<std::uint16_t, LateralBudget> budgets;
  std::map<const RuleCluster*, LateralBudget> cluster_budgets;
  // The typical tip of an order (carries_guard): the median of the order's tips (the one tip
  // of a tree's trunk), of all tips for an order without any. The fallback keeps every tip
  // within the observed lengths.
  std::map<std::uint16_t, double> typical_tip;
  std::map<std::uint16_t, double> next_ratio;  // median ratio of the branching continuations
  LengthRange tip_range{lengths.max, lengths.min};
  LateralBudget pooled_budget;
  if (options.axis_budget) {
    std::vector<std::uint32_t> next(n_in, kNone);
    for (std::uint32_t i = 0; i < n_in; ++i) {
      const Internode& in = rules.internodes[i];
      if (in.continuation && in.parent != kNone) next[in.parent] = i;
    }
    std::vector<std::uint32_t> chain;
    for (std::uint32_t i = 0; i < n_in; ++i) {
      const Internode& in = rules.internodes[i];
      if (in.continuation && in.parent != kNone) continue;  // not an axis start
      chain.clear();
      for (std::uint32_t j = i; j != kNone && chain.size() <= n_in; j = next[j]) chain.push_back(j);
      double sum = 0;
      for (auto j = chain.rbegin(); j != chain.rend(); ++j)
        remaining[*j] = (sum += rules.internodes[*j].length);
    }
    std::map<std::uint16_t, std::vector<BudgetSample>> samples;
    std::vector<BudgetSample> all;
    for (std::uint32_t i = 0; i < n_in; ++i) {
      const Internode& in = rules.internodes[i];
      if (in.continuation || in.parent == kNone) continue;
      const Internode& p = rules.internodes[in.parent];
      const BudgetSample b{std::log(std::max(p.length, kTiny)),
                           std::log(std::max(2 * p.radius, kTiny)), double(p.depth),
                           std::log(std::max(remaining[i], kTiny)),
                           own && rules.rules[i].child_count == 0};
      samples[std::uint16_t(std::min<int>(in.order, max_order))].push_back(b);
      all.push_back(b);
    }
    pooled_budget = fit_lateral_budget(all);
    std::vector<double> all_tips;
    for (const auto& [order, st] : stats)
      all_tips.insert(all_tips.end(), st.tip_lengths.begin(), st.tip_lengths.end());
    for (double t : all_tips)
      tip_range.min = std::min(tip_range.min, t), tip_range.max = std::max(tip_range.max, t);
    std::map<std::uint16_t, std::vector<double>> ratios;
    for (const Internode& in : rules.internodes) {
      if (!in.continuation || in.parent == kNone) continue;
      if (own && rules.rules[&in - rules.internodes.data()].child_count == 0) continue;
      const double lp = rules.internodes[in.parent].length;
      if (lp > kTiny && in.length > kTiny)
        ratios[std::uint16_t(std::min<int>(in.order, max_order))].push_back(in.length / lp);
    }
    for (auto& [order, v] : ratios) next_ratio[order] = own ? median(v) : lower_quartile(v);
    for (const auto& [order, st] : stats) {
      if (!st.tip_lengths.empty()) {
        typical_tip[order] = median(st.tip_lengths);
      } else if (!all_tips.empty()) {
        typical_tip[order] = median(all_tips);
      }
    }
    for (const auto& [order, v] : samples)
      budgets[order] = v.size() >= kMinBudgetAxes ? fit_lateral_budget(v) : pooled_budget;
    // Per cluster: the laterals of its rules, when there are enough of them.
    for (const RuleGroup& g : out.groups) {
      for (const RuleCluster& c : g.clusters) {
        std::vector<BudgetSample> v;
        for (std::uint32_t m : c.members) {
          const NodeRule& rule = rules.rules[m];
          const Internode& p = rules.internodes[m];
          for (const ChildRule* ch = rules.begin(rule); ch != rules.end(rule); ++ch) {
            const Internode& in = rules.internodes[ch->internode];
            if (in.continuation) continue;
            v.push_back({std::log(std::max(p.length, kTiny)),
                         std::log(std::max(2 * p.radius, kTiny)), double(p.depth),
                         std::log(std::max(remaining[ch->internode], kTiny)),
                         own && rules.rules[ch->internode].child_count == 0});
          }
        }
        if (v.size() >= kMinBudgetAxes) cluster_budgets[&c] = fit_lateral_budget(v);
      }
    }
  }
  auto lateral_budget = [&](const RuleCluster& c, std::uint16_t parent_order, double shift) {
    if (!options.axis_budget) return std::string();
    // The calibration moves only the budgets of the finest laterals (the deepest order group):
    // they add length but little reach, while the reach of the coarser axes is the input's.
    if (std::min<int>(parent_order + 1, max_order) < std::min<int>(deepest_order, max_order))
      shift = 0;
    if (const auto own = cluster_budgets.find(&c); own != cluster_budgets.end())
      return budget_draw(own->second, shift);
    const auto it = budgets.find(std::uint16_t(std::min<int>(parent_order + 1, max_order)));
    return budget_draw(it != budgets.end() ? it->second : pooled_budget, shift);
  };

  // The grammar with every tip hazard's intercept, or every log axis budget, moved by `shift`
  // (see calibration below).
  auto write = [&](double shift) {
    std::string text;
    text += "// Inferred by `ramus infer --method skeleton`";
    if (!options.source_name.empty()) text += " from " + options.source_name;
    text += ": " + std::to_string(out.internodes) + " internodes, " +
            std::to_string(out.branch_nodes) + " branch nodes.\n";
    text +=
        "// N(l, w, o, i, d" + std::string(options.axis_budget ? ", r" : "") +
        "): an internode of length l and width w, branch order o, position i on its axis, depth "
        "d" +
        std::string(options.axis_budget ? ", r the length left to its axis (itself included)"
                                        : "") +
        ".\n";
    text += "lsystem " + options.system_name + " {\n";
    text += "  derive " + std::to_string(out.derive) + ";\n";
    text += "  seed " + std::to_string(options.cluster.seed) + ";\n";
    if (out.tropism.elasticity != 0) {
      // ABOP 2.2: e > 0 bends towards the ground, e < 0 away from it (written as a tropism
      // towards the sky with |e|: the same turn, since |H x T| is the same).
      const double e = out.tropism.elasticity;
      std::string fits;
      for (std::size_t o = 0; o < out.tropism_by_order.size(); ++o) {
        if (out.tropism_by_order[o].pairs < 3) continue;
        fits += (fits.empty() ? "" : ", ") + std::string("order ") + std::to_string(o) + " " +
                grammar_number(out.tropism_by_order[o].elasticity);
      }
      text += "  // gravitropism fitted on " + std::to_string(out.tropism.pairs) +
              " continuations (R^2 " + grammar_number(out.tropism.r2) + "; per order: " + fits +
              ")\n";
      text += std::string("  tropism 0, 0, ") + (e > 0 ? "-1" : "1") + ";\n";
      text += "  elasticity " + grammar_number(std::abs(e)) + ";\n";
    }
    // The first internode and its children as observed (absolute lengths and widths): the trunk's
    // base is often far longer than any later internode, and no ratio describes that jump.
    std::string axiom = "/(" + grammar_number(phi0) + ")&(" + grammar_number(theta0) + ")!(" +
                        grammar_number(2 * t0.radius) + ")" +
                        segment(kink, grammar_number(t0.length), false);
    const NodeRule& root_rule = rules.rules[trunk];
    std::string continuation;
    for (const ChildRule* c = rules.begin(root_rule); c != rules.end(root_rule); ++c) {
      const Internode& ci = rules.internodes[c->internode];
      const std::string call =
          "$/(" + grammar_number(c->phi) + ")&(" + grammar_number(c->theta) + ")N(" +
          grammar_number(ci.length) + ", " + grammar_number(2 * ci.radius) + ", " +
          std::to_string(ci.order) + ", " + std::to_string(ci.axis_index) + ", 1" +
          (options.axis_budget ? ", " + grammar_number(remaining[c->internode]) : std::string()) +
          ")";
      if (ci.continuation) {
        continuation = call;
      } else {
        axiom += "[" + call + "]";
      }
    }
    axiom += continuation;
    text += "  axiom " + axiom + ";\n";

    out.productions = 1;
    out.alternatives = 1;
    for (const auto& entry : stats) {
      // Plain names, not a structured binding: the production lambda below captures `order`,
      // which clang before 16 refuses for a binding.
      const auto& order = entry.first;
      const auto& st = entry.second;
      std::vector<const RuleGroup*> mine;
      for (const RuleGroup& g : out.groups) {
        if (g.order == order) mine.push_back(&g);
      }
      const bool branches =
          std::any_of(mine.begin(), mine.end(), [](const RuleGroup* g) { return g->arity > 0; });
      if (!branches || st.max_axis_index == 0) continue;  // the fallback draws its tips
      std::string guard;
      if (order < max_order) {
        guard = "o == " + std::to_string(order);
      } else {
        guard = "o >= " + std::to_string(order) + " && o <= " + std::to_string(deepest_order);
      }
      guard += " && i < " + std::to_string(st.max_axis_index);
      text += "  // order " + std::to_string(order) + (order == max_order ? " and above" : "") +
              ": " + std::to_string(st.internodes) + " internodes, longest axis " +
              std::to_string(st.max_axis_index + 1) + "\n";
      const std::string params = options.axis_budget ? "l, w, o, i, d, r" : "l, w, o, i, d";
      // Without axis budgets: tips by the logistic hazard of depth, log width and log length;
      // branching alternatives share the rest by their observed frequencies among the branch
      // nodes of the order. With them, the budget ends the axes, and the last branch nodes of
      // the axes (RuleGroup::last) have a production of their own.
      const RuleGroup* tip_group = nullptr;
      std::vector<const RuleGroup*> going, ending;
      for (const RuleGroup* g : mine) {
        if (g->arity == 0) {
          tip_group = g;
        } else {
          (g->last ? ending : going).push_back(g);
        }
      }
      if (options.axis_budget) tip_group = nullptr;
      const TipHazard& h = hazards.at(order);
      std::string z = grammar_number(h.alpha + shift) + " + " + grammar_number(h.beta) + " * d";
      if (h.gamma != 0) z += " + " + grammar_number(h.gamma) + " * log(max(w, 1e-9))";
      if (h.delta != 0) z += " + " + grammar_number(h.delta) + " * log(max(l, 1e-9))";
      auto production = [&](const std::vector<const RuleGroup*>& groups,
                            const std::string& budget_guard, bool ends) {
        text += "  N(" + params + ") : " + guard + budget_guard + " ->";
        std::vector<std::size_t> counts;
        for (const RuleGroup* g : groups)
          for (const RuleCluster& c : g->clusters) counts.push_back(c.count);
        const std::vector<std::string> probs = probabilities(counts);
        bool first = true;
        if (tip_group != nullptr) {
          text += " (1 / (1 + exp(clamp(-(" + z + "), -30, 30)))) !(w)" + segment(kink, "l");
          first = false;
          ++out.alternatives;
        }
        std::size_t k = 0;
        for (const RuleGroup* g : groups) {
          for (const RuleCluster& c : g->clusters) {
            text += first ? " " : " | ";
            const std::string& q = probs[k++];
            if (tip_group != nullptr) {
              text += "(" + q + " / (1 + exp(clamp(" + z + ", -30, 30)))) ";
            } else {
              text += "(" + q + ") ";
            }
            first = false;
            text +=
                alternative(c, lengths, kink, lateral_budget(c, order, -shift / kBudgetShiftScale),
                            ends ? &tip_range : nullptr);
            ++out.alternatives;
          }
        }
        text += ";\n";
        ++out.productions;
      };
      const double tip = typical_tip.count(order) != 0 ? typical_tip.at(order) : 0.0;
      const double next = next_ratio.count(order) != 0 ? next_ratio.at(order) : 1.0;
      if (!going.empty()) {
        std::string budget_guard;
        if (options.axis_budget && !own) {
          budget_guard = continue_guard(next);
        } else if (options.axis_budget) {
          budget_guard = ending.empty() ? carries_guard(tip) : branching_guard(next, tip);
        }
        production(going, budget_guard, false);
      }
      if (!ending.empty()) production(ending, carries_guard(tip), true);
    }
    text += options.axis_budget ? "  // tips: axes whose budget is spent or past their longest "
                                  "observed length, orders past the deepest\n"
                                : "  // tips: axes past their longest observed length, orders "
                                  "past the deepest\n";
    const std::string tip = own && tip_range.min <= tip_range.max
                                ? "clamp(r, " + grammar_number(tip_range.min) + ", " +
                                      grammar_number(tip_range.max) + ")"
                                : std::string("l");
    text += std::string("  N(") + (options.axis_budget ? "l, w, o, i, d, r" : "l, w, o, i, d") +
            ") -> !(w)" + segment(kink, tip) + ";\n";
    text += "}\n";
    return text;
  };

  std::string text = write(0);
  if (options.calibration_seeds > 0) {
    const double target = rules.tree_length[tree];
    const double shift = calibrate_tip_shift(write, target, options.calibration_seeds);
    text = write(shift);
    out.tip_shift = options.axis_budget ? -shift / kBudgetShiftScale : shift;
  }

  out.text = canonical_layout(text);
  return out;
}

}  // namespace ramus::skeleton_infer
