// Format dispatch: magic bytes first, then the file extension, then plain text as XYZ.
#include "formats/point_cloud_io.h"

#include <filesystem>
#include <optional>
#include <stdexcept>

#include "core/input_file.h"
#include "formats/detail/mapped_file.h"
#include "formats/detail/reader_util.h"
#include "formats/voxel_thin.h"

namespace ramus {

using namespace formats_detail;

const char* format_name(Format f) {
  switch (f) {
    case Format::kPly:
      return "ply";
    case Format::kXyz:
      return "xyz";
    case Format::kLas:
      return "las";
    case Format::kPcd:
      return "pcd";
    case Format::kAuto:
      break;
  }
  return "auto";
}

Format format_from_extension(std::string_view path) {
  std::size_t slash = path.find_last_of("/\\");
  std::string_view base = slash == std::string_view::npos ? path : path.substr(slash + 1);
  std::size_t dot = base.rfind('.');
  if (dot == std::string_view::npos) return Format::kAuto;
  std::string ext = lowercase(base.substr(dot + 1));
  if (ext == "ply") return Format::kPly;
  if (ext == "xyz" || ext == "txt" || ext == "asc" || ext == "csv" || ext == "pts") {
    return Format::kXyz;
  }
  if (ext == "las" || ext == "laz") return Format::kLas;
  if (ext == "pcd") return Format::kPcd;
  return Format::kAuto;
}

// A PCD header starts with optional '#' comment lines followed by VERSION or FIELDS.
static bool looks_like_pcd(std::string_view bytes) {
  LineCursor lines(bytes.substr(0, 4096));
  std::string_view line;
  while (lines.next(line)) {
    line = trim(line);
    if (line.empty() || line.front() == '#') continue;
    return line.substr(0, 8) == "VERSION " || line.substr(0, 7) == "FIELDS ";
  }
  return false;
}

Format sniff_format(std::string_view bytes) {
  if (bytes.substr(0, 4) == "ply\n" || bytes.substr(0, 5) == "ply\r\n") return Format::kPly;
  if (bytes.substr(0, 4) == "LASF") return Format::kLas;
  if (looks_like_pcd(bytes)) return Format::kPcd;
  return Format::kAuto;
}

namespace {

PointCloud read_one_pass(std::string_view bytes, Format format, const std::string& name,
                         const ReadOptions& options, const ReadPass& pass, ReadReport* report) {
  switch (format) {
    case Format::kPly:
      return read_ply(bytes, name, options, pass, report);
    case Format::kLas:
      return read_las(bytes, name, options, pass, report);
    case Format::kPcd:
      return read_pcd(bytes, name, options, pass, report);
    case Format::kXyz:
    case Format::kAuto:
      break;
  }
  return read_xyz(bytes, name, options, pass, report);
}

// Unthinned: one pass. Thinned: a pass against the reader's guess of the offset (or one that
// only measures the bounding box), and a second one against the true offset when the guess was
// wrong, after the shared thinner forgot the first pass's cubes.
PointCloud read_passes(std::string_view bytes, Format format, const std::string& name,
                       const ReadOptions& options, ReadReport* report, MappedFile* mapped) {
  ReadPass pass;
  if (mapped) pass.release = [mapped](std::size_t byte) { mapped->release_before(byte); };
  if (!(options.thin > 0)) {
    PointCloud cloud = read_one_pass(bytes, format, name, options, pass, report);
    if (report) report->passes = 1;
    return cloud;
  }
  std::optional<VoxelThinner> own;
  const bool shared = options.thinner != nullptr;
  pass.thinner = shared ? options.thinner : &own.emplace(options.thin);
  if (shared) pass.thinner->mark();  // its cubes of other files stay on a retry
  for (int passes = 1;; ++passes) {
    try {
      PointCloud cloud = read_one_pass(bytes, format, name, options, pass, report);
      if (shared) pass.thinner->commit();
      if (report) report->passes = passes;
      return cloud;
    } catch (const OffsetRetry& retry) {
      // The second pass assumes the offset the first one measured, which is the offset of the
      // same points again: it cannot ask for a third.
      if (passes > 1) throw std::logic_error("a thinned read's second pass changed the offset");
      if (shared) {
        pass.thinner->undo_since_mark();
      } else {
        pass.thinner = &own.emplace(options.thin);
      }
      pass.offset = retry.offset;
      if (mapped) mapped->restart();
    }
  }
}

}  // namespace

PointCloud read_point_cloud_bytes(std::string_view bytes, Format format, const std::string& name,
                                  const ReadOptions& options, ReadReport* report) {
  if (bytes.empty()) fail(name, "the file is empty");
  if (format == Format::kAuto) format = sniff_format(bytes);
  if (format == Format::kAuto) format = format_from_extension(name);
  if (format == Format::kAuto) format = Format::kXyz;
  return read_passes(bytes, format, name, options, report, nullptr);
}

PointCloud read_point_cloud(const std::string& path, const ReadOptions& options,
                            ReadReport* report) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not a point-cloud file");
  // The size limit first (core/input_file.h): a mapping costs no memory, but the reader's cloud
  // may, and --max-file-size is the one bound every input shares.
  if (std::string e = input_file_size_error(std::filesystem::path(path)); !e.empty()) fail(path, e);
  MappedFile file(path);
  const std::string_view bytes = file.bytes();
  if (bytes.empty()) fail(path, "the file is empty");
  // Magic bytes decide when present, so a PLY saved as .txt still reads; otherwise the
  // extension, so a .las without its signature gets the LAS reader's precise complaint.
  Format format = sniff_format(bytes);
  if (format == Format::kAuto) format = format_from_extension(path);
  if (format == Format::kAuto) format = Format::kXyz;
  return read_passes(bytes, format, path, options, report, &file);
}

}  // namespace ramus
