// The buffer side of a tinygltf model, shared by the glTF writers (backends/mesh/gltf_writer.cpp,
// backends/pieces/gltf_pieces.cpp; include it from no other file: it pulls in tiny_gltf.h).
// One buffer; every view starts on a 4-byte boundary; float accessors may carry the exact min/max
// of the values written and index accessors always do, which is what the Khronos glTF-Validator
// checks.
#pragma once

#include <tiny_gltf.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace ramus::mesh {

class GltfBufferBuilder {
 public:
  GltfBufferBuilder() {
    model_.asset.version = "2.0";
    model_.asset.generator = "ramus";
    model_.buffers.emplace_back();
  }

  tinygltf::Model& model() { return model_; }

  // A texture (a PNG, or `mime`, image in the buffer, linear mipmapped sampler with `wrap`);
  // returns its index.
  int add_texture(const std::string& bytes, const std::string& name, int wrap,
                  const std::string& mime = "image/png") {
    tinygltf::Image image;
    image.name = name;
    image.mimeType = mime;
    image.bufferView = add_view(bytes.data(), bytes.size(), 0);
    model_.images.push_back(image);
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = sampler.wrapT = wrap;
    model_.samplers.push_back(sampler);
    tinygltf::Texture tex;
    tex.sampler = tex.source = int(model_.images.size() - 1);
    model_.textures.push_back(tex);
    return int(model_.textures.size() - 1);
  }

  // A view over a copy of `bytes` bytes at `data`; target 0 for views that are not vertex or
  // index data (images, inverse bind matrices, animation and instance data).
  int add_view(const void* data, std::size_t bytes, int target) {
    auto& buf = model_.buffers[0].data;
    while (buf.size() % 4) buf.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buf.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buf.insert(buf.end(), p, p + bytes);
    model_.bufferViews.push_back(view);
    return int(model_.bufferViews.size() - 1);
  }

  int add_accessor(int view, int component, std::size_t count, int type,
                   std::vector<double> lo = {}, std::vector<double> hi = {},
                   bool normalized = false) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.byteOffset = 0;
    a.componentType = component;
    a.count = count;
    a.type = type;
    a.normalized = normalized;
    a.minValues = std::move(lo);
    a.maxValues = std::move(hi);
    model_.accessors.push_back(a);
    return int(model_.accessors.size() - 1);
  }

  // `count` elements of `comps` floats each; with_bounds adds their exact min/max.
  int add_floats(const float* f, std::size_t count, int comps, int type, int target,
                 bool with_bounds) {
    std::vector<double> lo, hi;
    if (with_bounds) {
      lo.assign(comps, std::numeric_limits<double>::infinity());
      hi.assign(comps, -std::numeric_limits<double>::infinity());
      for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < comps; ++c) {
          lo[c] = std::min(lo[c], double(f[i * comps + c]));
          hi[c] = std::max(hi[c], double(f[i * comps + c]));
        }
      }
    }
    const int view = add_view(f, count * comps * sizeof(float), target);
    return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, count, type, std::move(lo),
                        std::move(hi));
  }

  // Triangle or line indices with their bounds: 16-bit when the vertices fit (65535 is the
  // primitive-restart value and is never an index), 32-bit otherwise.
  int add_indices(const std::vector<std::uint32_t>& idx, std::size_t vertex_count) {
    const double hi = idx.empty() ? 0 : *std::max_element(idx.begin(), idx.end());
    const double lo = idx.empty() ? 0 : *std::min_element(idx.begin(), idx.end());
    if (vertex_count < 0xffff) {
      std::vector<std::uint16_t> small(idx.begin(), idx.end());
      const int view =
          add_view(small.data(), small.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
      return add_accessor(view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, idx.size(),
                          TINYGLTF_TYPE_SCALAR, {lo}, {hi});
    }
    const int view = add_view(idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return add_accessor(view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, idx.size(),
                        TINYGLTF_TYPE_SCALAR, {lo}, {hi});
  }

 protected:
  tinygltf::Model model_;
};

}  // namespace ramus::mesh
