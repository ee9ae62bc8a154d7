#include "lsp/server.h"

#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <map>
#include <optional>

#include "lsp/analysis.h"
#include "lsp/completion.h"
#include "lsp/definition.h"
#include "lsp/diagnostics.h"
#include "lsp/document_symbols.h"
#include "lsp/formatting.h"
#include "lsp/framing.h"
#include "lsp/hover.h"
#include "lsp/protocol_json.h"
#include "lsp/uri.h"

namespace ramus::lsp {

using nlohmann::json;

namespace {

// An error to answer a request with.
struct RpcError {
  int code;
  std::string message;
};

// Params are read through these, so a missing member or one of the wrong type is InvalidParams
// naming the member.
const json& member(const json& object, const char* key) {
  if (!object.is_object())
    throw RpcError{kInvalidParams, std::string("expected an object holding '") + key + "'"};
  auto it = object.find(key);
  if (it == object.end()) throw RpcError{kInvalidParams, std::string("missing '") + key + "'"};
  return *it;
}

std::string string_member(const json& object, const char* key) {
  const json& v = member(object, key);
  if (!v.is_string()) throw RpcError{kInvalidParams, std::string("'") + key + "' must be a string"};
  return v.get<std::string>();
}

unsigned uint_member(const json& object, const char* key) {
  const json& v = member(object, key);
  if (!v.is_number_unsigned() || v.get<std::uint64_t>() > 0xFFFFFFFFu)
    throw RpcError{kInvalidParams, std::string("'") + key + "' must be a non-negative integer"};
  return v.get<unsigned>();
}

Position position_member(const json& object, const char* key) {
  const json& p = member(object, key);
  return {uint_member(p, "line"), uint_member(p, "character")};
}

// True when arrays and objects in `text` nest deeper than `limit`. Checked before parsing: the
// JSON library copies and destroys values recursively, so hostile nesting (a million `[`) would
// exhaust the stack; no LSP message nests more than a few dozen levels.
bool nested_deeper_than(std::string_view text, int limit) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

struct OpenDocument {
  std::string text;
  std::int64_t version = 0;
  std::unique_ptr<Analysis> analysis;
};

}  // namespace

struct Server::Impl {
  static constexpr int kMaxNesting = 256;
  enum class State { Uninitialized, Running, ShutDown, Exited };

  Send send;
  State state = State::Uninitialized;
  bool shutdown_received = false;
  PositionEncoding encoding = PositionEncoding::Utf16;
  std::map<std::string, OpenDocument> documents;

