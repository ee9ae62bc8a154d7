#include "compiler/turtle.h"

#include <cmath>
#include <numeric>

#include "compiler/bracket_balance.h"
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
      const ir::TurtleOp op = g_.symbols[s_.symbol(i)].turtle;
      if (op == ir::TurtleOp::None) continue;
      i = step(op, i);
    }
    if (!polygons_.empty()) {
      fail(polygons_.back().opened, "`{` opens a polygon that no `}` closes");
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
  // An error of the string itself (a `]` or `}` with nothing to close), named by the module of
  // the derived string it came from and the productions that could have written it.
  [[noreturn]] void fail(std::size_t i, const std::string& what) const {
    std::string msg = "interpretation: " + what + " (module " + std::to_string(i);
    if (origins_) msg += ", from module " + std::to_string(source(i)) + " of the derived string";
    msg += ")" + unbalanced_productions(g_, s_.symbol(i));
    throw DeriveError(msg);
  }
  // ABOP 5.2 (developmental surface models): `{` starts a polygon on a stack of open polygons,
  // which `[` and `]` do not save or restore, so that a polygon may collect vertices from several
  // branches (the cordate leaf's `[+A{.].C.}`) and polygons may nest (lily of the valley).
  void record_vertex() {
    if (!polygons_.empty()) polygons_.back().vertices.push_back(t_.pos);
  }
  void close_polygon(std::size_t i) {
    if (polygons_.empty()) fail(i, "`}` closes no polygon");
    OpenPolygon p = std::move(polygons_.back());
    polygons_.pop_back();
    // Consecutive repeats (a `.` after an `f` that recorded the same point) and a last vertex
    // equal to the first add no area.
    std::vector<Vec3> v;
    for (const Vec3& x : p.vertices) {
      if (v.empty() || length(x - v.back()) > 1e-12) v.push_back(x);
    }
    while (v.size() > 1 && length(v.back() - v.front()) <= 1e-12) v.pop_back();
    if (v.size() < 3) return;  // a point or a line has no surface
    OrganAnchor a;
    a.node = p.node;
    a.position = v.front();
    a.heading = t_.h;
    a.left = t_.l;
    a.up = t_.u;
    a.size = 1;
    a.vertices = std::move(v);
    sk_.organs.push_back(std::move(a));
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
        record_vertex();  // inside a polygon F and f trace its boundary (ABOP fig. 5.3)
        break;
      case ir::TurtleOp::Move:
        t_.pos += t_.h * arg(i, g_.settings.step);
        t_.node = kNoParent;  // the next F starts a disconnected segment
        record_vertex();
        break;
      case ir::TurtleOp::MoveNoVertex:  // G: a segment like F that records no vertex
        forward(i);
        break;
      case ir::TurtleOp::PolygonBegin:
        polygons_.push_back(OpenPolygon{{}, i, t_.node});
        break;
      case ir::TurtleOp::Vertex:
        if (polygons_.empty()) fail(i, "`.` records a vertex outside any polygon");
        record_vertex();
        break;
      case ir::TurtleOp::PolygonEnd:
        close_polygon(i);
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
        if (stack_.empty()) fail(i, "`]` closes no branch");
        t_ = stack_.back();
        stack_.pop_back();
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
  struct OpenPolygon {
    std::vector<Vec3> vertices;
    std::size_t opened = 0;          // the `{`
    std::uint32_t node = kNoParent;  // the node the turtle was at
  };
  std::vector<OpenPolygon> polygons_;
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
    if (may_unbalance_branches(g, ir::Kind::Interpret)) {
      check_branches(g, *in, ir::Kind::Interpret, info.where);
    }
  }
  return run_turtle(g, *in, &origins);
}

}  // namespace ramus
