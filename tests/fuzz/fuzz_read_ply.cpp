// Fuzz target for the PLY reader: any input either reads or raises FormatError; a cloud that
// reads must survive a PLY write and read-back with the same point count.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "formats/point_cloud_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (bool skip : {true, false}) {
    ramus::ReadOptions options;
    options.skip_non_finite = skip;
    try {
      ramus::PointCloud cloud =
          ramus::read_point_cloud_bytes(bytes, ramus::Format::kPly, "fuzz.ply", options);
      ramus::PointCloud again = ramus::read_point_cloud_bytes(ramus::point_cloud_to_ply(cloud),
                                                              ramus::Format::kPly, "again.ply");
      if (again.size() != cloud.size()) std::abort();
    } catch (const ramus::FormatError&) {
    }
  }
  return 0;
}
