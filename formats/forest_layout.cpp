#include "formats/forest_layout.h"


#include "core/input_file.h"
#include "formats/detail/json.h"
#include "formats/detail/json_reader.h"
#include "formats/detail/reader_util.h"

namespace ramus {

using formats_detail::JsonValue;

std::vector<LayoutTree> forest_layout_from_json(std::string_view text, const std::string& name) {
  const JsonValue root = formats_detail::parse_json(text, name);
  formats_detail::JsonReader r(name);
  r.expect_kind(root, JsonValue::Kind::kObject, "(top level)");
  r.known_keys(root, "(top level)", {"trees"});
  const JsonValue& trees = r.member(root, "trees", "(top level)");
  r.expect_kind(trees, JsonValue::Kind::kArray, "trees");
  if (trees.items.empty()) r.error(trees, "trees", "the layout has no tree");
  std::vector<LayoutTree> out;
  for (std::size_t i = 0; i < trees.items.size(); ++i) {
    const JsonValue& v = trees.items[i];
    const std::string path = "trees[" + std::to_string(i) + "]";
    r.expect_kind(v, JsonValue::Kind::kObject, path);
    r.known_keys(v, path, {"x", "y", "grammar", "seed"});
    LayoutTree t;
    t.x = r.number(r.member(v, "x", path), path + ".x");
    t.y = r.number(r.member(v, "y", path), path + ".y");
    if (const JsonValue* g = v.find("grammar")) {
      t.grammar = std::size_t(r.integer(*g, path + ".grammar", 0, 1'000'000));
    }
    if (const JsonValue* s = v.find("seed")) {
      t.seed = std::uint64_t(r.integer(*s, path + ".seed", 0, std::int64_t(1) << 53));
    }
    out.push_back(t);
  }
  return out;
}

std::vector<LayoutTree> read_forest_layout(const std::string& path) {
  std::string text, error;
  if (!read_input_file(path, text, error)) formats_detail::fail(path, error);
  return forest_layout_from_json(text, path);
}

}  // namespace ramus
