#include "backends/mesh/meshopt_encoder.h"

#include <meshoptimizer.h>

namespace ramus::mesh {

std::vector<std::uint32_t> meshopt_optimize_order(std::vector<std::uint32_t>& indices,
                                                  std::size_t vertex_count) {
  meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertex_count);
  std::vector<std::uint32_t> remap(vertex_count);
  meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), vertex_count);
  // Vertices no triangle uses get ~0u: append them in their old order, so nothing is lost.
  std::size_t next = 0;
  for (std::uint32_t r : remap)
    if (r != ~0u) next = std::max<std::size_t>(next, r + 1);
  for (std::uint32_t& r : remap)
    if (r == ~0u) r = std::uint32_t(next++);
  for (std::uint32_t& i : indices) i = remap[i];
  return remap;
}

std::string meshopt_encode_attributes(const void* data, std::size_t count, std::size_t stride) {
  meshopt_encodeVertexVersion(0);
  std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
  out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(),
                                        data, count, stride));
  return out;
}

std::string meshopt_encode_triangles(const std::vector<std::uint32_t>& indices,
                                     std::size_t vertex_count) {
  meshopt_encodeIndexVersion(1);
  std::string out(meshopt_encodeIndexBufferBound(indices.size(), vertex_count), '\0');
  out.resize(meshopt_encodeIndexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(),
                                       indices.data(), indices.size()));
  return out;
}

std::vector<std::int8_t> meshopt_octahedral(const float* normals, std::size_t count,
                                            int components) {
  // Tangents (4 components) keep their w, the handedness, in the fourth byte.
  std::vector<float> four(count * 4, 0.0f);
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c) four[4 * i + c] = normals[components * i + c];
  std::vector<std::int8_t> out(count * 4);
  meshopt_encodeFilterOct(out.data(), count, 4, 8, four.data());
  return out;
}

std::vector<std::uint32_t> meshopt_exponential(const float* data, std::size_t count, int components,
                                               int bits) {
  std::vector<std::uint32_t> out(count * components);
  meshopt_encodeFilterExp(out.data(), count, std::size_t(components) * 4, bits, data);
  return out;
}

}  // namespace ramus::mesh
