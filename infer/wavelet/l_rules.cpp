#include "infer/wavelet/l_rules.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace ramus::wavelet {
namespace {

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  // Array indices are below 2^kMaxLevels <= 2^20: 21 bits per axis.
  return std::uint64_t(x) | std::uint64_t(y) << 21 | std::uint64_t(z) << 42;
}

std::uint64_t box_volume(const SuccessorBox& b) {
  std::uint64_t v = 1;
  for (int k = 0; k < 3; ++k) v *= std::uint64_t(b.r2[k] - b.r1[k] + 1);
  return v;
}

}  // namespace

LRuleOffset parse_l_rule_offset(const std::string& word) {
  if (word == "exact") return LRuleOffset::exact;
  if (word == "scaled") return LRuleOffset::scaled;
  throw std::invalid_argument("unknown offset '" + word + "' (expected exact or scaled)");
}

const char* to_string(LRuleOffset offset) {
  return offset == LRuleOffset::exact ? "exact" : "scaled";
}

std::vector<DyadVector> dyad_vectors(const DyadTree& tree) {
  std::vector<DyadVector> out;
  for (std::uint32_t u = 0; u < tree.size(); ++u) {
    if (tree.parent[u] == kNoParent) continue;
    DyadVector v;
    v.from = tree.parent[u];
    v.to = u;
    v.start = tree.cells[v.from];
    v.end = tree.cells[u];
    out.push_back(v);
  }
  return out;
}

std::int64_t dyad_offset(int level) {  // Eq. 1
  return (std::int64_t(1) << (level + 1)) - (std::int64_t(1) << level);
}

SuccessorBox successor_box(const DyadVector& v, int level, LRuleOffset offset) {
  SuccessorBox b;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t lo = std::min(v.start[k], v.end[k]), hi = std::max(v.start[k], v.end[k]);
    if (offset == LRuleOffset::exact) {  // Eq. 2-3, extended to z
      b.r1[k] = lo + dyad_offset(level);
      b.r2[k] = hi + dyad_offset(level);
    } else {  // the same region of space one dyad finer (see l_rules.h)
      b.r1[k] = 2 * lo;
      b.r2[k] = 2 * hi + 1;
    }
  }
  return b;
}

std::vector<LRule> l_rules(int level, const std::vector<DyadVector>& coarse,
                           const std::vector<DyadVector>& fine, LRuleOffset offset) {
  // The fine vectors by the cells their ends lie in, so that a small box looks up its cells
  // instead of testing every fine vector; a box larger than the fine tree tests them all.
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> at;
  at.reserve(2 * fine.size());
  for (std::uint32_t i = 0; i < fine.size(); ++i) {
    const auto& s = fine[i].start;
    const auto& e = fine[i].end;
    at[cell_key(s[0], s[1], s[2])].push_back(i);
    if (e != s) at[cell_key(e[0], e[1], e[2])].push_back(i);
  }
  std::vector<LRule> rules;
  std::vector<std::uint32_t> found;
  for (std::uint32_t c = 0; c < coarse.size(); ++c) {
    const SuccessorBox box = successor_box(coarse[c], level, offset);
    found.clear();
    if (box_volume(box) > fine.size()) {
      for (std::uint32_t i = 0; i < fine.size(); ++i) {
        if (box.contains(fine[i].start) || box.contains(fine[i].end)) found.push_back(i);
      }
    } else {
      for (std::int64_t z = box.r1[2]; z <= box.r2[2]; ++z) {
        for (std::int64_t y = box.r1[1]; y <= box.r2[1]; ++y) {
          for (std::int64_t x = box.r1[0]; x <= box.r2[0]; ++x) {
            if (x < 0 || y < 0 || z < 0) continue;
            auto it = at.find(cell_key(x, y, z));
            if (it != at.end()) found.insert(found.end(), it->second.begin(), it->second.end());
          }
        }
      }
      std::sort(found.begin(), found.end());
      found.erase(std::unique(found.begin(), found.end()), found.end());
    }
    if (found.empty()) continue;
    rules.push_back(LRule{level, c, found});
  }
  return rules;
}

}  // namespace ramus::wavelet
