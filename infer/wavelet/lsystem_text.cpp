// The lsystem block from the coarse-to-fine trees (lsystem_text.h).
#include "infer/wavelet/lsystem_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <unordered_set>

#include "grammar/format.h"

namespace ramus::wavelet {
namespace {

// 5 significant digits: a hundredth of a degree, a ten-thousandth of a length ratio; far
// below a cell, and the file stays small.
std::string num(double v, int digits = 5) {
  if (!std::isfinite(v)) throw std::logic_error("non-finite number in an inferred grammar");
  if (v == 0) return "0";  // also turns -0 into 0
  char buf[40];
  // printf's %.*g, without its locale and format parsing (thousands of numbers per grammar).
  const auto end = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits).ptr;
  std::string s(buf, end);
  return s == "-0" ? "0" : s;
}

constexpr double kDegree = 180.0 / std::numbers::pi;

// One vector of a level tree: the segment from a node's parent to the node.
struct Vector {
  Vec3 heading{0, 0, 1};
  double azimuth = 0, elevation = 0;  // the turtle turns: roll about z, pitch down (degrees)
  double length = 0, width = 0;
};

Vector vector_of(const LevelTree& t, std::uint32_t u) {
  Vector v;
  const Vec3 d = t.nodes[u].position - t.nodes[t.nodes[u].parent].position;
  v.length = std::sqrt(dot(d, d));
  if (v.length > 0) v.heading = d / v.length;
  v.azimuth = std::atan2(v.heading.x, v.heading.y) * kDegree;
  v.elevation = std::acos(std::clamp(v.heading.z, -1.0, 1.0)) * kDegree;
  v.width = t.nodes[u].width;
  return v;
}

// A token of a bracketed successor string: a vector, or a bracket.
struct Token {
  std::uint32_t node = 0;
  int what = 0;          // 0: vector, 1: "[", 2: "]"
  bool lateral = false;  // the first vector of a bracket
};

// The subtree of `start` in tree t, restricted to nodes with `keep(node)`, depth first: the
// children other than the main one (most leaves, then smallest index) in brackets, the main one
// last and unbracketed. With `bracket_all`, every child of `start` is bracketed, the main one
// first: the turtle's first segment from a new root sets the root's radius, which must be the
// widest.
template <class Keep>
void subtree_tokens(const LevelTree& t, std::uint32_t start, bool bracket_all, Keep&& keep,
                    std::vector<Token>& out) {
  struct Item {
    std::uint32_t node;
    int what;  // 0: the vector into node, then its subtree; 1: "["; 2: "]"
    bool lateral;
  };
  std::vector<Item> stack;
  auto push_children = [&](std::uint32_t u, bool all) {
    std::vector<std::uint32_t> kids;
    for (std::uint32_t c : t.children[u]) {
      if (keep(c)) kids.push_back(c);
    }
    if (kids.empty()) return;
    auto main = std::max_element(kids.begin(), kids.end(), [&](std::uint32_t a, std::uint32_t b) {
      return t.nodes[a].leaves < t.nodes[b].leaves;
    });
    if (all) {
      std::rotate(kids.begin(), main, main + 1);
    } else {
      std::rotate(main, main + 1, kids.end());
    }
    for (std::size_t k = kids.size(); k-- > 0;) {
      const bool branch = all || k + 1 < kids.size();
      if (branch) stack.push_back({0, 2, false});
      stack.push_back({kids[k], 0, branch});
      if (branch) stack.push_back({0, 1, false});
    }
  };
  push_children(start, bracket_all);
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    out.push_back({it.node, it.what, it.lateral});
    if (it.what == 0) push_children(it.node, false);
  }
}

struct Successor {
  Vector v;
  int what = 0;
  bool lateral = false;
};

struct Production {
  int level = 0;  // of the predecessor
  Vector pred;
  double pred_cells = 0;
  Vec3 pred_end;
  std::vector<Successor> successors;
  std::size_t branches = 0;
};

std::string key_text(const Production& p) {
  return "@ (" + num(p.pred.heading.x, 4) + ", " + num(p.pred.heading.y, 4) + ", " +
         num(p.pred.heading.z, 4) + ", " + num(p.pred_cells, 4) + ")";
}

}  // namespace

