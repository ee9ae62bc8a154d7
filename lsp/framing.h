// The base protocol of LSP (JSON-RPC 2.0 over a byte stream): each message is a header block
// ("Content-Length: N\r\n", optionally "Content-Type: ...\r\n", then "\r\n") followed by N bytes
// of JSON. The reader never trusts the stream: a header block without a usable Content-Length is
// reported as a framing error (the server answers it with a ParseError) and reading goes on at
// the next header block; a body larger than the limit is skipped the same way.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace ramus::lsp {

struct Frame {
  enum class Kind { Message, BadHeader, End };
  Kind kind = Kind::End;
  std::string body;   // Message: the JSON text
  std::string error;  // BadHeader: what was wrong
};

class FrameReader {
 public:
  // `read` fills up to `size` bytes and returns how many (0 at the end of the stream).
  using ReadFn = std::function<std::size_t(char* data, std::size_t size)>;
  explicit FrameReader(ReadFn read, std::size_t max_body = std::size_t(64) << 20);

  // The next message, a header error, or the end of the stream (also when it ends inside a
  // message: a truncated body is not a message).
  Frame next();

 private:
  std::optional<std::string> line();  // one header line without its "\r\n"; nullopt at the end
  bool fill();
  bool read_exact(std::size_t n, std::string& out);

  ReadFn read_;
  std::size_t max_body_;
  std::string buffer_;
  std::size_t pos_ = 0;
};

// The header and body of one message, ready to write.
std::string frame_message(std::string_view json);

}  // namespace ramus::lsp
