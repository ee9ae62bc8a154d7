// Writes the binary of the pieces instance buffer (pieces_instance_buffer.h). Every integer is
// written little-endian byte by byte, so the bytes do not depend on the host.
#include "formats/pieces_instance_buffer.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "core/up_axis.h"

namespace ramus {
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

struct Offsets {
  std::uint64_t ranges, bones, instances, tiles, total;
};
Offsets offsets(std::size_t types, std::size_t bones, std::size_t instances, std::size_t tiles) {
  Offsets o;
  o.ranges = kInstanceBufferHeaderBytes;
  o.bones = (o.ranges + 8 * std::uint64_t(types) + 15) / 16 * 16;
  o.instances = o.bones + kBoneRecordBytes * std::uint64_t(bones);
  o.tiles = o.instances + kInstanceRecordBytes * std::uint64_t(instances);
  o.total = (o.tiles + 2 * std::uint64_t(tiles) + 3) / 4 * 4;
  return o;
}

}  // namespace

InstanceTypeOrder order_instances_by_type(const std::vector<std::uint32_t>& instance_type,
                                          std::size_t types) {
  InstanceTypeOrder out;
  out.ranges.resize(types);
  out.by_type.resize(instance_type.size());
  std::iota(out.by_type.begin(), out.by_type.end(), 0u);
  std::stable_sort(out.by_type.begin(), out.by_type.end(), [&](std::uint32_t a, std::uint32_t b) {
    return instance_type[a] < instance_type[b];
  });
  for (std::uint32_t i = 0; i < out.by_type.size(); ++i) {
    InstanceTypeRange& r = out.ranges[instance_type[out.by_type[i]]];
    if (r.count == 0) r.first = i;
    ++r.count;
  }
  return out;
}

std::uint64_t instance_buffer_bytes(std::size_t types, std::size_t bones, std::size_t instances,
                                    std::size_t tiles) {
  return offsets(types, bones, instances, tiles).total;
}

std::string write_instance_buffer_binary(const InstanceBufferTables& t) {
  const std::size_t types = t.ranges.size(), bones = t.skinning.size();
  const std::size_t instances = t.instances.size(), tiles = t.tiles.size();
  const Offsets o = offsets(types, bones, instances, tiles);
  std::string b;
  b.reserve(std::size_t(o.total));
  b.append(kInstanceBufferMagic, 4);
  for (std::uint64_t v :
       {std::uint64_t(kInstanceBufferVersion), std::uint64_t(kInstanceBufferHeaderBytes),
        std::uint64_t(types), std::uint64_t(t.trees), std::uint64_t(instances),
        std::uint64_t(bones), std::uint64_t(tiles), o.ranges, o.bones, o.instances, o.tiles}) {
    put_u32(b, std::uint32_t(v));
  }
  for (const InstanceTypeRange& r : t.ranges) {
    put_u32(b, r.first);
    put_u32(b, r.count);
  }
  pad_to(b, 16);
  // In the glTF file's y-up frame, since the bones skin that file's piece meshes.
  for (const Mat4& m : t.skinning)
    for (double x : mesh::z_up_to_y_up_matrix(m.m)) put_f32(b, float(x));
  for (const InstanceRecord& r : t.instances) {
    put_u32(b, r.bone_offset);
    put_u32(b, r.tile_offset);
    put_u32(b, r.tree);
    put_u16(b, r.type);
    put_u16(b, r.joints);
  }
  for (std::uint16_t v : t.tiles) put_u16(b, v);
  pad_to(b, 4);
  return b;
}

}  // namespace ramus
