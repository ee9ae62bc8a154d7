// The GLB is read back as JSON (nlohmann, which Debian's tinygltf brings along) and its binary
// chunk; only the triangle primitives' accessors are re-encoded (draco_encoder.h,
// meshopt_encoder.h), every other buffer view is copied into the new binary chunk unchanged.
#include "backends/mesh/gltf_compress.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "backends/mesh/draco_encoder.h"
#include "backends/mesh/meshopt_encoder.h"

namespace ramus::mesh {
namespace {

using json = nlohmann::json;

constexpr int kByte = 5120, kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
// Mantissa bits of the meshopt EXPONENTIAL filter, which shares one exponent per vector: 16 bits
// keep a position within 2^-15 of the vector's largest component (0.5 mm at 16 m from the
// origin), 12 bits a texture coordinate within 1/4096 of its larger component.
constexpr int kPositionBits = 16, kTexCoordBits = 12;

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("cannot compress this glTF: " + what);
}

struct Glb {
  json doc;
  std::string bin;
};

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

Glb parse_glb(const std::string& glb) {
  if (glb.size() < 20 || glb.compare(0, 4, "glTF") != 0) fail("not a GLB");
  const std::uint32_t json_len = u32_at(glb, 12);
  if (20 + std::size_t(json_len) > glb.size()) fail("truncated JSON chunk");
  Glb g;
  g.doc = json::parse(glb.substr(20, json_len));
  const std::size_t bin_at = 20 + json_len;
  if (bin_at + 8 <= glb.size()) g.bin = glb.substr(bin_at + 8, u32_at(glb, bin_at));
  return g;
}

void put_u32(std::string& s, std::uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }

std::string write_glb(const json& doc, std::string bin) {
  std::string text = doc.dump();
  while (text.size() % 4) text += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string out = "glTF";
  put_u32(out, 2);
  put_u32(out, std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  put_u32(out, std::uint32_t(text.size()));
  put_u32(out, 0x4E4F534Au);  // "JSON"
  out += text;
  put_u32(out, std::uint32_t(bin.size()));
  put_u32(out, 0x004E4942u);  // "BIN\0"
  out += bin;
  return out;
}

int component_bytes(int type) {
  switch (type) {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
  }
  fail("unknown component type " + std::to_string(type));
}

int component_count(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  fail("vertex attributes of type " + type);
}

// An accessor's elements, tightly packed.
struct Elements {
  int component_type = kFloat, components = 1;
  std::size_t count = 0;
  std::string bytes;
  std::size_t element() const { return std::size_t(components) * component_bytes(component_type); }
  const float* floats() const { return reinterpret_cast<const float*>(bytes.data()); }
};

Elements read_accessor(const Glb& g, int index) {
  const json& a = g.doc.at("accessors").at(index);
  if (!a.contains("bufferView") || a.contains("sparse")) fail("an accessor without plain data");
  Elements e;
  e.component_type = a.at("componentType");
  e.components = component_count(a.at("type"));
  e.count = a.at("count");
  const json& v = g.doc.at("bufferViews").at(int(a.at("bufferView")));
  if (v.value("buffer", 0) != 0) fail("data outside the GLB's buffer");
  const std::size_t start = std::size_t(v.value("byteOffset", 0)) + a.value("byteOffset", 0);
  const std::size_t elem = e.element();
  const std::size_t stride = v.value("byteStride", elem);
  if (e.count > 0 && start + stride * (e.count - 1) + elem > g.bin.size())
    fail("data out of range");
  e.bytes.resize(elem * e.count);
  for (std::size_t i = 0; i < e.count; ++i)
    std::memcpy(&e.bytes[i * elem], g.bin.data() + start + i * stride, elem);
  return e;
}

std::vector<std::uint32_t> read_indices(const Glb& g, int index) {
  const Elements e = read_accessor(g, index);
  std::vector<std::uint32_t> out(e.count);
  for (std::size_t i = 0; i < e.count; ++i) {
    const char* p = e.bytes.data() + i * e.element();
    if (e.component_type == kUnsignedInt) {
      std::memcpy(&out[i], p, 4);
    } else if (e.component_type == kUnsignedShort) {
      std::uint16_t s;
      std::memcpy(&s, p, 2);
      out[i] = s;
    } else {
      out[i] = std::uint8_t(*p);
    }
  }
  return out;
}

std::size_t append_aligned(std::string& bin, const std::string& bytes) {
  while (bin.size() % 4) bin += '\0';
  const std::size_t at = bin.size();
  bin += bytes;
  return at;
}

// The GLB with every buffer view that no primitive uses copied to a new binary chunk (renumbered
// in accessors and images); the primitives' views are dropped for the encoder to replace.
struct Rebuilt {
  Glb glb;
  std::set<int> geometry;  // accessors of primitive attributes and indices
};

Rebuilt keep_other_views(const Glb& in) {
  Rebuilt r;
  r.glb.doc = in.doc;
  json& doc = r.glb.doc;
  if (!doc.contains("meshes")) fail("no meshes");
  if (doc.contains("buffers") && doc["buffers"].size() != 1) fail("more than one buffer");
  std::set<int> geometry_views;
  for (const json& mesh : doc["meshes"]) {
    for (const json& prim : mesh.at("primitives")) {
      if (prim.value("mode", 4) != 4 || !prim.contains("indices"))
        fail("a primitive that is not indexed triangles");
      if (prim.contains("targets")) fail("morph targets");
      std::vector<int> used{int(prim["indices"])};
      for (const auto& [name, acc] : prim.at("attributes").items()) used.push_back(int(acc));
      for (int a : used) {
        if (!r.geometry.insert(a).second) fail("an accessor shared by two primitives");
        geometry_views.insert(int(doc["accessors"][a].at("bufferView")));
      }
    }
  }
  std::map<int, int> renumber;
  json views = json::array();
  for (int v = 0; v < int(doc["bufferViews"].size()); ++v) {
    if (geometry_views.count(v)) continue;
    json view = doc["bufferViews"][v];
    const std::size_t at = view.value("byteOffset", 0);
    view["byteOffset"] = append_aligned(r.glb.bin, in.bin.substr(at, view.at("byteLength")));
    renumber[v] = int(views.size());
    views.push_back(view);
  }
  for (int a = 0; a < int(doc["accessors"].size()); ++a) {
    json& acc = doc["accessors"][a];
    if (r.geometry.count(a) || !acc.contains("bufferView")) continue;
    if (!renumber.count(acc["bufferView"])) fail("a view shared by geometry and other data");
    acc["bufferView"] = renumber[acc["bufferView"]];
  }
  if (doc.contains("images")) {
    for (json& image : doc["images"])
      if (image.contains("bufferView")) image["bufferView"] = renumber.at(image["bufferView"]);
  }
  doc["bufferViews"] = views;
  return r;
}

void require_extension(json& doc, const std::string& name) {
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    json& list = doc[key];
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  }
}

// --- Draco -------------------------------------------------------------------------------

DracoAttribute draco_attribute(const std::string& name, const Elements& e) {
  DracoAttribute a;
  a.name = name;
  a.components = e.components;
  a.is_float = e.component_type == kFloat;
  a.component_bytes = component_bytes(e.component_type);
  if (!a.is_float && e.component_type != kUnsignedByte && e.component_type != kUnsignedShort)
    fail("attribute " + name + " of a type Draco does not take here");
  a.data.assign(e.bytes.begin(), e.bytes.end());
  if (name == "POSITION") {
    a.kind = DracoKind::kPosition;
    a.quantization_bits = 14;
  } else if (name == "NORMAL") {
    a.kind = DracoKind::kNormal;
    a.quantization_bits = 10;
  } else if (name.rfind("TEXCOORD_", 0) == 0) {
    a.kind = DracoKind::kTexCoord;
    a.quantization_bits = 12;
  } else {
    // Weights in [0, 1]: 8 bits, as KHR_mesh_quantization would store them.
    a.quantization_bits = name == "_WIND" || name.rfind("WEIGHTS_", 0) == 0 ? 8 : 12;
  }
  return a;
}

std::string compress_draco(const Glb& in) {
  Rebuilt r = keep_other_views(in);
  json& doc = r.glb.doc;
  for (json& mesh : doc["meshes"]) {
    for (json& prim : mesh["primitives"]) {
      std::vector<DracoAttribute> attributes;
      std::size_t count = 0;
      for (const auto& [name, acc] : prim["attributes"].items()) {
        const Elements e = read_accessor(in, acc);
        count = e.count;
        attributes.push_back(draco_attribute(name, e));
      }
      const std::vector<std::uint32_t> indices = read_indices(in, prim["indices"]);
      const DracoPrimitive d = draco_encode(attributes, count, indices);
      json view = {{"buffer", 0}, {"byteLength", d.bytes.size()}};
      view["byteOffset"] = append_aligned(r.glb.bin, d.bytes);
      json ids = json::object();
      for (const auto& [name, id] : d.attribute_id) ids[name] = id;
      prim["extensions"]["KHR_draco_mesh_compression"] = {{"bufferView", doc["bufferViews"].size()},
                                                          {"attributes", ids}};
      doc["bufferViews"].push_back(view);
      for (const auto& [name, acc] : prim["attributes"].items()) {
        json& a = doc["accessors"][int(acc)];
        a.erase("bufferView");
        a.erase("byteOffset");
        a["count"] = d.points;
      }
      json& ia = doc["accessors"][int(prim["indices"])];
      ia.erase("bufferView");
      ia.erase("byteOffset");
      ia.erase("min");
      ia.erase("max");
      ia["count"] = 3 * d.faces;
      ia["componentType"] = d.points < 0xffff ? kUnsignedShort : kUnsignedInt;
    }
  }
  doc["buffers"] = json::array({{{"byteLength", r.glb.bin.size()}}});
  require_extension(doc, "KHR_draco_mesh_compression");
  return write_glb(doc, r.glb.bin);
}

// --- meshopt -----------------------------------------------------------------------------

struct MeshoptStream {
  std::string bytes;  // uncompressed, `stride` bytes per element
  std::size_t stride = 0;
};

std::string remapped(const Elements& e, const std::vector<std::uint32_t>& remap) {
  std::string out(e.bytes.size(), '\0');
  const std::size_t elem = e.element();
  for (std::size_t i = 0; i < e.count; ++i)
    std::memcpy(&out[remap[i] * elem], e.bytes.data() + i * elem, elem);
  return out;
}

void set_float_bounds(json& acc, const std::vector<float>& v, int comps) {
  std::vector<double> lo(comps, std::numeric_limits<double>::infinity()), hi(comps, -lo[0]);
  for (std::size_t i = 0; i < v.size(); ++i) {
    lo[i % comps] = std::min(lo[i % comps], double(v[i]));
    hi[i % comps] = std::max(hi[i % comps], double(v[i]));
  }
  acc["min"] = lo;
  acc["max"] = hi;
}

// Unit weights as normalized bytes summing to exactly 255 (largest remainder).
std::array<std::uint8_t, 4> weight_bytes(const float* w) {
  std::array<std::uint8_t, 4> q{};
  int sum = 0;
  for (int c = 0; c < 4; ++c)
    sum += q[c] = std::uint8_t(std::floor(std::clamp(w[c], 0.0f, 1.0f) * 255));
  while (sum < 255) {
    int best = 0;
    double most = -1;
    for (int c = 0; c < 4; ++c) {
      const double rest = w[c] * 255.0 - q[c];
      if (rest > most) most = rest, best = c;
    }
    ++q[best];
    ++sum;
  }
  return q;
}

// The stream meshopt encodes for one attribute (already in the optimized order), with the
// accessor changed to what it now holds.
MeshoptStream meshopt_attribute(const std::string& name, const Elements& e, json& acc,
                                std::string& filter) {
  MeshoptStream s;
  const bool is_float = e.component_type == kFloat;
  if (is_float && (name == "POSITION" || name.rfind("TEXCOORD_", 0) == 0)) {
    const int bits = name == "POSITION" ? kPositionBits : kTexCoordBits;
    const std::vector<std::uint32_t> words =
        meshopt_exponential(e.floats(), e.count, e.components, bits);
    // The bounds are those of the floats the filter gives back: mantissa * 2^exponent.
    std::vector<float> back(words.size());
    for (std::size_t i = 0; i < words.size(); ++i) {
      const int exponent = std::int32_t(words[i]) >> 24;
      const int mantissa = std::int32_t(words[i] << 8) >> 8;
      back[i] = std::ldexp(float(mantissa), exponent);
    }
    set_float_bounds(acc, back, e.components);
    s.bytes.assign(reinterpret_cast<const char*>(words.data()), words.size() * 4);
    s.stride = e.element();
    filter = "EXPONENTIAL";
    return s;
  }
  if (is_float && ((name == "NORMAL" && e.components == 3) ||
                   (name == "TANGENT" && e.components == 4))) {
    const std::vector<std::int8_t> oct = meshopt_octahedral(e.floats(), e.count, e.components);
    s.bytes.assign(reinterpret_cast<const char*>(oct.data()), oct.size());
    s.stride = 4;
    filter = "OCTAHEDRAL";
    acc["componentType"] = kByte;
    acc["normalized"] = true;
    acc.erase("min");
    acc.erase("max");
    return s;
  }
  if (is_float && e.components == 4 && (name == "_WIND" || name.rfind("WEIGHTS_", 0) == 0)) {
    s.bytes.resize(e.count * 4);
    for (std::size_t i = 0; i < e.count; ++i) {
      const float* w = e.floats() + 4 * i;
      std::array<std::uint8_t, 4> q;
      if (name == "_WIND") {
        for (int c = 0; c < 4; ++c)
          q[c] = std::uint8_t(std::lround(std::clamp(w[c], 0.0f, 1.0f) * 255));
      } else {
        q = weight_bytes(w);
      }
      std::memcpy(&s.bytes[4 * i], q.data(), 4);
    }
    s.stride = 4;
    acc["componentType"] = kUnsignedByte;
    acc["normalized"] = true;
    acc.erase("min");
    acc.erase("max");
    return s;
  }
  if (e.element() % 4 != 0) fail("attribute " + name + " whose elements are not 4-byte aligned");
  s.bytes = e.bytes;
  s.stride = e.element();
  return s;
}

std::string compress_meshopt(const Glb& in) {
  Rebuilt r = keep_other_views(in);
  json& doc = r.glb.doc;
  std::size_t fallback = 0;  // the size of the uncompressed data the views describe
  auto add_view = [&](const std::string& raw, const std::string& packed, std::size_t stride,
                      std::size_t count, bool indices, const std::string& filter) {
    while (fallback % 4) ++fallback;
    json ext = {{"buffer", 0},
                {"byteLength", packed.size()},
                {"byteStride", stride},
                {"count", count},
                {"mode", indices ? "TRIANGLES" : "ATTRIBUTES"}};
    ext["byteOffset"] = append_aligned(r.glb.bin, packed);
    if (!filter.empty()) ext["filter"] = filter;
    json view = {{"buffer", 1},
                 {"byteOffset", fallback},
                 {"byteLength", raw.size()},
                 {"target", indices ? kElementArrayBuffer : kArrayBuffer}};
    if (!indices) view["byteStride"] = stride;
    view["extensions"]["EXT_meshopt_compression"] = ext;
    fallback += raw.size();
    doc["bufferViews"].push_back(view);
    return int(doc["bufferViews"].size() - 1);
  };
  for (json& mesh : doc["meshes"]) {
    for (json& prim : mesh["primitives"]) {
      const int ia = prim["indices"];
      std::vector<std::uint32_t> indices = read_indices(in, ia);
      if (indices.size() % 3) fail("a triangle list whose length is not a multiple of 3");
      std::size_t count = 0;
      for (const auto& [name, acc] : prim["attributes"].items())
        count = std::max(count, std::size_t(doc["accessors"][int(acc)]["count"]));
      const std::vector<std::uint32_t> remap = meshopt_optimize_order(indices, count);
      for (const auto& [name, acc] : prim["attributes"].items()) {
        Elements e = read_accessor(in, acc);
        if (e.count != count) fail("attributes of different lengths");
        e.bytes = remapped(e, remap);
        json& a = doc["accessors"][int(acc)];
        std::string filter;
        const MeshoptStream s = meshopt_attribute(name, e, a, filter);
        a["bufferView"] =
            add_view(s.bytes, meshopt_encode_attributes(s.bytes.data(), count, s.stride), s.stride,
                     count, false, filter);
        a.erase("byteOffset");
      }
      json& acc = doc["accessors"][ia];
      const bool wide = int(acc["componentType"]) == kUnsignedInt;
      std::string raw(indices.size() * (wide ? 4 : 2), '\0');
      for (std::size_t i = 0; i < indices.size(); ++i) {
        if (wide) {
          std::memcpy(&raw[4 * i], &indices[i], 4);
        } else {
          const std::uint16_t v = std::uint16_t(indices[i]);
          std::memcpy(&raw[2 * i], &v, 2);
        }
      }
      if (int(acc["componentType"]) == kUnsignedByte) fail("byte indices");
      acc["bufferView"] = add_view(raw, meshopt_encode_triangles(indices, count), wide ? 4 : 2,
                                   indices.size(), true, "");
      acc.erase("byteOffset");
      if (!indices.empty()) {
        acc["min"] = {*std::min_element(indices.begin(), indices.end())};
        acc["max"] = {*std::max_element(indices.begin(), indices.end())};
      }
    }
  }
  // The views' uncompressed data lives in a buffer without bytes of its own (the extension's
  // fallback buffer): a loader decodes into it.
  doc["buffers"] =
      json::array({{{"byteLength", r.glb.bin.size()}},
                   {{"byteLength", fallback},
                    {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
  require_extension(doc, "EXT_meshopt_compression");
  require_extension(doc, "KHR_mesh_quantization");
  return write_glb(doc, r.glb.bin);
}

}  // namespace

std::string compress_glb(const std::string& glb, GltfCompression how) {
  if (how == GltfCompression::kNone) return glb;
  const Glb in = parse_glb(glb);
  return how == GltfCompression::kDraco ? compress_draco(in) : compress_meshopt(in);
}

}  // namespace ramus::mesh
