// Malformed input to `ramus lsp`: each gets a JSON-RPC error response (or, for a notification,
// nothing) and the session goes on; nothing makes the server crash or stop answering.
#include <catch2/catch.hpp>

#include "core/rng.h"
#include "tests/lsp/lsp_session.h"

namespace {

using lsp_test::json;
using lsp_test::LspSession;

int error_code(const json& m) { return m.at("error").at("code").get<int>(); }

json next(LspSession& s) {
  std::optional<json> m = s.receive();
  REQUIRE(m.has_value());
  return *m;
}

void initialize(LspSession& s) {
  s.request(1, "initialize", {{"capabilities", json::object()}});
  REQUIRE(s.response(1).contains("result"));
  s.notify("initialized");
}

// The server still answers: a known request gets its result.
void still_answers(LspSession& s, int id) {
  s.request(id, "textDocument/documentSymbol", {{"textDocument", {{"uri", "untitled:none"}}}});
  json r = s.response(id);
  CHECK(error_code(r) == -32602);  // answered (the document is not open)
}

}  // namespace

TEST_CASE("lsp malformed: requests before initialize get ServerNotInitialized") {
  LspSession s;
  s.request(7, "textDocument/hover",
            {{"textDocument", {{"uri", "file:///x.ramus"}}},
             {"position", {{"line", 0}, {"character", 0}}}});
  json r = s.response(7);
  CHECK(error_code(r) == -32002);
  s.notify("textDocument/didOpen",
           {{"textDocument", {{"uri", "file:///x.ramus"}, {"text", "x"}, {"version", 1}}}});
  initialize(s);  // the notification before initialize was dropped, not answered
  s.request(2, "initialize", {{"capabilities", json::object()}});
  CHECK(error_code(s.response(2)) == -32600);  // initialize only once
  s.notify("exit");
  CHECK(s.wait_exit() == 1);
}

TEST_CASE("lsp malformed: bad JSON, bad messages, unknown methods, wrong params") {
  LspSession s;
  initialize(s);

  s.send_body("{\"jsonrpc\": \"2.0\", \"id\": 3, \"method\": ");
  json m = next(s);
  CHECK(error_code(m) == -32700);
  CHECK(m["id"].is_null());

  s.send_body("[1, 2, 3]");
  CHECK(error_code(next(s)) == -32600);

  s.send_body("{\"jsonrpc\": \"1.0\", \"id\": 4, \"method\": \"shutdown\"}");
  m = next(s);
  CHECK(error_code(m) == -32600);
  CHECK(m["id"] == 4);

  s.send_body("{\"jsonrpc\": \"2.0\", \"id\": {\"a\": 1}, \"method\": \"shutdown\"}");
  CHECK(error_code(next(s)) == -32600);

  s.send_body("{\"jsonrpc\": \"2.0\", \"id\": 5, \"method\": 42}");
  CHECK(error_code(next(s)) == -32600);

  // Nesting that would exhaust the stack of a recursive JSON library is refused before parsing.
  s.send_body(R"({"jsonrpc":"2.0","id":40,"method":"x","params":)" + std::string(1000000, '[') +
              std::string(1000000, ']') + "}");
  m = next(s);
  CHECK(error_code(m) == -32700);
  CHECK(m["error"]["message"].get<std::string>().find("nested deeper") != std::string::npos);

  s.request(6, "textDocument/frobnicate");
  m = s.response(6);
  CHECK(error_code(m) == -32601);

  // A string id is echoed as a string.
  s.send({{"jsonrpc", "2.0"}, {"id", "abc"}, {"method", "workspace/unknown"}});
  m = next(s);
  CHECK(m["id"] == "abc");
  CHECK(error_code(m) == -32601);

  // Params of the wrong types.
  s.request(8, "textDocument/hover",
            {{"textDocument", {{"uri", 17}}}, {"position", {{"line", 0}, {"character", 0}}}});
  CHECK(error_code(s.response(8)) == -32602);
  s.notify("textDocument/didOpen", {{"textDocument",
                                     {{"uri", "untitled:a"},
                                      {"languageId", "ramus"},
                                      {"version", 1},
                                      {"text", "lsystem t { axiom F; }"}}}});
  s.diagnostics("untitled:a");
  s.request(9, "textDocument/hover",
            {{"textDocument", {{"uri", "untitled:a"}}},
             {"position", {{"line", -1}, {"character", "x"}}}});
  CHECK(error_code(s.response(9)) == -32602);
  s.request(10, "textDocument/definition", {{"textDocument", {{"uri", "untitled:a"}}}});
  CHECK(error_code(s.response(10)) == -32602);
  s.send({{"jsonrpc", "2.0"}, {"id", 11}, {"method", "textDocument/completion"}, {"params", 3}});
  CHECK(error_code(s.response(11)) == -32600);
  // A position far past the end is clamped, not an error.
  s.request(12, "textDocument/hover",
            {{"textDocument", {{"uri", "untitled:a"}}},
             {"position", {{"line", 4000}, {"character", 99999}}}});
  CHECK(s.response(12)["result"].is_null());
  // Malformed notifications change nothing and get no answer.
  s.notify("textDocument/didChange", {{"textDocument", 5}, {"contentChanges", "x"}});
  s.notify("textDocument/didOpen", {{"textDocument", {{"uri", 5}}}});
  s.notify("$/someExtension", {{"x", 1}});
  still_answers(s, 13);

  s.request(14, "shutdown", nullptr);
  CHECK(s.response(14)["result"].is_null());
  s.request(15, "textDocument/hover", json::object());
  CHECK(error_code(s.response(15)) == -32600);  // after shutdown
  s.notify("exit");
  CHECK(s.wait_exit() == 0);
}

TEST_CASE("lsp malformed: bad headers are answered and the stream resynchronizes") {
  LspSession s;
  initialize(s);
  s.write_raw("Content-Length: lots\r\n\r\n");
  CHECK(error_code(next(s)) == -32700);
  s.write_raw("Content-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n");
  CHECK(error_code(next(s)) == -32700);
  s.write_raw("garbage without a colon\r\n\r\n");
  CHECK(error_code(next(s)) == -32700);
  // Lower-case header name and bare "\n" line ends are accepted.
  const std::string body = R"({"jsonrpc":"2.0","id":20,"method":"shutdown"})";
  s.write_raw("content-length: " + std::to_string(body.size()) + "\n\n" + body);
  CHECK(s.response(20)["result"].is_null());
  s.notify("exit");
  CHECK(s.wait_exit() == 0);
}

TEST_CASE("lsp malformed: random bytes in well-framed messages, then a truncated one") {
  LspSession s;
  initialize(s);
  ramus::Rng rng(20);
  for (int i = 0; i < 200; ++i) {
    std::string body(1 + rng.next_u64() % 64, '\0');
    for (char& c : body) c = char(rng.next_u64() & 0xFF);
    if (i % 2 == 0) body[0] = '{';  // half of them start like an object
    s.send_body(body);
    json m = next(s);  // bytes that are not JSON: one ParseError each
    CHECK(error_code(m) == -32700);
  }
  still_answers(s, 30);
  // The input ends in the middle of a body: the server ends (no shutdown: code 1), no crash.
  s.write_raw("Content-Length: 100\r\n\r\n{\"jsonrpc\":");
  CHECK(s.wait_exit() == 1);
}
