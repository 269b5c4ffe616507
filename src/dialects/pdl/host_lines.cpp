// The D-series host protocol (pdl-drive.md, "Host protocol"): reading and writing variables and
// states by name, run/kill/halt/reset/level, and the DL download lines; one phase a line.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

#include "dialects/pdl/firmware.h"
#include "dialects/pdl/system_names.h"
#include "drive/axis.h"

namespace uprog::pdl {
namespace {

using dialect::Answer;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool parse_int(std::string_view s, int32_t& out) {
  s = trim(s);
  const auto [p, e] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && e == std::errc() && p == s.data() + s.size();
}

// A number as the host writes it: decimal, 0x hex, or a float.
bool parse_value(std::string_view s, double& out) {
  s = trim(s);
  bool negative = false;
  std::string_view digits = s;
  if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) {
    negative = digits[0] == '-';
    digits.remove_prefix(1);
  }
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    uint32_t v = 0;
    const auto [p, e] = std::from_chars(digits.data() + 2, digits.data() + digits.size(), v, 16);
    if (e != std::errc() || p != digits.data() + digits.size()) return false;
    out = static_cast<double>(static_cast<int32_t>(v)) * (negative ? -1 : 1);
    return true;
  }
  const auto [p, e] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && e == std::errc() && p == s.data() + s.size() && std::isfinite(out);
}

std::string format_float(float f) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, f);
  return std::string(buffer, r.ptr);
}

Answer error(int32_t code, std::string text) { return Answer{std::move(text), code}; }

bool is_name(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// "name[i]" -> name and i.
bool split_index(std::string_view text, std::string_view& name, std::optional<int32_t>& index) {
  text = trim(text);
  const size_t open = text.find('[');
  if (open == std::string_view::npos) {
    name = text;
    index.reset();
    return is_name(name);
  }
  if (text.back() != ']') return false;
  name = trim(text.substr(0, open));
  if (!is_name(name)) return false;
  int32_t i = 0;
  if (!parse_int(text.substr(open + 1, text.size() - open - 2), i)) return false;
  index = i;
  return !name.empty();
}

int32_t rounded(double v) {
  const double r = std::round(v);
  if (r >= 2147483647.0) return INT32_MAX;
  if (r <= -2147483648.0) return INT32_MIN;
  return static_cast<int32_t>(r);
}

}  // namespace

std::vector<Answer> Firmware::query(std::string_view line) {
  int32_t level = 0;
  return host_line(line, level, nullptr, false);
}

std::vector<Answer> Firmware::host_line(std::string_view line, int32_t& level,
                                        dialect::DlReceiver* download, bool takes_time) {
  std::vector<Answer> answers;
  for (const dialect::Frame& frame : dialect::frame_text(line, wire_.framing())) {
    if (frame.kind == dialect::Frame::Kind::kTooLong ||
        frame.kind == dialect::Frame::Kind::kBadCharacter) {
      answers.push_back(error(kUnknownCommand, "unknown command"));
    } else if (frame.kind == dialect::Frame::Kind::kLine) {
      answer_one(frame.text, level, download, answers);
    } else {
      continue;
    }
    if (takes_time) runtime_.advance_ns(cycle_ns());  // a line takes one phase
  }
  return answers;
}

void Firmware::answer_one(std::string_view text, int32_t& level, dialect::DlReceiver* download,
                          std::vector<Answer>& answers) {
  text = trim(text);
  if (download != nullptr && dialect::DlReceiver::is_download_command(text)) {
    std::vector<uint8_t> image;
    if (auto e = download->handle(text, image)) return answers.push_back(*e);
    if (image.empty()) return;
    const dialect::DownloadResult r = this->download(image);
    if (!r.ok)
      answers.push_back(
          error(r.storage_failed ? dialect::kDlStorage : dialect::kDlImageRefused, r.error));
    return;
  }
  auto word = [&](std::string_view w) {
    return text.size() >= w.size() && equal_ignoring_case(text.substr(0, w.size()), w);
  };
  if (equal_ignoring_case(text, "halt")) {
    if (vm::Machine* m = machine())
      for (uint32_t t = 1; t <= kTasks; ++t) m->kill(t);
    schedule_.reset();
    return;
  }
  if (equal_ignoring_case(text, "reset")) return reset_drive();
  if (debug_line(text, answers)) return;
  if (word("level/")) {
    int32_t n = 0;
    if (!parse_int(text.substr(6), n) || n < 0)
      return answers.push_back(error(kBadValue, "level/n takes n >= 0"));
    level = n;
    return;
  }
  if (word("run/") || word("kill/")) {
    const bool run = word("run/");
    std::string_view rest = trim(text.substr(run ? 4 : 5));
    const size_t space = rest.find_first_of(" \t");
    int32_t t = 0;
    if (!parse_int(rest.substr(0, space), t) || t < 1 || t > static_cast<int32_t>(kTasks)) {
      return answers.push_back(error(kBadTask, "the task is 1, 2 or 3"));
    }
    if (!program_) return answers.push_back(error(kNoProgram, "no program"));
    if (!run) {
      machine()->kill(static_cast<uint32_t>(t));
      schedule_.unlock(static_cast<uint32_t>(t));
      return;
    }
    if (space == std::string_view::npos)
      return answers.push_back(error(kNoSuchLabel, "run/t needs a _label"));
    if (auto e = run_label(static_cast<uint32_t>(t), trim(rest.substr(space))))
      answers.push_back(*e);
    return;
  }
  const size_t eq = text.find('=');
  std::string_view name;
  std::optional<int32_t> index;
  if (!split_index(eq == std::string_view::npos ? text : text.substr(0, eq), name, index)) {
    return answers.push_back(error(kUnknownCommand, "unknown command"));
  }
  if (eq == std::string_view::npos) return answers.push_back(read_name(name, index, level));
  std::string_view rhs = trim(text.substr(eq + 1));
  std::vector<double> values;
  if (!rhs.empty() && rhs.front() == '{') {
    if (rhs.back() != '}') return answers.push_back(error(kBadValue, "a list is {v, ...}"));
    rhs = rhs.substr(1, rhs.size() - 2);
    while (true) {
      const size_t comma = rhs.find(',');
      double v = 0;
      if (!parse_value(rhs.substr(0, comma), v))
        return answers.push_back(error(kBadValue, "bad value"));
      values.push_back(v);
      if (comma == std::string_view::npos) break;
      rhs = rhs.substr(comma + 1);
    }
  } else {
    double v = 0;
    if (!parse_value(rhs, v)) return answers.push_back(error(kBadValue, "bad value"));
    values.push_back(v);
  }
  if (auto e = write_name(name, index, values, level)) answers.push_back(*e);
}

