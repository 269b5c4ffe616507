// Printing diagnostics as gcc does and as JSON, with the source line, escaped for a terminal.
#include "support/diagnostic.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <nlohmann/json.hpp>

namespace uprog {
namespace {

// A message is a sentence; one that quotes a whole line of a binary file is cut.
constexpr size_t kMaxMessageColumns = 200;
// Gold's lines hold 128 characters (its error 51); longer ones show this much around the column.
constexpr size_t kExcerptColumns = 160;

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

std::string place(const Location& w) {
  const std::string file =
      escape_unprintable(w.file);  // a path is the user's, but may hold anything
  if (w.line <= 0) return file;
  if (w.column <= 0) return fmt::format("{}:{}", file, w.line);
  return fmt::format("{}:{}:{}", file, w.line, w.column);
}

bool is_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// The length of the well-formed UTF-8 character at s[i] when a terminal shows it as a
// character, else 0: C1 controls (U+0080-U+009F) and the bidirectional controls would act.
size_t printable_utf8_length(std::string_view s, size_t i) {
  const auto b0 = static_cast<unsigned char>(s[i]);
  size_t n = 0;
  uint32_t cp = 0;
  if (b0 >= 0xC2 && b0 <= 0xDF)
    n = 2, cp = b0 & 0x1Fu;
  else if (b0 >= 0xE0 && b0 <= 0xEF)
    n = 3, cp = b0 & 0x0Fu;
  else if (b0 >= 0xF0 && b0 <= 0xF4)
    n = 4, cp = b0 & 0x07u;
  else
    return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if (!is_continuation(s[i + k])) return 0;
    cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3Fu);
  }
  const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
  const bool surrogate = cp >= 0xD800 && cp <= 0xDFFF;
  const bool bidi = cp == 0x061C || cp == 0x200E || cp == 0x200F ||
                    (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069);
  if (overlong || surrogate || cp > 0x10FFFF || cp < 0xA0 || bidi) return 0;
  return n;
}

// One character of source text as it is shown: how many bytes it is, whether they are shown as
// \xNN, and how many columns it takes (0 for a tab: it keeps its own width in the caret line).
struct Shown {
  size_t bytes;
  bool escaped;
  int width;
};

Shown show(std::string_view s, size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  if (c == '\t') return {1, false, 0};
  if (c >= 0x20 && c < 0x7F) return {1, false, 1};
  if (const size_t n = c >= 0x80 ? printable_utf8_length(s, i) : 0; n > 0) return {n, false, 1};
  return {1, true, 4};
}

void append_shown(std::string& out, std::string_view s, size_t i, const Shown& u) {
  if (u.escaped)
    fmt::format_to(std::back_inserter(out), "\\x{:02X}", static_cast<unsigned char>(s[i]));
  else
    out.append(s.substr(i, u.bytes));
}

// The line and a caret under `column`, as gcc prints them.
void append_excerpt(std::string& out, const SourceLine& l, int line, int column) {
  const std::string number = std::to_string(line);
  std::string shown = l.first_column > 1 ? "..." : "";
  std::string caret = l.first_column > 1 ? "   " : "";
  const long target = column - l.first_column;  // the caret's byte in l.text
  bool placed = column <= 0;                    // no column: no caret
  const std::string_view t = l.text;
  for (size_t i = 0; i < t.size();) {
    const Shown u = show(t, i);
    append_shown(shown, t, i, u);
    if (!placed && target < static_cast<long>(i + u.bytes)) {
      caret += '^';
      placed = true;
    } else if (!placed) {
      caret += u.width == 0 ? std::string(1, '\t') : std::string(static_cast<size_t>(u.width), ' ');
    }
    i += u.bytes;
  }
  if (l.cut_after) shown += "...";
  if (!placed) caret += std::string(static_cast<size_t>(target) - t.size(), ' ') + '^';
  out += fmt::format(" {} | {}\n", number, shown);
  if (column > 0) out += fmt::format(" {:{}} | {}\n", "", number.size(), caret);
}

