// The Gold command line: a host line split into expressions, each compiled with
// gold::compile_line into a tiny image and run to its end on a machine of its own, which sees
// the loaded program's globals (copied in before, and back after).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "dialects/gold/firmware.h"
#include "dialects/gold/interpreter_errors.h"
#include "dialects/gold/number_format.h"
#include "vm/run_error.h"

namespace uprog::gold {

// Gold's list names the DL lines' codes (interpreter_errors.def); they are the protocol's.
static_assert(kErrorSyntax == dialect::kDlSyntax && kErrorStorage == dialect::kDlStorage &&
              kErrorNoDownload == dialect::kDlNoDownload &&
              kErrorDownloadSize == dialect::kDlBadSize &&
              kErrorDownloadChunk == dialect::kDlBadChunk &&
              kErrorDownloadRefused == dialect::kDlImageRefused);

using dialect::Answer;

namespace {

// A command line is one statement list; it may not wait, so a small budget is plenty and a
// runaway line (a loop typed at the prompt) ends with an error instead of hanging the drive.
constexpr uint64_t kLineInstructionBudget = 1'000'000;

vm::MachineConfig line_config() {
  vm::MachineConfig c;
  c.threads = 1;
  c.locals = 64;
  c.breakpoints = 0;
  return c;
}

// "BH=n" (any case, blanks around '='): n's text, else nullopt. BH takes a number as host tools
// send it (decimal or 0x hexadecimal, MAN-SIMSW 7.4.7: "BH=0x4000"), not an expression.
std::optional<std::string_view> upload_request(std::string_view text) {
  if (text.size() < 2 || (text[0] | 0x20) != 'b' || (text[1] | 0x20) != 'h') return std::nullopt;
  text.remove_prefix(2);
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  if (text.empty()) return std::string_view{};
  if (text.front() != '=') return std::nullopt;
  text.remove_prefix(1);
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

std::optional<int32_t> upload_number(std::string_view digits) {
  int base = 10;
  if (digits.size() > 2 && digits[0] == '0' && (digits[1] | 0x20) == 'x') {
    base = 16;
    digits.remove_prefix(2);
  }
  uint32_t n = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n, base);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
    return std::nullopt;
  return static_cast<int32_t>(n);
}

}  // namespace

Answer Firmware::error_answer(int32_t code, std::string why) {
  ec_ = code;
  return Answer{std::move(why), code};
}

void Firmware::spend_expression_time() { runtime_.advance_ns(servo_cycle_ns()); }

std::vector<Answer> Firmware::send(std::string_view text, bool takes_time) {
  return send_line(text, takes_time, nullptr);
}

std::vector<Answer> Firmware::send_line(std::string_view text, bool takes_time,
                                        dialect::DlReceiver* download) {
  std::vector<Answer> answers;
  const dialect::FramerOptions framing = command_line_framing();
  for (const dialect::Frame& frame : dialect::frame_text(text, framing)) {
    if (frame.kind == dialect::Frame::Kind::kTooLong) {
      answers.push_back(
          error_answer(kErrorSyntax, "Command syntax error: the expression is longer than " +
                                         std::to_string(framing.max_line_length) + " characters"));
    } else if (frame.kind == dialect::Frame::Kind::kBadCharacter) {
      answers.push_back(error_answer(
          kErrorSyntax, "Command syntax error: a character that is not printable ASCII"));
    } else if (download != nullptr && dialect::DlReceiver::is_download_command(frame.text)) {
      download_expression(frame.text, *download, answers);
    } else {
      expression(frame.text, answers);
    }
    // The drive answers from its background loop: every expression takes one servo cycle.
    if (takes_time) spend_expression_time();
  }
  return answers;
}

void Firmware::download_expression(std::string_view expression, dialect::DlReceiver& download,
                                   std::vector<Answer>& answers) {
  std::vector<uint8_t> image;
  if (auto error = download.handle(expression, image)) {
    answers.push_back(error_answer(error->error, std::move(error->text)));
    return;
  }
  if (image.empty()) return;  // BEGIN, a chunk or ABORT: nothing more to do
  // The image's CRC and the verifier are checked before anything is stored.
  const dialect::DownloadResult r = this->download(image);
  if (!r.ok)
    answers.push_back(
        error_answer(r.storage_failed ? kErrorStorage : kErrorDownloadRefused, r.error));
}

void Firmware::recorder_upload(std::string_view argument, std::vector<Answer>& answers) {
  const std::optional<int32_t> n = upload_number(argument);
  if (!n) {
    answers.push_back(error_answer(kErrorSyntax, "Command syntax error: BH=n takes a number"));
    return;
  }
  std::string record;
  if (const int32_t e = drive_commands_->recorder().upload(*n, record)) {
    answers.push_back(error_answer(e, interpreter_error_text(e)));
    return;
  }
  answers.push_back(Answer{std::move(record), 0});
}

void Firmware::expression(std::string_view text, std::vector<Answer>& answers) {
  if (program_control(std::string(text), answers)) return;
  if (const std::optional<std::string_view> argument = upload_request(text)) {
    recorder_upload(*argument, answers);
    return;
  }
  // A command that answers text (VR) is no expression: its text is the answer.
  if (const CommandInfo* c = find_command(text); c != nullptr && (c->flags & kText) != 0) {
    if (auto answer = drive_commands_->text(c->id))
      answers.push_back(Answer{std::move(*answer), 0});
    return;
  }
  run_line(std::string(text), answers);
}

void Firmware::bind_program_globals(vm::Machine& line) {
  if (!program_) return;
  vm::Machine& program = program_->machine();
  for (uint32_t g = 0; g < known_globals_.size(); ++g) {
    const std::span<Value> words = program.global_words(g);
    line.bind_global(g, words.data(), static_cast<uint32_t>(words.size()));
  }
}

vm::SliceResult Firmware::run_bound(vm::Machine& line, uint64_t budget) {
  bound_line_running_ = true;
  line.start(0, 0);
  const vm::SliceResult r = line.run_slice(0, vm::Budget::of_instructions(budget));
  bound_line_running_ = false;
  retired_program_.reset();
  return r;
}

void Firmware::run_line(const std::string& text, std::vector<Answer>& answers) {
  const gold::CompiledLine line = compile_line(text, known_globals_);
  if (!line.ok()) {
    std::string why = "Command syntax error";
    if (!line.diagnostics.empty()) {
      const Diagnostic& d = line.diagnostics.front();
      why += ": " + d.message + " [gold " + std::to_string(d.code) + "]";
    }
    answers.push_back(error_answer(kErrorSyntax, why));
    return;
  }
  std::string why;
  const auto loaded =
      dialect::LoadedProgram::load(bytecode::encode(line.image), line_config(), *this, &why, false);
  if (!loaded) {
    answers.push_back(
        error_answer(kErrorSyntax, "Command syntax error: the line's image is unsound: " + why));
    return;
  }
  vm::Machine& m = loaded->machine();
  // Whatever the line assigns is assigned in the program at once, and stays assigned when the
  // line ends in an error; a program replaced meanwhile keeps it (and is then dropped).
  bind_program_globals(m);
  const vm::SliceResult r = run_bound(m, kLineInstructionBudget);
  if (r.end == vm::SliceEnd::Error) {
    const vm::RunError e = m.last_error(0);
    if (e == vm::RunError::CommandRefused) {
      // The drive's own refusal: its code, and what it means.
      const int32_t code = m.error_detail(0);
      const char* meaning = interpreter_error_text(code);
      answers.push_back(
          error_answer(code, meaning != nullptr ? meaning : "drive error " + std::to_string(code)));
    } else {
      answers.push_back(
          error_answer(kErrorRunTimeBase + static_cast<int32_t>(e), vm::run_error_text(e)));
    }
    return;
  }
  if (r.end != vm::SliceEnd::Finished) {
    answers.push_back(error_answer(kErrorLineDidNotFinish,
                                   "the line did not finish (it waited or ran too long)"));
    return;
  }
  for (const gold::LineValue& v : line.values) {
    Value value;
    m.read_global(v.value_global, 0, value);
    bool is_float = v.kind == gold::Kind::Float;
    if (v.kind == gold::Kind::Dynamic && v.tag_global >= 0) {
      Value tag;
      m.read_global(static_cast<uint32_t>(v.tag_global), 0, tag);
      is_float = tag.i == 1;
    }
    if (is_float && !(std::fabs(value.f) < 1e37f)) {
      // 1.3.2: "If a floating-point number exceeds the floating-point range, it is also
      // interpreted as an error" (-1e37 < N < 1e37): 1e36*100 is not shown as inf.
      const vm::RunError overflow = vm::RunError::Overflow;
      answers.push_back(error_answer(kErrorRunTimeBase + static_cast<int32_t>(overflow),
                                     vm::run_error_text(overflow)));
      continue;
    }
    answers.push_back(Answer{is_float ? format_gold_float(value.f) : format_gold_int(value.i), 0});
  }
}

}  // namespace uprog::gold
