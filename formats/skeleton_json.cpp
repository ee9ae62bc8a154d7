#include "formats/skeleton_json.h"

#include <charconv>
#include <cmath>

#include "core/atomic_file.h"
#include "core/input_file.h"
#include "core/number_text.h"
#include "formats/detail/json.h"
#include "formats/detail/json_reader.h"
#include "formats/detail/reader_util.h"

namespace ramus {

using formats_detail::JsonValue;

namespace {

constexpr const char* kFormatName = "ramus-skeleton";
constexpr int kVersion = 1;

void put_number(std::string& out, double v) {
  // JSON has no NaN or infinity; a skeleton holding one is a bug upstream, not a file to write.
  if (!std::isfinite(v)) throw WriteError("cannot write a non-finite number in a skeleton file");
  append_shortest(out, v);
}

void put_vec(std::string& out, const char* key, const Vec3& v) {
  out += ", \"";
  out += key;
  out += "\": [";
  for (int k = 0; k < 3; ++k) {
    if (k) out += ", ";
    put_number(out, v[k]);
  }
  out += ']';
}

void put_node(std::string& out, const SkeletonNode& n) {
  out += "    {\"position\": [";
  for (int k = 0; k < 3; ++k) {
    if (k) out += ", ";
    put_number(out, n.position[k]);
  }
  out += ']';
  put_vec(out, "heading", n.heading);
  put_vec(out, "left", n.left);
  put_vec(out, "up", n.up);
  out += ", \"radius\": ";
  put_number(out, n.radius);
  out += ", \"parent\": ";
  out += n.parent == kNoParent ? std::string("-1") : std::to_string(n.parent);
  out += ", \"order\": " + std::to_string(n.order);
  if (n.source_module != kNoSource) out += ", \"source\": " + std::to_string(n.source_module);
  out += '}';
}

void put_organ(std::string& out, const OrganAnchor& o) {
  out += "    {\"node\": ";
  out += o.node == kNoParent ? std::string("-1") : std::to_string(o.node);
  put_vec(out, "position", o.position);
  put_vec(out, "heading", o.heading);
  put_vec(out, "left", o.left);
  put_vec(out, "up", o.up);
  out += ", \"size\": ";
  put_number(out, o.size);
  out += ", \"kind\": " + std::to_string(o.kind);
  if (!o.vertices.empty()) {  // a polygon organ (docs/skeleton-format.md)
    out += ", \"vertices\": [";
    for (std::size_t i = 0; i < o.vertices.size(); ++i) {
      out += i ? ", [" : "[";
      for (int k = 0; k < 3; ++k) {
        if (k) out += ", ";
        put_number(out, o.vertices[i][k]);
      }
      out += ']';
    }
    out += ']';
  }
  out += '}';
}

// The skeleton file's objects, read with the shared JSON reader.
class Reader : public formats_detail::JsonReader {
 public:
  using JsonReader::JsonReader;

  SkeletonNode node(const JsonValue& v, const std::string& path, std::size_t count) {
    expect_kind(v, JsonValue::Kind::kObject, path);
    known_keys(v, path,
               {"position", "heading", "left", "up", "radius", "parent", "order", "source"});
    SkeletonNode n;
    const JsonValue* pos = v.find("position");
    if (!pos) error(v, path, "missing \"position\"");
    n.position = vec3(*pos, path + ".position");
    if (auto* h = v.find("heading")) n.heading = vec3(*h, path + ".heading");
    if (auto* l = v.find("left")) n.left = vec3(*l, path + ".left");
    if (auto* u = v.find("up")) n.up = vec3(*u, path + ".up");
    if (auto* r = v.find("radius")) {
      n.radius = number(*r, path + ".radius");
      if (n.radius < 0) error(*r, path + ".radius", "the radius must not be negative");
    }
    if (auto* p = v.find("parent")) {
      if (p->kind != JsonValue::Kind::kNull) {
        std::int64_t parent = integer(*p, path + ".parent", -1, 0xfffffffeLL);
        if (parent >= std::int64_t(count)) {
          error(*p, path + ".parent",
                "parent " + std::to_string(parent) + " is out of range (the file has " +
                    std::to_string(count) + " nodes)");
        }
        n.parent = parent < 0 ? kNoParent : std::uint32_t(parent);
      }
    }
    if (auto* o = v.find("order")) n.order = std::uint16_t(integer(*o, path + ".order", 0, 65535));
    if (auto* s = v.find("source")) {
      n.source_module = std::uint32_t(integer(*s, path + ".source", 0, 0xfffffffeLL));
    }
    return n;
  }

