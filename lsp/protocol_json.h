// The message types of protocol.h as JSON (nlohmann-json's to_json/from_json, found by ADL),
// and the JSON-RPC error codes. Included only by protocol_json.cpp and server.cpp, so the JSON
// library's header stays out of the features.
#pragma once

#include <nlohmann/json.hpp>

#include "lsp/protocol.h"

namespace ramus::lsp {

// JSON-RPC 2.0 and LSP error codes.
enum ErrorCode : int {
  kParseError = -32700,
  kInvalidRequest = -32600,
  kMethodNotFound = -32601,
  kInvalidParams = -32602,
  kInternalError = -32603,
  kServerNotInitialized = -32002,
  kRequestFailed = -32803,
};

void to_json(nlohmann::json& j, const Position& p);
void to_json(nlohmann::json& j, const Range& r);
void to_json(nlohmann::json& j, const Location& l);
void to_json(nlohmann::json& j, const LspDiagnostic& d);
void to_json(nlohmann::json& j, const TextEdit& e);
void to_json(nlohmann::json& j, const Hover& h);
void to_json(nlohmann::json& j, const CompletionItem& c);
void to_json(nlohmann::json& j, const DocumentSymbol& s);

}  // namespace ramus::lsp