  void write(const json& message) {
    // Replace, not throw, on bytes that are not UTF-8 (a file's text in a message).
    send(message.dump(-1, ' ', false, json::error_handler_t::replace));
  }
  void respond(const json& id, json result) {
    write({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}});
  }
  void respond_error(const json& id, int code, const std::string& message) {
    write({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
  }
  void notify(const char* method, json params) {
    write({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
  }

  void handle(std::string_view text) {
    if (nested_deeper_than(text, kMaxNesting)) {
      respond_error(nullptr, kParseError,
                    "JSON nested deeper than " + std::to_string(kMaxNesting) + " levels");
      return;
    }
    json message;
    try {
      message = json::parse(text);
    } catch (const json::parse_error& e) {
      respond_error(nullptr, kParseError, std::string("invalid JSON: ") + e.what());
      return;
    }
    if (!message.is_object()) {
      respond_error(nullptr, kInvalidRequest, "a message must be a JSON object");
      return;
    }
    json id = nullptr;
    const bool has_id = message.contains("id");
    if (has_id) {
      id = message["id"];
      if (!id.is_string() && !id.is_number_integer()) {
        respond_error(nullptr, kInvalidRequest, "'id' must be an integer or a string");
        return;
      }
    }
    auto jsonrpc = message.find("jsonrpc");
    if (jsonrpc == message.end() || *jsonrpc != "2.0") {
      if (has_id) respond_error(id, kInvalidRequest, "'jsonrpc' must be \"2.0\"");
      return;
    }
    auto method_it = message.find("method");
    if (method_it == message.end()) return;  // a response: the server sends no requests
    if (!method_it->is_string()) {
      respond_error(id, kInvalidRequest, "'method' must be a string");
      return;
    }
    const std::string method = method_it->get<std::string>();
    json params = message.contains("params") ? message["params"] : json(nullptr);
    if (!params.is_null() && !params.is_object() && !params.is_array()) {
      if (has_id) respond_error(id, kInvalidRequest, "'params' must be an object or an array");
      return;
    }
    if (has_id) {
      request(id, method, params);
    } else {
      notification(method, params);
    }
  }

  void request(const json& id, const std::string& method, const json& params) {
    if (state == State::Uninitialized && method != "initialize") {
      respond_error(id, kServerNotInitialized, "the server has not been initialized");
      return;
    }
    if (state == State::ShutDown) {
      respond_error(id, kInvalidRequest, "the server is shut down; only 'exit' is accepted");
      return;
    }
    try {
      std::optional<json> result = answer(method, params);
      if (!result) {
        respond_error(id, kMethodNotFound, "unknown method '" + method + "'");
      } else {
        respond(id, std::move(*result));
      }
    } catch (const RpcError& e) {
      respond_error(id, e.code, e.message);
    } catch (const json::exception& e) {
      respond_error(id, kInvalidParams, e.what());
    } catch (const std::exception& e) {
      respond_error(id, kInternalError, e.what());
    }
  }

  // The result of a request, or nullopt for an unknown method.
  std::optional<json> answer(const std::string& method, const json& params) {
    if (method == "initialize") return initialize(params);
    if (method == "shutdown") {
      state = State::ShutDown;
      shutdown_received = true;
      return json(nullptr);
    }
    if (method == "textDocument/hover") {
      const Analysis& a = analysis(params);
      std::optional<Hover> h = hover_at(a, position_member(params, "position"));
      return h ? json(*h) : json(nullptr);
    }
    if (method == "textDocument/definition") {
      const Analysis& a = analysis(params);
      return json(definition_at(a, position_member(params, "position")));
    }
    if (method == "textDocument/completion") {
      const Analysis& a = analysis(params);
      return json(completion_at(a, position_member(params, "position")));
    }
    if (method == "textDocument/documentSymbol") return json(document_symbols(analysis(params)));
    if (method == "textDocument/formatting") return formatting(params);
    return std::nullopt;
  }

  json initialize(const json& params) {
    if (state != State::Uninitialized)
      throw RpcError{kInvalidRequest, "initialize was already sent"};
    if (!params.is_object()) throw RpcError{kInvalidParams, "initialize takes an object"};
    // LSP 3.17: the client lists the encodings it supports; UTF-16 is the mandatory default.
    encoding = PositionEncoding::Utf16;
    if (auto caps = params.find("capabilities"); caps != params.end() && caps->is_object()) {
      if (auto general = caps->find("general"); general != caps->end() && general->is_object()) {
        if (auto encs = general->find("positionEncodings");
            encs != general->end() && encs->is_array()) {
          for (const json& e : *encs) {
            if (e == "utf-8") encoding = PositionEncoding::Utf8;
          }
        }
      }
    }
    state = State::Running;
    return {
        {"capabilities",
         {{"positionEncoding", encoding_name(encoding)},
          {"textDocumentSync", {{"openClose", true}, {"change", 1}, {"save", true}}},  // 1: full
          {"hoverProvider", true},
          {"definitionProvider", true},
          {"completionProvider", json::object()},
          {"documentFormattingProvider", true},
          {"documentSymbolProvider", true}}},
        {"serverInfo", {{"name", "ramus"}}}};
  }

  OpenDocument& document(const json& params) {
    std::string uri = string_member(member(params, "textDocument"), "uri");
    auto it = documents.find(uri);
    if (it == documents.end()) throw RpcError{kInvalidParams, "document is not open: " + uri};
    return it->second;
  }

  const Analysis& analysis(const json& params) {
    OpenDocument& d = document(params);
    if (!d.analysis) throw RpcError{kRequestFailed, "the document could not be analysed"};
    return *d.analysis;
  }

  json formatting(const json& params) {
    std::string uri = string_member(member(params, "textDocument"), "uri");
    OpenDocument& doc = document(params);
    std::string name = path_of_uri(uri).value_or(uri);
    auto result = format_document(name, doc.text, encoding);
    if (const auto* failure = std::get_if<FormatFailure>(&result)) {
      throw RpcError{kRequestFailed, failure->message};
    }
    return json(std::get<std::vector<TextEdit>>(result));
  }

  void notification(const std::string& method, const json& params) {
    if (method == "exit") {
      state = State::Exited;
      return;
    }
    if (state != State::Running) return;  // dropped, as the specification says
    try {
      if (method == "textDocument/didOpen") {
        const json& doc = member(params, "textDocument");
        std::string uri = string_member(doc, "uri");
        std::string text = string_member(doc, "text");
        const json& version = member(doc, "version");
        OpenDocument& d = documents[uri];
        d.text = std::move(text);
        d.version = version.is_number_integer() ? version.get<std::int64_t>() : 0;
        analyse(uri, d);
      } else if (method == "textDocument/didChange") {
        changed(params);
      } else if (method == "textDocument/didClose") {
        std::string uri = string_member(member(params, "textDocument"), "uri");
        if (documents.erase(uri))
          notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
      } else if (method == "textDocument/didSave") {
        saved(string_member(member(params, "textDocument"), "uri"));
      }
      // Other notifications (initialized, $/cancelRequest, ...) need nothing.
    } catch (const std::exception&) {
      // A notification has no response to carry an error; a malformed one changes nothing.
    } catch (const RpcError&) {
    }
  }

  void changed(const json& params) {
    const json& doc = member(params, "textDocument");
    std::string uri = string_member(doc, "uri");
    auto it = documents.find(uri);
    if (it == documents.end()) return;
    std::string text = it->second.text;
    const json& changes = member(params, "contentChanges");
    if (!changes.is_array()) return;
    for (const json& change : changes) {
      std::string piece = string_member(change, "text");
      if (auto r = change.find("range"); r != change.end()) {
        // A client that sends ranges although full sync was asked for: apply them all the same.
        LineIndex lines(text, encoding);
        std::uint32_t b = lines.offset(position_member(*r, "start"));
        std::uint32_t e = lines.offset(position_member(*r, "end"));
        if (e < b) std::swap(b, e);
        text.replace(b, e - b, piece);
      } else {
        text = std::move(piece);
      }
    }
    it->second.text = std::move(text);
    if (auto v = doc.find("version"); v != doc.end() && v->is_number_integer())
      it->second.version = v->get<std::int64_t>();
    analyse(uri, it->second);
  }

  // Imports are read from disk: the documents that import a file see its new text once saved.
  void saved(const std::string& uri) {
    std::optional<std::string> path = path_of_uri(uri);
    if (!path) return;
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::weakly_canonical(*path, ec);
    for (auto& [other, d] : documents) {
      if (other == uri || !d.analysis) continue;
      const SourceManager& sources = d.analysis->sources();
      for (std::uint32_t id = 0; id < sources.size(); ++id) {
        if (id != d.analysis->root_id() &&
            std::filesystem::weakly_canonical(sources.name(id), ec) == file) {
          analyse(other, d);
          break;
        }
      }
    }
  }

  void analyse(const std::string& uri, OpenDocument& d) {
    d.analysis.reset();  // a failure below leaves no stale analysis behind
    d.analysis = std::make_unique<Analysis>(uri, path_of_uri(uri).value_or(""), d.text, encoding);
    notify(
        "textDocument/publishDiagnostics",
        {{"uri", uri}, {"version", d.version}, {"diagnostics", document_diagnostics(*d.analysis)}});
  }
};

Server::Server(Send send) : impl_(std::make_unique<Impl>()) { impl_->send = std::move(send); }
Server::~Server() = default;

void Server::handle(std::string_view json) { impl_->handle(json); }

void Server::handle_bad_frame(const std::string& what) {
  impl_->respond_error(nullptr, kParseError, "bad message header: " + what);
}

bool Server::exited() const { return impl_->state == Impl::State::Exited; }

int Server::exit_code() const { return impl_->shutdown_received ? 0 : 1; }

int run_server(int in_fd, int out_fd) {
  auto write_all = [out_fd](const std::string& json) {
    std::string framed = frame_message(json);
    std::size_t done = 0;
    while (done < framed.size()) {
      ssize_t n = ::write(out_fd, framed.data() + done, framed.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return;  // the client is gone; the read side will see the end
      done += std::size_t(n);
    }
  };
  Server server(write_all);
  FrameReader reader([in_fd](char* data, std::size_t size) -> std::size_t {
    for (;;) {
      ssize_t n = ::read(in_fd, data, size);
      if (n < 0 && errno == EINTR) continue;
      return n > 0 ? std::size_t(n) : 0;
    }
  });
  while (!server.exited()) {
    Frame f = reader.next();
    if (f.kind == Frame::Kind::End) break;
    if (f.kind == Frame::Kind::BadHeader) {
      server.handle_bad_frame(f.error);
    } else {
      server.handle(f.body);
    }
  }
  return server.exit_code();
}

}  // namespace ramus::lsp
