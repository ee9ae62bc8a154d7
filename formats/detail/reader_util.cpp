#include "formats/detail/reader_util.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "core/input_file.h"
#include "formats/voxel_thin.h"

namespace ramus {

static std::string position_text(std::size_t line, std::size_t column, std::size_t byte) {
  constexpr std::size_t none = FormatError::kNoPosition;
  if (line != none && column != none) {
    return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
  }
  if (line != none) return "line " + std::to_string(line) + ": ";
  if (byte != none) return "byte " + std::to_string(byte) + ": ";
  return {};
}

FormatError::FormatError(std::string file, std::size_t line, std::size_t byte, std::string message,
                         std::size_t column)
    : std::runtime_error(file + ": " + position_text(line, column, byte) + message),
      file_(std::move(file)),
      line_(line),
      byte_(byte),
      message_(std::move(message)),
      column_(column) {}

}  // namespace ramus

namespace ramus::formats_detail {

void fail_at_line(const std::string& file, std::size_t line, std::string message) {
  throw FormatError(file, line, FormatError::kNoPosition, std::move(message));
}

void fail_at_byte(const std::string& file, std::size_t byte, std::string message) {
  throw FormatError(file, FormatError::kNoPosition, byte, std::move(message));
}

void fail(const std::string& file, std::string message) {
  throw FormatError(file, FormatError::kNoPosition, FormatError::kNoPosition, std::move(message));
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (token.size() > kMax) out += "...";
  return out + "'";
}

static char lower(char c) { return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c; }

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = lower(c);
  return out;
}

bool parse_double(std::string_view token, double& out) {
  const char* b = token.data();
  const char* e = b + token.size();
  if (b != e && *b == '+') ++b;
  if (b == e) return false;
  auto [ptr, ec] = std::from_chars(b, e, out);
  if (ec == std::errc::result_out_of_range && ptr == e) {
    // from_chars leaves `out` unset on overflow/underflow; strtod (rare path only) gives the
    // IEEE result: +-inf or a (denormal) number near zero.
    std::string copy(b, e);
    out = std::strtod(copy.c_str(), nullptr);
    if (token.front() == '-' && out > 0) out = -out;
    return true;
  }
  return ec == std::errc() && ptr == e;
}

bool parse_u64(std::string_view token, std::uint64_t& out) {
  if (token.empty()) return false;
  auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  return ec == std::errc() && ptr == token.data() + token.size();
}

bool LineCursor::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;
  ++line_;
  return true;
}

