// The language server: JSON-RPC 2.0 messages in, responses and notifications out (LSP 3.17).
// It follows the specification's lifecycle: before `initialize` every request is answered with
// ServerNotInitialized; after `shutdown` requests are refused; `exit` ends the session with
// exit code 0 after a shutdown, 1 without. Whatever arrives (malformed JSON, a message that is
// not a request, an unknown method, params of the wrong types) gets a JSON-RPC error response
// when it has an id, and never ends the session.
#pragma once

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace ramus::lsp {

class Server {
 public:
  // `send` writes one JSON message (the caller frames it).
  using Send = std::function<void(const std::string& json)>;
  explicit Server(Send send);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // One message's JSON text.
  void handle(std::string_view json);
  // A message whose header could not be read: answered with a ParseError.
  void handle_bad_frame(const std::string& what);

  bool exited() const;
  // 0 after shutdown and exit, 1 when the session ended otherwise (spec: "exit" notification).
  int exit_code() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Runs a server on file descriptors (stdin and stdout for `ramus lsp`) until `exit` or the end
// of the input; returns the exit code.
int run_server(int in_fd, int out_fd);

}  // namespace ramus::lsp
