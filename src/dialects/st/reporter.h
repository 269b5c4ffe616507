// Collects a compile's diagnostics: after kMaxErrors errors one TooManyErrors and nothing more.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "dialects/st/errors.h"
#include "preproc/source_locator.h"

namespace uprog::st {

class Reporter {
 public:
  explicit Reporter(const preproc::SourceLocator& locator) : locator_(locator) {}

  // A syntax error on a line that already has an error is the first one's consequence: dropped.
  void error(Error e, size_t offset, const std::string& note = {}) {
    Location where = locator_.locate(offset);
    if (e == Error::Syntax && line_has_error(where.line)) return;
    error_lines_.insert(where.line);
    add(e, std::move(where), note);
  }
  bool line_has_error(int line) const { return error_lines_.count(line) != 0; }
  void add(Error e, Location where, const std::string& note = {}) {
    if (full_) return;
    if (errors_ == kMaxErrors) {
      full_ = true;
      items_.push_back(make_error(Error::TooManyErrors, std::move(where)));
      return;
    }
    ++errors_;
    Diagnostic d = make_error(e, where);
    if (!note.empty()) d.notes.push_back(DiagnosticNote{std::move(where), note});
    items_.push_back(std::move(d));
  }
  void add(Diagnostic d) {
    if (full_) return;
    ++errors_;
    items_.push_back(std::move(d));
  }
  bool has_errors() const { return errors_ > 0; }
  std::vector<Diagnostic> take() { return std::move(items_); }
  const preproc::SourceLocator& locator() const { return locator_; }

 private:
  const preproc::SourceLocator& locator_;
  std::vector<Diagnostic> items_;
  size_t errors_ = 0;
  bool full_ = false;
  std::set<int> error_lines_;
};

}  // namespace uprog::st
