// One open document as the editor features see it: its words and declarations (the dialect's
// outline), its reference, and LSP positions of the words; built for each request, from the
// text as it is. The features themselves: assist.cpp (hover, completion, signature help),
// navigation.cpp (definition, references, rename, outline, folding), semantic_tokens.cpp.
#pragma once
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "dialect/outline.h"
#include "lsp/reference_index.h"
#include "lsp/text_document.h"
#include "lsp/workspace.h"

namespace uprog::lsp {

// A request the document cannot serve (rename of a drive command): answered as RequestFailed.
class FeatureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ClientSupport {
  bool snippets = false;              // completionItem.snippetSupport
  bool hierarchical_symbols = false;  // documentSymbol.hierarchicalDocumentSymbolSupport
};

class Analysis {
 public:
  // `outline`: the document's declarations when the caller has them already (the server keeps
  // them per version); null: the dialect's outline of the text, made here.
  Analysis(const TextDocument& doc, const ReferenceIndex* reference, PositionEncoding encoding,
           const std::vector<dialect::SourceSymbol>* outline = nullptr);

  const TextDocument& doc() const { return doc_; }
  const ReferenceIndex* reference() const { return reference_; }
  PositionEncoding encoding() const { return encoding_; }
  const std::vector<dialect::SourceSymbol>& symbols() const { return symbols_; }
  const std::vector<dialect::SourceWord>& words() const { return words_; }

  // The word under `p` (or just before it: the cursor at a word's end); nullptr on none.
  const dialect::SourceWord* word_at(Position p) const;
  // The name a word stands for: a Gold label's "##start" is "start".
  static std::string_view name_of(const dialect::SourceWord& w);
  // The declaration `name` means on 1-based `line`: a local of the function there, else a
  // global one (functions and tasks first). nullptr when the document declares none.
  const dialect::SourceSymbol* symbol_for(std::string_view name, int line) const;
  // The function or task whose lines hold `line`; nullptr outside them.
  const dialect::SourceSymbol* scope_at(int line) const;
  // The words that name `symbol`: in its function when it is a local, else in the document.
  std::vector<const dialect::SourceWord*> uses_of(const dialect::SourceSymbol& symbol) const;

  // LSP positions and ranges of byte places.
  Position position(size_t offset) const;
  Position position(int line, int column) const;  // 1-based line, byte column
  size_t offset(Position p) const;
  nlohmann::json range(size_t begin, size_t end) const;
  nlohmann::json name_range(const dialect::SourceWord& w) const;  // the name part of the word
  nlohmann::json symbol_range(const dialect::SourceSymbol& s) const;
  nlohmann::json lines_range(int first_line, int last_line) const;

 private:
  const TextDocument& doc_;
  const ReferenceIndex* reference_;
  PositionEncoding encoding_;
  std::vector<size_t> line_starts_;
  std::vector<dialect::SourceSymbol> symbols_;
  std::vector<dialect::SourceWord> words_;
  std::unordered_map<std::string_view, std::vector<size_t>> by_name_;  // into symbols_
  std::vector<size_t> scopes_;  // the functions and tasks with a body, by their first line
};

// A name declared at the top level of a file the document includes (a PDL procedure in its
// header, a PUP #define in a .puh): that file and the declaration.
struct IncludedSymbol {
  const TextDocument* file = nullptr;
  dialect::SourceSymbol symbol;
};
std::optional<IncludedSymbol> included_symbol(const Analysis& a, const Workspace& w,
                                              std::string_view name);
std::vector<IncludedSymbol> included_symbols(const Analysis& a, const Workspace& w);

// The features. A name the document does not declare may come from a file it includes; the
// references to a global name reach the open documents that include its file.
nlohmann::json hover(const Analysis& a, const Workspace& w, Position p);
nlohmann::json completion(const Analysis& a, const Workspace& w, Position p,
                          const ClientSupport& client);
nlohmann::json signature_help(const Analysis& a, const Workspace& w, Position p);
nlohmann::json definition(const Analysis& a, const Workspace& w, Position p);
nlohmann::json references(const Analysis& a, const Workspace& w, Position p,
                          bool include_declaration);
nlohmann::json rename(const Analysis& a, const Workspace& w, Position p,
                      const std::string& new_name);
// LSP 3.17 prepareRename: the name's range and text, or FeatureError when it is not renamed.
nlohmann::json prepare_rename(const Analysis& a, const Workspace& w, Position p);
nlohmann::json document_symbols(const Analysis& a, const ClientSupport& client);
nlohmann::json folding_ranges(const Analysis& a);

// The semantic token legend the server announces, and the tokens of a document (LSP 3.17's
// relative encoding: five integers per token).
nlohmann::json semantic_token_legend();
nlohmann::json semantic_tokens(const Analysis& a, const Workspace& w);

}  // namespace uprog::lsp