// The columns a character takes when the budget of an excerpt is counted (a tab as 8).
int budget_width(const Shown& u) { return u.width == 0 ? 8 : u.width; }

// Whether `text` shows in at most `columns` columns.
bool fits(std::string_view text, size_t columns) {
  if (text.size() > columns) return false;  // every byte shows at least one column
  size_t width = 0;
  for (size_t i = 0; i < text.size() && width <= columns;) {
    const Shown u = show(text, i);
    width += static_cast<size_t>(budget_width(u));
    i += u.bytes;
  }
  return width <= columns;
}

// A long line's window around `column`, about kExcerptColumns wide as shown (a binary file's
// line is mostly \xNN), not splitting a UTF-8 character.
SourceLine window(std::string_view line, int column) {
  SourceLine l;
  if (fits(line, kExcerptColumns)) {
    l.text = std::string(line);
    return l;
  }
  const size_t at = column > 0 ? std::min(static_cast<size_t>(column - 1), line.size()) : 0;
  // Every byte shows at least one column: the window starts at most this far before `at`.
  size_t begin = at > kExcerptColumns / 2 ? at - kExcerptColumns / 2 : 0;
  for (int k = 0; k < 3 && begin < at && is_continuation(line[begin]); ++k) ++begin;
  std::vector<std::pair<size_t, int>> left;  // the characters before `at`: offset, width
  for (size_t i = begin; i < at;) {
    const Shown u = show(line, i);
    left.emplace_back(i, budget_width(u));
    i += u.bytes;
  }
  int width = 0;
  size_t from = at;
  for (size_t k = left.size();
       k-- > 0 && width + left[k].second <= static_cast<int>(kExcerptColumns / 2);) {
    width += left[k].second;
    from = left[k].first;
  }
  size_t to = at;
  while (to < line.size()) {
    const Shown u = show(line, to);
    if (width + budget_width(u) > static_cast<int>(kExcerptColumns)) break;
    width += budget_width(u);
    to += u.bytes;
  }
  l.text = std::string(line.substr(from, to - from));
  l.first_column = static_cast<int>(from) + 1;
  l.cut_after = to < line.size();
  return l;
}

}  // namespace

bool DiagnosticList::add(Diagnostic d) {
  if (full()) return false;
  items_.push_back(std::move(d));
  return true;
}

size_t DiagnosticList::error_count() const {
  size_t n = 0;
  for (const auto& d : items_) n += d.severity == Severity::Error ? 1 : 0;
  return n;
}

void attach_source_lines(std::vector<Diagnostic>& ds, const SourceFile& source) {
  struct Wanted {
    int line, column;
    std::optional<SourceLine>* slot;
  };
  std::vector<Wanted> wanted;
  auto names = [&](const Location& w) { return w.line > 0 && w.file == source.name; };
  for (Diagnostic& d : ds) {
    if (names(d.where) && !d.line) wanted.push_back({d.where.line, d.where.column, &d.line});
    for (DiagnosticNote& n : d.notes) {
      const bool own_line = n.where.line != d.where.line || n.where.file != d.where.file;
      if (names(n.where) && !n.line && own_line)
        wanted.push_back({n.where.line, n.where.column, &n.line});
    }
  }
  if (wanted.empty()) return;
  std::stable_sort(wanted.begin(), wanted.end(),
                   [](const Wanted& a, const Wanted& b) { return a.line < b.line; });
  const std::string_view t = source.text;
  int line = 1;
  size_t start = 0;  // of `line`
  for (const Wanted& w : wanted) {
    while (line < w.line) {
      const void* nl = std::memchr(t.data() + start, '\n', t.size() - start);
      if (nl == nullptr) return;  // the text has fewer lines
      start = static_cast<size_t>(static_cast<const char*>(nl) - t.data()) + 1;
      ++line;
    }
    const void* nl = std::memchr(t.data() + start, '\n', t.size() - start);
    size_t end =
        nl == nullptr ? t.size() : static_cast<size_t>(static_cast<const char*>(nl) - t.data());
    if (end > start && t[end - 1] == '\r') --end;
    *w.slot = window(t.substr(start, end - start), w.column);
  }
}

