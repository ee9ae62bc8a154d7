// The base protocol's framing (lsp/framing.h): Content-Length headers, several messages in one
// read or one message over many, header errors and resynchronization, truncated input.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>

#include "lsp/framing.h"

namespace {

using ramus::lsp::Frame;
using ramus::lsp::FrameReader;

// A reader over `bytes` that hands out at most `chunk` bytes per read.
FrameReader reader_over(const std::string& bytes, std::size_t chunk,
                        std::size_t max_body = 1 << 20) {
  auto pos = std::make_shared<std::size_t>(0);
  return FrameReader(
      [bytes, chunk, pos](char* data, std::size_t size) {
        std::size_t n = std::min({size, chunk, bytes.size() - *pos});
        std::memcpy(data, bytes.data() + *pos, n);
        *pos += n;
        return n;
      },
      max_body);
}

}  // namespace

TEST_CASE("framing: messages whole and in pieces") {
  const std::string bytes = ramus::lsp::frame_message("{\"a\":1}") +
                            "Content-Type: application/vscode-jsonrpc; charset=utf-8\r\n"
                            "Content-Length: 2\r\n\r\n[]" +
                            ramus::lsp::frame_message("\"é\"");
  for (std::size_t chunk : {std::size_t(1), std::size_t(3), std::size_t(1000)}) {
    FrameReader r = reader_over(bytes, chunk);
    Frame a = r.next(), b = r.next(), c = r.next(), end = r.next();
    CHECK(a.kind == Frame::Kind::Message);
    CHECK(a.body == "{\"a\":1}");
    CHECK(b.body == "[]");
    CHECK(c.body == "\"é\"");  // the length counts bytes, not characters
    CHECK(end.kind == Frame::Kind::End);
  }
  CHECK(ramus::lsp::frame_message("{}") == "Content-Length: 2\r\n\r\n{}");
}

TEST_CASE("framing: bad headers are reported and reading goes on") {
  FrameReader r = reader_over(
      "Content-Length: x1\r\n\r\nContent-Type: a\r\n\r\nno colon\r\n\r\ncontent-length:  3 \n\n[1]",
      7);
  Frame a = r.next();
  CHECK(a.kind == Frame::Kind::BadHeader);
  CHECK(a.error.find("not a number") != std::string::npos);
  Frame b = r.next();
  CHECK(b.kind == Frame::Kind::BadHeader);
  CHECK(b.error == "no Content-Length header");
  CHECK(r.next().kind == Frame::Kind::BadHeader);
  Frame d = r.next();
  CHECK(d.kind == Frame::Kind::Message);
  CHECK(d.body == "[1]");
}

TEST_CASE("framing: a body over the limit is skipped, a truncated one ends the stream") {
  FrameReader r =
      reader_over("Content-Length: 10\r\n\r\n0123456789" + ramus::lsp::frame_message("{}"), 4, 8);
  Frame big = r.next();
  CHECK(big.kind == Frame::Kind::BadHeader);
  CHECK(big.error.find("over the limit") != std::string::npos);
  CHECK(r.next().body == "{}");
  FrameReader t = reader_over("Content-Length: 10\r\n\r\n0123", 100);
  CHECK(t.next().kind == Frame::Kind::End);
  FrameReader h = reader_over("Content-Len", 100);
  CHECK(h.next().kind == Frame::Kind::End);
}
