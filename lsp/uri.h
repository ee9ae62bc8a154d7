// Document URIs (RFC 3986 `file:` URIs, as LSP clients send them) and file paths.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace ramus::lsp {

// The path of a `file://` URI, percent-decoded; nullopt for other schemes (`untitled:`) and for
// URIs whose escapes are malformed.
std::optional<std::string> path_of_uri(std::string_view uri);

// The `file://` URI of an absolute path, with every byte outside RFC 3986's unreserved set
// (and '/') percent-encoded.
std::string uri_of_path(std::string_view path);

}  // namespace ramus::lsp
