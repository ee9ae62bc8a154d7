#include "formats/rmb/rmb_voxels.h"

#include <cmath>

#include "core/number_text.h"
#include "grammar/const_eval.h"

namespace ramus {

namespace {

double fold(const ast::Expr& e, const ir::Grammar& g, const std::string& block, const char* what) {
  const std::optional<double> v = fold_constant(e, [&g](std::string_view name) {
    for (const ir::Constant& c : g.constants) {
      if (c.name == name) return std::optional<double>(c.value);
    }
    return std::optional<double>();
  });
  if (!v) throw RmbError(0, "cannot encode voxels " + block + ": " + what + " is not constant");
  return *v;
}

std::uint64_t integer(const ast::Expr& e, const ir::Grammar& g, const std::string& block,
                      const char* what, double lo, double hi) {
  const double v = fold(e, g, block, what);
  if (!(v >= lo && v <= hi) || v != std::floor(v)) {
    throw RmbError(0, "cannot encode voxels " + block + ": " + what + " " + shortest_text(v) +
                          " is not an integer in " + shortest_text(lo) + ".." + shortest_text(hi));
  }
  return std::uint64_t(v);
}

// Every number of a voxels block is a non-negative integer: written in full, never as 4e+09.
ast::Expr number(std::uint64_t v) {
  return ast::Expr{ast::NumberLit{double(v), std::to_string(v)}, {}, false};
}

}  // namespace

std::vector<RmbVoxelTable> voxel_tables_of(const ast::File& file, const ir::Grammar& g) {
  std::vector<RmbVoxelTable> out;
  for (const ast::Decl& d : file.decls) {
    const auto* vx = std::get_if<ast::Voxels>(&d);
    if (!vx) continue;
    RmbVoxelTable t;
    t.name = vx->name.name;
    const std::string& b = t.name;
    for (const ast::VoxelsItem& item : vx->items) {
      const auto* s = std::get_if<ast::VoxelSetting>(&item);
      if (!s) continue;
      const std::string& key = s->key.name;
      if (key == "axiom" && s->path) {
        t.axiom = *s->path;
      } else if (s->values.size() == 1 && key == "levels") {
        t.levels = std::uint32_t(integer(s->values[0], g, b, "levels", 1, 64));
      } else if (s->values.size() == 1 && key == "classes") {
        t.classes = std::uint32_t(integer(s->values[0], g, b, "classes", 1, 256));
      } else if (s->values.size() == 1 && key == "seed") {
        t.seed = integer(s->values[0], g, b, "seed", 0, 9007199254740992.0);  // 2^53
      } else {
        throw RmbError(0, "cannot encode voxels " + b + ": the setting '" + key + "'");
      }
    }
    const double top = t.classes ? *t.classes - 1 : 255;
    for (const ast::VoxelsItem& item : vx->items) {
      const auto* r = std::get_if<ast::VoxelRule>(&item);
      if (!r) continue;
      if (r->children.size() != 8) {
        throw RmbError(0, "cannot encode voxels " + b + ": a rule without 8 children");
      }
      wavelet::VoxelRule rule;
      rule.parent = std::uint8_t(integer(r->parent, g, b, "class", 0, top));
      for (int c = 0; c < 8; ++c) {
        rule.children[c] = std::uint8_t(integer(r->children[c], g, b, "class", 0, top));
      }
      rule.count =
          r->weight ? std::uint32_t(integer(*r->weight, g, b, "weight", 1, 4294967295.0)) : 0;
      t.rules.push_back(rule);
    }
    out.push_back(std::move(t));
  }
  return out;
}

ast::Voxels voxels_to_ast(const RmbVoxelTable& t) {
  ast::Voxels v;
  v.name.name = t.name;
  auto setting = [&v](const char* key, std::optional<std::uint64_t> value,
                      std::optional<std::string> path) {
    ast::VoxelSetting s;
    s.key.name = key;
    if (value) s.values.push_back(number(*value));
    s.path = std::move(path);
    v.items.emplace_back(std::move(s));
  };
  if (t.levels) setting("levels", *t.levels, std::nullopt);
  if (t.classes) setting("classes", *t.classes, std::nullopt);
  if (t.seed) setting("seed", *t.seed, std::nullopt);
  if (t.axiom) setting("axiom", std::nullopt, *t.axiom);
  for (const wavelet::VoxelRule& r : t.rules) {
    ast::VoxelRule rule;
    rule.parent = number(r.parent);
    for (std::uint8_t c : r.children) rule.children.push_back(number(c));
    if (r.count > 0) rule.weight = number(r.count);
    v.items.emplace_back(std::move(rule));
  }
  return v;
}

}  // namespace ramus
