// XYZ/TXT/ASC/CSV reader: one point per line, columns separated by whitespace, commas or
// semicolons; an optional header line (a first line that is not numeric, or a comment such as
// CloudCompare's "//X,Y,Z,Nx,Ny,Nz") names the columns. Without a header the first three columns
// are x y z and further columns are ignored.
#include <algorithm>
#include <array>

#include "formats/detail/reader_util.h"

namespace ramus::formats_detail {
namespace {

// Column index of each channel, -1 when the file has none.
struct Columns {
  std::array<int, 3> xyz{0, 1, 2};
  std::array<int, 3> normal{-1, -1, -1};
  int intensity = -1;
  int classification = -1;
  bool from_header = false;

  int needed() const {
    int m = std::max(
        {xyz[0], xyz[1], xyz[2], normal[0], normal[1], normal[2], intensity, classification});
    return m + 1;
  }
};

std::string strip_name(std::string_view t) {
  while (!t.empty() && (t.front() == '"' || t.front() == '\'' || t.front() == '/')) {
    t.remove_prefix(1);
  }
  while (!t.empty() && (t.back() == '"' || t.back() == '\'')) t.remove_suffix(1);
  return lowercase(t);
}

int channel_of(const std::string& n) {
  // 0..2 x y z, 3..5 normal, 6 intensity, 7 classification, -1 unknown
  if (n == "x") return 0;
  if (n == "y") return 1;
  if (n == "z") return 2;
  if (n == "nx" || n == "normal_x" || n == "normalx") return 3;
  if (n == "ny" || n == "normal_y" || n == "normaly") return 4;
  if (n == "nz" || n == "normal_z" || n == "normalz") return 5;
  if (n == "intensity" || n == "scalar_intensity" || n == "i") return 6;
  if (n == "classification" || n == "class" || n == "scalar_classification") return 7;
  return -1;
}

// Interprets `tokens` as column names. Returns false when they name none of x, y, z (then the
// caller uses the default layout); throws when they name some but not all three.
bool columns_from_names(const std::vector<std::string_view>& tokens, Columns& cols,
                        const std::string& file, std::size_t line) {
  Columns c;
  c.xyz = {-1, -1, -1};
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    int ch = channel_of(strip_name(tokens[i]));
    int col = int(i);
    if (ch >= 0 && ch < 3) c.xyz[ch] = col;
    if (ch >= 3 && ch < 6) c.normal[ch - 3] = col;
    if (ch == 6) c.intensity = col;
    if (ch == 7) c.classification = col;
  }
  int named = (c.xyz[0] >= 0) + (c.xyz[1] >= 0) + (c.xyz[2] >= 0);
  if (named == 0) return false;
  if (named < 3) {
    fail_at_line(file, line, "the header names only some of the columns x, y and z");
  }
  if (c.normal[0] < 0 || c.normal[1] < 0 || c.normal[2] < 0) c.normal = {-1, -1, -1};
  c.from_header = true;
  cols = c;
  return true;
}

bool is_number(std::string_view t) {
  double d;
  return parse_double(t, d);
}

const char* column_label(const Columns& c, int col) {
  static const char* names[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (c.xyz[k] == col) return names[k];
  }
  for (int k = 0; k < 3; ++k) {
    if (c.normal[k] == col) return "normal";
  }
  if (c.intensity == col) return "intensity";
  return "classification";
}

class XyzReader {
 public:
  XyzReader(std::string_view bytes, const std::string& name, const ReadOptions& options,
            const ReadPass& pass)
      : bytes_(bytes), name_(name), builder_(name, options, pass) {}

  PointCloud read(ReadReport* report);

 private:
  void header_or_first_line(std::string_view line);
  void data_line(std::string_view line);
  double number(int col);

