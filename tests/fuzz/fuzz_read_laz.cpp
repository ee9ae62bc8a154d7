// Fuzz target for the LAZ decoder (formats/laz/, reached through the LAS reader when the point
// format's compression bit is set): any input either reads or raises FormatError; a cloud that
// reads must survive a PLY write and read-back with the same point count. The seeds are small
// LAZ files of point formats 0 and 3 (LASzip 2 items) and 6 (the layered coder), with one chunk
// and with chunks of a few points (so the chunk table is exercised), and a truncated chunk.
#include <cstddef>
#include <cstdint>

#include "fuzz_read_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ramus::fuzz::read_point_cloud_once(data, size, ramus::Format::kLas, "fuzz.laz");
}
