// The placed-pieces block of ramus_runtime.h: decode_rmb_contents -> expand_piece_stream
// (formats/rmb/rmb_piece_stream_expand.h), the expansion the pieces back end's instance buffer
// is checked against byte for byte (tests/runtime/test_runtime_pieces.cpp).
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_piece_stream_expand.h"
#include "runtime/c_api_guard.h"
#include "runtime/ramus_runtime.h"

struct ramus_pieces {
  ramus::InstanceBufferTables tables;
  std::vector<std::string> type_names;
  std::vector<std::uint32_t> ranges;  // first, count per type
  std::vector<ramus_piece_instance> instances;
  std::vector<float> bones;  // as the file holds them
  std::string binary;        // the instance buffer file
};

namespace {

using ramus::runtime::guarded;

// Reads the file's own bytes back for the arrays, so the arrays are the file.
std::uint32_t u32_at(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | std::uint8_t(b[at + i]);
  return v;
}

}  // namespace

extern "C" {

ramus_pieces* ramus_pieces_expand(const void* rmb_bytes, size_t n, char* err, size_t errlen) {
  return guarded<ramus_pieces*>(err, errlen, nullptr, [&] {
    if (!rmb_bytes && n > 0) throw std::invalid_argument("ramus_pieces_expand: null bytes");
    const std::string_view image(static_cast<const char*>(rmb_bytes), rmb_bytes ? n : 0);
    const ramus::RmbContents c = ramus::decode_rmb_contents(image);
    if (c.placed.empty()) {
      throw std::invalid_argument(
          "the .rmb holds no placed pieces (section 12): build it with --placed-pieces");
    }
    auto p = std::make_unique<ramus_pieces>();
    p->tables = ramus::expand_piece_stream(c.placed);
    p->binary = ramus::write_instance_buffer_binary(p->tables);
    for (const ramus::RmbStreamType& t : c.placed.types) p->type_names.push_back(t.name);
    for (const ramus::InstanceTypeRange& r : p->tables.ranges) {
      p->ranges.push_back(r.first);
      p->ranges.push_back(r.count);
    }
    for (const ramus::InstanceRecord& r : p->tables.instances)
      p->instances.push_back({r.bone_offset, r.tile_offset, r.tree, r.type, r.joints});
    const std::size_t bones_at = u32_at(p->binary, 36);
    p->bones.resize(16 * p->tables.skinning.size());
    for (std::size_t i = 0; i < p->bones.size(); ++i) {
      const std::uint32_t bits = u32_at(p->binary, bones_at + 4 * i);
      std::memcpy(&p->bones[i], &bits, 4);
    }
    return p.release();
  });
}

void ramus_free_pieces(ramus_pieces* p) { delete p; }

size_t ramus_pieces_type_count(const ramus_pieces* p) { return p ? p->type_names.size() : 0; }
size_t ramus_pieces_tree_count(const ramus_pieces* p) { return p ? p->tables.trees : 0; }
size_t ramus_pieces_instance_count(const ramus_pieces* p) { return p ? p->instances.size() : 0; }
size_t ramus_pieces_bone_count(const ramus_pieces* p) { return p ? p->tables.skinning.size() : 0; }
size_t ramus_pieces_tile_count(const ramus_pieces* p) { return p ? p->tables.tiles.size() : 0; }

const char* ramus_pieces_type_name(const ramus_pieces* p, size_t t) {
  return p && t < p->type_names.size() ? p->type_names[t].c_str() : nullptr;
}

const uint32_t* ramus_pieces_ranges(const ramus_pieces* p) {
  return p && !p->ranges.empty() ? p->ranges.data() : nullptr;
}
const ramus_piece_instance* ramus_pieces_instances(const ramus_pieces* p) {
  return p && !p->instances.empty() ? p->instances.data() : nullptr;
}
const float* ramus_pieces_bones(const ramus_pieces* p) {
  return p && !p->bones.empty() ? p->bones.data() : nullptr;
}
const uint16_t* ramus_pieces_tiles(const ramus_pieces* p) {
  return p && !p->tables.tiles.empty() ? p->tables.tiles.data() : nullptr;
}

const void* ramus_pieces_instance_buffer(const ramus_pieces* p, size_t* size) {
  if (size) *size = p ? p->binary.size() : 0;
  return p ? p->binary.data() : nullptr;
}

}  // extern "C"
