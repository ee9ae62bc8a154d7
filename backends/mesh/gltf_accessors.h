// Reading glTF 2.0 accessors (spec 3.6-3.7) out of a tinygltf model, with every offset checked
// against its buffer view and buffer: the pieces' glTF files (backends/pieces/piece_file_gltf.cpp)
// and the preview's mesh reader (gltf_reader.cpp) read vertices and indices the same way.
//
// Header-only and including tinygltf: only those two translation units, which include it
// already, may include this header (tinygltf is heavy; CONTRIBUTING.md).
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/mesh/gltf_container.h"
#include "core/input_file.h"
#include "core/vec3.h"

namespace ramus::gltf_accessors {

// What is wrong with the file, without its name: the caller adds it and its own error type.
struct AccessorError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The bytes of element 0 of accessor `a` and its stride.
inline const unsigned char* element_data(const tinygltf::Model& m, const tinygltf::Accessor& a,
                                         std::size_t& stride) {
  if (a.bufferView < 0 || a.bufferView >= int(m.bufferViews.size())) {
    throw AccessorError("an accessor has no buffer view");
  }
  const tinygltf::BufferView& v = m.bufferViews[a.bufferView];
  if (v.buffer < 0 || v.buffer >= int(m.buffers.size())) {
    throw AccessorError("a buffer view has no buffer");
  }
  const auto& bytes = m.buffers[v.buffer].data;
  const int comps = tinygltf::GetNumComponentsInType(a.type);
  const int size = tinygltf::GetComponentSizeInBytes(a.componentType);
  if (comps <= 0 || size <= 0) throw AccessorError("an accessor has an unknown type");
  const std::size_t elem = std::size_t(comps) * std::size_t(size);
  stride = v.byteStride ? v.byteStride : elem;
  const std::size_t begin = v.byteOffset + a.byteOffset;
  if (a.count > 0 && (begin + stride * (a.count - 1) + elem > bytes.size() ||
                      a.byteOffset + stride * (a.count - 1) + elem > v.byteLength)) {
    throw AccessorError("an accessor reaches past its buffer");
  }
  return bytes.data() + begin;
}

// A float VEC3 accessor (POSITION, NORMAL); `what` names it in messages.
inline std::vector<Vec3> vec3s(const tinygltf::Model& m, int index, const std::string& what) {
  if (index < 0 || index >= int(m.accessors.size())) throw AccessorError("no such " + what);
  const tinygltf::Accessor& a = m.accessors[index];
  if (a.type != TINYGLTF_TYPE_VEC3 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
    throw AccessorError(what + " must be float VEC3");
  }
  std::size_t stride = 0;
  const unsigned char* p = element_data(m, a, stride);
  std::vector<Vec3> out(a.count);
  for (std::size_t i = 0; i < a.count; ++i) {
    float f[3];
    std::memcpy(f, p + i * stride, sizeof f);
    out[i] = {f[0], f[1], f[2]};
  }
  return out;
}

// The primitive's vertex indices (0 .. vertices-1 when it has none), each checked.
inline std::vector<std::uint32_t> indices(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                                          std::size_t vertices) {
  std::vector<std::uint32_t> out;
  if (prim.indices < 0) {
    for (std::size_t i = 0; i < vertices; ++i) out.push_back(std::uint32_t(i));
    return out;
  }
  if (prim.indices >= int(m.accessors.size())) throw AccessorError("no such index accessor");
  const tinygltf::Accessor& a = m.accessors[prim.indices];
  std::size_t stride = 0;
  const unsigned char* p = element_data(m, a, stride);
  for (std::size_t i = 0; i < a.count; ++i) {
    std::uint32_t v = 0;
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
      v = p[i * stride];
    } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      std::uint16_t s;
      std::memcpy(&s, p + i * stride, 2);
      v = s;
    } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      std::memcpy(&v, p + i * stride, 4);
    } else {
      throw AccessorError("indices must be unsigned integers");
    }
    if (v >= vertices) throw AccessorError("an index names a missing vertex");
    out.push_back(v);
  }
  return out;
}

// Filesystem callbacks for the files a .gltf names (buffers, images): tinygltf's own, except that
// files are read with read_input_file (core/input_file.h), which refuses a directory and a file
// over the size limit before reading. tinygltf's reader took a directory's size for 2^63 - 1 bytes
// and tried to allocate them (found by fuzz_piece_gltf).
inline tinygltf::FsCallbacks checked_file_callbacks() {
  tinygltf::FsCallbacks fs{};
  fs.FileExists = &tinygltf::FileExists;
  fs.ExpandFilePath = &tinygltf::ExpandFilePath;
  fs.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err, const std::string& path,
                        void*) {
    std::string bytes, e;
    if (!read_input_file(path, bytes, e)) {
      if (err) *err += path + ": " + e + "\n";
      return false;
    }
    out->assign(bytes.begin(), bytes.end());
    return true;
  };
  fs.WriteWholeFile = &tinygltf::WriteWholeFile;
  fs.user_data = nullptr;
  return fs;
}

// Reads a model from the bytes of a glTF file that `path` names (for the container's choice
// only: nothing is read from it): a GLB when the bytes begin with its magic or the name ends in
// .glb (a .glb without the magic is a damaged container, and glb_layout_error says where), its
// layout checked before tinygltf sees it (gltf_container.h); JSON text otherwise. `base` is the
// folder of the files a .gltf names, read through the loader's callbacks. Returns what is wrong
// (no file name: the caller adds it and its own error type), "" when the model was read.
inline std::string load_model(tinygltf::TinyGLTF& loader, tinygltf::Model& model,
                              const std::string& path, const std::string& bytes,
                              const std::string& base) {
  const bool binary = bytes.starts_with("glTF") || path.ends_with(".glb") || path.ends_with(".GLB");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (binary) {
    if (std::string e = mesh::glb_layout_error(data, bytes.size()); !e.empty()) {
      return "cannot read the glTF file: " + e;
    }
  }
  std::string err, warn;
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary
                      ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, size, base)
                      : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, base);
  if (ok) return "";
  while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
  return "cannot read the glTF file" + (err.empty() ? "" : ": " + err);
}

// Reads the glTF file at `path` with read_input_file (a directory and the size limit refused
// first), and the files it names through checked_file_callbacks, from its folder.
inline std::string load_model_file(tinygltf::TinyGLTF& loader, tinygltf::Model& model,
                                   const std::string& path) {
  std::string bytes, e;
  if (!read_input_file(path, bytes, e)) return e;
  loader.SetFsCallbacks(checked_file_callbacks());
  return load_model(loader, model, path, bytes, std::filesystem::path(path).parent_path().string());
}

}  // namespace ramus::gltf_accessors