std::optional<Answer> Firmware::run_label(uint32_t task, std::string_view label) {
  const bytecode::Image& image = program_->image();
  const int r = image.find_routine(std::string(label));
  if (label.empty() || label[0] != '_' || r < 0 ||
      image.routines[static_cast<size_t>(r)].kind != bytecode::RoutineKind::Label) {
    return error(kNoSuchLabel, "no such _label");
  }
  vm::Machine& m = *machine();
  for (uint32_t t = 1; t <= kTasks; ++t) {
    const vm::ThreadStatus s = m.status(t);
    const bool busy = s == vm::ThreadStatus::Running || s == vm::ThreadStatus::Waiting;
    if (busy && (t == task || task_routine_[t] == static_cast<uint32_t>(r)))
      return error(kTaskBusy, "task busy or label running");
  }
  if (start_task(task, static_cast<uint32_t>(r)) != 0) return error(kBadValue, "cannot start");
  return std::nullopt;
}

void Firmware::reset_drive() { runtime_.reboot(); }

Answer Firmware::read_name(std::string_view name, std::optional<int32_t> index, int32_t level) {
  for (const HostVariable& v : variables_) {
    if (v.name != name) continue;
    if (level < v.level_read) return error(kLevelTooLow, "level too low");
    const int32_t i = index.value_or(0);
    if (i < 0 || static_cast<uint32_t>(i) >= v.length) return error(kBadIndex, "bad index");
    Value value;
    if (!machine()->read_memory(static_cast<uint32_t>(v.address + i), value))
      return error(kBadIndex, "bad index");
    return Answer{v.kind == 'f' ? format_float(value.f) : std::to_string(value.i), 0};
  }
  if (const StateName* s = find_state(name)) {
    if (index) return error(kBadIndex, "a state has no index");
    return Answer{state_value(s->number) ? "1" : "0", 0};
  }
  bool axis_zero = false;
  const SystemVariable* s = find_system_variable(name, &axis_zero);
  if (!s)
    return program_ ? error(kNoSuchVariable, "no such variable") : error(kNoProgram, "no program");
  if (!s->readable()) return error(kUnknownCommand, "write-only");
  if (axis_zero && index) return error(kBadIndex, "bad index");
  int32_t v = 0;
  const int32_t code = read_variable(s->id, index.value_or(0), v);
  if (code != 0) return error(code, "refused");
  return Answer{std::to_string(v), 0};
}

std::optional<Answer> Firmware::write_name(std::string_view name, std::optional<int32_t> index,
                                           const std::vector<double>& values, int32_t level) {
  for (const HostVariable& v : variables_) {
    if (v.name != name) continue;
    if (v.read_only) return error(kReadOnly, "read-only");
    if (level < v.level_write) return error(kLevelTooLow, "level too low");
    const int32_t i = index.value_or(0);
    if (i < 0 || static_cast<uint64_t>(i) + values.size() > v.length)
      return error(kBadIndex, "bad index");
    for (size_t k = 0; k < values.size(); ++k) {
      Value value;
      if (v.kind == 'f') {
        value = Value::of_float(static_cast<float>(values[k]));
      } else {
        int32_t n = rounded(values[k]);
        if (v.kind == 's') n = static_cast<int16_t>(static_cast<uint16_t>(n & 0xFFFF));
        value = Value::of_int(n);
      }
      machine()->write_memory(static_cast<uint32_t>(v.address + i) + static_cast<uint32_t>(k),
                              value);
    }
    return std::nullopt;
  }
  if (values.size() != 1) return error(kBadValue, "one value");
  if (const StateName* s = find_state(name)) {
    if (index) return error(kBadIndex, "a state has no index");
    const int32_t code = write_state(s->number, values[0] != 0, true);
    if (code != 0) return error(code, code == kEnableRefused ? "enable refused" : "refused");
    return std::nullopt;
  }
  bool axis_zero = false;
  const SystemVariable* s = find_system_variable(name, &axis_zero);
  if (!s)
    return program_ ? error(kNoSuchVariable, "no such variable") : error(kNoProgram, "no program");
  if (!s->writable()) return error(kReadOnly, "read-only");
  if (axis_zero && index) return error(kBadIndex, "bad index");
  const int32_t code = write_variable(s->id, index.value_or(0), rounded(values[0]), true);
  if (code != 0) return error(code, "refused");
  return std::nullopt;
}

}  // namespace uprog::pdl
