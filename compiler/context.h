// Context matching with the branch-aware semantics of cpfg, lpfg and L-Py (Prusinkiewicz &
// Lindenmayer, ABOP ch. 1.7; the lpfg manual, "context"):
//  - a left context skips `[` and whole sibling branches `[...]` to its left;
//  - a right context skips lateral branches `[...]` and fails at the `]` closing the branch;
//  - modules of the ignored set (or outside the considered set) are invisible to both.
// Matching is linear in the string length: the tables below give, for every position, the
// nearest visible neighbour on each side in O(1), built once per pass in O(n).
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/ir.h"
#include "compiler/module_string.h"

namespace ramus {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct ContextTables {
  std::vector<std::uint32_t> partner;  // for [ and ]: the matching bracket, kNone if unmatched
  std::vector<std::uint32_t> left;     // nearest left-context candidate of i, or kNone
  std::vector<std::uint32_t> right;    // nearest right-context candidate of i (may be a `]`)

  // Only the tables asked for are filled (a grammar with left contexts only needs no `right`).
  void build(const ModuleString& s, const std::vector<std::uint8_t>& ignored, bool need_left = true,
             bool need_right = true);
  std::size_t bytes() const { return partner.size() * 12; }
};

// Binds the parameters of production `p` for the module at `i` into `slots` and checks its
// predecessor and contexts (not its guard). `ctx` may be null when `p` has no context.
bool match_production(const ir::Grammar& g, const ir::Production& p, const ModuleString& s,
                      const ContextTables* ctx, std::size_t i, double* slots);

}  // namespace ramus
