// PLY reader (Turk's polygon file format): ascii, binary_little_endian and binary_big_endian.
// The header is validated line by line; the vertex element may appear anywhere among the
// elements, its properties in any order and of any numeric type. Recognized vertex properties:
// x y z, nx ny nz (or normal_x ...), intensity / scalar_intensity, classification /
// scalar_classification. Other properties, other elements and list properties (faces) are
// skipped; reading stops after the vertex element.
#include <array>
#include <limits>

#include "formats/detail/reader_util.h"

namespace ramus::formats_detail {
namespace {

enum class PlyType : std::uint8_t { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64 };

bool ply_type(std::string_view s, PlyType& t) {
  static const std::pair<const char*, PlyType> table[] = {
      {"char", PlyType::kI8},     {"int8", PlyType::kI8},     {"uchar", PlyType::kU8},
      {"uint8", PlyType::kU8},    {"short", PlyType::kI16},   {"int16", PlyType::kI16},
      {"ushort", PlyType::kU16},  {"uint16", PlyType::kU16},  {"int", PlyType::kI32},
      {"int32", PlyType::kI32},   {"uint", PlyType::kU32},    {"uint32", PlyType::kU32},
      {"float", PlyType::kF32},   {"float32", PlyType::kF32}, {"double", PlyType::kF64},
      {"float64", PlyType::kF64},
  };
  for (const auto& [name, type] : table) {
    if (s == name) {
      t = type;
      return true;
    }
  }
  return false;
}

std::size_t type_size(PlyType t) {
  static constexpr std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[std::size_t(t)];
}

double decode(const char* p, PlyType t, bool big_endian) {
  switch (t) {
    case PlyType::kI8:
      return double(load<std::int8_t>(p, big_endian));
    case PlyType::kU8:
      return double(load<std::uint8_t>(p, big_endian));
    case PlyType::kI16:
      return double(load<std::int16_t>(p, big_endian));
    case PlyType::kU16:
      return double(load<std::uint16_t>(p, big_endian));
    case PlyType::kI32:
      return double(load<std::int32_t>(p, big_endian));
    case PlyType::kU32:
      return double(load<std::uint32_t>(p, big_endian));
    case PlyType::kF32:
      return double(load<float>(p, big_endian));
    case PlyType::kF64:
      return load<double>(p, big_endian);
  }
  return 0;
}

// What a vertex property means to us.
enum Role : int { kX, kY, kZ, kNx, kNy, kNz, kIntensity, kClass, kNone };

Role role_of(std::string_view name) {
  std::string n = lowercase(name);
  if (n == "x") return kX;
  if (n == "y") return kY;
  if (n == "z") return kZ;
  if (n == "nx" || n == "normal_x") return kNx;
  if (n == "ny" || n == "normal_y") return kNy;
  if (n == "nz" || n == "normal_z") return kNz;
  if (n == "intensity" || n == "scalar_intensity") return kIntensity;
  if (n == "classification" || n == "scalar_classification") return kClass;
  return kNone;
}

struct Property {
  std::string name;
  PlyType type = PlyType::kF32;
  bool is_list = false;
  PlyType count_type = PlyType::kU8;
  Role role = kNone;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t line = 0;  // header line that declared it
};

enum class Encoding { kAscii, kLittle, kBig };

struct Header {
  Encoding encoding = Encoding::kAscii;
  std::string encoding_name;
  std::vector<Element> elements;
  std::size_t body_offset = 0;
  std::size_t body_line = 0;  // line number of the first body line (ascii)
};

void parse_property(const std::vector<std::string_view>& tok, Header& h, const std::string& file,
                    std::size_t line) {
  if (h.elements.empty()) fail_at_line(file, line, "'property' before any 'element'");
  Property p;
  std::size_t name_at = 2;
  if (tok.size() >= 2 && tok[1] == "list") {
    if (tok.size() != 5) {
      fail_at_line(file, line, "expected 'property list <count type> <item type> <name>'");
    }
    p.is_list = true;
    if (!ply_type(tok[2], p.count_type) || p.count_type == PlyType::kF32 ||
        p.count_type == PlyType::kF64) {
      fail_at_line(file, line,
                   "expected an integer type for the list count, found " + quoted(tok[2]));
    }
    if (!ply_type(tok[3], p.type)) {
      fail_at_line(file, line, "expected a property type, found " + quoted(tok[3]));
    }
    name_at = 4;
  } else {
    if (tok.size() != 3) fail_at_line(file, line, "expected 'property <type> <name>'");
    if (!ply_type(tok[1], p.type)) {
      fail_at_line(file, line,
                   "expected a property type (char, uchar, short, ushort, int, uint, "
                   "float, double or a sized name), found " +
                       quoted(tok[1]));
    }
  }
  p.name = std::string(tok[name_at]);
  Element& e = h.elements.back();
  if (e.name == "vertex") p.role = p.is_list ? kNone : role_of(p.name);
  for (const Property& q : e.props) {
    if (q.name == p.name) {
      fail_at_line(file, line,
                   "element '" + e.name + "' has two properties named " + quoted(p.name));
    }
  }
  e.props.push_back(std::move(p));
}

Header parse_header(std::string_view bytes, const std::string& file) {
  Header h;
  LineCursor lines(bytes);
  std::string_view line;
  std::vector<std::string_view> tok;
  if (!lines.next(line) || line != "ply") fail_at_line(file, 1, "expected 'ply' on the first line");
  bool have_format = false;
  while (lines.next(line)) {
    const std::size_t n = lines.line_number();
    split_tokens(line, {}, tok);
    if (tok.empty()) continue;
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "end_header") {
      if (!have_format) fail_at_line(file, n, "end of header without a 'format' line");
      h.body_offset = lines.offset();
      h.body_line = n + 1;
      return h;
    }
    if (tok[0] == "format") {
      if (have_format) fail_at_line(file, n, "a second 'format' line");
      if (tok.size() != 3) fail_at_line(file, n, "expected 'format <encoding> 1.0'");
      if (tok[1] == "ascii") {
        h.encoding = Encoding::kAscii;
      } else if (tok[1] == "binary_little_endian") {
        h.encoding = Encoding::kLittle;
      } else if (tok[1] == "binary_big_endian") {
        h.encoding = Encoding::kBig;
      } else {
        fail_at_line(
            file, n,
            "expected ascii, binary_little_endian or binary_big_endian, found " + quoted(tok[1]));
      }
      if (tok[2].substr(0, 1) != "1") {
        fail_at_line(file, n, "unsupported PLY version " + quoted(tok[2]) + " (expected 1.0)");
      }
      h.encoding_name = std::string(tok[1]);
      have_format = true;
    } else if (tok[0] == "element") {
      if (!have_format) fail_at_line(file, n, "'element' before the 'format' line");
      Element e;
      if (tok.size() != 3 || !parse_u64(tok[2], e.count)) {
        fail_at_line(file, n,
                     "expected 'element <name> <count>'" +
                         (tok.size() == 3 ? ", found count " + quoted(tok[2]) : ""));
      }
      e.name = std::string(tok[1]);
      e.line = n;
      // Two elements of one name leave it open which one holds the data (the reader would take
      // the first, the property checks the last: a property-less `vertex` of 500 million
      // zero-byte records, then one with x, y, z).
      for (const Element& other : h.elements) {
        if (other.name == e.name) {
          fail_at_line(file, n,
                       "element " + quoted(e.name) + " is declared twice (first on line " +
                           std::to_string(other.line) + ")");
        }
      }
      h.elements.push_back(std::move(e));
    } else if (tok[0] == "property") {
      parse_property(tok, h, file, n);
    } else {
      fail_at_line(file, n,
                   "expected a header keyword (format, element, property, comment, "
                   "end_header), found " +
                       quoted(tok[0]));
    }
  }
  fail_at_line(file, lines.line_number(), "the file ends before 'end_header'");
}

const Element& check_vertex(const Header& h, const std::string& file) {
  const Element* vertex = nullptr;
  for (const Element& e : h.elements) {
    if (e.name == "vertex") vertex = &e;
  }
  if (!vertex) fail(file, "the header declares no 'vertex' element");
  for (Role r : {kX, kY, kZ}) {
    bool found = false;
    for (const Property& p : vertex->props) found = found || p.role == r;
    if (!found) {
      fail_at_line(file, vertex->line,
                   std::string("element 'vertex' has no scalar property '") + "xyz"[r] + "'");
    }
  }
  return *vertex;
}

void enable_channels(const Element& vertex, CloudBuilder& b) {
  int normals = 0;
  for (const Property& p : vertex.props) {
    if (p.role >= kNx && p.role <= kNz) ++normals;
    if (p.role == kIntensity) b.enable_intensity();
    if (p.role == kClass) b.enable_classification();
  }
  if (normals == 3) b.enable_normals();
}

// Values of one vertex by role, then handed to the builder.
struct VertexValues {
  std::array<double, kNone + 1> v{};
  void add_to(CloudBuilder& b) const {
    double c = v[kClass];
    std::uint8_t cls = (c >= 0 && c <= 255) ? std::uint8_t(c) : 0;
    (void)b.add({v[kX], v[kY], v[kZ]}, {v[kNx], v[kNy], v[kNz]}, v[kIntensity], cls);
  }
};

class BinaryBody {
 public:
  BinaryBody(std::string_view bytes, const Header& h, const std::string& file, CloudBuilder& b)
      : bytes_(bytes),
        pos_(h.body_offset),
        big_(h.encoding == Encoding::kBig),
        file_(file),
        b_(b) {}