void limit_errors(std::vector<Diagnostic>& ds, size_t max_errors) {
  size_t kept = 0, cut = ds.size();
  for (size_t i = 0; i < ds.size() && cut == ds.size(); ++i) {
    if (ds[i].severity != Severity::Error) continue;
    if (kept == max_errors)
      cut = i;
    else
      ++kept;
  }
  if (cut == ds.size()) return;
  size_t rest = 0;
  for (size_t i = cut; i < ds.size(); ++i) rest += ds[i].severity == Severity::Error ? 1 : 0;
  Diagnostic more;
  more.severity = Severity::Note;
  more.where.file = ds[cut].where.file;  // no line: the note is about the file, not a place in it
  more.message = fmt::format("{} more error{} not shown", rest, rest == 1 ? "" : "s");
  ds.resize(cut);
  ds.push_back(std::move(more));
}

std::string escape_unprintable(std::string_view text, size_t max_columns) {
  std::string out;
  size_t width = 0;
  for (size_t i = 0; i < text.size();) {
    const Shown u = show(text, i);
    width += static_cast<size_t>(budget_width(u));
    if (width > max_columns) return out + "...";
    append_shown(out, text, i, u);
    i += u.bytes;
  }
  return out;
}

std::string format_text(const Diagnostic& d) {
  std::string out = fmt::format("{}: {}: {}", place(d.where), severity_name(d.severity),
                                escape_unprintable(d.message, kMaxMessageColumns));
  if (!d.scheme.empty()) out += fmt::format(" [{} {}]", d.scheme, d.code);
  out += '\n';
  if (d.line && d.where.line > 0) append_excerpt(out, *d.line, d.where.line, d.where.column);
  for (const auto& n : d.notes) {
    out += fmt::format("{}: note: {}\n", place(n.where),
                       escape_unprintable(n.message, kMaxMessageColumns));
    if (n.line && n.where.line > 0) append_excerpt(out, *n.line, n.where.line, n.where.column);
  }
  return out;
}

std::string format_text(const std::vector<Diagnostic>& ds) {
  std::string out;
  for (const auto& d : ds) out += format_text(d);
  return out;
}

namespace {

// The excerpt's text as JSON holds it: escaped, with the marks of a cut window.
std::string shown_line(const SourceLine& l) {
  return (l.first_column > 1 ? "..." : "") + escape_unprintable(l.text) +
         (l.cut_after ? "..." : "");
}

}  // namespace

std::string format_json(const std::vector<Diagnostic>& ds) {
  nlohmann::json array = nlohmann::json::array();
  for (const auto& d : ds) {
    nlohmann::json notes = nlohmann::json::array();
    for (const auto& n : d.notes) {
      notes.push_back({{"file", escape_unprintable(n.where.file)},
                       {"line", n.where.line},
                       {"column", n.where.column},
                       {"message", escape_unprintable(n.message, kMaxMessageColumns)}});
      if (n.line) notes.back()["source_line"] = shown_line(*n.line);
    }
    array.push_back({{"file", escape_unprintable(d.where.file)},
                     {"line", d.where.line},
                     {"column", d.where.column},
                     {"severity", severity_name(d.severity)},
                     {"code", d.code},
                     {"scheme", d.scheme},
                     {"message", escape_unprintable(d.message, kMaxMessageColumns)},
                     {"notes", notes}});
    if (d.line) array.back()["source_line"] = shown_line(*d.line);
  }
  return array.dump(2) + "\n";
}

}  // namespace uprog
