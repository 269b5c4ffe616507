// Which file of the page's folder an HTTP target names, and its content type. Only plain names
// under the folder: no "..", no hidden files, no escapes, so a request cannot read elsewhere.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace uprog::studio {

// The file's path for a GET of `target` ("/", "/app.js?v=2"); nullopt for a target that names
// nothing the page may serve.
std::optional<std::string> page_file_path(const std::string& folder, std::string_view target);
std::string_view content_type(std::string_view path);

}  // namespace uprog::studio
