// The transcript runner; docs/transcripts.md is the format's specification, every directive
// and option of it.
#include "transcript/transcript.h"

#include <fmt/core.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "controller/controller.h"
#include "dialects/registry.h"
#include "drive/axis.h"
#include "support/files.h"
#include "transcript/recording_options.h"

namespace uprog::transcript {

using controller::Answer;
using controller::DownloadResult;
namespace {

std::string trim(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t\r");
  const size_t last = s.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

// A trailing comment starts with whitespace, '#' and whitespace (or the end): "XQ##main" keeps
// its '#'s, "> 3+4   # why" drops the note.
std::string without_comment(const std::string& s) {
  for (size_t i = 1; i < s.size(); ++i) {
    if (s[i] == '#' && (s[i - 1] == ' ' || s[i - 1] == '\t') &&
        (i + 1 == s.size() || s[i + 1] == ' ' || s[i + 1] == '\t')) {
      return trim(s.substr(0, i));
    }
  }
  return trim(s);
}

struct Pending {
  int line = 0;  // the '>' line
  std::string sent;
  std::vector<Answer> answers;
  size_t next = 0;
  bool expected_any = false;
};

class Runner {
 public:
  Runner(std::string name, std::string base_dir, const controller::Timing& timing,
         const dialect::Dialect* d, Extension* extension)
      : name_(std::move(name)),
        base_dir_(std::move(base_dir)),
        timing_(timing),
        dialect_(d != nullptr ? d : &dialects::default_dialect()),
        extension_(extension) {}

  TranscriptResult run(const std::string& text) {
    size_t start = 0;
    int number = 0;
    while (start <= text.size()) {
      const size_t end = text.find('\n', start);
      const std::string raw =
          text.substr(start, end == std::string::npos ? std::string::npos : end - start);
      ++number;
      line(number, raw);
      if (end == std::string::npos) break;
      start = end + 1;
    }
    finish_pending();
    result_.ok = result_.failures.empty();
    return result_;
  }

  controller::Controller& drive() {
    if (!drive_) {
      controller::ControllerOptions o;
      o.dialect = dialect_;
      o.timing = timing_;
      o.axes = axes_;
      o.servo_period_us = servo_period_us_;
      drive_ = std::make_unique<controller::Controller>(o);
      host_ = drive_->open_session();
    }
    return *drive_;
  }

 private:
  void fail(int line, const std::string& why) {
    result_.failures.push_back(name_ + ":" + std::to_string(line) + ": " + why);
  }

  void finish_pending() {
    if (!pending_) return;
    Pending& p = *pending_;
    if (!p.expected_any) {
      for (const Answer& a : p.answers) {
        if (a.is_error())
          fail(p.line, "expected no error from '" + p.sent + "', got ! " + std::to_string(a.error) +
                           " (" + a.text + ")");
      }
    } else {
      for (size_t i = p.next; i < p.answers.size(); ++i) {
        fail(p.line, "expected no more answers to '" + p.sent + "', got " + shown(p.answers[i]));
      }
    }
    pending_.reset();
  }

  static std::string shown(const Answer& a) {
    return a.is_error() ? "! " + std::to_string(a.error) + " (" + a.text + ")" : "'" + a.text + "'";
  }

  void expect(int number, bool is_error, const std::string& what) {
    if (!pending_) {
      fail(number, "an expected answer without a '>' line before it");
      return;
    }
    Pending& p = *pending_;
    p.expected_any = true;
    ++result_.checks;
    if (p.next >= p.answers.size()) {
      fail(number, "expected " + std::string(is_error ? "! " : "'") + what + (is_error ? "" : "'") +
                       ", got no answer to '" + p.sent + "'");
      return;
    }
    const Answer& a = p.answers[p.next++];
    if (!is_error) {
      if (a.is_error() || a.text != what) fail(number, "expected '" + what + "', got " + shown(a));
      return;
    }
    if (!a.is_error()) {
      fail(number, "expected ! " + what + ", got " + shown(a));
      return;
    }
    if (!what.empty() && what != std::to_string(a.error))
      fail(number, "expected ! " + what + ", got " + shown(a));
  }

  void line(int number, const std::string& raw) {
    const std::string text = trim(raw);
    if (text.empty() || text[0] == '#') return;
    if (text[0] == '<') {
      expect(number, false, without_comment(text.substr(1)));
      return;
    }
    if (text[0] == '!') {
      std::string code = without_comment(text.substr(1));
      const size_t space = code.find_first_of(" \t");
      if (space != std::string::npos)
        code = code.substr(0, space);  // text after the code is ignored
      expect(number, true, code);
      return;
    }
    finish_pending();
    if (text[0] == '>') {
      std::string sent = without_comment(text.substr(1));
      Pending p;
      p.line = number;
      p.sent = sent;
      drive();
      // As a host sends it (DL lines too), or taking no time while an extension holds it.
      p.answers = extension_ != nullptr && extension_->holds_time() ? drive_->query(sent)
                                                                    : host_->send(sent);
      collect_output();
      pending_ = std::move(p);
      return;
    }
    const std::string body = without_comment(text);
    const size_t space = body.find_first_of(" \t");
    const std::string directive = body.substr(0, space);
    const std::string arg = space == std::string::npos ? std::string() : trim(body.substr(space));
    if (directive == "dialect") {
      choose_dialect(number, arg);
    } else if (directive == "drive") {
      configure_drive(number, arg);
    } else if (directive == "output" || directive == "quiet") {
      expect_output(number, directive == "quiet", arg);
    } else if (directive == "load") {
      load(number, arg);
    } else if (directive == "store") {
      store(number, arg);
    } else if (directive == "boot") {
      // An extension: power-cycles the drive (saved parameters, the stored program as at power-up).
      drive().reboot();
      collect_output();
    } else if (directive == "compile") {
      compile(number, arg);
    } else if (directive == "wait") {
      uint64_t us = 0;
      uint64_t cycles = 0;
      if (parse_cycles(arg, cycles))
        drive().advance_ns(cycles * drive().firmware().cycle_ns());
      else if (!parse_duration_us(arg, us))
        fail(number, "wait needs a duration such as 500ms, 2s, 10us or 40ph");
      else if (extension_ != nullptr)
        extension_->wait(drive(), us);
      else
        drive().advance(us);
      collect_output();
    } else if (directive == "input") {
      input(number, arg);
    } else if (directive == "switch") {
      position_switch(number, arg);
    } else if (directive == "index") {
      // An extension: the encoder's index pulse at OFFSET + k * CA[18] motor counts.
      double offset = 0;
      if (!parse_number(arg, offset))
        fail(number, "index needs 'index OFFSET' in motor counts");
      else
        drive().axis().place_index_pulse(offset);
    } else if (directive == "endstops") {
      end_stops(number, arg);
    } else if (directive == "record") {
      if (const std::string why = record_directive(drive(), arg); !why.empty())
        fail(number, "record: " + why);
    } else if (directive == "expect") {
      ++result_.checks;
      if (const std::string why = expect_directive(drive(), arg, base_dir_); !why.empty())
        fail(number, "expect " + why);
    } else if (directive == "fault") {
      if (!drive().inject_fault(arg)) fail(number, "no fault named '" + arg + "'");
    } else if (directive == "program-error") {
      // An extension: the program's last run-time error (vm run_errors.def code), 0 for none.
      int32_t code = 0;
      const auto [p, e] = std::from_chars(arg.data(), arg.data() + arg.size(), code);
      ++result_.checks;
      if (e != std::errc() || p != arg.data() + arg.size())
        fail(number, "program-error needs a number");
      else if (drive().program_error() != code) {
        fail(number,
             "expected program error " + arg + ", got " + std::to_string(drive().program_error()));
      }
    } else if (std::string failure; drive().firmware().world_directive(directive, arg, failure)) {
      // A directive of the dialect's drive (docs/transcripts.md: PUP's analog, comm-error).
      if (!failure.empty()) fail(number, directive + ": " + failure);
      collect_output();
    } else if (std::string why;
               extension_ != nullptr && extension_->directive(drive(), directive, arg, why)) {
      ++result_.checks;
      if (!why.empty()) fail(number, why);
      collect_output();
    } else {
      fail(number, "unknown directive '" + directive + "'");
    }
  }

  // Compiles and downloads FILE; false (with the failure noted) when that fails.
  bool download(int number, const std::string& directive, const std::string& arg) {
    if (arg.empty()) {
      fail(number, directive + " needs a path");
      return false;
    }
    const std::filesystem::path path = std::filesystem::path(arg).is_absolute()
                                           ? std::filesystem::path(arg)
                                           : std::filesystem::path(base_dir_) / arg;
    std::vector<Diagnostic> diagnostics;
    if (!drive().download_source_file(path.string(), diagnostics)) {
      fail(number, directive + " " + arg + " failed:\n" + format_text(diagnostics));
      return false;
    }
    return true;
  }

  // An extension: only stores FILE, as a download does, without loading it to run. A dialect
  // whose stored form is the source itself (its stored extension is a source extension: the
  // drive compiles it) gets the file as it is even when it does not compile, as its drive would.
  void store(int number, const std::string& arg) {
    const dialect::Dialect& d = drive().dialect();
    bool source_is_stored = false;
    for (std::string_view e : d.source_extensions()) source_is_stored |= e == d.stored_extension();
    std::string error;
    const std::optional<std::string> text =
        source_is_stored ? read_text_file(resolve(arg), &error) : std::nullopt;
    if (!source_is_stored) {
      download(number, "store", arg);
    } else if (!text) {
      fail(number, "store " + arg + ": " + error);
    } else if (const DownloadResult r =
                   drive().download(std::vector<uint8_t>(text->begin(), text->end()));
               !r.ok) {
      fail(number, "store " + arg + ": " + r.error);
    }
    collect_output();
  }

  std::string resolve(const std::string& arg) const {
    return std::filesystem::path(arg).is_absolute()
               ? arg
               : (std::filesystem::path(base_dir_) / arg).string();
  }

  void load(int number, const std::string& arg) {
    if (!download(number, "load", arg)) return;
    // Loaded as the dialect's host loads a downloaded program (Gold: CC), taking no time.
    const std::string line = drive().dialect().load_line();
    if (!line.empty()) {
      for (const Answer& a : drive().query(line)) {
        if (a.is_error()) fail(number, "load " + arg + ": " + a.text);
      }
    }
    collect_output();
  }

  // An extension: "compile SOURCE EXPECTED": the dialect compiles SOURCE (date 0, a reproducible
  // build) into a stored form equal to EXPECTED's bytes.
  void compile(int number, const std::string& arg) {
    ++result_.checks;
    const size_t space = arg.find_first_of(" \t");
    if (space == std::string::npos) return fail(number, "compile needs 'compile SOURCE EXPECTED'");
    const std::string source = resolve(arg.substr(0, space)),
                      expected_path = resolve(trim(arg.substr(space)));
    const dialect::CompileOutput out = dialect_->compile_file(source, {});
    if (!out.ok())
      return fail(number, "compile " + source + " failed:\n" + format_text(out.diagnostics));
    std::string error;
    const auto expected = read_binary_file(expected_path, &error);
    if (!expected) return fail(number, "compile: " + error);
    if (out.stored_form != *expected)
      return fail(number, "compile " + source + ": the stored form differs from " + expected_path);
  }

  // `drive axes=N phase_us=N`, either or both: the drive's axes and their servo period, before
  // anything uses the drive.
  void configure_drive(int number, const std::string& arg) {
    if (drive_) return fail(number, "drive must come before anything that uses the drive");
    std::istringstream words(arg);
    for (std::string word; words >> word;) {
      const size_t eq = word.find('=');
      double value = 0;
      const std::string key = word.substr(0, eq);
      const bool number_ok = eq != std::string::npos && parse_number(word.substr(eq + 1), value) &&
                             value == static_cast<double>(static_cast<uint32_t>(value));
      if (key == "axes" && number_ok && value >= 1 && value <= controller::kMaxAxes) {
        axes_ = static_cast<uint32_t>(value);
      } else if (key == "phase_us" && number_ok && value >= drive::kMinPeriod_us &&
                 value <= drive::kMaxPeriod_us) {
        servo_period_us_ = static_cast<uint32_t>(value);
      } else {
        return fail(number, fmt::format("drive takes axes=1..{} and phase_us={}..{}, not '{}'",
                                        controller::kMaxAxes, drive::kMinPeriod_us,
                                        drive::kMaxPeriod_us, word));
      }
    }
  }

  void choose_dialect(int number, const std::string& arg) {
    const dialect::Dialect* d = dialects::find(arg);
    if (d == nullptr) {
      fail(number, "no dialect named '" + arg + "' (uprog dialects lists them)");
    } else if (drive_ && d != dialect_) {
      fail(number, "dialect must come before anything that uses the drive");
    } else {
      dialect_ = d;
    }
  }

  // What the drive sent on its own, cut into lines (CR dropped); a text without its LF waits.
  void collect_output() {
    if (!drive_) return;
    for (const std::string& text : drive_->take_output()) {
      for (char c : text) {
        if (c == '\r') continue;
        if (c != '\n') {
          partial_output_.push_back(c);
          continue;
        }
        output_.push_back(std::move(partial_output_));
        partial_output_.clear();
      }
    }
  }

  static std::string without_trailing_blanks(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.pop_back();
    return s;
  }

  void expect_output(int number, bool quiet, const std::string& arg) {
    ++result_.checks;
    if (quiet) {
      if (!output_.empty()) fail(number, "expected no output, got '" + output_.front() + "'");
      return;
    }
    if (output_.empty()) {
      fail(number, "expected output '" + arg + "', got none");
      return;
    }
    const std::string got = without_trailing_blanks(output_.front());
    output_.erase(output_.begin());
    if (got != without_trailing_blanks(arg))
      fail(number, "expected output '" + arg + "', got '" + got + "'");
  }

  static bool parse_number(const std::string& text, double& out) {
    const std::string t = trim(text);
    char* end = nullptr;
    out = std::strtod(t.c_str(), &end);
    return !t.empty() && end == t.c_str() + t.size() && std::isfinite(out);
  }

  // An extension: "switch N FROM TO": input N is high while the motor's position (counts) lies
  // in [FROM, TO]; a later "input N = ..." takes the input back.
  void position_switch(int number, const std::string& arg) {
    const size_t a = arg.find_first_of(" \t");
    const size_t b =
        a == std::string::npos ? a : arg.find_first_of(" \t", arg.find_first_not_of(" \t", a));
    int n = 0;
    double from = 0, to = 0;
    const std::string first = arg.substr(0, a);
    const auto [p, e] = std::from_chars(first.data(), first.data() + first.size(), n);
    if (a == std::string::npos || b == std::string::npos || e != std::errc() ||
        p != first.data() + first.size() || n < 1 || n > 6 ||
        !parse_number(arg.substr(a, b - a), from) || !parse_number(arg.substr(b), to)) {
      fail(number,
           "switch needs 'switch N FROM TO' with N from 1 to 6 and positions in motor counts");
      return;
    }
    drive().axis().place_position_switch(n, from, to);
  }

  // An extension: "endstops LOW HIGH": mechanical stops keep the load within [LOW, HIGH] motor
  // counts (docs/drive.md).
  void end_stops(int number, const std::string& arg) {
    const std::string both = trim(arg);
    const size_t a = both.find_first_of(" \t");
    double low = 0, high = 0;
    if (a == std::string::npos || !parse_number(both.substr(0, a), low) ||
        !parse_number(both.substr(a), high) || low > high) {
      fail(number, "endstops needs 'endstops LOW HIGH' in motor counts, LOW not above HIGH");
      return;
    }
    drive().axis().place_end_stops(low, high);
  }

  void input(int number, const std::string& arg) {
    // "2 = 1"
    const size_t eq = arg.find('=');
    int n = 0, level = 0;
    const std::string left = eq == std::string::npos ? arg : trim(arg.substr(0, eq));
    const std::string right = eq == std::string::npos ? std::string() : trim(arg.substr(eq + 1));
    const auto [p, e] = std::from_chars(left.data(), left.data() + left.size(), n);
    const auto [q, f] = std::from_chars(right.data(), right.data() + right.size(), level);
    if (eq == std::string::npos || e != std::errc() || f != std::errc() ||
        p != left.data() + left.size() || q != right.data() + right.size() || n < 1 || n > 6 ||
        (level != 0 && level != 1)) {
      fail(number, "input needs 'input N = 0|1' with N from 1 to 6");
      return;
    }
    drive().set_input_level(n, level == 1);
  }

  std::string name_, base_dir_;
  controller::Timing timing_;
  const dialect::Dialect* dialect_;
  Extension* extension_;
  std::unique_ptr<controller::Controller> drive_;
  uint32_t axes_ = 1;
  uint32_t servo_period_us_ = 0;  // 0: the drive's own
  std::unique_ptr<dialect::Session> host_;
  std::vector<std::string> output_;  // lines the drive sent on its own, not yet expected
  std::string partial_output_;
  std::optional<Pending> pending_;
  TranscriptResult result_;
};

}  // namespace

// "40ph": a number of the firmware's cycles (PDL's phases).
bool parse_cycles(const std::string& text, uint64_t& out) {
  if (text.size() < 3 || !text.ends_with("ph")) return false;
  const auto [p, e] = std::from_chars(text.data(), text.data() + text.size() - 2, out);
  return e == std::errc() && p == text.data() + text.size() - 2;
}

bool parse_duration_us(const std::string& text, uint64_t& out_us) {
  const std::string t = trim(text);
  size_t unit = 0;
  while (unit < t.size() && (std::isdigit(static_cast<unsigned char>(t[unit])) || t[unit] == '.'))
    ++unit;
  if (unit == 0) return false;
  const std::string number = t.substr(0, unit), suffix = trim(t.substr(unit));
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size()) return false;
  double scale = 0;
  if (suffix == "us")
    scale = 1;
  else if (suffix == "ms")
    scale = 1e3;
  else if (suffix == "s")
    scale = 1e6;
  else
    return false;
  const double us = std::round(v * scale);
  if (!(us >= 0) || us > 1e13) return false;  // beyond ~4 months of virtual time is a typo
  out_us = static_cast<uint64_t>(us);
  return true;
}

TranscriptResult run_transcript_text(const std::string& text, const std::string& name,
                                     const std::string& base_dir, const controller::Timing& timing,
                                     const dialect::Dialect* dialect, Extension* extension) {
  return Runner(name, base_dir, timing, dialect, extension).run(text);
}

TranscriptResult run_transcript_file(const std::string& path, const controller::Timing& timing,
                                     const dialect::Dialect* dialect, Extension* extension) {
  std::string error;
  auto text = read_text_file(path, &error);
  if (!text) {
    TranscriptResult r;
    r.failures.push_back(path + ": cannot read: " + error);
    return r;
  }
  return run_transcript_text(*text, path, std::filesystem::path(path).parent_path().string(),
                             timing, dialect, extension);
}

}  // namespace uprog::transcript
