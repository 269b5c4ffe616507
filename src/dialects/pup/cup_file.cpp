// Writing and reading CUP files (cup_file.h).
#include "dialects/pup/cup_file.h"

#include <fmt/core.h>

#include <string_view>

#include "dialects/pup/message.h"
#include "support/crc32.h"

namespace uprog::pup {
namespace {

constexpr size_t kCrcLineSize = 11;  // "% XXXXXXXX" and its CR, as write_cup writes it
constexpr std::string_view kUncheckedCrcLine = "% 000000\r";  // the manual's and the vendor's

uint32_t crc_of(const std::string& text) {
  return crc32(reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

std::vector<std::string> split_cr(const std::string& bytes, bool* clean) {
  std::vector<std::string> out;
  std::string line;
  *clean = bytes.empty() || bytes.back() == '\r';
  for (char c : bytes) {
    if (c == '\r') {
      out.push_back(std::move(line));
      line.clear();
    } else {
      if (c == '\n') *clean = false;
      line.push_back(c);
    }
  }
  if (!line.empty()) out.push_back(std::move(line));
  return out;
}

std::vector<std::string> split_any(const std::string& text) {
  std::vector<std::string> out;
  std::string line;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\r' || c == '\n') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      out.push_back(std::move(line));
      line.clear();
    } else {
      line.push_back(c);
    }
  }
  if (!line.empty()) out.push_back(std::move(line));
  return out;
}

// "%T 1,1" → {1, 1}.
bool read_pair(const std::string& line, int32_t& a, int32_t& b) {
  const size_t comma = line.find(',');
  if (line.size() < 4 || comma == std::string::npos) return false;
  const auto x = parse_number(std::string_view(line).substr(3, comma - 3));
  const auto y = parse_number(std::string_view(line).substr(comma + 1));
  if (!x || !y) return false;
  a = *x, b = *y;
  return true;
}

// Reads a %I/%T/%E line into `p`; false when it is none of them or malformed.
bool read_table_line(const std::string& line, CupProgram& p) {
  if (line.starts_with("%I ")) {
    p.info.push_back(line.substr(3));
    return true;
  }
  int32_t a = 0, b = 0;
  if (line.starts_with("%T ") && read_pair(line, a, b) && b > 0) {
    p.tasks.push_back({a, static_cast<uint32_t>(b)});
    return true;
  }
  if (line.starts_with("%E ") && read_pair(line, a, b)) {
    p.events.push_back({a, b});
    return true;
  }
  return false;
}

}  // namespace

std::string flash_refusal(size_t size) {
  if (size <= kMaxProgramBytes) return "";
  return fmt::format("the CUP file has {} characters, the flash sector {}", size, kMaxProgramBytes);
}

std::string cup_date(uint64_t unix_s) {
  if (unix_s == 0) return "01/01/00";
  // Days to civil date (proleptic Gregorian), as in Howard Hinnant's public-domain algorithm.
  const int64_t z = static_cast<int64_t>(unix_s / 86400) + 719468;
  const int64_t era = z / 146097;
  const int64_t doe = z - era * 146097;
  const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const int64_t mp = (5 * doy + 2) / 153;
  const int64_t d = doy - (153 * mp + 2) / 5 + 1;
  const int64_t m = mp < 10 ? mp + 3 : mp - 9;
  const int64_t y = yoe + era * 400 + (m <= 2 ? 1 : 0);
  return fmt::format("{:02}/{:02}/{:02}", d, m, y % 100);
}

std::vector<CupTask> task_table(const std::vector<std::string>& lines) {
  std::vector<CupTask> tasks;
  for (size_t i = 0; i < lines.size(); ++i) {
    int32_t error = 0;
    const auto m = parse_message(lines[i], &error);
    if (m && m->tail == Message::Tail::None && m->target.has_index) {
      std::string key = m->target.key;
      for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (key == "aprogtask") tasks.push_back({m->target.index, static_cast<uint32_t>(i + 1)});
    }
  }
  return tasks;
}

std::string write_cup(const CupProgram& program) {
  std::string info, tasks, events, body;
  for (const std::string& s : program.info) info += "%I " + s + "\r";
  for (const CupTask& t : task_table(program.lines))
    tasks += fmt::format("%T {},{}\r", t.task, t.line);
  for (const CupEvent& e : program.events) events += fmt::format("%E {},{}\r", e.event, e.function);
  for (const std::string& l : program.lines) body += l + "\r";
  std::string head = "% " + program.date + "\r% " + program.name + "\r";
  const size_t info_at = kCrcLineSize + head.size() + 5 * 9;
  const size_t tasks_at = info_at + info.size(), events_at = tasks_at + tasks.size();
  const size_t program_at = events_at + events.size(), end = program_at + body.size();
  for (size_t offset : {info_at, tasks_at, events_at, program_at, end})
    head += fmt::format("% {:06}\r", offset);
  const std::string rest = head + info + tasks + events + body;
  return fmt::format("% {:08X}\r", crc_of(rest)) + rest;
}

std::optional<DeclaredCrc> declared_crc(const std::string& bytes) {
  if (bytes.starts_with(kUncheckedCrcLine)) return DeclaredCrc{0, false, kUncheckedCrcLine.size()};
  if (bytes.size() < kCrcLineSize || bytes.compare(0, 2, "% ") != 0 || bytes[10] != '\r')
    return std::nullopt;
  const auto crc = parse_number("0x" + bytes.substr(2, 8));
  if (!crc) return std::nullopt;
  return DeclaredCrc{static_cast<uint32_t>(*crc), true, kCrcLineSize};
}

uint32_t expected_crc(const std::string& bytes) {
  const auto declared = declared_crc(bytes);
  if (!declared || !declared->checked) return 0;
  return crc_of(bytes.substr(declared->line_size));
}

std::optional<CupProgram> read_cup(const std::string& bytes, CupReadError* error) {
  auto fail = [&](int32_t code, std::string text) -> std::optional<CupProgram> {
    if (error) *error = {code, std::move(text)};
    return std::nullopt;
  };
  // Line 1 and the CRC first: a changed byte anywhere is a CRC error (43), not a header one.
  const auto crc = declared_crc(bytes);
  if (!crc) return fail(44, "header line 1 is the CRC, 8 hex digits (or 000000: not checked)");
  if (crc->checked && crc->value != expected_crc(bytes))
    return fail(43, "the CRC in the header does not match the file");
  bool clean = false;
  const std::vector<std::string> lines = split_cr(bytes, &clean);
  if (!clean) return fail(44, "lines must end with CR alone");
  if (lines.size() < 8) return fail(44, "the header has 8 lines");
  for (size_t i = 0; i < 8; ++i) {
    if (!lines[i].starts_with("% "))
      return fail(44, fmt::format("header line {} must start with '% '", i + 1));
  }
  CupProgram p;
  p.date = lines[1].substr(2);
  p.name = lines[2].substr(2);
  size_t offsets[5] = {};
  for (size_t i = 0; i < 5; ++i) {
    const std::string& l = lines[3 + i];
    const auto v = l.size() == 8 ? parse_number(l.substr(2)) : std::nullopt;
    if (!v || *v < 0) return fail(44, fmt::format("header line {} is an offset, 6 digits", 4 + i));
    offsets[i] = static_cast<size_t>(*v);
  }
  // Walk the rest, checking each offset where its part starts: a table's where it has lines (an
  // empty table's offset may be anywhere before the program: the manual's listing has 68, 70
  // and 72 for empty tables and its program at 73).
  size_t at = 0;
  for (size_t k = 0; k < 8; ++k) at += lines[k].size() + 1;
  size_t i = 8;
  const char kinds[3] = {'I', 'T', 'E'};
  for (int part = 0; part < 3; ++part) {
    const bool empty = !(i < lines.size() && lines[i].size() >= 2 && lines[i][0] == '%' &&
                         lines[i][1] == kinds[part]);
    if (empty ? offsets[part] > offsets[3] : offsets[part] != at) {
      return fail(44, fmt::format("the offset of the %{} table is wrong", kinds[part]));
    }
    while (i < lines.size() && lines[i].size() >= 2 && lines[i][0] == '%' &&
           lines[i][1] == kinds[part]) {
      if (!read_table_line(lines[i], p))
        return fail(44, fmt::format("bad table line '{}'", lines[i]));
      at += lines[i++].size() + 1;
    }
  }
  if (offsets[3] != at) return fail(44, "the offset of the program is wrong");
  for (; i < lines.size(); ++i) {
    if (lines[i].starts_with("%")) return fail(44, "a table line after the program starts");
    p.lines.push_back(lines[i]);
    at += lines[i].size() + 1;
  }
  if (offsets[4] != at || at != bytes.size()) return fail(44, "the length in the header is wrong");
  std::vector<CupTask> from_markers = task_table(p.lines);
  if (from_markers.size() != p.tasks.size())
    return fail(44, "the task table does not match the markers");
  for (size_t k = 0; k < from_markers.size(); ++k) {
    if (from_markers[k].task != p.tasks[k].task || from_markers[k].line != p.tasks[k].line) {
      return fail(44, "the task table does not match the markers");
    }
  }
  return p;
}

CupProgram read_cup_text(const std::string& text, const std::string& default_name) {
  CupProgram p;
  p.name = default_name;
  const std::vector<std::string> lines = split_any(text);
  size_t i = 0;
  // A header of 8 `% ` lines gives the name; tables follow.
  if (lines.size() >= 8) {
    bool header = true;
    for (size_t k = 0; k < 8; ++k) header = header && lines[k].starts_with("% ");
    if (header) {
      p.name = lines[2].substr(2);
      i = 8;
    }
  }
  for (; i < lines.size(); ++i) {
    if (lines[i].starts_with("%")) {
      CupProgram scratch;
      if (read_table_line(lines[i], scratch)) {
        p.info.insert(p.info.end(), scratch.info.begin(), scratch.info.end());
        p.events.insert(p.events.end(), scratch.events.begin(), scratch.events.end());
        continue;
      }
    }
    p.lines.push_back(lines[i]);
  }
  return p;
}

}  // namespace uprog::pup
