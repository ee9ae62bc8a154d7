#include "formats/tile_manifest.h"


#include "core/input_file.h"
#include "core/number_text.h"
#include "formats/detail/json.h"
#include "formats/detail/json_reader.h"
#include "formats/detail/reader_util.h"

namespace ramus {

using formats_detail::JsonValue;

namespace {

constexpr const char* kFormatName = "ramus-tiles";
constexpr int kVersion = 1;

void put_box(std::string& out, const TileBox& b) {
  out += '[';
  const double v[4] = {b.x0, b.y0, b.x1, b.y1};
  for (int k = 0; k < 4; ++k) {
    if (k) out += ", ";
    append_shortest(out, v[k]);
  }
  out += ']';
}

TileBox read_box(formats_detail::JsonReader& r, const JsonValue& v, const std::string& path) {
  r.expect_kind(v, JsonValue::Kind::kArray, path);
  if (v.items.size() != 4) {
    r.error(v, path,
            "expected [x0, y0, x1, y1], found " + std::to_string(v.items.size()) + " values");
  }
  double c[4];
  for (std::size_t k = 0; k < 4; ++k)
    c[k] = r.number(v.items[k], path + "[" + std::to_string(k) + "]");
  if (!(c[0] < c[2] && c[1] < c[3])) r.error(v, path, "expected x0 < x1 and y0 < y1");
  return {c[0], c[1], c[2], c[3]};
}

}  // namespace

std::string tile_manifest_to_json(const TileManifest& m) {
  std::string out = "{\n  \"format\": \"ramus-tiles\",\n  \"version\": 1,\n  \"size\": ";
  append_shortest(out, m.size);
  out += ",\n  \"buffer\": ";
  append_shortest(out, m.buffer);
  out += ",\n  \"thin\": ";
  append_shortest(out, m.thin);
  out += ",\n  \"sources\": [";
  for (std::size_t i = 0; i < m.sources.size(); ++i) {
    out += i ? ", " : "";
    formats_detail::append_json_string(out, m.sources[i]);
  }
  out += "],\n  \"tiles\": [";
  for (std::size_t i = 0; i < m.tiles.size(); ++i) {
    const TileEntry& t = m.tiles[i];
    out += i ? ",\n    {\"id\": " : "\n    {\"id\": ";
    out += std::to_string(t.id);
    out += ", \"core\": ";
    put_box(out, t.core);
    out += ", \"buffered\": ";
    put_box(out, t.buffered);
    out += ", \"file\": ";
    formats_detail::append_json_string(out, t.file);
    out += ", \"points\": " + std::to_string(t.points) + '}';
  }
  out += m.tiles.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

TileManifest tile_manifest_from_json(std::string_view text, const std::string& name) {
  const JsonValue root = formats_detail::parse_json(text, name);
  formats_detail::JsonReader r(name);
  const std::string top = "(top level)";
  r.expect_kind(root, JsonValue::Kind::kObject, top);
  r.known_keys(root, top, {"format", "version", "size", "buffer", "thin", "sources", "tiles"});
  const JsonValue& format = r.member(root, "format", top);
  if (r.text(format, "format") != kFormatName) {
    r.error(format, "format", std::string("expected \"") + kFormatName + "\"");
  }
  const JsonValue& version = r.member(root, "version", top);
  if (r.integer(version, "version", 0, 1'000'000) != kVersion) {
    r.error(version, "version", "this ramus reads version 1 only");
  }
  TileManifest m;
  m.size = r.number(r.member(root, "size", top), "size");
  m.buffer = r.number(r.member(root, "buffer", top), "buffer");
  if (const JsonValue* thin = root.find("thin")) m.thin = r.number(*thin, "thin");
  if (!(m.size > 0)) r.error(r.member(root, "size", top), "size", "the tile size must be positive");
  if (!(m.buffer >= 0))
    r.error(r.member(root, "buffer", top), "buffer", "the buffer must not be negative");
  if (const JsonValue* sources = root.find("sources")) {
    r.expect_kind(*sources, JsonValue::Kind::kArray, "sources");
    for (std::size_t i = 0; i < sources->items.size(); ++i) {
      m.sources.push_back(r.text(sources->items[i], "sources[" + std::to_string(i) + "]"));
    }
  }
  const JsonValue& tiles = r.member(root, "tiles", top);
  r.expect_kind(tiles, JsonValue::Kind::kArray, "tiles");
  for (std::size_t i = 0; i < tiles.items.size(); ++i) {
    const JsonValue& v = tiles.items[i];
    const std::string path = "tiles[" + std::to_string(i) + "]";
    r.expect_kind(v, JsonValue::Kind::kObject, path);
    r.known_keys(v, path, {"id", "core", "buffered", "file", "points"});
    TileEntry t;
    const JsonValue& id = r.member(v, "id", path);
    t.id = int(r.integer(id, path + ".id", 0, 1'000'000'000));
    if (t.id != int(i))
      r.error(id, path + ".id",
              "expected id " + std::to_string(i) + " (ids count from 0 in order)");
    t.core = read_box(r, r.member(v, "core", path), path + ".core");
    t.buffered = read_box(r, r.member(v, "buffered", path), path + ".buffered");
    if (t.core.x0 < t.buffered.x0 || t.core.y0 < t.buffered.y0 || t.core.x1 > t.buffered.x1 ||
        t.core.y1 > t.buffered.y1) {
      r.error(v, path, "the core must lie inside the buffered box");
    }
    t.file = r.text(r.member(v, "file", path), path + ".file");
    if (t.file.empty()) r.error(v, path + ".file", "empty file name");
    if (const JsonValue* points = v.find("points")) {
      t.points = std::uint64_t(r.integer(*points, path + ".points", 0, std::int64_t(1) << 53));
    }
    m.tiles.push_back(t);
  }
  return m;
}

void write_tile_manifest(const std::string& path, const TileManifest& manifest) {
  write_file_atomically(path, tile_manifest_to_json(manifest));
}

TileManifest read_tile_manifest(const std::string& path) {
  std::string text, error;
  if (!read_input_file(path, text, error)) formats_detail::fail(path, error);
  return tile_manifest_from_json(text, path);
}

}  // namespace ramus
