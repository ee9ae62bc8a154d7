// Reads back what the tests need from a .glb the writers made, with ramus's own strict JSON reader
// (formats/detail/json.h) rather than tinygltf, so the checks do not share the writer's library:
// the JSON chunk, the binary chunk, and VEC3 float accessors with their min/max.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "formats/detail/json.h"

namespace ramus::testing {

struct Glb {
  formats_detail::JsonValue json;
  std::string bin;

  const formats_detail::JsonValue& at(const char* key) const {
    const formats_detail::JsonValue* v = json.find(key);
    if (v == nullptr) throw std::runtime_error(std::string("glTF without ") + key);
    return *v;
  }
};

inline std::uint32_t glb_u32(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// GLB container (glTF 2.0, "Binary glTF Layout"): 12-byte header, JSON chunk, BIN chunk.
inline Glb read_glb(const std::string& bytes) {
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) throw std::runtime_error("not a GLB");
  Glb g;
  const std::uint32_t json_len = glb_u32(bytes, 12);
  g.json = formats_detail::parse_json(std::string_view(bytes).substr(20, json_len), "test.glb");
  const std::size_t bin_at = 20 + json_len;
  if (bin_at + 8 <= bytes.size()) g.bin = bytes.substr(bin_at + 8, glb_u32(bytes, bin_at));
  return g;
}

inline const formats_detail::JsonValue& item(const formats_detail::JsonValue& array, int i) {
  return array.items.at(std::size_t(i));
}

inline double number(const formats_detail::JsonValue& object, const char* key, double fallback) {
  const formats_detail::JsonValue* v = object.find(key);
  return v == nullptr ? fallback : v->number;
}

// The accessor of `attribute` in primitive `prim` of mesh `mesh`.
inline int attribute_accessor(const Glb& g, int mesh, int prim, const char* attribute) {
  const auto& p = item(*item(g.at("meshes"), mesh).find("primitives"), prim);
  return int(p.find("attributes")->find(attribute)->number);
}

// Every element of a VEC3 float accessor (tightly packed, as the writers store them).
inline std::vector<Vec3f> read_vec3(const Glb& g, int accessor) {
  const auto& a = item(g.at("accessors"), accessor);
  const auto& view = item(g.at("bufferViews"), int(a.find("bufferView")->number));
  const std::size_t at = std::size_t(number(view, "byteOffset", 0) + number(a, "byteOffset", 0));
  std::vector<Vec3f> out(std::size_t(a.find("count")->number));
  std::memcpy(out.data(), g.bin.data() + at, out.size() * sizeof(Vec3f));
  return out;
}

// An accessor's "min" or "max" as a vector.
inline Vec3 accessor_bound(const Glb& g, int accessor, const char* which) {
  const auto& v = item(g.at("accessors"), accessor).find(which)->items;
  return {v.at(0).number, v.at(1).number, v.at(2).number};
}

}  // namespace ramus::testing
