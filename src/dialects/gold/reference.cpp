// Gold's reference (reference.h). The commands' text, range and access come from their rows in
// commands.cpp, so no command the compiler knows lacks an entry; the words and functions are
// written from the manual (seed 000) with its section.
#include "dialects/gold/reference.h"

#include <fmt/core.h>

#include <array>
#include <string_view>

#include "dialects/gold/commands.h"

namespace uprog::gold {
namespace {

using dialect::ReferenceEntry;
using dialect::ReferenceKind;

// The first row the Elmo Command Reference adds to the simulated drive's spec (commands.cpp).
constexpr uint16_t kFirstReferenceRow = 57;

// The units the command table's texts end with (", counts/s").
constexpr std::array<std::string_view, 12> kUnits = {
    "counts/s^2", "counts/s", "counts", "ms", "us", "s", "A", "V", "mA", "rpm", "Hz", "%"};

std::string unit_of(std::string_view meaning) {
  const size_t comma = meaning.rfind(", ");
  if (comma == std::string_view::npos) return "";
  const std::string_view tail = meaning.substr(comma + 2);
  for (std::string_view u : kUnits)
    if (tail == u) return std::string(u);
  return "";
}

std::string number(double v) {
  if (v == -2147483648.0) return "-2147483648";
  if (v == 2147483647.0) return "2147483647";
  return fmt::format("{}", v);
}

std::string access_of(const CommandInfo& c) {
  if ((c.flags & kNotProgram) != 0) return "host only: not in a program (compile error 79)";
  if ((c.flags & kAction) != 0) return "action: executed, neither read nor assigned";
  if ((c.flags & kReadOnly) != 0) return "read only";
  if ((c.flags & kMotorOffOnly) != 0) return "read/write; written only while MO=0";
  return "read/write";
}

std::string range_of(const CommandInfo& c) {
  std::string range;
  if ((c.flags & kAction) == 0 && c.min_value <= c.max_value)
    range = number(c.min_value) + " to " + number(c.max_value);
  if ((c.flags & kIndexed) != 0) {
    if (!range.empty()) range += "; ";
    range += fmt::format("index {} to {}", c.min_index, c.max_index);
  }
  return range;
}

ReferenceEntry command_entry(const CommandInfo& c) {
  const std::string name(c.name);
  std::string summary(c.meaning);
  summary += c.type == ValueType::Float ? " (a float)" : (c.flags & kText) != 0 ? " (text)" : "";
  return {name,
          ReferenceKind::Command,
          summary,
          unit_of(c.meaning),
          range_of(c),
          access_of(c),
          c.id < kFirstReferenceRow
              ? "shared/spec/gold-drive.md, the simulated drive's commands; Elmo Command "
                "Reference for Gold Line Drives, " +
                    name
              : "Elmo Command Reference for Gold Line Drives, " + name +
                    " (docs/dialects/gold.md, commands from the reference)",
          ""};
}

struct Word {
  const char* name;
  const char* summary;
  const char* source;
};

// Manual 2.3 lists the keywords; each one's meaning is in the section named.
constexpr Word kKeywords[] = {
    {"break", "Leaves the innermost for, while or switch.", "manual 2.3, 2.11.5"},
    {"case", "A switch branch: case value.", "manual 2.3, 2.11.3"},
    {"catch", "Ends a try block; the catch block runs when a run-time error happens in it.",
     "manual 2.3, 2.11.7"},
    {"continue", "Goes on with the next iteration of the innermost for or while.",
     "manual 2.3, 2.11.4"},
    {"else", "The branch of an if taken when no condition held.", "manual 2.3, 2.11.1"},
    {"elseif", "A further condition of an if.", "manual 2.3, 2.11.1"},
    {"end", "Ends an if, for, while, switch or try block.", "manual 2.3, 2.11, 2.12"},
    {"exit", "Ends the program.", "manual 2.3, 2.11.6"},
    {"float", "Declares floating-point variables: float x, y[10].", "manual 2.3, 2.6"},
    {"for", "A counted loop: for k = first:step:last ... end.", "manual 2.3, 2.12.2"},
    {"function", "Declares or defines a function: function [out1, out2] = name(a, b).",
     "manual 2.3, 2.5"},
    {"global", "Declares a variable shared by all functions and the command line.",
     "manual 2.3, 2.6.2"},
    {"goto", "Jumps to a label: goto ##LABEL.", "manual 2.3, 2.11.2"},
    {"if", "A conditional block: if cond ... elseif cond ... else ... end.", "manual 2.3, 2.11.1"},
    {"int", "Declares integer (32-bit) variables: int x, y[10].", "manual 2.3, 2.6"},
    {"nargout", "The number of outputs the caller takes from the function; only inside a function.",
     "manual 2.5; 2.7.2, error 75"},
    {"otherwise", "The switch branch taken when no case matched.", "manual 2.3, 2.11.3"},
    {"reset",
     "Restarts the program at an auto-routine, a global label or a function without inputs,"
     " dropping the call stack.",
     "manual 2.3; 2.7.2, error 73"},
    {"return", "Returns from the function (its outputs are the named output variables).",
     "manual 2.3, 2.5"},
    {"switch", "Chooses a branch by value: switch expr case v ... otherwise ... end.",
     "manual 2.3, 2.11.3"},
    {"try", "Starts a block whose run-time errors the catch block handles.", "manual 2.3, 2.11.7"},
    {"until", "Waits until a condition holds: until (MS == 0).", "manual 2.3, 2.12.3"},
    {"wait", "Waits a time in milliseconds: wait 100.", "manual 2.3, 2.13.1"},
    {"while", "A loop while a condition holds: while cond ... end.", "manual 2.3, 2.12.1"},
};

struct Function {
  const char* name;
  const char* signature;
  const char* summary;
  const char* unit;
  const char* source;
};

constexpr Function kFunctions[] = {
    {"sin", "sin(x)", "Sine of x, x in radians. Returns a float.", "", "manual 1.7"},
    {"cos", "cos(x)", "Cosine of x, x in radians. Returns a float.", "", "manual 1.7"},
    {"abs", "abs(x)", "Absolute value; abs(0x80000000) is limited to the largest long.", "",
     "manual 1.7"},
    {"sqrt", "sqrt(x)", "Square root, or zero for a negative argument. Returns a float.", "",
     "manual 1.7"},
    {"fix", "fix(x)", "Truncates toward zero to an integer: fix(-3.8) is -3.", "", "manual 1.7"},
    {"rnd", "rnd(x)", "Rounds to the nearest integer: rnd(3.8) is 4, rnd(3.4) is 3.", "",
     "manual 1.7"},
    {"sign", "sign(x)", "-1 for negative numbers, 1 for positive numbers, 0 for zero.", "",
     "manual 1.7"},
    {"real", "real(x)", "Converts an integer to a float: real(5)/2 is 2.5.", "", "manual 1.7"},
    {"tdif", "tdif(x)", "The time since x = TM was sampled.", "ms", "manual 1.12"},
    {"prgerr", "prgerr(0)", "The last program error of the virtual machine (for AUTO_PERR).", "",
     "manual 1.12"},
    {"tick", "tick(n)", "The system time from the internal hardware timer.", "ms", "manual 1.12"},
    {"tock", "tock(t)", "The time since t = tick(0) was sampled; at most 28.5 s.", "ms",
     "manual 1.12, 1.13"},
    {"utick", "utick(n)", "The system time from the internal hardware timer.", "us", "manual 1.12"},
    {"utock", "utock(t)", "The time since t = utick(0) was sampled; at most 28.5 s.", "us",
     "manual 1.12, 1.13"},
};

}  // namespace

std::vector<dialect::ReferenceEntry> reference() {
  std::vector<ReferenceEntry> out;
  for (const CommandInfo& c : all_commands()) out.push_back(command_entry(c));
  for (const Word& w : kKeywords)
    out.push_back({w.name, ReferenceKind::Keyword, w.summary, "", "", "", w.source, ""});
  for (const Function& f : kFunctions) {
    out.push_back(
        {f.name, ReferenceKind::Function, f.summary, f.unit, "", "", f.source, f.signature});
  }
  return out;
}

}  // namespace uprog::gold
