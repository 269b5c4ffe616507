// Program-control lines of the Gold command line, handled as text before compiling: XQ##name(args),
// HP, XC, KL, CC, LS, SV, LD, RS and DB##RV[n]=var (manual 2.2, 2.7, 2.16;
// shared/spec/gold-drive.md).
#include <cctype>
#include <charconv>
#include <cstdlib>

#include "dialects/gold/firmware.h"
#include "drive/axis.h"

namespace uprog::gold {

using dialect::Answer;
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string strip_spaces(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c != ' ' && c != '\t') out.push_back(c);
  }
  return out;
}

bool is_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

// "2000,-1.5" -> numbers; false on anything else.
bool parse_numbers(const std::string& text, std::vector<double>& out) {
  if (text.empty()) return true;
  size_t start = 0;
  for (;;) {
    const size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty()) return false;
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end != item.c_str() + item.size()) return false;
    out.push_back(v);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

std::string kind_name(bytecode::RoutineKind k) {
  switch (k) {
    case bytecode::RoutineKind::Function:
      return "function";
    case bytecode::RoutineKind::Label:
      return "label";
    case bytecode::RoutineKind::AutoRoutine:
      return "auto-routine";
    case bytecode::RoutineKind::Task:
      return "task";
  }
  return "routine";
}

}  // namespace

bool Firmware::program_control(const std::string& text, std::vector<Answer>& answers) {
  const std::string compact = strip_spaces(text);
  const std::string word = upper(compact);
  auto fail = [&](int32_t code, const std::string& why) {
    answers.push_back(error_answer(code, why));
  };

  if (word.rfind("XQ##", 0) == 0) {
    std::string rest = compact.substr(4);
    std::vector<double> args;
    const size_t paren = rest.find('(');
    if (paren != std::string::npos) {
      if (rest.back() != ')' ||
          !parse_numbers(rest.substr(paren + 1, rest.size() - paren - 2), args)) {
        fail(kErrorBadArguments, "XQ## takes numbers as arguments: XQ##name(1,2.5)");
        return true;
      }
      rest = rest.substr(0, paren);
    }
    if (!is_name(rest)) {
      fail(kErrorNoSuchEntry, "XQ## needs the name of a function, label or auto-routine");
      return true;
    }
    const int32_t code = execute_program(rest, args);
    if (code == kErrorNoProgram)
      fail(code, "no program is loaded");
    else if (code == kErrorProgramRunning)
      fail(code, "the program is running (HP or KL first)");
    else if (code == kErrorNoSuchEntry)
      fail(code, "the program has no function or label " + rest);
    else if (code != 0)
      fail(code, "wrong arguments for " + rest);
    return true;
  }
  if (word.rfind("DB##", 0) == 0) {
    if (debug_command(word.substr(4), answers)) return true;
    const int32_t code = map_recorder(compact.substr(4));
    if (code != 0) fail(code, "DB##RV[n]=name with n 1..8 and a global variable of the program");
    return true;
  }
  if (word == "HP") {
    if (!program_) return fail(kErrorNoProgram, "no program is loaded"), true;
    machine()->halt(kProgramThread);
    log("program halted");
    return true;
  }
  if (word == "XC") {
    if (!program_) return fail(kErrorNoProgram, "no program is loaded"), true;
    if (machine()->status(kProgramThread) != vm::ThreadStatus::Halted &&
        machine()->status(kProgramThread) != vm::ThreadStatus::AtBreakpoint) {
      return fail(kErrorNotHalted, "the program is not halted"), true;
    }
    machine()->resume(kProgramThread);
    log("program continued");
    return true;
  }
  if (word == "KL") {
    // "Halt program execution and stop the motor" (docs/dialects/gold.md, KL): the program ends
    // and the motion decelerates as ST stops it; the motor stays on.
    if (!program_) return fail(kErrorNoProgram, "no program is loaded"), true;
    machine()->kill(kProgramThread);
    autos_.forget_activity();
    runtime_.axis().stop();
    log("program killed, motion stopped");
    return true;
  }
  if (word == "CC") {
    if (program_status() == 1)
      return fail(kErrorProgramRunning, "the program is running (KL first)"), true;
    std::string error;
    const int32_t code = load_stored(&error);
    if (code != 0)
      fail(code, error);
    else
      log("program loaded into RAM");
    return true;
  }
  if (word == "LS") {
    if (!program_) return fail(kErrorNoProgram, "no program is loaded"), true;
    for (std::string& l : listing()) answers.push_back(Answer{std::move(l), 0});
    return true;
  }
  if (word == "SV") {
    if (const int32_t code = save_parameters(); code != 0)
      fail(code, "the parameters could not be saved");
    return true;
  }
  if (word == "LD") {
    if (const int32_t code = load_parameters(); code != 0) {
      fail(code,
           code == kErrorMotorMustBeOff ? "LD needs the motor off" : "no saved parameters to load");
    }
    return true;
  }
  if (word == "RS") {
    reset_drive();
    return true;
  }
  return false;
}

