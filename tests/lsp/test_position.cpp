// Positions (lsp/position.h): byte offsets to and from LSP line/character in UTF-16 code units
// (the default) and UTF-8, with the specification's line ends and clamping.
#include <catch2/catch.hpp>

#include "lsp/position.h"
#include "lsp/uri.h"

using ramus::lsp::LineIndex;
using ramus::lsp::Position;
using ramus::lsp::PositionEncoding;

TEST_CASE("position: UTF-16 counts a 4-byte character as two units, others as one") {
  // "aé€😀b": a (1 byte), é (2), € (3), 😀 (4), b (1)
  const std::string text =
      "x\na\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80"
      "b\n";
  LineIndex u16(text, PositionEncoding::Utf16);
  CHECK(u16.position(2) == Position{1, 0});   // a
  CHECK(u16.position(3) == Position{1, 1});   // é
  CHECK(u16.position(5) == Position{1, 2});   // €
  CHECK(u16.position(8) == Position{1, 3});   // 😀
  CHECK(u16.position(12) == Position{1, 5});  // b: after a surrogate pair
  CHECK(u16.position(10) == Position{1, 3});  // inside 😀: its start
  for (std::uint32_t off : {2u, 3u, 5u, 8u, 12u, 13u}) CHECK(u16.offset(u16.position(off)) == off);
  CHECK(u16.offset({1, 4}) == 8);            // between the surrogates: the character's start
  CHECK(u16.offset({1, 99}) == 13);          // past the line's end: the end of the line
  CHECK(u16.offset({9, 0}) == text.size());  // past the last line: the end of the text

  LineIndex u8(text, PositionEncoding::Utf8);
  CHECK(u8.position(12) == Position{1, 10});
  CHECK(u8.offset({1, 10}) == 12);
  CHECK(u8.offset({1, 7}) == 8 + 0);  // inside 😀 (bytes 8..11): back to its start
  CHECK(std::string(ramus::lsp::encoding_name(PositionEncoding::Utf8)) == "utf-8");
}

TEST_CASE("position: \\n, \\r\\n and \\r end lines") {
  const std::string text = "ab\r\ncd\ref\ngh";
  LineIndex l(text, PositionEncoding::Utf16);
  CHECK(l.line_count() == 4);
  CHECK(l.position(4) == Position{1, 0});
  CHECK(l.position(7) == Position{2, 0});
  CHECK(l.position(10) == Position{3, 0});
  CHECK(l.position(2) == Position{0, 2});  // the \r of \r\n belongs to the line end
  CHECK(l.position(3) == Position{0, 2});
  CHECK(l.offset({0, 5}) == 2);
  CHECK(l.range(4, 6).end == Position{1, 2});
}

TEST_CASE("uri: file URIs and paths") {
  CHECK(ramus::lsp::path_of_uri("file:///home/a%20b/t%C3%A9.ramus") == "/home/a b/t\xC3\xA9.ramus");
  CHECK(ramus::lsp::path_of_uri("file://localhost/x.ramus") == "/x.ramus");
  CHECK_FALSE(ramus::lsp::path_of_uri("untitled:Untitled-1").has_value());
  CHECK_FALSE(ramus::lsp::path_of_uri("file:///a%2").has_value());
  CHECK_FALSE(ramus::lsp::path_of_uri("file:///a%00b").has_value());
  CHECK(ramus::lsp::uri_of_path("/home/a b/t\xC3\xA9.ramus") == "file:///home/a%20b/t%C3%A9.ramus");
}