void split_tokens(std::string_view line, std::string_view extra_separators,
                  std::vector<std::string_view>& tokens) {
  tokens.clear();
  auto is_sep = [&](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' ||
           extra_separators.find(c) != std::string_view::npos;
  };
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && is_sep(line[i])) ++i;
    std::size_t start = i;
    while (i < n && !is_sep(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
}

std::string_view trim(std::string_view s) {
  auto ws = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (!s.empty() && ws(s.front())) s.remove_prefix(1);
  while (!s.empty() && ws(s.back())) s.remove_suffix(1);
  return s;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

CloudBuilder::CloudBuilder(std::string name, const ReadOptions& options, const ReadPass& pass)
    : name_(std::move(name)),
      options_(options),
      pass_(pass),
      max_points_(max_input_points()),
      assumed_(pass.offset),
      lo_{kInf, kInf, kInf},
      hi_{-kInf, -kInf, -kInf} {}

void CloudBuilder::reserve(std::uint64_t n, std::uint64_t cap) {
  if (pass_.thinner) return;  // the kept points are not known in advance
  std::size_t r = std::size_t(std::min(n, cap));
  points_.reserve(r);
  if (has_normals_) normals_.reserve(r);
  if (has_intensity_) intensity_.reserve(r);
  if (has_classification_) classification_.reserve(r);
}

// The offset finish() gives a cloud with this bounding box: its centre rounded to a whole unit,
// so the offset prints nicely and every float position is a small number near zero (best
// resolution for UTM-scale data).
static Vec3 offset_of_box(const Vec3& lo, const Vec3& hi) {
  Vec3 o;
  for (int k = 0; k < 3; ++k) o[k] = std::round(lo[k] * 0.5 + hi[k] * 0.5);
  return o;
}

void CloudBuilder::guess_offset(const Vec3& lo, const Vec3& hi) {
  if (!pass_.thinner || assumed_ || added_ > 0) return;
  if (!is_finite(lo) || !is_finite(hi)) return;
  assumed_ = offset_of_box(lo, hi);
}
float to_float(double d) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (d > kMax) return std::numeric_limits<float>::infinity();
  if (d < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(d);
}

bool CloudBuilder::add(const Vec3& p, const Vec3& normal, double intensity, std::uint8_t cls) {
  if (!is_finite(p)) {
    ++skipped_;
    return false;
  }
  ++added_;
  for (int k = 0; k < 3; ++k) {
    lo_[k] = std::min(lo_[k], p[k]);
    hi_[k] = std::max(hi_[k], p[k]);
  }
  if (has_intensity_ && intensity != 0) any_intensity_ = true;
  if (has_classification_ && cls != 0) any_classification_ = true;
  if (pass_.thinner) {
    if (!assumed_) return true;  // a first pass that only measures the box
    // Exactly what thin_cloud sees: the world position of the narrowed point.
    const Vec3f local(p - *assumed_);
    if (!pass_.thinner->keep(*assumed_, local)) return true;
    kept_.push_back(local);
  } else {
    points_.push_back(p);
  }
  // The limit counts the points the cloud holds, so --thin lets a larger scan through.
  if (kept_.size() + points_.size() > max_points_) {
    fail(name_, "more than " + std::to_string(max_points_) +
                    " points (--max-points): thin the scan while reading (--thin S), tile it "
                    "(ramus tile) or raise the limit");
  }
  if (has_normals_)
    normals_.push_back({to_float(normal.x), to_float(normal.y), to_float(normal.z)});
  if (has_intensity_) intensity_.push_back(to_float(intensity));
  if (has_classification_) classification_.push_back(cls);
  return true;
}

PointCloud CloudBuilder::finish(ReadReport* report, Format format, std::string variant) {
  if (added_ == 0) {
    if (skipped_ > 0) {
      fail(name_, "no points: all " + std::to_string(skipped_) +
                      " points have non-finite (NaN or infinite) coordinates");
    }
    fail(name_, "no points: the file holds no point data");
  }
  for (int k = 0; k < 3; ++k) {
    // Beyond this the float positions around the centre would overflow or be meaningless.
    if (!(hi_[k] - lo_[k] <= 1e30)) {
      char span[32];
      std::snprintf(span, sizeof span, "%g", hi_[k] - lo_[k]);
      fail(name_, std::string("the points span ") + span + " units along " + "xyz"[k] +
                      ", more than single precision can hold around one offset");
    }
  }
  PointCloud cloud;
  cloud.offset = offset_of_box(lo_, hi_);
  if (pass_.thinner) {
    if (!assumed_ || !(*assumed_ == cloud.offset)) throw OffsetRetry{cloud.offset};
    cloud.positions = std::move(kept_);
  } else {
    cloud.positions.resize(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      cloud.positions[i] = Vec3f(points_[i] - cloud.offset);
    }
  }
  cloud.normals = std::move(normals_);
  cloud.intensity = std::move(intensity_);
  cloud.classification = std::move(classification_);
  if (has_scanner_) cloud.scanner = scanner_;
  cloud.source = name_;
  if (report) {
    report->format = format;
    report->variant = std::move(variant);
    report->points_read = cloud.size();
    report->skipped = skipped_;
    report->points_before_thinning = added_;
  }
  return cloud;
}

}  // namespace ramus::formats_detail