  void read(const Header& h) {
    for (const Element& e : h.elements) {
      if (e.name == "vertex") {
        vertices(e);
        return;  // what follows (faces, ...) is not needed
      }
      skip(e);
    }
  }

 private:
  std::size_t remaining() const { return bytes_.size() - pos_; }

  [[noreturn]] void cut_off(const Element& e, std::uint64_t i, std::size_t need) {
    fail_at_byte(file_, pos_,
                 e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) +
                     " is cut off: it needs " + std::to_string(need) + " more bytes, " +
                     std::to_string(remaining()) + " remain");
  }

  void skip_list(const Element& e, std::uint64_t i, const Property& p) {
    std::size_t cs = type_size(p.count_type);
    if (remaining() < cs) cut_off(e, i, cs);
    double n = decode(bytes_.data() + pos_, p.count_type, big_);
    if (n < 0) fail_at_byte(file_, pos_, "negative list length in property '" + p.name + "'");
    pos_ += cs;
    double need = n * double(type_size(p.type));
    if (need > double(remaining())) cut_off(e, i, std::size_t(need));
    pos_ += std::size_t(need);
  }

  void skip(const Element& e) {
    bool has_list = false;
    std::size_t stride = 0;
    for (const Property& p : e.props) {
      has_list = has_list || p.is_list;
      stride += type_size(p.type);
    }
    if (!has_list) {
      if (stride != 0 && e.count > remaining() / stride) cut_off(e, remaining() / stride, stride);
      pos_ += std::size_t(e.count * stride);
      return;
    }
    // Every instance consumes at least one byte (its first list count), so this loop is bounded
    // by the file size even when the header's count is huge.
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.props) {
        if (p.is_list) {
          skip_list(e, i, p);
        } else {
          if (remaining() < type_size(p.type)) cut_off(e, i, type_size(p.type));
          pos_ += type_size(p.type);
        }
      }
    }
  }

  void vertices(const Element& e) {
    b_.reserve(e.count, remaining() / 3 + 1);
    VertexValues values;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const std::size_t start = pos_;
      for (const Property& p : e.props) {
        if (p.is_list) {
          skip_list(e, i, p);
          continue;
        }
        const std::size_t s = type_size(p.type);
        if (remaining() < s) cut_off(e, i, s);
        if (p.role != kNone) values.v[p.role] = decode(bytes_.data() + pos_, p.type, big_);
        pos_ += s;
      }
      std::size_t before = b_.count();
      values.add_to(b_);
      if (b_.count() == before && b_.strict()) {
        fail_at_byte(file_, start, "vertex " + std::to_string(i) + " has a non-finite coordinate");
      }
      if ((i & 0xffff) == 0xffff) b_.release(pos_);
    }
  }

  std::string_view bytes_;
  std::size_t pos_;
  bool big_;
  const std::string& file_;
  CloudBuilder& b_;
};

