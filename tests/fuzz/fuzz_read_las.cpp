// Fuzz target for the LAS reader: any input either reads or raises FormatError; a cloud that
// reads must survive a PLY write and read-back with the same point count.
#include <cstddef>
#include <cstdint>

#include "fuzz_read_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ramus::fuzz::read_point_cloud_once(data, size, ramus::Format::kLas, "fuzz.las");
}
