// meshoptimizer (Debian libmeshoptimizer-dev) for glTF's EXT_meshopt_compression: vertex order
// optimization, the vertex and index codecs, and the octahedral normal filter. The one file that
// includes meshoptimizer.h is meshopt_encoder.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ramus::mesh {

// Reorders `indices` for the vertex cache and returns the vertex remap that puts vertices in the
// order the triangles first use them (remap[old] = new), which the codec compresses best.
std::vector<std::uint32_t> meshopt_optimize_order(std::vector<std::uint32_t>& indices,
                                                  std::size_t vertex_count);

// The attribute codec (mode ATTRIBUTES, codec version 0) over `count` elements of `stride` bytes
// (a multiple of 4, at most 256).
std::string meshopt_encode_attributes(const void* data, std::size_t count, std::size_t stride);

// The index codec (mode TRIANGLES, codec version 1).
std::string meshopt_encode_triangles(const std::vector<std::uint32_t>& indices,
                                     std::size_t vertex_count);

// Unit normals (count * 3 floats) or tangents (count * 4, w = +-1 kept) as the OCTAHEDRAL
// filter's 8-bit x, y, z, w per vertex.
std::vector<std::int8_t> meshopt_octahedral(const float* normals, std::size_t count,
                                            int components = 3);

// Floats (count vectors of `components` each) as the EXPONENTIAL filter stores them: one 8-bit
// exponent per vector and a `bits`-bit integer mantissa per component, as 32-bit words.
std::vector<std::uint32_t> meshopt_exponential(const float* data, std::size_t count, int components,
                                               int bits);

}  // namespace ramus::mesh
