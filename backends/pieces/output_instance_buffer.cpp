// Encodes the instance buffer and its manifest (output_instance_buffer.h,
// docs/instance-buffer.md). Every integer is written little-endian byte by byte, so the bytes
// do not depend on the host.
#include "backends/pieces/output_instance_buffer.h"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "mesh/up_axis.h"
#include "core/atomic_file.h"

namespace ramus::pieces {
namespace {

void put_u16(std::string& out, std::uint16_t v) {
  out += char(v & 0xff);
  out += char(v >> 8);
}
void put_u32(std::string& out, std::uint32_t v) {
  for (int s = 0; s < 32; s += 8) out += char((v >> s) & 0xff);
}
void put_f32(std::string& out, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  put_u32(out, u);
}
void pad_to(std::string& out, std::size_t alignment) {
  while (out.size() % alignment) out += '\0';
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      static const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}

std::string section(const char* name, std::size_t offset, std::size_t bytes, bool last = false) {
  return std::string("    ") + json_string(name) + ": {\"offset\": " + std::to_string(offset) +
         ", \"bytes\": " + std::to_string(bytes) + "}" + (last ? "\n" : ",\n");
}

}  // namespace

InstanceBufferBytes encode_instance_buffer(const PieceSet& set, const Forest& forest,
                                           const std::string& binary_name,
                                           const std::string& meshes_name) {
  const PiecesLayout layout = layout_forest(set, forest);
  const std::size_t types = set.types.size(), trees = forest.trees.size();
  const std::size_t instances = layout.instances.size(), bones = layout.bone_count();
  const std::size_t tiles = layout.tiles.size();
  const std::size_t ranges_offset = kInstanceBufferHeaderBytes;
  const std::size_t bones_offset = (ranges_offset + 8 * types + 15) / 16 * 16;
  const std::size_t instances_offset = bones_offset + kBoneRecordBytes * bones;
  const std::size_t tiles_offset = instances_offset + kInstanceRecordBytes * instances;
  const std::size_t total = (tiles_offset + 2 * tiles + 3) / 4 * 4;
  if (total > 0xffffffffull) {
    throw PiecesError("the instance buffer would exceed 4 GiB (" + std::to_string(total) +
                      " bytes); write fewer trees");
  }
  InstanceBufferBytes out;
  std::string& b = out.binary;
  b.reserve(total);
  b.append(kInstanceBufferMagic, 4);
  for (std::size_t v :
       {std::size_t(kInstanceBufferVersion), std::size_t(kInstanceBufferHeaderBytes), types, trees,
        instances, bones, tiles, ranges_offset, bones_offset, instances_offset, tiles_offset}) {
    put_u32(b, std::uint32_t(v));
  }
  for (const TypeRange& r : layout.type_ranges) {
    put_u32(b, r.first);
    put_u32(b, r.count);
  }
  pad_to(b, 16);
  // In the glTF file's y-up frame, since the bones skin that file's piece meshes.
  for (const Mat4& m : layout.skinning)
    for (double x : mesh::z_up_to_y_up_matrix(m.m)) put_f32(b, float(x));
  for (std::uint32_t i : layout.by_type) {
    const OutputInstance& inst = layout.instances[i];
    put_u32(b, inst.bone_offset);
    put_u32(b, inst.tile_offset);
    put_u32(b, inst.tree);
    put_u16(b, std::uint16_t(inst.type));
    put_u16(b, std::uint16_t(set.types[inst.type].joints.size()));
  }
  for (std::uint16_t t : layout.tiles) put_u16(b, t);
  pad_to(b, 4);

  std::string& j = out.manifest;
  j += "{\n";
  j += "  \"format\": \"ramus-pieces-instance-buffer\",\n";
  j += "  \"version\": " + std::to_string(kInstanceBufferVersion) + ",\n";
  j += "  \"binary\": " + json_string(binary_name) + ",\n";
  j += "  \"bytes\": " + std::to_string(total) + ",\n";
  if (!meshes_name.empty()) j += "  \"meshes\": " + json_string(meshes_name) + ",\n";
  j += "  \"pieceSet\": " + json_string(set.name) + ",\n";
  j += "  \"trees\": " + std::to_string(trees) + ",\n";
  j += "  \"instances\": " + std::to_string(instances) + ",\n";
  j += "  \"bones\": " + std::to_string(bones) + ",\n";
  j += "  \"tiles\": " + std::to_string(tiles) + ",\n";
  std::uint32_t slices = 0;  // texture-array slices the tiles address
  for (std::uint16_t t : layout.tiles) slices = std::max<std::uint32_t>(slices, t + 1u);
  j += "  \"tileSlices\": " + std::to_string(slices) + ",\n";
  j += "  \"sections\": {\n";
  j += section("ranges", ranges_offset, 8 * types);
  j += section("bones", bones_offset, kBoneRecordBytes * bones);
  j += section("instances", instances_offset, kInstanceRecordBytes * instances);
  j += section("tiles", tiles_offset, 2 * tiles, true);
  j += "  },\n";
  j += "  \"pieceTypes\": [\n";
  for (std::size_t t = 0; t < types; ++t) {
    const PieceType& type = set.types[t];
    const std::size_t quads = type.lods.empty() ? 0 : type.lods[0].quads.size();
    j += "    {\"index\": " + std::to_string(t) + ", \"name\": " + json_string(type.name) +
         ", \"mesh\": " + json_string(type.name) +
         ", \"joints\": " + std::to_string(type.joints.size()) +
         ", \"quads\": " + std::to_string(quads) +
         ", \"firstInstance\": " + std::to_string(layout.type_ranges[t].first) +
         ", \"instanceCount\": " + std::to_string(layout.type_ranges[t].count) + "}" +
         (t + 1 < types ? ",\n" : "\n");
  }
  j += "  ]\n}\n";
  return out;
}

std::string write_instance_buffer(const PieceSet& set, const Forest& forest,
                                  const std::string& path, const std::string& meshes_name) {
  std::filesystem::path manifest(path);
  manifest.replace_extension(".json");
  if (manifest == std::filesystem::path(path)) manifest += ".manifest.json";
  const InstanceBufferBytes bytes = encode_instance_buffer(
      set, forest, std::filesystem::path(path).filename().string(), meshes_name);
  write_file_atomically(path, bytes.binary);
  write_file_atomically(manifest.string(), bytes.manifest);
  return manifest.string();
}

}  // namespace ramus::pieces
