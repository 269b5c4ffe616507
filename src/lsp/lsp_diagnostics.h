// The compiler's diagnostics as LSP Diagnostic objects for one open document: each over the word
// at its place, with the dialect's code and text; notes become relatedInformation. A diagnostic
// in an #include'd file is shown on the #include line that brings the file in, its own place as
// relatedInformation, since an editor shows a document's diagnostics only in that document.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lsp/text_document.h"
#include "lsp/workspace.h"
#include "support/diagnostic.h"

namespace uprog::lsp {

// `compiled_as` is the file name the document was compiled under (its path, or its URI);
// `workspace`, when given, has the included files' texts (open or on disk) for their ranges.
nlohmann::json to_lsp_diagnostics(const TextDocument& doc, const std::string& compiled_as,
                                  const std::vector<Diagnostic>& diagnostics,
                                  PositionEncoding encoding, const Workspace* workspace = nullptr);

}  // namespace uprog::lsp
