// Reads values out of a parsed JSON tree for ramus's own JSON files (skeletons, tile manifests,
// forest layouts), naming their location ("nodes[3].radius") in errors: every complaint is a
// FormatError with the file, line and column of the offending value.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>

#include "core/number_text.h"
#include "core/vec3.h"
#include "formats/detail/json.h"
#include "formats/point_cloud_io.h"  // FormatError

namespace ramus::formats_detail {

class JsonReader {
 public:
  explicit JsonReader(const std::string& file) : file_(file) {}

  [[noreturn]] void error(const JsonValue& at, const std::string& path, const std::string& msg) {
    throw FormatError(file_, at.line, FormatError::kNoPosition, path + ": " + msg, at.column);
  }

  void expect_kind(const JsonValue& v, JsonValue::Kind k, const std::string& path) {
    if (v.kind != k) {
      error(v, path,
            std::string("expected ") + formats_detail::json_kind_name(k) + ", found " +
                formats_detail::json_kind_name(v.kind));
    }
  }

  // Rejects keys outside `allowed` (a typo must not silently become a default).
  void known_keys(const JsonValue& obj, const std::string& path,
                  std::initializer_list<const char*> allowed) {
    for (const auto& [key, value] : obj.members) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || key == a;
      if (!ok) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        error(value, path + "." + key, "unknown key (expected one of " + list + ")");
      }
    }
  }

  // The member `key` of `obj`; an error naming it when it is missing.
  const JsonValue& member(const JsonValue& obj, const char* key, const std::string& path) {
    const JsonValue* v = obj.find(key);
    if (!v) error(obj, path, std::string("missing \"") + key + "\"");
    return *v;
  }

  const std::string& text(const JsonValue& v, const std::string& path) {
    expect_kind(v, JsonValue::Kind::kString, path);
    return v.text;
  }

  double number(const JsonValue& v, const std::string& path) {
    expect_kind(v, JsonValue::Kind::kNumber, path);
    return v.number;
  }

  // An integer in [lo, hi].
  std::int64_t integer(const JsonValue& v, const std::string& path, std::int64_t lo,
                       std::int64_t hi) {
    double d = number(v, path);
    if (!(d >= double(lo) && d <= double(hi)) || d != std::floor(d)) {
      error(v, path,
            "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                ", found " + number_text(d));
    }
    return std::int64_t(d);
  }

  Vec3 vec3(const JsonValue& v, const std::string& path) {
    expect_kind(v, JsonValue::Kind::kArray, path);
    if (v.items.size() != 3) {
      error(v, path, "expected 3 numbers, found " + std::to_string(v.items.size()) + " values");
    }
    Vec3 out;
    for (int k = 0; k < 3; ++k)
      out[k] = number(v.items[std::size_t(k)], path + "[" + std::to_string(k) + "]");
    return out;
  }

  static std::string number_text(double d) { return shortest_text(d); }

 private:
  const std::string& file_;
};

}  // namespace ramus::formats_detail