  std::string_view bytes_;
  const std::string& name_;
  CloudBuilder builder_;
  LineCursor lines_{bytes_};
  Columns cols_;
  std::string_view separators_;
  bool seen_first_line_ = false;
  bool channels_fixed_ = false;
  std::vector<std::string_view> tokens_;
};

PointCloud XyzReader::read(ReadReport* report) {
  std::string_view line;
  while (lines_.next(line)) {
    line = trim(line);
    if (line.empty()) continue;
    bool comment = line.front() == '#' || line.substr(0, 2) == "//";
    if (comment) {
      // A comment before any data that starts with the names x, y, z is a header (CloudCompare's
      // "//X,Y,Z,...", our writer's "# x y z ..."); prose that merely mentions x, y and z is not.
      if (!seen_first_line_ && !cols_.from_header) {
        std::string_view body = line.substr(line.front() == '#' ? 1 : 2);
        split_tokens(body, ",;", tokens_);
        if (tokens_.size() >= 3 && strip_name(tokens_[0]) == "x" && strip_name(tokens_[1]) == "y" &&
            strip_name(tokens_[2]) == "z") {
          columns_from_names(tokens_, cols_, name_, lines_.line_number());
        }
      }
      continue;
    }
    if (!seen_first_line_) {
      header_or_first_line(line);
      continue;
    }
    data_line(line);
    // (Offsets count from after a byte order mark: 3 bytes fewer released, never more.)
    if ((lines_.line_number() & 0xffff) == 0) builder_.release(lines_.offset());
  }
  std::string variant = separators_ == ";"   ? "semicolon-separated"
                        : separators_ == "," ? "comma-separated"
                                             : "whitespace-separated";
  if (cols_.from_header) variant += ", columns named by a header";
  return builder_.finish(report, Format::kXyz, variant);
}

void XyzReader::header_or_first_line(std::string_view line) {
  seen_first_line_ = true;
  // The separator is fixed by the first line: ';' lines may use ',' as a decimal mark, which we
  // do not read, but we never split numbers at it silently either (the number check fails).
  if (line.find(';') != std::string_view::npos) {
    separators_ = ";";
  } else if (line.find(',') != std::string_view::npos) {
    separators_ = ",";
  }
  split_tokens(line, separators_, tokens_);
  if (!tokens_.empty() && !is_number(tokens_[0])) {
    // A header of other names keeps the default layout (or the comment header's).
    columns_from_names(tokens_, cols_, name_, lines_.line_number());
    return;
  }
  data_line(line);
}

double XyzReader::number(int col) {
  double v;
  if (!parse_double(tokens_[std::size_t(col)], v)) {
    fail_at_line(name_, lines_.line_number(),
                 "expected a number in column " + std::to_string(col + 1) + " (" +
                     column_label(cols_, col) + "), found " + quoted(tokens_[std::size_t(col)]));
  }
  return v;
}

void XyzReader::data_line(std::string_view line) {
  if (!channels_fixed_) {
    // Channels are fixed before the first point: normals, intensity, classification only when
    // a header names them.
    channels_fixed_ = true;
    if (cols_.normal[0] >= 0) builder_.enable_normals();
    if (cols_.intensity >= 0) builder_.enable_intensity();
    if (cols_.classification >= 0) builder_.enable_classification();
  }
  split_tokens(line, separators_, tokens_);
  const int needed = cols_.needed();
  if (int(tokens_.size()) < needed) {
    fail_at_line(name_, lines_.line_number(),
                 "expected " + std::to_string(needed) + " numbers, found " +
                     std::to_string(tokens_.size()) +
                     (tokens_.empty() ? std::string() : " (" + quoted(line) + ")"));
  }
  Vec3 p{number(cols_.xyz[0]), number(cols_.xyz[1]), number(cols_.xyz[2])};
  Vec3 n;
  if (cols_.normal[0] >= 0) {
    n = {number(cols_.normal[0]), number(cols_.normal[1]), number(cols_.normal[2])};
  }
  double intensity = cols_.intensity >= 0 ? number(cols_.intensity) : 0.0;
  std::uint8_t cls = 0;
  if (cols_.classification >= 0) {
    double c = number(cols_.classification);
    if (!(c >= 0 && c <= 255 && c == double(int(c)))) {
      fail_at_line(name_, lines_.line_number(),
                   "expected a whole number 0-255 for the classification, found " +
                       quoted(tokens_[std::size_t(cols_.classification)]));
    }
    cls = std::uint8_t(c);
  }
  if (!builder_.add(p, n, intensity, cls) && builder_.strict()) {
    fail_at_line(name_, lines_.line_number(), "the point has a non-finite coordinate");
  }
}

}  // namespace

PointCloud read_xyz(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report) {
  // A UTF-8 byte order mark (spreadsheet exports) would otherwise make line 1 look like a header.
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  XyzReader reader(bytes, name, options, pass);
  return reader.read(report);
}

}  // namespace ramus::formats_detail
