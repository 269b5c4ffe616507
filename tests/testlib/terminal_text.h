// Test support: whether text may go to a terminal as it is (no byte the terminal would act on).
#pragma once
#include <string>

namespace uprog::test {

// False for control characters other than tab and newline, DEL, and bytes that are not UTF-8.
inline bool safe_for_terminal(const std::string& s) {
  for (size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F) return false;
    if (c < 0x80) continue;
    const size_t n = c >= 0xF5 ? 0 : c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 ? 2 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    i += n - 1;
  }
  return true;
}

}  // namespace uprog::test
