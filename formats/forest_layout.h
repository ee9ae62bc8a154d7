// A hand-made plot for `ramus scan --forest --layout FILE.json`: where each tree stands and,
// optionally, which of the command's grammars grows it and from which seed. Documented in
// docs/scale.md:
//   {"trees": [{"x": 3.5, "y": 12, "grammar": 1, "seed": 7}, {"x": 10, "y": 4}]}
// x, y are world metres of the tree's base on the ground plane (z = 0); "grammar" is a 0-based
// index into the grammars given on the command line; missing values are chosen as for a random
// plot (tree i: grammar i mod count, its own seed from the plot's).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/point_cloud_io.h"  // FormatError

namespace ramus {

struct LayoutTree {
  double x = 0, y = 0;
  std::optional<std::size_t> grammar;
  std::optional<std::uint64_t> seed;
};

// Strict: FormatError with line, column and JSON location for unknown keys and wrong types.
std::vector<LayoutTree> forest_layout_from_json(std::string_view text, const std::string& name);
std::vector<LayoutTree> read_forest_layout(const std::string& path);

}  // namespace ramus
