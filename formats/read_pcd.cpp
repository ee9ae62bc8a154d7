// PCD reader (the Point Cloud Library's format, v0.7 and older): ascii and binary data.
// Header keywords: VERSION FIELDS SIZE TYPE COUNT WIDTH HEIGHT VIEWPOINT POINTS DATA, each on its
// own line, DATA last. Recognized fields: x y z, normal_x normal_y normal_z, intensity,
// classification; others (rgb, curvature, padding "_", arrays with COUNT > 1) are skipped.
// VIEWPOINT's translation becomes the scanner origin unless it is PCL's default (identity at 0).
// binary_compressed (LZF) is rejected clearly.
#include <array>
#include <cmath>

#include "formats/detail/reader_util.h"

namespace ramus::formats_detail {
namespace {

enum Role : int { kX, kY, kZ, kNx, kNy, kNz, kIntensity, kClass, kNone };

Role role_of(std::string_view n) {
  static const char* names[] = {"x",        "y",        "z",         "normal_x",
                                "normal_y", "normal_z", "intensity", "classification"};
  for (int r = 0; r < kNone; ++r) {
    if (n == names[r]) return Role(r);
  }
  return kNone;
}

struct Field {
  std::string name;
  std::size_t size = 4;
  char type = 'F';
  std::size_t count = 1;
  std::size_t offset = 0;  // within a binary record
  std::size_t column = 0;  // first ascii column
  Role role = kNone;
};

struct PcdHeader {
  std::vector<Field> fields;
  std::uint64_t width = 0, height = 1, points = 0;
  bool have_width = false, have_points = false, have_size = false, have_type = false;
  std::string data;
  std::size_t data_offset = 0;
  std::size_t data_line = 0;
  std::size_t record_size = 0;  // binary
  std::size_t columns = 0;      // ascii
  std::optional<Vec3> viewpoint;
};

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& file) : lines_(bytes), file_(file) {}

  PcdHeader parse() {
    std::string_view line;
    while (lines_.next(line)) {
      split_tokens(line, {}, tok_);
      if (tok_.empty() || tok_[0].front() == '#') continue;
      if (keyword()) {
        finish();
        return h_;
      }
    }
    fail_at_line(file_, lines_.line_number(), "the file ends before the 'DATA' line");
  }

 private:
  [[noreturn]] void error(const std::string& msg) {
    fail_at_line(file_, lines_.line_number(), msg);
  }

  std::uint64_t integer(std::size_t i) {
    std::uint64_t v;
    if (i >= tok_.size() || !parse_u64(tok_[i], v)) {
      error("expected a whole number after " + std::string(tok_[0]) +
            (i < tok_.size() ? ", found " + quoted(tok_[i]) : ""));
    }
    return v;
  }

  // Checks that a per-field line has one entry per field.
  void per_field(const char* what) {
    if (h_.fields.empty()) error(std::string(what) + " before FIELDS");
    if (tok_.size() - 1 != h_.fields.size()) {
      error(std::string(what) + " has " + std::to_string(tok_.size() - 1) +
            " entries but FIELDS has " + std::to_string(h_.fields.size()));
    }
  }

