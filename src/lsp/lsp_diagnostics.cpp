// Compiler diagnostics as LSP diagnostics (lsp_diagnostics.h).
#include "lsp/lsp_diagnostics.h"

#include <cctype>
#include <filesystem>

#include "lsp/uri.h"

namespace uprog::lsp {
namespace {

using json = nlohmann::json;

json position_json(Position p) { return {{"line", p.line}, {"character", p.character}}; }

bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
}

// The range of the word at 1-based (line, byte column) of `text`; the whole line when the
// column is unknown or past its end; one character where no word starts.
json range_in(std::string_view text, int line, int column, PositionEncoding encoding) {
  const size_t start = line_start(text, line > 0 ? line - 1 : 0);
  size_t end_of_line = text.find('\n', start);
  if (end_of_line == std::string_view::npos) end_of_line = text.size();
  if (end_of_line > start && text[end_of_line - 1] == '\r') --end_of_line;
  size_t from = start, to = end_of_line;
  if (column > 0 && start + static_cast<size_t>(column - 1) < end_of_line) {
    from = start + static_cast<size_t>(column - 1);
    to = from;
    while (to < end_of_line && word_char(text[to])) ++to;
    if (to == from) ++to;
  }
  return {{"start", position_json(position_of(text, from, encoding))},
          {"end", position_json(position_of(text, to, encoding))}};
}

// A place in another file: its line's text, when the diagnostic carries it, places the column.
json range_elsewhere(const Location& where, const std::optional<SourceLine>& line,
                     PositionEncoding encoding, const std::string* file_text) {
  if (file_text != nullptr) return range_in(*file_text, where.line, where.column, encoding);
  if (line && line->first_column == 1) {
    std::string text(static_cast<size_t>(std::max(where.line - 1, 0)), '\n');
    text += line->text;
    return range_in(text, where.line, where.column, encoding);
  }
  const int64_t l = std::max(where.line - 1, 0);
  const int64_t c = std::max(where.column - 1, 0);
  return {{"start", {{"line", l}, {"character", c}}}, {"end", {{"line", l}, {"character", c}}}};
}

std::string uri_of(const std::string& file) {
  std::error_code ec;
  const auto absolute = std::filesystem::absolute(file, ec);
  return uri_from_path(ec ? file : absolute.lexically_normal().string());
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec1, ec2;
  const auto ca = std::filesystem::weakly_canonical(a, ec1);
  const auto cb = std::filesystem::weakly_canonical(b, ec2);
  return !ec1 && !ec2 && ca == cb;
}

// The 1-based line of the document's #include that names `file` (resolved beside the
// document); 0 when none does (the file comes in through another header).
int include_line(const TextDocument& doc, const std::string& compiled_as, const std::string& file) {
  const std::filesystem::path dir = std::filesystem::path(compiled_as).parent_path();
  std::string_view text = doc.text;
  int line = 1, first_include = 0;
  for (size_t at = 0; at <= text.size(); ++line) {
    size_t eol = text.find('\n', at);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view l = text.substr(at, eol - at);
    at = eol + 1;
    const size_t hash = l.find_first_not_of(" \t");
    if (hash == std::string_view::npos || l.substr(hash, 8) != "#include") continue;
    if (first_include == 0) first_include = line;
    const size_t open = l.find_first_of("\"<", hash + 8);
    if (open == std::string_view::npos) continue;
    const size_t close = l.find_first_of("\">", open + 1);
    if (close == std::string_view::npos) continue;
    std::string name(l.substr(open + 1, close - open - 1));
    for (char& c : name)
      if (c == '\\') c = '/';
    if (same_file((dir / name).string(), file) ||
        std::filesystem::path(name).filename() == std::filesystem::path(file).filename())
      return line;
  }
  return first_include;
}

int severity_of(Severity s) {
  switch (s) {
    case Severity::Error:
      return 1;
    case Severity::Warning:
      return 2;
    case Severity::Note:
      return 3;
  }
  return 1;
}

}  // namespace

std::map<std::string, json> included_file_diagnostics(const TextDocument& doc,
                                                      const std::string& compiled_as,
                                                      const std::vector<Diagnostic>& diagnostics,
                                                      PositionEncoding encoding,
                                                      const Workspace& workspace) {
  std::map<std::string, json> out;
  for (const Diagnostic& d : diagnostics) {
    if (d.where.file.empty() || d.where.file == compiled_as) continue;
    const TextDocument* file = workspace.load(d.where.file, doc);
    if (file == nullptr) continue;  // PUP's built-in akribis.puh, a file gone since
    const int line = include_line(doc, compiled_as, d.where.file);
    json& list = out[file->uri];
    if (list.is_null()) list = json::array();
    list.push_back(
        {{"range", range_in(file->text, d.where.line, d.where.column, encoding)},
         {"severity", severity_of(d.severity)},
         {"code", d.code},
         {"source", "uprog " + d.scheme},
         {"message", d.message},
         {"relatedInformation",
          json::array(
              {{{"location", {{"uri", doc.uri}, {"range", range_in(doc.text, line, 0, encoding)}}},
                {"message", "included from here"}}})}});
  }
  return out;
}

json to_lsp_diagnostics(const TextDocument& doc, const std::string& compiled_as,
                        const std::vector<Diagnostic>& diagnostics, PositionEncoding encoding,
                        const Workspace* workspace) {
  // The text of an included file, as the compiler read it (an open document's, else the disk's).
  const auto text_of = [&](const std::string& file) -> const std::string* {
    const TextDocument* d = workspace != nullptr ? workspace->load(file, doc) : nullptr;
    return d != nullptr ? &d->text : nullptr;
  };
  json out = json::array();
  for (const Diagnostic& d : diagnostics) {
    json related = json::array();
    json range;
    std::string message = d.message;
    if (d.where.file.empty() || d.where.file == compiled_as) {
      range = range_in(doc.text, d.where.line, d.where.column, encoding);
    } else {
      range = range_in(doc.text, include_line(doc, compiled_as, d.where.file), 0, encoding);
      message = "in " + std::filesystem::path(d.where.file).filename().string() + ":" +
                std::to_string(d.where.line) + ": " + d.message;
      related.push_back(
          {{"location",
            {{"uri", uri_of(d.where.file)},
             {"range", range_elsewhere(d.where, d.line, encoding, text_of(d.where.file))}}},
           {"message", d.message}});
    }
    for (const DiagnosticNote& n : d.notes) {
      const bool here = n.where.file.empty() || n.where.file == compiled_as;
      json note_range = here ? range_in(doc.text, n.where.line, n.where.column, encoding)
                             : range_elsewhere(n.where, n.line, encoding, text_of(n.where.file));
      related.push_back(
          {{"location", {{"uri", here ? doc.uri : uri_of(n.where.file)}, {"range", note_range}}},
           {"message", n.message}});
    }
    json j = {{"range", std::move(range)},
              {"severity", severity_of(d.severity)},
              {"code", d.code},
              {"source", "uprog " + d.scheme},
              {"message", std::move(message)}};
    if (!related.empty()) j["relatedInformation"] = std::move(related);
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace uprog::lsp
