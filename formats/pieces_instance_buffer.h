// The binary half of the pieces instance buffer (docs/instance-buffer.md): the layout of the
// little-endian file a renderer uploads, written from plain tables. Two producers share it, so
// that their files agree byte for byte: the pieces back end (backends/pieces/
// output_instance_buffer.h, from an assembled forest) and the expansion of an .rmb's
// placed-pieces stream (formats/rmb/rmb_piece_stream_expand.h, which the runtime compiles too).
// Standard library and core/ only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/similarity.h"

namespace ramus {

inline constexpr char kInstanceBufferMagic[4] = {'R', 'P', 'I', 'B'};
inline constexpr std::uint32_t kInstanceBufferVersion = 1;
inline constexpr std::uint32_t kInstanceBufferHeaderBytes = 48;
inline constexpr std::uint32_t kInstanceRecordBytes = 16;
inline constexpr std::uint32_t kBoneRecordBytes = 64;

// One instance record (a placed piece), as the file stores it.
struct InstanceRecord {
  std::uint32_t bone_offset = 0;  // global index of its root-joint bone
  std::uint32_t tile_offset = 0;  // its first entry in the tile table
  std::uint32_t tree = 0;
  std::uint16_t type = 0;    // piece type
  std::uint16_t joints = 0;  // joints of that piece type
};

struct InstanceTypeRange {
  std::uint32_t first = 0;  // into the by-type order
  std::uint32_t count = 0;
};

// The instances grouped by piece type for one instanced draw call per type (section 3 of
// Burkus et al. 2017): `by_type` lists the instance indices ordered by type, stable (within a
// type the instances keep their order), `ranges` gives each type's run in it.
struct InstanceTypeOrder {
  std::vector<std::uint32_t> by_type;
  std::vector<InstanceTypeRange> ranges;
};
InstanceTypeOrder order_instances_by_type(const std::vector<std::uint32_t>& instance_type,
                                          std::size_t types);

struct InstanceBufferTables {
  std::uint32_t trees = 0;
  std::vector<InstanceTypeRange> ranges;  // per piece type
  std::vector<Mat4> skinning;             // per bone, z up (written y up)
  std::vector<InstanceRecord> instances;  // in by-type order, as written
  std::vector<std::uint16_t> tiles;       // every instance's tiles, in tree order
};

// The file's size for these counts, or more than 0xffffffff when it would not fit 32-bit offsets.
std::uint64_t instance_buffer_bytes(std::size_t types, std::size_t bones, std::size_t instances,
                                    std::size_t tiles);

// The binary file (version 1). The caller checks instance_buffer_bytes first.
std::string write_instance_buffer_binary(const InstanceBufferTables& tables);

}  // namespace ramus