std::vector<std::string> Firmware::listing() const {
  // The drive keeps the image, not the source text: LS lists the program's entry points.
  std::vector<std::string> out;
  for (const bytecode::Routine& r : program_->image().routines) {
    if (r.name.empty() || r.name[0] == '$') continue;
    out.push_back(kind_name(r.kind) + " " + r.name);
  }
  for (const bytecode::Global& g : program_->image().globals) {
    out.push_back(std::string(g.type == ValueType::Float ? "float " : "int ") + g.name +
                  (g.length > 1 ? "[" + std::to_string(g.length) + "]" : ""));
  }
  return out;
}

int32_t Firmware::save_parameters() {
  std::string error;
  if (!runtime_.save_axis_parameters(&error)) {
    log("SV failed: " + error);
    return kErrorStorage;
  }
  log("parameters saved");
  return 0;
}

int32_t Firmware::load_parameters() {
  std::string error;
  const std::optional<drive::Parameters> params = runtime_.saved_axis_parameters(&error);
  if (!params) return kErrorStorage;
  const drive::Status s = runtime_.axis().load_parameters(*params);
  if (s != drive::Status::kOk) return error_for(s);
  log("parameters loaded");
  return 0;
}

void Firmware::reset_drive() {
  log("drive reset");
  runtime_.reboot();
}

// "RV[3]=arrname[2]" or "RV[1]=name".
int32_t Firmware::map_recorder(const std::string& text) {
  const std::string up = upper(text);
  if (up.rfind("RV[", 0) != 0) return kErrorBadCommand;
  const size_t close = text.find(']');
  if (close == std::string::npos || close + 1 >= text.size() || text[close + 1] != '=')
    return kErrorSyntax;
  int32_t n = 0;
  const auto [p, e] = std::from_chars(text.data() + 3, text.data() + close, n);
  if (e != std::errc() || p != text.data() + close || n < 1 || n > 8) return kErrorBadIndex;
  std::string name = text.substr(close + 2);
  int32_t element = 0;
  if (const size_t open = name.find('['); open != std::string::npos) {
    if (name.back() != ']') return kErrorSyntax;
    const auto [q, f] =
        std::from_chars(name.data() + open + 1, name.data() + name.size() - 1, element);
    if (f != std::errc() || q != name.data() + name.size() - 1) return kErrorSyntax;
    name = name.substr(0, open);
  }
  for (const KnownGlobal& g : known_globals_) {
    if (g.name != name) continue;
    if (element < 0 || element >= std::max<int32_t>(g.length, 1)) return kErrorBadIndex;
    recorder_map_[n] = text.substr(close + 2);
    drive_commands_->recorder().map_variable(n, text.substr(close + 2));
    return 0;
  }
  return kErrorNoSuchVariable;
}

}  // namespace uprog::gold
