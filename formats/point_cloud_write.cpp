// Point-cloud writers: PLY (binary little endian or ascii) and XYZ text.
// Positions are float relative to PointCloud::offset; a file has no such offset, so when the
// offset is non-zero the writers emit world coordinates in double precision (exact: offset +
// float is representable in double for any offset a reader chooses), otherwise float.
#include <charconv>
#include <cstring>
#include <string>

#include "core/atomic_file.h"
#include "core/little_endian.h"
#include "core/number_text.h"
#include "formats/point_cloud_io.h"

namespace ramus {
namespace {

// Shortest decimal that reads back to the same value.
template <typename T>
void put_text(std::string& out, T v) {
  append_shortest(out, v);
}

bool has_offset(const PointCloud& c) { return c.offset != Vec3{0, 0, 0}; }

void check_channels(const PointCloud& c) {
  const std::size_t n = c.size();
  if ((!c.normals.empty() && c.normals.size() != n) ||
      (!c.intensity.empty() && c.intensity.size() != n) ||
      (!c.classification.empty() && c.classification.size() != n)) {
    throw WriteError("point cloud '" + c.source +
                     "' has a channel whose length differs from the point count");
  }
}

// World coordinate k of point i: float when the offset is zero, else double.
void put_world_text(std::string& out, const PointCloud& c, std::size_t i, int k) {
  if (c.offset[k] == 0) {
    put_text(out, c.positions[i][k]);
  } else {
    put_text(out, c.offset[k] + double(c.positions[i][k]));
  }
}

// One line: world position, then the channels that are present.
void put_point_text(std::string& out, const PointCloud& c, std::size_t i) {
  const bool n = !c.normals.empty(), in = !c.intensity.empty(), cl = !c.classification.empty();
  for (int k = 0; k < 3; ++k) {
    if (k) out += ' ';
    put_world_text(out, c, i, k);
  }
  if (n) {
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      put_text(out, c.normals[i][k]);
    }
  }
  if (in) {
    out += ' ';
    put_text(out, c.intensity[i]);
  }
  if (cl) out += ' ' + std::to_string(unsigned(c.classification[i]));
  out += '\n';
}

}  // namespace

std::string point_cloud_to_ply(const PointCloud& c, bool binary) {
  check_channels(c);
  const bool dbl = has_offset(c);
  const char* pos_type = dbl ? "double" : "float";
  std::string out = "ply\nformat ";
  out += binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
  out += "comment ramus point cloud";
  if (dbl) out += " (world coordinates in double precision)";
  out += "\nelement vertex " + std::to_string(c.size()) + "\n";
  for (const char* axis : {"x", "y", "z"})
    out += std::string("property ") + pos_type + " " + axis + "\n";
  const bool n = !c.normals.empty(), in = !c.intensity.empty(), cl = !c.classification.empty();
  if (n) out += "property float nx\nproperty float ny\nproperty float nz\n";
  if (in) out += "property float intensity\n";
  if (cl) out += "property uchar classification\n";
  out += "end_header\n";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (binary) {
      for (int k = 0; k < 3; ++k) {
        if (dbl) {
          append_little_endian(out, c.offset[k] + double(c.positions[i][k]));
        } else {
          append_little_endian(out, c.positions[i][k]);
        }
      }
      if (n) {
        for (int k = 0; k < 3; ++k) append_little_endian(out, c.normals[i][k]);
      }
      if (in) append_little_endian(out, c.intensity[i]);
      if (cl) append_little_endian(out, c.classification[i]);
      continue;
    }
    put_point_text(out, c, i);
  }
  return out;
}

std::string point_cloud_to_xyz(const PointCloud& c) {
  check_channels(c);
  const bool n = !c.normals.empty(), in = !c.intensity.empty(), cl = !c.classification.empty();
  std::string out = "# x y z";
  if (n) out += " nx ny nz";
  if (in) out += " intensity";
  if (cl) out += " classification";
  out += '\n';
  for (std::size_t i = 0; i < c.size(); ++i) {
    put_point_text(out, c, i);
  }
  return out;
}

void write_point_cloud_ply(const std::string& path, const PointCloud& cloud, bool binary) {
  write_file_atomically(path, point_cloud_to_ply(cloud, binary));
}

void write_point_cloud_xyz(const std::string& path, const PointCloud& cloud) {
  write_file_atomically(path, point_cloud_to_xyz(cloud));
}

}  // namespace ramus
