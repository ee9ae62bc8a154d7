// The mesher block of ramus_runtime.h: the skeleton's frames and orders, and the tree mesh of
// mesh/ (build_tree_lods, the code `ramus build` runs) with its arrays in the frame the caller
// asks for (mesh/vertex_arrays.h, the arrays the glTF writer writes). Every entry point catches
// everything: exceptions never cross the C boundary.
#include <array>
#include <memory>
#include <stdexcept>
#include <vector>

#include "mesh/tree_mesh.h"
#include "mesh/vertex_arrays.h"
#include "runtime/ramus_runtime.h"
#include "runtime/runtime_handles.h"

namespace {

using ramus::runtime::guarded;

// One part of one level: the arrays a renderer uploads. Positions, normals and tangents come in
// the requested frame; UVs, wind weights, skin nodes and indices do not depend on it.
struct PartArrays {
  ramus::mesh::VertexArrays frame;
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::array<float, 4>> wind;
  std::vector<std::uint32_t> skin_node;
  std::vector<std::uint32_t> indices;
};

constexpr int kParts = 3;  // RAMUS_PART_BARK, _LEAVES, _SURFACES

// Moves what does not depend on the frame out of the TreeMesh part (nothing is copied twice).
PartArrays part_arrays(ramus::mesh::MeshPart&& part, ramus::mesh::UpAxis up, bool tangents) {
  PartArrays a;
  a.frame = ramus::mesh::vertex_arrays(part, up, tangents);
  a.uvs = std::move(part.uvs);
  a.wind = std::move(part.wind);
  a.skin_node = std::move(part.skin_node);
  a.indices = std::move(part.indices);
  return a;
}

void copy3(const ramus::Vec3& v, double* out) {
  if (out) out[0] = v.x, out[1] = v.y, out[2] = v.z;
}

// The turtle frame of a node or an organ (either has heading, left and up).
template <typename T>
void copy_frame(const T& x, double* heading, double* left, double* up) {
  copy3(x.heading, heading);
  copy3(x.left, left);
  copy3(x.up, up);
}

}  // namespace

struct ramus_mesh {
  std::vector<std::array<PartArrays, kParts>> lods;
  ramus::Vec3 origin;
};

namespace {

const PartArrays* part_of(const ramus_mesh* m, int lod, int part) {
  if (!m || lod < 0 || std::size_t(lod) >= m->lods.size() || part < 0 || part >= kParts)
    return nullptr;
  return &m->lods[std::size_t(lod)][std::size_t(part)];
}

// The first element of a part's array, or NULL for an empty array or a part out of range.
template <typename T, typename Member>
auto data_of(const ramus_mesh* m, int lod, int part, Member member) -> const T* {
  const PartArrays* a = part_of(m, lod, part);
  if (!a) return nullptr;
  const auto& v = member(*a);
  return v.empty() ? nullptr : reinterpret_cast<const T*>(v.data());
}

// Mirrors `ramus build` (cli/cmd_build.cpp): the options map onto MeshOptions one for one.
ramus::mesh::MeshOptions mesh_options(const ramus_mesh_options& o) {
  if (o.crossed_leaves != 0 && o.crossed_leaves != 1)
    throw std::invalid_argument("ramus_mesh_build: crossed_leaves must be 0 or 1");
  if (o.y_up != 0 && o.y_up != 1)
    throw std::invalid_argument("ramus_mesh_build: y_up must be 0 or 1");
  ramus::mesh::MeshOptions m;
  m.lod_count = o.lod_count;
  m.pipe_exponent = o.pipe_exponent;
  m.leaf_style =
      o.crossed_leaves ? ramus::mesh::LeafStyle::kCrossed : ramus::mesh::LeafStyle::kQuad;
  m.leaf_scale = o.leaf_scale;
  return m;
}

}  // namespace

