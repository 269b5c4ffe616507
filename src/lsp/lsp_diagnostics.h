// The compiler's diagnostics as LSP Diagnostic objects for one open document: each over the word
// at its place, with the dialect's code and text; notes become relatedInformation. A diagnostic
// in an #include'd file is shown on the #include line that brings the file in, its own place as
// relatedInformation, since an editor shows a document's diagnostics only in that document.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lsp/text_document.h"
#include "lsp/workspace.h"
#include "support/diagnostic.h"

namespace uprog::lsp {

// `compiled_as` is the file name the document was compiled under (its path, or its URI);
// `workspace`, when given, has the included files' texts (open or on disk) for their ranges.
// The diagnostics in files `doc` includes, by the file's URI (an open document's, else its
// path's): each over its word in that file, with relatedInformation at the document's #include
// line, so that an editor shows them in the header too. Only files the workspace can read.
std::map<std::string, nlohmann::json> included_file_diagnostics(
    const TextDocument& doc, const std::string& compiled_as,
    const std::vector<Diagnostic>& diagnostics, PositionEncoding encoding,
    const Workspace& workspace);

nlohmann::json to_lsp_diagnostics(const TextDocument& doc, const std::string& compiled_as,
                                  const std::vector<Diagnostic>& diagnostics,
                                  PositionEncoding encoding, const Workspace* workspace = nullptr);

}  // namespace uprog::lsp