class AsciiBody {
 public:
  AsciiBody(std::string_view bytes, const Header& h, const std::string& file, CloudBuilder& b)
      : text_(bytes.substr(h.body_offset)), line_(h.body_line), file_(file), b_(b) {}

  void read(const Header& h) {
    for (const Element& e : h.elements) {
      if (e.props.empty()) continue;  // instances without properties occupy no text
      if (e.name == "vertex") b_.reserve(e.count, text_.size() / 6 + 1);
      VertexValues values;
      for (std::uint64_t i = 0; i < e.count; ++i) {
        std::size_t first_line = 0;
        for (const Property& p : e.props) {
          std::size_t n = p.is_list ? list_length(e, i, p) : 1;
          for (std::size_t k = 0; k < n; ++k) {
            double v = number(e, i, p);
            if (first_line == 0) first_line = line_;
            if (!p.is_list && p.role != kNone) values.v[p.role] = v;
          }
        }
        if (e.name != "vertex") continue;
        const std::size_t before = b_.count();
        values.add_to(b_);
        if (b_.count() == before && b_.strict()) {
          fail_at_line(file_, first_line,
                       "vertex " + std::to_string(i) + " has a non-finite coordinate");
        }
      }
      if (e.name == "vertex") return;  // what follows (faces, ...) is not needed
    }
  }