LsystemText lsystem_text(const std::vector<LevelTree>& trees, const LsystemTextOptions& o) {
  LsystemText r;
  const int levels = int(trees.size());
  const int axiom = o.axiom_level;
  const double cell = trees.back().cell;

  // The productions, finest level pair first, so that the rules the default derivation uses win
  // the (rare) equal keys.
  std::vector<Production> productions;
  std::unordered_set<std::string> keys;
  for (int j = levels - 1; j >= 1; --j) {
    const LevelTree& coarse = trees[std::size_t(j - 1)];
    const LevelTree& fine = trees[std::size_t(j)];
    for (std::uint32_t u = 1; u < coarse.nodes.size(); ++u) {
      Production p;
      p.level = j - 1;
      p.pred = vector_of(coarse, u);
      if (!(p.pred.length > 0)) continue;
      ++r.rules;
      p.pred_cells = p.pred.length / coarse.cell;
      p.pred_end = coarse.nodes[u].position;
      if (!keys.insert(key_text(p)).second) continue;
      // The link into u's cells (a chain through the points between), then their tree, every
      // branch bracketed.
      const std::uint32_t e = fine.entry[u];
      std::vector<std::uint32_t> chain;
      for (std::uint32_t v = e; v != fine.entry[coarse.nodes[u].parent]; v = fine.nodes[v].parent) {
        chain.push_back(v);
      }
      // The chain is the predecessor refined: it keeps the predecessor's width, so widths
      // never grow along the regrown tree whichever rule a vector picks (III-G), and u's
      // branches are narrower by their Da Vinci share of the entry's width.
      for (std::size_t k = chain.size(); k-- > 0;) {
        Successor s{vector_of(fine, chain[k]), 0, false};
        s.v.width = p.pred.width;
        p.successors.push_back(s);
      }
      const double entry_width = fine.nodes[e].width;
      std::vector<Token> tokens;
      subtree_tokens(
          fine, e, true, [&](std::uint32_t c) { return fine.nodes[c].owner == u; }, tokens);
      for (const Token& t : tokens) {
        Successor s;
        s.what = t.what;
        s.lateral = t.lateral;
        if (t.what == 0) {
          s.v = vector_of(fine, t.node);
          s.v.width = p.pred.width * std::min(1.0, fine.nodes[t.node].width / entry_width);
        }
        if (t.what == 1) ++p.branches;
        p.successors.push_back(s);
      }
      productions.push_back(std::move(p));
    }
  }
  // The named quantities: means over the laterals of all productions.
  double tilt = 0, ratio = 0;
  std::size_t laterals = 0;
  for (const Production& p : productions) {
    for (const Successor& s : p.successors) {
      if (!s.lateral || !(p.pred.width > 0)) continue;
      tilt += s.v.elevation;
      ratio += s.v.width / p.pred.width;
      ++laterals;
    }
  }
  const bool named = laterals > 0 && tilt > 0 && ratio > 0;
  if (named) {
    tilt /= double(laterals);
    ratio /= double(laterals);
  }

  r.params =
      "// Measured quantities; `ramus derive -D name=value` overrides them.\n"
      "// Edge of one cell of the finest dyad (m): the axiom's lengths and widths are\n"
      "// multiples of it, so it scales the whole tree.\n"
      "param cell = " +
      num(cell) + ";\n";
  if (named) {
    r.params +=
        "// Mean angle of a lateral branch from the vertical (degrees): every lateral's\n"
        "// angle is a multiple of it.\n"
        "param branch_tilt = " +
        num(tilt) +
        ";\n"
        "// Mean width of a lateral branch / width of the vector it refines.\n"
        "param width_ratio = " +
        num(ratio) + ";\n";
  }

  std::string text;
  text += "lsystem " + o.name + " {\n";
  text += "  derive 1;\n";
  text += "  seed " + std::to_string(o.seed) + ";\n";
  text += "  // III-G: a vector takes the production whose key (heading, length in cells of its\n";
  text += "  // dyad) is nearest.\n";
  text += "  select nearest(sin(e) * sin(a), sin(e) * cos(a), cos(e), l / s);\n";

  // The axiom: tree `axiom` from the base (the turtle starts there, heading up).
  {
    const LevelTree& t = trees[std::size_t(axiom)];
    std::vector<Token> tokens;
    subtree_tokens(
        t, 0, true, [](std::uint32_t) { return true; }, tokens);
    const double s_cells = t.cell / cell;
    std::string axiom_text;
    for (const Token& k : tokens) {
      if (k.what == 1) {
        axiom_text += axiom_text.empty() ? "[" : " [";
        continue;
      }
      if (k.what == 2) {
        axiom_text += "]";
        continue;
      }
      const Vector v = vector_of(t, k.node);
      ++r.axiom_vectors;
      if (!axiom_text.empty() && axiom_text.back() != '[') axiom_text += ' ';
      axiom_text += "V(" + num(v.azimuth) + ", " + num(v.elevation) + ", " + num(v.length / cell) +
                    " * cell, " + num(s_cells) + " * cell, " + num(v.width / cell) + " * cell)";
    }
    text += "  // The axiom: the tree of dyad " + std::to_string(t.level) + " (" +
            std::to_string(r.axiom_vectors) + " vectors) from the trunk's foot.\n";
    // The turtle starts at the origin (the lowest point); the tree starts at the base, the
    // trunk's foot: a move there first (it draws nothing and makes no node).
    const Vec3 foot = t.nodes[0].position;
    const double away = std::sqrt(foot.x * foot.x + foot.y * foot.y);
    std::string move;
    if (away > 1e-6 * cell) {
      const std::string a = num(std::atan2(foot.x, foot.y) * kDegree);
      move = "/(" + a + ") &(90) f(" + num(away) + ") ^(90) \\(" + a + ") ";
    }
    // Branches leaving the base in brackets would each start a root of their own (the turtle's
    // state before the first segment has no node): a zero-length segment makes the root first.
    if (t.children[0].size() > 1) {
      double widest = 0;
      for (std::uint32_t c : t.children[0]) widest = std::max(widest, t.nodes[c].width);
      move += "!(" + num(widest / cell) + " * cell) F(0) ";
    }
    text += "  axiom " + move + axiom_text + ";\n";
  }
  text += "  // Each vector turns from the initial frame (heading up) to its heading: roll a\n";
  text += "  // about the vertical, pitch down e; it draws and turns back.\n";
  text += "  interpret V(a, e, l, s, w) -> !(w) /(a) &(e) F(l) ^(e) \\(a);\n";

  for (const Production& p : productions) {
    std::size_t count = 0;
    for (const Successor& s : p.successors) count += s.what == 0;
    const std::string comment =
        "  // Grows a " + num(p.pred.length, 3) + " m vector of dyad " + std::to_string(p.level) +
        " ending " + num(p.pred_end.z, 3) + " m up, " + num(p.pred.elevation, 3) +
        " deg from the vertical, into " + std::to_string(count) + " vectors of dyad " +
        std::to_string(p.level + 1) + " (" + std::to_string(p.branches) + " branches).\n";
    std::vector<std::string> modules;
    for (const Successor& s : p.successors) {
      if (s.what != 0) {
        modules.push_back(s.what == 1 ? "[" : "]");
        continue;
      }
      const double len = s.v.length / p.pred.length;
      const double wid = p.pred.width > 0 ? s.v.width / p.pred.width : 1.0;
      std::string elevation = num(s.v.elevation), width = wid == 1.0 ? "w" : "w * " + num(wid);
      if (s.lateral && named) {
        elevation = num(s.v.elevation / tilt) + " * branch_tilt";
        width = "w * " + num(wid / ratio) + " * width_ratio";
      }
      modules.push_back("V(" + num(s.v.azimuth) + ", " + elevation + ", l * " + num(len) +
                        ", s * 0.5, " + width + ")");
    }
    r.productions_text += comment;
    r.productions_text += wrap_modules("  V(a, e, l, s, w) " + key_text(p) + " ->", modules, ";");
    ++r.productions;
  }
  text += "}\n";
  r.lsystem = text;
  return r;
}

}  // namespace ramus::wavelet
