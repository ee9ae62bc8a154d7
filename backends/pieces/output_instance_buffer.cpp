// Encodes the instance buffer and its manifest (output_instance_buffer.h,
// docs/instance-buffer.md). Every integer is written little-endian byte by byte, so the bytes
// do not depend on the host.
#include "backends/pieces/output_instance_buffer.h"

#include <algorithm>
#include <filesystem>

#include "core/atomic_file.h"

namespace ramus::pieces {
namespace {

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
  const std::uint64_t total = instance_buffer_bytes(types, bones, instances, tiles);
  if (total > 0xffffffffull) {
    throw PiecesError("the instance buffer would exceed 4 GiB (" + std::to_string(total) +
                      " bytes); write fewer trees");
  }
  InstanceBufferTables tables;
  tables.trees = std::uint32_t(trees);
  tables.ranges = layout.type_ranges;
  tables.skinning = layout.skinning;
  for (std::uint32_t i : layout.by_type) {
    const OutputInstance& inst = layout.instances[i];
    tables.instances.push_back({inst.bone_offset, inst.tile_offset, inst.tree,
                                std::uint16_t(inst.type),
                                std::uint16_t(set.types[inst.type].joints.size())});
  }
  tables.tiles = layout.tiles;
  InstanceBufferBytes out;
  out.binary = write_instance_buffer_binary(tables);
  const std::size_t ranges_offset = kInstanceBufferHeaderBytes;
  const std::size_t bones_offset = (ranges_offset + 8 * types + 15) / 16 * 16;
  const std::size_t instances_offset = bones_offset + kBoneRecordBytes * bones;
  const std::size_t tiles_offset = instances_offset + kInstanceRecordBytes * instances;

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