 private:
  bool next_token(std::string_view& tok) {
    auto ws = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (pos_ < text_.size() && ws(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= text_.size()) return false;
    std::size_t start = pos_;
    while (pos_ < text_.size() && !ws(text_[pos_])) ++pos_;
    tok = text_.substr(start, pos_ - start);
    return true;
  }

  double number(const Element& e, std::uint64_t i, const Property& p) {
    std::string_view tok;
    std::string what = "property '" + p.name + "' of " + e.name + " " + std::to_string(i);
    if (!next_token(tok)) {
      fail_at_line(
          file_, line_,
          "the file ends where " + what + " (of " + std::to_string(e.count) + ") was expected");
    }
    double v;
    if (!parse_double(tok, v)) {
      fail_at_line(file_, line_, "expected a number for " + what + ", found " + quoted(tok));
    }
    return v;
  }

  std::size_t list_length(const Element& e, std::uint64_t i, const Property& p) {
    double n = number(e, i, p);
    // Range first: casting a huge double to an integer is undefined.
    if (!(n >= 0 && n <= double(text_.size()) && n == double(std::uint64_t(n)))) {
      fail_at_line(file_, line_, "invalid list length in property '" + p.name + "'");
    }
    return std::size_t(n);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
  const std::string& file_;
  CloudBuilder& b_;
};

}  // namespace

PointCloud read_ply(std::string_view bytes, const std::string& name, const ReadOptions& options,
                    const ReadPass& pass, ReadReport* report) {
  Header h = parse_header(bytes, name);
  const Element& vertex = check_vertex(h, name);
  CloudBuilder builder(name, options, pass);
  enable_channels(vertex, builder);
  if (h.encoding == Encoding::kAscii) {
    AsciiBody(bytes, h, name, builder).read(h);
  } else {
    BinaryBody(bytes, h, name, builder).read(h);
  }
  return builder.finish(report, Format::kPly, h.encoding_name);
}

}  // namespace ramus::formats_detail
