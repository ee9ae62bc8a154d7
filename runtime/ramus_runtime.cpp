// The C API of ramus_runtime.h over decode_rmb -> derive -> interpret. Every entry point
// catches everything: exceptions never cross the C boundary.
#include "runtime/ramus_runtime.h"

#include <stdexcept>
#include <string>
#include <string_view>

#include "compiler/derive.h"
#include "compiler/module_string.h"
#include "compiler/turtle.h"
#include "formats/rmb/rmb_codec.h"
#include "runtime/runtime_handles.h"

namespace {

using ramus::runtime::guarded;

// Mirrors grow_file (compiler/grow.cpp): the seed replaces the grammar's, as lowering with a
// seed override does, so the axiom's arguments and every pass draw from the same streams.
ramus::Skeleton grow(const ramus::ir::Grammar& source, int steps, std::uint64_t seed) {
  if (steps < -1) throw ramus::DeriveError("the number of steps must not be negative");
  ramus::ir::Grammar g = source;
  g.settings.seed = seed;
  ramus::DeriveOptions d;
  if (steps >= 0) d.steps = steps;
  ramus::TurtleOptions t;
  t.seed = seed;
  t.steps = steps >= 0 ? steps : g.settings.derive;
  return ramus::interpret(g, ramus::derive(g, d), t);
}

}  // namespace

extern "C" {

ramus_grammar* ramus_load(const void* bytes, size_t n, char* err, size_t errlen) {
  return guarded<ramus_grammar*>(err, errlen, nullptr, [&] {
    if (!bytes && n > 0) throw std::invalid_argument("ramus_load: null bytes");
    const std::string_view image(static_cast<const char*>(bytes), bytes ? n : 0);
    return new ramus_grammar{ramus::decode_rmb(image)};
  });
}

void ramus_free_grammar(ramus_grammar* g) { delete g; }

int ramus_grammar_steps(const ramus_grammar* g) { return g ? g->g.settings.derive : 0; }

uint64_t ramus_grammar_seed(const ramus_grammar* g) { return g ? g->g.settings.seed : 0; }

ramus_skeleton* ramus_grow(const ramus_grammar* g, int steps, uint64_t seed, char* err,
                           size_t errlen) {
  return guarded<ramus_skeleton*>(err, errlen, nullptr, [&] {
    if (!g) throw std::invalid_argument("ramus_grow: null grammar");
    return new ramus_skeleton{grow(g->g, steps, seed)};
  });
}

void ramus_free_skeleton(ramus_skeleton* s) { delete s; }

size_t ramus_release_memory(void) { return ramus::release_kept_buffers(); }

size_t ramus_node_count(const ramus_skeleton* s) { return s ? s->s.nodes.size() : 0; }

int ramus_node_position(const ramus_skeleton* s, size_t i, double xyz[3]) {
  if (!s || !xyz || i >= s->s.nodes.size()) return -1;
  const ramus::Vec3& p = s->s.nodes[i].position;
  xyz[0] = p.x, xyz[1] = p.y, xyz[2] = p.z;
  return 0;
}

int ramus_node_radius(const ramus_skeleton* s, size_t i, double* radius) {
  if (!s || !radius || i >= s->s.nodes.size()) return -1;
  *radius = s->s.nodes[i].radius;
  return 0;
}

int64_t ramus_node_parent(const ramus_skeleton* s, size_t i) {
  if (!s || i >= s->s.nodes.size()) return -1;
  const std::uint32_t p = s->s.nodes[i].parent;
  return p == ramus::kNoParent ? -1 : int64_t(p);
}

size_t ramus_organ_count(const ramus_skeleton* s) { return s ? s->s.organs.size() : 0; }

int ramus_organ_position(const ramus_skeleton* s, size_t i, double xyz[3]) {
  if (!s || !xyz || i >= s->s.organs.size()) return -1;
  const ramus::Vec3& p = s->s.organs[i].position;
  xyz[0] = p.x, xyz[1] = p.y, xyz[2] = p.z;
  return 0;
}

int ramus_organ_size(const ramus_skeleton* s, size_t i, double* size) {
  if (!s || !size || i >= s->s.organs.size()) return -1;
  *size = s->s.organs[i].size;
  return 0;
}

}  // extern "C"
