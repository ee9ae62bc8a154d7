#include "infer/wavelet/voxel_grammar.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace ramus::wavelet {
namespace {

// subband, parent, eight children: one observation of a rule.
using RuleKey = std::array<std::uint8_t, 10>;

std::vector<int> chains(Decomposition d) {
  if (d == Decomposition::standard) return {kDiagonalSubband};
  return {1, 2, 3, 4, 5, 6, 7};
}

// Appends the observations of one (level -> level + 1) pair of one subband; all-zero
// observations (the empty space and the solid interior) are only counted.
void observe(const VoxelGrammar& g, const WaveletPyramid& p, const std::vector<VoxelGrid>& a,
             int level, int subband, std::vector<RuleKey>& keys, std::uint64_t& all_zero) {
  CoefficientBlock parent = p.subband(level, subband), child = p.subband(level + 1, subband);
  const CoefficientQuantizer& q = g.quantizer;
  const std::uint8_t zero = std::uint8_t(q.zero_class());
  const std::size_t side = parent.size[0];
  for (std::size_t k = 0; k < side; ++k) {
    for (std::size_t j = 0; j < side; ++j) {
      for (std::size_t i = 0; i < side; ++i) {
        RuleKey key;
        key[0] = std::uint8_t(subband);
        key[1] = q.quantize(grammar_value(g, p, a, level, parent, i, j, k));
        bool nonzero = key[1] != zero;
        for (int c = 0; c < 8; ++c) {
          key[2 + c] = q.quantize(grammar_value(g, p, a, level + 1, child, 2 * i + (c & 1),
                                                2 * j + (c >> 1 & 1), 2 * k + (c >> 2)));
          nonzero = nonzero || key[2 + c] != zero;
        }
        if (nonzero) {
          keys.push_back(key);
        } else {
          all_zero += 1;
        }
      }
    }
  }
}

VoxelRule rule_from(const RuleKey& key, std::uint64_t count) {
  VoxelRule r;
  r.subband = key[0];
  r.parent = key[1];
  std::copy(key.begin() + 2, key.end(), r.children.begin());
  r.count = std::uint32_t(std::min<std::uint64_t>(count, 0xffffffffu));
  return r;
}

}  // namespace

double grammar_value(const VoxelGrammar& grammar, const WaveletPyramid& pyramid,
                     const std::vector<VoxelGrid>& approximations, int level,
                     const CoefficientBlock& block, std::size_t i, std::size_t j, std::size_t k) {
  double c = pyramid.at(block, i, j, k);
  if (!grammar.relative) return c;
  double mean = approximations[std::size_t(level)].at(i, j, k);
  return mean > 0 ? c / mean : 0.0;
}

VoxelGrammar learn_voxel_grammar(const WaveletPyramid& pyramid,
                                 const VoxelGrammarOptions& options) {
  return learn_voxel_grammar(pyramid, approximation_levels(haar_inverse(pyramid)), options);
}

VoxelGrammar learn_voxel_grammar(const WaveletPyramid& pyramid,
                                 const std::vector<VoxelGrid>& approximations,
                                 const VoxelGrammarOptions& options) {
  if (options.first_level < 0) throw std::invalid_argument("first_level must be >= 0");
  if (approximations.size() != std::size_t(pyramid.levels()) + 1) {
    throw std::invalid_argument("learn_voxel_grammar: approximations do not match the pyramid");
  }
  VoxelGrammar g;
  g.decomposition = pyramid.decomposition;
  g.levels = pyramid.levels();
  g.relative = options.relative;
  // The range: the largest magnitude of the values to quantize, over the levels that are used.
  double range = 0;
  for (int s : chains(pyramid.decomposition)) {
    for (int level = options.first_level; level < pyramid.levels(); ++level) {
      CoefficientBlock b = pyramid.subband(level, s);
      for (std::size_t k = 0; k < b.size[2]; ++k) {
        for (std::size_t j = 0; j < b.size[1]; ++j) {
          for (std::size_t i = 0; i < b.size[0]; ++i) {
            range = std::max(
                range, std::abs(grammar_value(g, pyramid, approximations, level, b, i, j, k)));
          }
        }
      }
    }
  }
  g.quantizer = make_quantizer(range, options.classes);
  for (int s : chains(pyramid.decomposition)) {
    std::vector<RuleKey> keys;
    std::uint64_t all_zero = 0;
    for (int level = options.first_level; level + 1 < pyramid.levels(); ++level) {
      observe(g, pyramid, approximations, level, s, keys, all_zero);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
      std::size_t j = i;
      while (j < keys.size() && keys[j] == keys[i]) ++j;
      g.rules.push_back(rule_from(keys[i], j - i));
      i = j;
    }
    if (all_zero > 0) {
      RuleKey zero;
      zero.fill(std::uint8_t(g.quantizer.zero_class()));
      zero[0] = std::uint8_t(s);
      g.rules.push_back(rule_from(zero, all_zero));
    }
  }
  g.build_index();
  return g;
}

