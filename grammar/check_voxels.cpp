// voxels blocks: the settings levels, classes, axiom and seed, and the rules `c -> [c0 .. c7] xN`
// (one voxel to its eight children in Morton order; every class in [0, classes)).
#include <cmath>
#include <cstdio>

#include "grammar/detail/check_context.h"

namespace ramus::detail {
namespace {

bool is_count(double v) { return v >= 0 && v == std::floor(v); }

class VoxelsChecker {
 public:
  VoxelsChecker(CheckContext& cx, std::uint32_t file, const ast::Voxels& vx)
      : cx_(cx), file_(file), vx_(vx) {
    env_.file = file;
    env_.constant_context = "a voxels block";
  }

  void run() {
    // Settings first: `classes` bounds the rules wherever it is written.
    for (const ast::VoxelsItem& item : vx_.items) {
      if (const auto* s = std::get_if<ast::VoxelSetting>(&item)) setting(*s);
    }
    for (const ast::VoxelsItem& item : vx_.items) {
      if (const auto* r = std::get_if<ast::VoxelRule>(&item)) rule(*r);
    }
  }

 private:
  void setting(const ast::VoxelSetting& s) {
    const std::string& key = s.key.name;
    if (key != "levels" && key != "classes" && key != "axiom" && key != "seed") {
      cx_.error(DiagCode::UnknownVoxelSetting, s.key.span, "unknown setting '" + key + "'");
      cx_.note("the settings of a voxels block are levels, classes, axiom and seed");
      return;
    }
    auto [it, fresh] = settings_.emplace(key, s.key.span);
    if (!fresh) {
      cx_.error(DiagCode::DuplicateDefinition, s.key.span, "setting '" + key + "' is given twice");
      cx_.note(it->second, "first given here");
    }
    if (key == "axiom") {
      if (!s.path || !s.values.empty()) {
        cx_.error(DiagCode::InvalidVoxelSetting, s.span, "'axiom' takes one file name");
        cx_.note("e.g. axiom \"oak.axiom.rvx\";");
      }
      return;
    }
    if (s.path || s.values.size() != 1) {
      cx_.error(DiagCode::InvalidVoxelSetting, s.span, "'" + key + "' takes one number");
      return;
    }
    cx_.check_number(s.values[0], env_, "'" + key + "'");
    std::optional<double> v = cx_.fold(s.values[0], file_);
    if (!v) return;
    bool positive = key != "seed";
    if (!is_count(*v) || (positive && *v < 1)) {
      cx_.error(DiagCode::InvalidVoxelSetting, s.values[0].span,
                "'" + key + "' must be a " + (positive ? "positive" : "non-negative") + " integer");
      return;
    }
    if (key == "classes") classes_ = *v;
  }

  void class_value(const ast::Expr& e) {
    cx_.check_number(e, env_, "a voxel class");
    std::optional<double> v = cx_.fold(e, file_);
    if (!v) return;
    if (!is_count(*v) || (classes_ && *v >= *classes_)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.10g", *v);
      std::string range = classes_ ? "[0, " + std::to_string(std::int64_t(*classes_)) + ")"
                                   : std::string("the non-negative integers");
      cx_.error(DiagCode::VoxelClassOutOfRange, e.span,
                std::string("class ") + buf + " is not in " + range);
      if (classes_) cx_.note(settings_.at("classes"), "the number of classes is set here");
    }
  }

  void rule(const ast::VoxelRule& r) {
    if (r.children.size() != 8) {
      cx_.error(DiagCode::VoxelChildCount, r.span,
                "a voxel rule needs 8 children, found " + std::to_string(r.children.size()));
      cx_.note("one voxel splits into its eight octants, in Morton order (x fastest)");
    }
    class_value(r.parent);
    for (const ast::Expr& c : r.children) class_value(c);
    if (r.weight) {
      cx_.check_number(*r.weight, env_, "a rule weight");
      std::optional<double> w = cx_.fold(*r.weight, file_);
      if (w && !(*w > 0)) {
        cx_.error(DiagCode::InvalidVoxelWeight, r.weight->span,
                  "the weight of a voxel rule must be positive");
      }
    }
  }

  CheckContext& cx_;
  std::uint32_t file_;
  const ast::Voxels& vx_;
  ExprEnv env_;
  std::optional<double> classes_;
  std::unordered_map<std::string, SourceSpan> settings_;
};

}  // namespace

void check_voxels(CheckContext& cx, std::uint32_t file, const ast::Voxels& vx) {
  VoxelsChecker(cx, file, vx).run();
}

}  // namespace ramus::detail
