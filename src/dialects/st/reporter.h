// Collects a compile's diagnostics: after kMaxErrors errors one TooManyErrors and nothing more.
#pragma once
#include <string>
#include <vector>

#include "dialects/st/errors.h"
#include "dialects/st/locator.h"

namespace uprog::st {

class Reporter {
 public:
  explicit Reporter(const Locator& locator) : locator_(locator) {}

  void error(Error e, size_t offset, const std::string& note = {}) { add(e, locator_.at(offset), note); }
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
  const Locator& locator() const { return locator_; }

 private:
  const Locator& locator_;
  std::vector<Diagnostic> items_;
  size_t errors_ = 0;
  bool full_ = false;
};

}  // namespace uprog::st