  // Handles one header line; returns true at DATA.
  bool keyword() {
    std::string_view k = tok_[0];
    if (k == "VERSION") return false;
    if (k == "FIELDS") {
      if (tok_.size() < 2) error("FIELDS names no field");
      for (std::size_t i = 1; i < tok_.size(); ++i) {
        Field f;
        f.name = std::string(tok_[i]);
        f.role = role_of(f.name);
        h_.fields.push_back(f);
      }
    } else if (k == "SIZE") {
      per_field("SIZE");
      for (std::size_t i = 0; i < h_.fields.size(); ++i) {
        std::uint64_t s = integer(i + 1);
        if (s != 1 && s != 2 && s != 4 && s != 8)
          error("SIZE must be 1, 2, 4 or 8, found " + quoted(tok_[i + 1]));
        h_.fields[i].size = std::size_t(s);
      }
      h_.have_size = true;
    } else if (k == "TYPE") {
      per_field("TYPE");
      for (std::size_t i = 0; i < h_.fields.size(); ++i) {
        std::string_view t = tok_[i + 1];
        if (t != "F" && t != "I" && t != "U") error("TYPE must be F, I or U, found " + quoted(t));
        h_.fields[i].type = t[0];
      }
      h_.have_type = true;
    } else if (k == "COUNT") {
      per_field("COUNT");
      for (std::size_t i = 0; i < h_.fields.size(); ++i) {
        std::uint64_t c = integer(i + 1);
        if (c == 0 || c > 1 << 20)
          error("COUNT must be between 1 and 2^20, found " + quoted(tok_[i + 1]));
        h_.fields[i].count = std::size_t(c);
      }
    } else if (k == "WIDTH") {
      h_.width = integer(1);
      h_.have_width = true;
    } else if (k == "HEIGHT") {
      h_.height = integer(1);
    } else if (k == "POINTS") {
      h_.points = integer(1);
      h_.have_points = true;
    } else if (k == "VIEWPOINT") {
      viewpoint();
    } else if (k == "DATA") {
      if (tok_.size() != 2) error("expected 'DATA ascii' or 'DATA binary'");
      h_.data = std::string(tok_[1]);
      h_.data_offset = lines_.offset();
      h_.data_line = lines_.line_number() + 1;
      return true;
    } else {
      error(
          "expected a PCD header keyword (VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, "
          "VIEWPOINT, POINTS, DATA), found " +
          quoted(k));
    }
    return false;
  }

  void viewpoint() {
    if (tok_.size() != 8) error("expected 'VIEWPOINT tx ty tz qw qx qy qz'");
    double v[7];
    for (int i = 0; i < 7; ++i) {
      if (!parse_double(tok_[std::size_t(i) + 1], v[i]) || !std::isfinite(v[i])) {
        error("expected a number in VIEWPOINT, found " + quoted(tok_[std::size_t(i) + 1]));
      }
    }
    const bool is_default =
        v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 1 && v[4] == 0 && v[5] == 0 && v[6] == 0;
    if (!is_default) h_.viewpoint = Vec3{v[0], v[1], v[2]};
  }

  // Cross-field checks once DATA is reached.
  void finish() {
    if (h_.fields.empty()) error("DATA before FIELDS");
    if (!h_.have_size || !h_.have_type) error("the header needs SIZE and TYPE lines before DATA");
    if (!h_.have_width) error("the header needs a WIDTH line before DATA");
    if (h_.height != 0 && h_.width > UINT64_MAX / h_.height) error("WIDTH x HEIGHT overflows");
    if (!h_.have_points) h_.points = h_.width * h_.height;
    if (h_.points != h_.width * h_.height) {
      error("POINTS " + std::to_string(h_.points) +
            " differs from WIDTH x HEIGHT = " + std::to_string(h_.width * h_.height));
    }
    for (Field& f : h_.fields) {
      if (f.type == 'F' && f.size != 4 && f.size != 8) {
        error("field '" + f.name + "' has TYPE F with SIZE " + std::to_string(f.size) +
              " (floats are 4 or 8 bytes)");
      }
      if (f.count != 1) f.role = kNone;  // arrays (histograms, ...) are not point channels
      f.offset = h_.record_size;
      f.column = h_.columns;
      h_.record_size += f.size * f.count;
      h_.columns += f.count;
    }
    for (Role r : {kX, kY, kZ}) {
      bool found = false;
      for (const Field& f : h_.fields) found = found || f.role == r;
      if (!found) error(std::string("FIELDS has no '") + "xyz"[r] + "' field (with COUNT 1)");
    }
  }

  LineCursor lines_;
  const std::string& file_;
  std::vector<std::string_view> tok_;
  PcdHeader h_;
};

double decode(const char* p, const Field& f) {
  switch (f.type) {
    case 'F':
      return f.size == 4 ? double(load_le<float>(p)) : load_le<double>(p);
    case 'I':
      switch (f.size) {
        case 1:
          return double(load_le<std::int8_t>(p));
        case 2:
          return double(load_le<std::int16_t>(p));
        case 4:
          return double(load_le<std::int32_t>(p));
        default:
          return double(load_le<std::int64_t>(p));
      }
    default:
      switch (f.size) {
        case 1:
          return double(load_le<std::uint8_t>(p));
        case 2:
          return double(load_le<std::uint16_t>(p));
        case 4:
          return double(load_le<std::uint32_t>(p));
        default:
          return double(load_le<std::uint64_t>(p));
      }
  }
}

