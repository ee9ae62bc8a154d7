#include "compiler/turtle.h"

#include <cmath>
#include <numeric>

#include "compiler/turtle_frame.h"

namespace ramus {

namespace {

// The turtle's frame (turtle_frame.h) and the rest of its state, saved by `[`.
struct State : TurtleFrame {
  Vec3 pos;
  double width = 1;
  double colour = 0;
  std::uint32_t node = kNoParent;  // the node the next segment starts from
  std::uint16_t order = 0;
};

class Walker {
 public:
  Walker(const ir::Grammar& g, const ModuleString& s, const std::vector<std::uint32_t>* origins)
      : g_(g), s_(s), origins_(origins) {
    const auto& st = g.settings;
    tropism_ = Vec3{st.tropism[0], st.tropism[1], st.tropism[2]};
    t_.width = st.width;
  }

  Skeleton run() {
    for (std::size_t i = 0; i < s_.size(); ++i) {
      const ir::SymbolId sym = s_.symbol(i);
      if (sym >= ir::kTurtleSymbolCount) continue;
      i = step(ir::TurtleOp(sym), i);
    }
    return std::move(sk_);
  }

 private:
  double arg(std::size_t i, double fallback) const {
    return s_.nparams(i) > 0 ? s_.param(i, 0) : fallback;
  }
  std::uint32_t source(std::size_t i) const { return origins_ ? (*origins_)[i] : std::uint32_t(i); }
  std::uint32_t add_node(std::size_t i, std::uint32_t parent) {
    SkeletonNode n;
    n.position = t_.pos;
    n.heading = t_.h;
    n.left = t_.l;
    n.up = t_.u;
    n.radius = t_.width / 2;
    n.parent = parent;
    n.order = t_.order;
    n.source_module = source(i);
    return sk_.add(n);
  }
  void forward(std::size_t i) {
    if (t_.node == kNoParent) t_.node = add_node(i, kNoParent);
    t_.pos += t_.h * arg(i, g_.settings.step);
    t_.node = add_node(i, t_.node);
    t_.bend(tropism_, g_.settings.elasticity);
  }
  void organ(std::size_t i) {
    OrganAnchor a;
    a.node = t_.node;
    a.position = t_.pos;
    a.heading = t_.h;
    a.left = t_.l;
    a.up = t_.u;
    a.size = arg(i, 1.0);
    if (s_.nparams(i) > 1) {
      const double k = s_.param(i, 1);
      if (k >= 0 && k < 256) a.kind = std::uint32_t(k);
      while (sk_.organ_kinds.size() <= a.kind) {
        sk_.organ_kinds.push_back("organ" + std::to_string(sk_.organ_kinds.size()));
      }
    }
    sk_.organs.push_back(a);
  }
  // The `]` closing the current branch, or the end of the string (cut, `%`).
  std::size_t branch_end(std::size_t i) const {
    int depth = 0;
    for (std::size_t j = i + 1; j < s_.size(); ++j) {
      if (s_.symbol(j) == ir::kPush) ++depth;
      if (s_.symbol(j) == ir::kPop && depth-- == 0) return j - 1;
    }
    return s_.size();
  }
  std::size_t step(ir::TurtleOp op, std::size_t i) {
    const double angle = g_.settings.angle;
    switch (op) {
      case ir::TurtleOp::Forward:
        forward(i);
        break;
      case ir::TurtleOp::Move:
        t_.pos += t_.h * arg(i, g_.settings.step);
        t_.node = kNoParent;  // the next F starts a disconnected segment
        break;
      case ir::TurtleOp::Left:
        rotate_pair(t_.h, t_.l, arg(i, angle));
        break;
      case ir::TurtleOp::Right:
        rotate_pair(t_.h, t_.l, -arg(i, angle));
        break;
      case ir::TurtleOp::PitchDown:
        rotate_pair(t_.h, t_.u, -arg(i, angle));
        break;
      case ir::TurtleOp::PitchUp:
        rotate_pair(t_.h, t_.u, arg(i, angle));
        break;
      case ir::TurtleOp::RollLeft:
        rotate_pair(t_.l, t_.u, arg(i, angle));
        break;
      case ir::TurtleOp::RollRight:
        rotate_pair(t_.l, t_.u, -arg(i, angle));
        break;
      case ir::TurtleOp::TurnAround:
        rotate_pair(t_.h, t_.l, 180);
        break;
      case ir::TurtleOp::Level:
        t_.level();
        break;
      case ir::TurtleOp::Push:
        stack_.push_back(t_);
        ++t_.order;
        break;
      case ir::TurtleOp::Pop:
        if (!stack_.empty()) {
          t_ = stack_.back();
          stack_.pop_back();
        }
        break;
      case ir::TurtleOp::Width:
        t_.width = s_.nparams(i) > 0 ? s_.param(i, 0) : t_.width * g_.settings.width_decay;
        break;
      case ir::TurtleOp::Colour:
        t_.colour = s_.nparams(i) > 0 ? s_.param(i, 0) : t_.colour + 1;
        break;
      case ir::TurtleOp::Organ:
        organ(i);
        break;
      case ir::TurtleOp::Cut:
        return branch_end(i);
      case ir::TurtleOp::None:
        break;
    }
    if (op >= ir::TurtleOp::Left && op <= ir::TurtleOp::TurnAround) t_.orthonormalize();
    return i;
  }

  const ir::Grammar& g_;
  const ModuleString& s_;
  const std::vector<std::uint32_t>* origins_;
  Vec3 tropism_;
  State t_;
  std::vector<State> stack_;
  Skeleton sk_;
};

}  // namespace

Skeleton run_turtle(const ir::Grammar& g, const ModuleString& s,
                    const std::vector<std::uint32_t>* origins) {
  return Walker(g, s, origins).run();
}

Skeleton interpret(const ir::Grammar& g, const ModuleString& s, const TurtleOptions& options) {
  if (g.interpret.empty()) return run_turtle(g, s, nullptr);
  std::vector<std::uint32_t> origins(s.size());
  std::iota(origins.begin(), origins.end(), 0u);
  ModuleString cur, next;
  const ModuleString* in = &s;
  PassInfo info;
  info.seed = options.seed;
  info.max_modules = options.max_modules;
  info.max_bytes = options.max_bytes;
  info.threads = options.threads;
  for (int level = 1; level <= std::min(g.settings.max_depth, 255); ++level) {
    info.key = std::uint64_t(options.steps) * 512 + 256 + level;
    info.where = "interpretation level " + std::to_string(level);
    if (!apply_pass(g, ir::Kind::Interpret, *in, next, info, &origins)) break;
    std::swap(cur, next);
    in = &cur;
  }
  return run_turtle(g, *in, &origins);
}

}  // namespace ramus
