// Diagnostics as values: a code from the dialect's registered list, the text, the place, notes,
// and the source line they name. Printed the way gcc and clang print them, or as JSON.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/source.h"

namespace uprog {

enum class Severity { Error, Warning, Note };

// The line a diagnostic names, as the source has it, for the excerpt under the message. It is
// carried, not read again when printed: the source may be a string, stdin or a file that has
// changed since. A long line (a binary file's) keeps only a window around the column.
struct SourceLine {
  std::string text;        // without its line end
  int first_column = 1;    // the column of text[0]; above 1 when the line is cut before it
  bool cut_after = false;  // the line goes on after text
};

struct DiagnosticNote {
  Location where;
  std::string message;
  std::optional<SourceLine> line = std::nullopt;  // only when on another line than its diagnostic
};

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string scheme;  // who owns the code: "gold", "image", "cli", ...
  int code = 0;
  std::string message;
  Location where;
  std::vector<DiagnosticNote> notes;
  std::optional<SourceLine> line = std::nullopt;  // the line `where` names, when known
};

// Collects diagnostics up to a limit; the dialect decides what to add when the limit is hit.
class DiagnosticList {
 public:
  explicit DiagnosticList(size_t limit = 1000) : limit_(limit) {}

  // Returns false (and adds nothing) once the limit is reached.
  bool add(Diagnostic d);
  bool full() const { return items_.size() >= limit_; }
  size_t error_count() const;
  bool has_errors() const { return error_count() > 0; }
  const std::vector<Diagnostic>& items() const { return items_; }
  std::vector<Diagnostic>& items() { return items_; }

 private:
  size_t limit_;
  std::vector<Diagnostic> items_;
};

// Gives every diagnostic and note that names a line of `source` (by file name) and has no line
// yet its SourceLine. One pass over the text, up to the last line asked for; nothing at all when
// no diagnostic names the file, so a clean compile pays nothing. A compiler whose sources are
// several files (an #include) calls it once per file.
void attach_source_lines(std::vector<Diagnostic>& ds, const SourceFile& source);

// Keeps the first `max_errors` errors (with the warnings and notes before the next error); the
// errors after them become one note, "N more errors not shown", at the first one left out. For
// the schemes with no "too many errors" code of their own (Gold has 46).
void limit_errors(std::vector<Diagnostic>& ds, size_t max_errors);

// `text` as it may go to a terminal: printable ASCII, tabs and valid UTF-8 stay; every other
// byte (control characters, escape sequences, invalid UTF-8, C1 and bidirectional controls)
// becomes \xNN. What would show wider than `max_columns` (a tab counts 8) is cut, "..." added.
std::string escape_unprintable(std::string_view text, size_t max_columns = std::string_view::npos);

// "file:line:col: error: text [scheme code]", then the line and a caret under the column as
// gcc prints them (" 12 |     x = y +", "    |         ^"), then each note the same way.
// Message, note and line are escaped with escape_unprintable (message and note cut at 200 columns).
std::string format_text(const Diagnostic& d);
std::string format_text(const std::vector<Diagnostic>& ds);
// A JSON array of {file, line, column, severity, code, scheme, message, notes}, with
// "source_line" where the line is known; texts escaped as in format_text.
std::string format_json(const std::vector<Diagnostic>& ds);

}  // namespace uprog
