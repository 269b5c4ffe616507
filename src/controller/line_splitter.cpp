// Expression splitting for the Gold command line; see line_splitter.h.
#include "controller/line_splitter.h"

namespace uprog::controller {
namespace {

bool is_blank(const std::string& s) {
  for (char c : s) {
    if (c != ' ' && c != '\t') return false;
  }
  return true;
}

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  const size_t last = s.find_last_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

}  // namespace

std::vector<std::string> split_expressions(std::string_view text) {
  std::vector<std::string> out;
  std::string current;
  bool in_comment = false;
  auto flush = [&] {
    if (!is_blank(current)) out.push_back(trimmed(current));
    current.clear();
  };
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\r' || c == '\n') {
      in_comment = false;
      flush();
    } else if (in_comment) {
      continue;
    } else if (c == '*' && i + 1 < text.size() && text[i + 1] == '*') {
      in_comment = true;
      ++i;
    } else if (c == ';') {
      flush();
    } else {
      current.push_back(c);
    }
  }
  flush();
  return out;
}

}  // namespace uprog::controller
