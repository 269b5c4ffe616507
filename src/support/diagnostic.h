// Diagnostics as values: a code from the dialect's registered list, the text, the place, notes.
// Printed the way gcc and clang print them, or as JSON for editors and CI.
#pragma once
#include <string>
#include <vector>

#include "support/source.h"

namespace uprog {

enum class Severity { Error, Warning, Note };

struct DiagnosticNote {
  Location where;
  std::string message;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string scheme;  // who owns the code: "gold", "image", "cli", ...
  int code = 0;
  std::string message;
  Location where;
  std::vector<DiagnosticNote> notes;
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

// "file:line:col: error: text [scheme code]" and its notes, one per line.
std::string format_text(const Diagnostic& d);
std::string format_text(const std::vector<Diagnostic>& ds);
// A JSON array of {file, line, column, severity, code, message, notes}.
std::string format_json(const std::vector<Diagnostic>& ds);

}  // namespace uprog
