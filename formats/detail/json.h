// A small strict JSON reader (RFC 8259) for ramus's own files (skeletons): no extensions, no
// comments, no trailing commas, duplicate keys rejected, nesting limited to 200 levels so hostile
// input cannot exhaust the stack. Every value remembers its line and column for messages.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ramus::formats_detail {

struct JsonMember;

struct JsonValue {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  double number = 0;
  std::string text;                 // kString
  std::vector<JsonValue> items;     // kArray
  std::vector<JsonMember> members;  // kObject, in file order
  std::size_t line = 1, column = 1;

  const JsonValue* find(std::string_view key) const;
};

// A key and its value. Not std::pair<std::string, JsonValue>: a pair of a type still incomplete
// inside JsonValue does not compile with clang and libstdc++.
struct JsonMember {
  std::string first;
  JsonValue second;
};

// "null", "true or false", "a number", ... for messages.
const char* json_kind_name(JsonValue::Kind k);

// Parses `text` (one JSON value, optional surrounding whitespace). Throws FormatError naming
// `file`, line and column on malformed input.
JsonValue parse_json(std::string_view text, const std::string& file);

// Appends `s` as a JSON string literal (quotes and escapes).
void append_json_string(std::string& out, std::string_view s);

}  // namespace ramus::formats_detail