void VoxelGrammar::build_index() {
  std::sort(rules.begin(), rules.end(), [](const VoxelRule& a, const VoxelRule& b) {
    return std::tuple(a.subband, a.parent, b.count, a.children) <
           std::tuple(b.subband, b.parent, a.count, b.children);
  });
  const int k = quantizer.classes;
  index_.assign(std::size_t(8 * k), {0, 0});
  for (std::size_t i = 0; i < rules.size();) {
    std::size_t j = i;
    while (j < rules.size() && rules[j].subband == rules[i].subband &&
           rules[j].parent == rules[i].parent) {
      ++j;
    }
    if (rules[i].subband < 8 && rules[i].parent < k) {
      index_[rules[i].subband * k + rules[i].parent] = {std::uint32_t(i), std::uint32_t(j)};
    }
    i = j;
  }
  // Unobserved parents borrow the rules of the nearest observed class of the same subband.
  for (int s = 1; s < 8; ++s) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> row(index_.begin() + s * k,
                                                             index_.begin() + (s + 1) * k);
    for (int p = 0; p < k; ++p) {
      if (row[p].first != row[p].second) continue;
      for (int d = 1; d < k; ++d) {
        if (p - d >= 0 && row[p - d].first != row[p - d].second) {
          index_[s * k + p] = row[p - d];
          break;
        }
        if (p + d < k && row[p + d].first != row[p + d].second) {
          index_[s * k + p] = row[p + d];
          break;
        }
      }
    }
  }
}

std::pair<std::uint32_t, std::uint32_t> VoxelGrammar::rules_for(int subband, int parent) const {
  const int k = quantizer.classes;
  if (subband < 1 || subband > 7 || parent < 0 || parent >= k || index_.empty()) return {0, 0};
  return index_[subband * k + parent];
}

std::uint64_t VoxelGrammar::observations() const {
  std::uint64_t total = 0;
  for (const VoxelRule& r : rules) total += r.count;
  return total;
}

const VoxelRule* pick_rule(const VoxelGrammar& grammar, int subband, int parent, Rng& rng) {
  auto [first, last] = grammar.rules_for(subband, parent);
  if (first == last) return nullptr;
  std::uint64_t total = 0;
  for (std::uint32_t i = first; i < last; ++i) total += grammar.rules[i].count;
  std::uint64_t draw = rng.below(total);
  for (std::uint32_t i = first; i < last; ++i) {
    if (draw < grammar.rules[i].count) return &grammar.rules[i];
    draw -= grammar.rules[i].count;
  }
  return &grammar.rules[last - 1];
}

std::vector<double> synthesize_subband(const VoxelGrammar& grammar, const WaveletPyramid& pyramid,
                                       const std::vector<VoxelGrid>& approximations, int level,
                                       int subband, std::uint64_t seed) {
  CoefficientBlock parent = pyramid.subband(level, subband);
  const std::size_t side = parent.size[0], out_side = 2 * side;
  std::vector<double> out(out_side * out_side * out_side, 0.0);
  const CoefficientQuantizer& q = grammar.quantizer;
  for (std::size_t k = 0; k < side; ++k) {
    for (std::size_t j = 0; j < side; ++j) {
      for (std::size_t i = 0; i < side; ++i) {
        std::uint64_t id = i + side * (j + side * k);
        Rng rng = Rng::stream(seed, std::uint64_t(subband), id);
        double v = grammar_value(grammar, pyramid, approximations, level, parent, i, j, k);
        const VoxelRule* r = pick_rule(grammar, subband, q.quantize(v), rng);
        if (r == nullptr) continue;
        for (int c = 0; c < 8; ++c) {
          std::size_t x = 2 * i + (c & 1), y = 2 * j + (c >> 1 & 1), z = 2 * k + (c >> 2);
          out[x + out_side * (y + out_side * z)] = q.value(r->children[c]);
        }
      }
    }
  }
  return out;
}

}  // namespace ramus::wavelet