  OrganAnchor organ(const JsonValue& v, const std::string& path, std::size_t nodes,
                    std::size_t kinds) {
    expect_kind(v, JsonValue::Kind::kObject, path);
    known_keys(v, path, {"node", "position", "heading", "left", "up", "size", "kind", "vertices"});
    OrganAnchor o;
    const JsonValue* node = v.find("node");
    if (!node) error(v, path, "missing \"node\"");
    std::int64_t idx = integer(*node, path + ".node", -1, 0xfffffffeLL);
    if (idx >= std::int64_t(nodes)) {
      error(*node, path + ".node",
            "node " + std::to_string(idx) + " is out of range (the file has " +
                std::to_string(nodes) + " nodes)");
    }
    o.node = idx < 0 ? kNoParent : std::uint32_t(idx);
    const JsonValue* pos = v.find("position");
    if (!pos) error(v, path, "missing \"position\"");
    o.position = vec3(*pos, path + ".position");
    if (auto* h = v.find("heading")) o.heading = vec3(*h, path + ".heading");
    if (auto* l = v.find("left")) o.left = vec3(*l, path + ".left");
    if (auto* u = v.find("up")) o.up = vec3(*u, path + ".up");
    if (auto* s = v.find("size")) o.size = number(*s, path + ".size");
    if (auto* k = v.find("kind")) {
      o.kind = std::uint32_t(integer(*k, path + ".kind", 0, std::int64_t(kinds) - 1));
    }
    if (auto* vs = v.find("vertices")) {
      expect_kind(*vs, JsonValue::Kind::kArray, path + ".vertices");
      if (vs->items.size() < 3)
        error(*vs, path + ".vertices", "a polygon needs 3 or more vertices");
      for (std::size_t i = 0; i < vs->items.size(); ++i) {
        o.vertices.push_back(vec3(vs->items[i], path + ".vertices[" + std::to_string(i) + "]"));
      }
    }
    return o;
  }
};

void read_header(Reader& r, const JsonValue& root) {
  r.expect_kind(root, JsonValue::Kind::kObject, "(top level)");
  r.known_keys(root, "(top level)", {"format", "version", "organ_kinds", "nodes", "organs"});
  const JsonValue* format = root.find("format");
  if (!format || format->kind != JsonValue::Kind::kString || format->text != kFormatName) {
    r.error(format ? *format : root, "format",
            std::string("expected \"format\": \"") + kFormatName + "\"");
  }
  const JsonValue* version = root.find("version");
  if (!version) r.error(root, "version", "missing \"version\"");
  if (r.integer(*version, "version", 0, 1 << 30) != kVersion) {
    r.error(*version, "version", "unsupported version (this build reads version 1)");
  }
}

}  // namespace

std::string skeleton_to_json(const Skeleton& s) {
  std::string out = "{\n  \"format\": \"";
  out += kFormatName;
  out += "\",\n  \"version\": " + std::to_string(kVersion) + ",\n  \"organ_kinds\": [";
  for (std::size_t i = 0; i < s.organ_kinds.size(); ++i) {
    if (i) out += ", ";
    formats_detail::append_json_string(out, s.organ_kinds[i]);
  }
  out += "],\n  \"nodes\": [";
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    out += i ? ",\n" : "\n";
    put_node(out, s.nodes[i]);
  }
  out += s.nodes.empty() ? "],\n  \"organs\": [" : "\n  ],\n  \"organs\": [";
  for (std::size_t i = 0; i < s.organs.size(); ++i) {
    out += i ? ",\n" : "\n";
    put_organ(out, s.organs[i]);
  }
  out += s.organs.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

Skeleton skeleton_from_json(std::string_view text, const std::string& name) {
  JsonValue root = formats_detail::parse_json(text, name);
  Reader r(name);
  read_header(r, root);
  Skeleton s;
  if (const JsonValue* kinds = root.find("organ_kinds")) {
    r.expect_kind(*kinds, JsonValue::Kind::kArray, "organ_kinds");
    s.organ_kinds.clear();
    for (std::size_t i = 0; i < kinds->items.size(); ++i) {
      const std::string path = "organ_kinds[" + std::to_string(i) + "]";
      r.expect_kind(kinds->items[i], JsonValue::Kind::kString, path);
      s.organ_kinds.push_back(kinds->items[i].text);
    }
  }
  const JsonValue* nodes = root.find("nodes");
  if (!nodes) r.error(root, "nodes", "missing \"nodes\"");
  r.expect_kind(*nodes, JsonValue::Kind::kArray, "nodes");
  s.nodes.reserve(nodes->items.size());
  for (std::size_t i = 0; i < nodes->items.size(); ++i) {
    s.nodes.push_back(
        r.node(nodes->items[i], "nodes[" + std::to_string(i) + "]", nodes->items.size()));
  }
  if (const JsonValue* organs = root.find("organs")) {
    r.expect_kind(*organs, JsonValue::Kind::kArray, "organs");
    for (std::size_t i = 0; i < organs->items.size(); ++i) {
      s.organs.push_back(r.organ(organs->items[i], "organs[" + std::to_string(i) + "]",
                                 s.nodes.size(), s.organ_kinds.size()));
    }
  }
  // Range checks above name the exact value; validate() adds what needs the whole structure
  // (cycles, self-parents, non-finite values).
  std::string problem = s.validate();
  if (!problem.empty()) r.error(*nodes, "nodes", problem);
  return s;
}

void write_skeleton_json(const std::string& path, const Skeleton& skeleton) {
  write_file_atomically(path, skeleton_to_json(skeleton));
}

Skeleton read_skeleton_json(const std::string& path) {
  std::string text, error;
  if (!read_input_file(path, text, error)) formats_detail::fail(path, error);
  return skeleton_from_json(text, path);
}

}  // namespace ramus