void enable_channels(const PcdHeader& h, CloudBuilder& b) {
  int normals = 0;
  for (const Field& f : h.fields) {
    if (f.role >= kNx && f.role <= kNz) ++normals;
    if (f.role == kIntensity) b.enable_intensity();
    if (f.role == kClass) b.enable_classification();
  }
  if (normals == 3) b.enable_normals();
  if (h.viewpoint) b.set_scanner(*h.viewpoint);
}

bool add(CloudBuilder& b, const std::array<double, kNone + 1>& v) {
  double c = v[kClass];
  std::uint8_t cls = (c >= 0 && c <= 255) ? std::uint8_t(c) : 0;
  return b.add({v[kX], v[kY], v[kZ]}, {v[kNx], v[kNy], v[kNz]}, v[kIntensity], cls);
}

void read_binary(std::string_view bytes, const std::string& file, const PcdHeader& h,
                 CloudBuilder& b) {
  const std::size_t available = bytes.size() - h.data_offset;
  const std::size_t complete = available / h.record_size;
  if (h.points > complete) {
    fail_at_byte(file, h.data_offset + complete * h.record_size,
                 "point " + std::to_string(complete) + " of " + std::to_string(h.points) +
                     " is cut off: the header announces " + std::to_string(h.points) +
                     " records of " + std::to_string(h.record_size) + " bytes");
  }
  b.reserve(h.points, complete);
  std::array<double, kNone + 1> v{};
  const char* rec = bytes.data() + h.data_offset;
  for (std::uint64_t i = 0; i < h.points; ++i, rec += h.record_size) {
    for (const Field& f : h.fields) {
      if (f.role != kNone) v[f.role] = decode(rec + f.offset, f);
    }
    if (!add(b, v) && b.strict()) {
      fail_at_byte(file, std::size_t(rec - bytes.data()),
                   "point " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
}

void read_ascii(std::string_view bytes, const std::string& file, const PcdHeader& h,
                CloudBuilder& b) {
  LineCursor lines(bytes.substr(h.data_offset));
  std::string_view line;
  std::vector<std::string_view> tok;
  std::array<double, kNone + 1> v{};
  b.reserve(h.points, (bytes.size() - h.data_offset) / 6 + 1);
  std::uint64_t i = 0;
  while (i < h.points && lines.next(line)) {
    const std::size_t n = h.data_line + lines.line_number() - 1;
    split_tokens(line, {}, tok);
    if (tok.empty()) continue;
    if (tok.size() < h.columns) {
      fail_at_line(
          file, n,
          "expected " + std::to_string(h.columns) + " values, found " + std::to_string(tok.size()));
    }
    for (const Field& f : h.fields) {
      if (f.role == kNone) continue;
      if (!parse_double(tok[f.column], v[f.role])) {
        fail_at_line(
            file, n,
            "expected a number for field '" + f.name + "', found " + quoted(tok[f.column]));
      }
    }
    if (!add(b, v) && b.strict()) fail_at_line(file, n, "the point has a non-finite coordinate");
    ++i;
  }
  if (i < h.points) {
    fail_at_line(file, h.data_line + lines.line_number(),
                 "the file ends after " + std::to_string(i) + " of the " +
                     std::to_string(h.points) + " points the header announces");
  }
}

}  // namespace

PointCloud read_pcd(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report) {
  PcdHeader h = HeaderParser(bytes, name).parse();
  if (h.data == "binary_compressed") {
    fail_at_line(name, h.data_line - 1,
                 "DATA binary_compressed (LZF) is not supported; save the "
                 "cloud as 'binary' or 'ascii' (e.g. pcl_convert_pcd_ascii_binary)");
  }
  CloudBuilder builder(name, options, pass);
  enable_channels(h, builder);
  if (h.data == "ascii") {
    read_ascii(bytes, name, h, builder);
  } else if (h.data == "binary") {
    read_binary(bytes, name, h, builder);
  } else {
    fail_at_line(name, h.data_line - 1,
                 "expected 'DATA ascii' or 'DATA binary', found " + quoted(h.data));
  }
  return builder.finish(report, Format::kPcd, "DATA " + h.data);
}

}  // namespace ramus::formats_detail
