// printl and retprintl (2.4): two hex modes, a C format checked against up to eight parameters,
// sent as MSG with the modes first; retprintl returns (or ends the task) in the same phase.
#include <cctype>
#include <charconv>

#include "dialects/pdl/compiler.h"

namespace uprog::pdl {
namespace {

struct FormatInfo {
  std::vector<char> kinds;  // 'i' an integer, 'f' a float, 's' the words of a string
  bool bad = false;
  std::vector<size_t> without_space;  // conversions not followed by a space (2.4.2)
};

FormatInfo read_format(std::string_view f) {
  FormatInfo out;
  for (size_t i = 0; i < f.size(); ++i) {
    if (f[i] != '%') continue;
    if (i + 1 < f.size() && f[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t k = i + 1;
    while (k < f.size() && std::string_view("-+ #0").find(f[k]) != std::string_view::npos) ++k;
    while (k < f.size() && std::isdigit(static_cast<unsigned char>(f[k]))) ++k;
    if (k < f.size() && f[k] == '.') {
      ++k;
      while (k < f.size() && std::isdigit(static_cast<unsigned char>(f[k]))) ++k;
    }
    if (k < f.size() && f[k] == 'l') ++k;
    if (k >= f.size()) {
      out.bad = true;
      break;
    }
    const char c = f[k];
    if (std::string_view("diuxXc").find(c) != std::string_view::npos)
      out.kinds.push_back('i');
    else if (std::string_view("feEgG").find(c) != std::string_view::npos)
      out.kinds.push_back('f');
    else if (c == 's')
      out.kinds.push_back('s');
    else
      out.bad = true;
    if (k + 1 < f.size() && f[k + 1] != ' ') out.without_space.push_back(i);
    i = k;
  }
  return out;
}

}  // namespace

void Compiler::printl_command(bool ret) {
  const size_t at = next().offset;
  begin_command(2);
  int32_t modes[2] = {0, 0};
  for (int m = 0; m < 2 && at_op("/"); ++m) {
    next();
    const Token& t = next();
    uint32_t v = 0;
    const auto [p, e] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v, 16);
    if (t.text.empty() || t.text.size() > 8 || e != std::errc() ||
        p != t.text.data() + t.text.size()) {
      error(Error::BadMode, t.offset, t.text);
    }
    modes[m] = static_cast<int32_t>(v);
  }
  expect_op("(");
  const Token& format = peek();
  if (format.kind != Tok::String) {
    error(Error::Expected, format.offset, "the format string of printl");
    return skip_to_command_end();
  }
  next();
  const FormatInfo info = read_format(format.text);
  if (info.bad) error(Error::BadFormat, format.offset, format.text);
  for (size_t i = 0; i < info.without_space.size(); ++i)
    error(Error::NoSpaceAfterFormat, format.offset);
  push_int(modes[0]);
  push_int(modes[1]);
  std::vector<Ty> types;
  std::vector<size_t> places;
  while (accept_op(",")) {
    places.push_back(peek().offset);
    types.push_back(expr());
  }
  expect_op(")");
  const size_t k = types.size();
  if (k > 8) error(Error::TooManyPrintParameters, places[8]);
  // Match the parameters against the conversions; a %s takes what the later ones leave.
  size_t s_at = info.kinds.size();
  for (size_t i = 0; i < info.kinds.size(); ++i)
    if (info.kinds[i] == 's') s_at = i;
  const size_t fixed = info.kinds.size() - (s_at < info.kinds.size() ? 1 : 0);
  if (s_at == info.kinds.size() ? k != fixed : k < fixed + 1) {
    error(Error::FormatMismatch, format.offset,
          std::to_string(k) + " parameters for " + std::to_string(info.kinds.size()) +
              " conversions");
  } else {
    const size_t after = info.kinds.size() - s_at - (s_at < info.kinds.size() ? 1 : 0);
    for (size_t i = 0; i < k; ++i) {
      char want = 0;
      if (i < s_at)
        want = info.kinds[i];
      else if (s_at < info.kinds.size() && i >= k - after)
        want = info.kinds[info.kinds.size() - (k - i)];
      if (want == 0) continue;
      if ((want == 'f') != is_float(types[i])) {
        error(Error::FormatMismatch, places[i],
              want == 'f' ? "%g wants a float" : "an integer format wants an integer");
      }
    }
  }
  image_.texts.push_back(format.text);
  text_bytes_ += format.text.size() + 1;
  slots_ += static_cast<uint32_t>(k);
  check_code_size();
  code_.emit(Op::MSG, static_cast<uint32_t>(image_.texts.size() - 1), static_cast<uint32_t>(k + 2));
  if (ret) {
    emit_ret();
    return;
  }
  end_line();
  (void)at;
}

}  // namespace uprog::pdl
