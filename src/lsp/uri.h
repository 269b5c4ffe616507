// file:// URIs (RFC 8089) as LSP clients send them, and the paths they name.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace uprog::lsp {

// The path a file URI names ("file:///home/a%20b.ehl" → "/home/a b.ehl"); nullopt for another
// scheme or a bad percent escape.
std::optional<std::string> path_from_uri(std::string_view uri);
// The file URI of an absolute path, with the characters a URI path may not hold escaped.
std::string uri_from_path(std::string_view path);

}  // namespace uprog::lsp
