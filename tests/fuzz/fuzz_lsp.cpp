// Fuzz target for the language server (lsp/server.h): the input is the byte stream a client
// writes, framed by lsp/framing.h and handed message by message to a server that has been
// initialized; whatever it holds (broken headers, JSON of any shape, grammar text of any kind in
// didOpen/didChange, positions anywhere) the server must answer without crashing, and every
// answer must be JSON.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

#include "lsp/framing.h"
#include "lsp/server.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ramus::lsp::Server server([](const std::string& out) {
    if (!nlohmann::json::accept(out)) std::abort();
  });
  server.handle(R"({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}})");
  std::size_t pos = 0;
  ramus::lsp::FrameReader reader(
      [&](char* out, std::size_t n) {
        n = std::min(n, size - pos);
        if (n > 0) std::memcpy(out, data + pos, n);
        pos += n;
        return n;
      },
      std::size_t(1) << 20);
  for (int i = 0; i < 64 && !server.exited(); ++i) {
    ramus::lsp::Frame f = reader.next();
    if (f.kind == ramus::lsp::Frame::Kind::End) break;
    if (f.kind == ramus::lsp::Frame::Kind::BadHeader) {
      server.handle_bad_frame(f.error);
    } else {
      server.handle(f.body);
    }
  }
  return 0;
}