extern "C" {

int ramus_node_frame(const ramus_skeleton* s, size_t i, double heading[3], double left[3],
                     double up[3]) {
  if (!s || i >= s->s.nodes.size()) return -1;
  copy_frame(s->s.nodes[i], heading, left, up);
  return 0;
}

int ramus_node_order(const ramus_skeleton* s, size_t i) {
  if (!s || i >= s->s.nodes.size()) return -1;
  return s->s.nodes[i].order;
}

int ramus_organ_frame(const ramus_skeleton* s, size_t i, double heading[3], double left[3],
                      double up[3]) {
  if (!s || i >= s->s.organs.size()) return -1;
  copy_frame(s->s.organs[i], heading, left, up);
  return 0;
}

int64_t ramus_organ_node(const ramus_skeleton* s, size_t i) {
  if (!s || i >= s->s.organs.size()) return -1;
  const std::uint32_t node = s->s.organs[i].node;
  return node == ramus::kNoParent ? -1 : int64_t(node);
}

void ramus_mesh_options_init(ramus_mesh_options* o) {
  if (!o) return;
  const ramus::mesh::MeshOptions defaults;
  o->lod_count = defaults.lod_count;
  o->pipe_exponent = defaults.pipe_exponent;
  o->crossed_leaves = defaults.leaf_style == ramus::mesh::LeafStyle::kCrossed;
  o->leaf_scale = defaults.leaf_scale;
  o->y_up = 1;
}

ramus_mesh* ramus_mesh_build(const ramus_skeleton* s, const ramus_mesh_options* o, char* err,
                             size_t errlen) {
  return guarded<ramus_mesh*>(err, errlen, nullptr, [&] {
    if (!s) throw std::invalid_argument("ramus_mesh_build: null skeleton");
    ramus_mesh_options given;
    ramus_mesh_options_init(&given);
    if (o) given = *o;
    const ramus::mesh::UpAxis up = given.y_up ? ramus::mesh::UpAxis::kY : ramus::mesh::UpAxis::kZ;
    std::vector<ramus::mesh::TreeMesh> lods =
        ramus::mesh::build_tree_lods(s->s, mesh_options(given));
    auto mesh = std::make_unique<ramus_mesh>();
    mesh->origin = lods.empty() ? ramus::Vec3{} : lods.front().origin;
    if (up == ramus::mesh::UpAxis::kY) mesh->origin = ramus::mesh::z_up_to_y_up(mesh->origin);
    for (ramus::mesh::TreeMesh& level : lods) {
      // Tangents for the bark only, as the glTF writer gives them (its normal map needs them).
      mesh->lods.push_back({part_arrays(std::move(level.bark), up, true),
                            part_arrays(std::move(level.leaves), up, false),
                            part_arrays(std::move(level.surfaces), up, false)});
      level = {};  // the rest of the level (positions and normals in z up) is no longer needed
    }
    return mesh.release();
  });
}

void ramus_free_mesh(ramus_mesh* m) { delete m; }

int ramus_mesh_lod_count(const ramus_mesh* m) { return m ? int(m->lods.size()) : 0; }

int ramus_mesh_origin(const ramus_mesh* m, double xyz[3]) {
  if (!m || !xyz) return -1;
  copy3(m->origin, xyz);
  return 0;
}

size_t ramus_mesh_vertex_count(const ramus_mesh* m, int lod, int part) {
  const PartArrays* a = part_of(m, lod, part);
  return a ? a->uvs.size() : 0;
}

size_t ramus_mesh_index_count(const ramus_mesh* m, int lod, int part) {
  const PartArrays* a = part_of(m, lod, part);
  return a ? a->indices.size() : 0;
}

const float* ramus_mesh_positions(const ramus_mesh* m, int lod, int part) {
  return data_of<float>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.frame.positions; });
}

const float* ramus_mesh_normals(const ramus_mesh* m, int lod, int part) {
  return data_of<float>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.frame.normals; });
}

const float* ramus_mesh_uvs(const ramus_mesh* m, int lod, int part) {
  return data_of<float>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.uvs; });
}

const float* ramus_mesh_tangents(const ramus_mesh* m, int lod, int part) {
  return data_of<float>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.frame.tangents; });
}

const float* ramus_mesh_wind(const ramus_mesh* m, int lod, int part) {
  return data_of<float>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.wind; });
}

const uint32_t* ramus_mesh_skin_nodes(const ramus_mesh* m, int lod, int part) {
  return data_of<uint32_t>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.skin_node; });
}

const uint32_t* ramus_mesh_indices(const ramus_mesh* m, int lod, int part) {
  return data_of<uint32_t>(
      m, lod, part, [](const PartArrays& a) -> auto& { return a.indices; });
}

}  // extern "C"
