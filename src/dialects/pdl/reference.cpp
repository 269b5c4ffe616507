// PDL's reference (reference.h): every system variable and state the drive defines gets its
// entry from the tables the compiler reads, with the meaning shared/spec/pdl-drive.md gives it
// ("System variables and states"); commands and functions from the manual (seed 001).
#include "dialects/pdl/reference.h"

#include <string_view>

#include "dialects/pdl/system_names.h"

namespace uprog::pdl {
namespace {

using dialect::ReferenceEntry;
using dialect::ReferenceKind;

constexpr const char* kVariablesSource =
    "shared/spec/pdl-drive.md, System variables and states; manual 1.3";

struct Meaning {
  std::string_view name;
  const char* summary;
  const char* unit;
};

// pdl-drive.md's meaning of each system variable and state.
constexpr Meaning kMeanings[] = {
    {"vel_max", "Profile speed, > 0 (Gold's SP). An axis (slave) variable: X_vel_max.", "counts/s"},
    {"acc", "Profile acceleration, > 0 (Gold's AC). An axis variable.", "counts/s^2"},
    {"dcc", "Profile deceleration, > 0 (Gold's DC). An axis variable.", "counts/s^2"},
    {"stop_dcc", "Deceleration of stop_m=2 and of limit stops (Gold's SD).", "counts/s^2"},
    {"new_sm_fac", "Smoothing from the next move at rest; 0 is a trapezoid (Gold's SF).", "ms"},
    {"trg", "Assigning starts a move there (Gold's PA BG); while not X_ready, a run-time error.",
     "counts"},
    {"jvl", "Nonzero starts an endless jog (Gold's JV BG); 0 stops with dcc.", "counts/s"},
    {"stop_m", "1 stops with dcc (Gold's ST), 2 with stop_dcc.", ""},
    {"abspos", "Position feedback (Gold's PX); assigning redefines it. Also X_pos.", "counts"},
    {"pos", "Position feedback, as X_pos (abspos).", "counts"},
    {"ref_pos", "Reference position (Gold's DV[3]).", "counts"},
    {"vel", "Velocity feedback (Gold's VX).", "counts/s"},
    {"pos_err", "Following error (Gold's PE).", "counts"},
    {"err", "Fault bits (Gold's MF).", ""},
    {"fclk", "Phase counter; wraps; a host may set it.", "phases"},
    {"status", "The states: state s is bit s%32 of status[s/32].", ""},
    {"inputs", "Bit n-1 is input INn.", ""},
    {"outputs", "Bit n-1 is output OUTn.", ""},
    {"in_func",
     "The IL code of input n, n = 1..6; by default 9, 11, 17, 7, 7, 7 (left, right "
     "limit, home).",
     ""},
    {"task_st",
     "Task t's state, t = 1..3: 0 idle, 1 running, 2 sleeping, 3 holds the lock, "
     "-code stopped by that error.",
     ""},
    {"IN1", "Digital input 1 (logical), state 0.", ""},
    {"IN2", "Digital input 2 (logical), state 1.", ""},
    {"IN3", "Digital input 3 (logical), state 2.", ""},
    {"IN4", "Digital input 4 (logical), state 3.", ""},
    {"IN5", "Digital input 5 (logical), state 4.", ""},
    {"IN6", "Digital input 6 (logical), state 5.", ""},
    {"OUT1", "Digital output 1, state 8: #define vacum_sl OUT1.", ""},
    {"OUT2", "Digital output 2, state 9.", ""},
    {"OUT3", "Digital output 3, state 10.", ""},
    {"OUT4", "Digital output 4, state 11.", ""},
    {"X_run", "The profile is moving (state 32).", ""},
    {"X_enable",
     "Servo on (Gold's MO, state 33); seton is refused during a fault or inhibit, "
     "else clears err.",
     ""},
    {"X_ready", "Loop closed, 20 ms after enable (Gold's SO, state 34).", ""},
    {"X_home", "The home input is active (state 35).", ""},
    {"X_homed", "Latched when the home input activates; setoff clears it (state 36).", ""},
    {"LEFT_LIM", "Reverse limit active; motion toward it stops (state 37).", ""},
    {"RIGHT_LIM", "Forward limit active; motion toward it stops (state 38).", ""},
    {"X_fault", "A fault is latched, the servo off (state 39).", ""},
};

// A name without a meaning here gets an empty one: the reference test names it.
const Meaning* meaning_of(std::string_view name) {
  static constexpr Meaning kNone{"", "", ""};
  for (const Meaning& m : kMeanings)
    if (m.name == name) return &m;
  return &kNone;
}

const char* access_of(char access) {
  return access == 'r' ? "read only" : access == 'w' ? "write only" : "read/write";
}

struct Word {
  const char* name;
  ReferenceKind kind;
  const char* summary;
  const char* signature;
  const char* source;
};

constexpr Word kWords[] = {
    {"if", ReferenceKind::Keyword, "A conditional block: if cond do ... end (or else ... end).", "",
     "manual 2.2.8"},
    {"else", ReferenceKind::Keyword, "Closes an if's do block and opens the other branch.", "",
     "manual 2.2.8"},
    {"do", ReferenceKind::Keyword, "Opens the block of an if, while or loop.", "",
     "manual 2.2.7-2.2.9"},
    {"end", ReferenceKind::Keyword, "Closes a do block, or a procedure.", "", "manual 2.2.7-2.2.9"},
    {"while", ReferenceKind::Keyword, "Repeats its do block while the condition holds.", "",
     "manual 2.2.9"},
    {"loop", ReferenceKind::Keyword, "Repeats its do block a number of times.", "", "manual 2.2.7"},
    {"till", ReferenceKind::Keyword, "Waits until a condition holds: till X_ready;", "",
     "manual 2.2.10"},
    {"TOUT", ReferenceKind::Keyword, "A time-out condition in till, if and while.", "",
     "manual 2.2.11"},
    {"goto", ReferenceKind::Keyword, "Jumps to a label; goto (var) jumps indirectly.", "",
     "manual 2.2.3, 2.2.4"},
    {"call", ReferenceKind::Keyword, "Calls a label as a subroutine; ret returns.", "",
     "manual 2.2.5"},
    {"ret", ReferenceKind::Keyword, "Returns from a call; with an empty stack the task ends.", "",
     "manual 2.2.5"},
    {"halt", ReferenceKind::Keyword, "Stops the task: it is idle, ready for run.", "",
     "manual 2.2.1"},
    {"exitproc", ReferenceKind::Keyword, "Leaves the procedure.", "", "manual 2.2.6"},
    {"proc", ReferenceKind::Keyword,
     "Defines a procedure: proc name(long a, float b, instate s) do ... end.", "", "manual 1.4"},
    {"wait", ReferenceKind::Keyword, "Waits a number of phases, using its turns.", "",
     "manual 2.2.2"},
    {"sleep", ReferenceKind::Keyword,
     "Waits a number of phases without taking turns; not between lock and unlock.", "",
     "manual 2.2.2"},
    {"lock", ReferenceKind::Keyword,
     "From the next phase only this task runs, every phase, until unlock.", "", "manual 1.2"},
    {"unlock", ReferenceKind::Keyword, "Ends a lock: the other tasks run again.", "", "manual 1.2"},
    {"run", ReferenceKind::Keyword, "run/t label; starts idle task t at a global label.", "",
     "manual 1.2; shared/spec/pdl-drive.md, Phases and tasks"},
    {"kill", ReferenceKind::Keyword, "kill/t; ends task t.", "",
     "manual 1.2; shared/spec/pdl-drive.md, Phases and tasks"},
    {"level", ReferenceKind::Keyword, "A word PDL reserves; no command of this drive uses it.", "",
     "src/dialects/pdl/compiler.cpp, the reserved words"},
    {"reset", ReferenceKind::Keyword, "A word PDL reserves; the host's reset restarts the drive.",
     "", "src/dialects/pdl/compiler.cpp, the reserved words"},
    {"seton", ReferenceKind::Keyword, "Sets a state: seton X_enable;", "", "manual 2.4.3"},
    {"setoff", ReferenceKind::Keyword, "Clears a state: setoff OUT1;", "", "manual 2.4.3"},
    {"toggle", ReferenceKind::Keyword, "Inverts a state.", "", "manual 2.4.3"},
    {"printl", ReferenceKind::Keyword,
     "Sends an event to the host: printl/mode1/mode2(\"text %ld\", v);", "", "manual 2.4.1, 2.4.2"},
    {"retprintl", ReferenceKind::Keyword, "printl and ret in the same phase.", "", "manual 2.4.1"},
    {"sttovar", ReferenceKind::Keyword, "A state expression's value as a number: v = sttovar s1;",
     "", "manual 2.1.3"},
    {"sizeof", ReferenceKind::Keyword, "The size of a variable or array.", "", "manual 2.1.4"},
    {"long", ReferenceKind::Keyword, "A 32-bit integer type; #long declares a global.", "",
     "manual 1.3, 2.5.2"},
    {"short", ReferenceKind::Keyword, "A 16-bit integer type; #short declares a global.", "",
     "manual 1.3, 2.5.2"},
    {"float", ReferenceKind::Keyword, "A floating-point type; #float declares a global.", "",
     "manual 1.3, 2.5.2"},
    {"max", ReferenceKind::Function, "The larger of two values.", "max(a, b)", "manual 2.3.1"},
    {"min", ReferenceKind::Function, "The smaller of two values.", "min(a, b)", "manual 2.3.1"},
    {"abs", ReferenceKind::Function, "Absolute value.", "abs(a)", "manual 2.3.2"},
    {"sign", ReferenceKind::Function, "-1, 0 or 1 by the sign of the value.", "sign(a)",
     "manual 2.3.3"},
    {"sin", ReferenceKind::Function, "Sine.", "sin(a)", "manual 2.3.4"},
    {"cos", ReferenceKind::Function, "Cosine.", "cos(a)", "manual 2.3.4"},
    {"sqrt", ReferenceKind::Function, "Square root.", "sqrt(a)", "manual 2.3.5"},
    {"divi", ReferenceKind::Function, "Integer division.", "divi(a, b)", "manual 2.3.6"},
    {"shift", ReferenceKind::Function, "Shifts a value by n bits (left for n > 0).", "shift(a, n)",
     "manual 2.3.7"},
    {"bitset", ReferenceKind::Function, "Sets bit n.", "bitset(a, n)", "manual 2.3.8"},
    {"bitclr", ReferenceKind::Function, "Clears bit n.", "bitclr(a, n)", "manual 2.3.8"},
    {"bittog", ReferenceKind::Function, "Inverts bit n.", "bittog(a, n)", "manual 2.3.8"},
    {"memcpy", ReferenceKind::Function, "Copies n elements.", "memcpy(dst, src, n)",
     "manual 2.3.9"},
    {"memset", ReferenceKind::Function, "Sets n elements to a value.", "memset(dst, v, n)",
     "manual 2.3.10"},
    {"memmin", ReferenceKind::Function, "The smallest of n elements.", "memmin(src, n)",
     "manual 2.3.11"},
    {"memmax", ReferenceKind::Function, "The largest of n elements.", "memmax(src, n)",
     "manual 2.3.11"},
    {"memsum", ReferenceKind::Function, "The sum of n elements.", "memsum(src, n)",
     "manual 2.3.12"},
    {"#task", ReferenceKind::Directive, "#task/t; task t starts here after a reset.", "",
     "manual 2.5.1"},
    {"#define", ReferenceKind::Directive, "Defines a macro, as C does.", "", "manual 2.5.3"},
    {"#undef", ReferenceKind::Directive, "Removes a macro.", "", "manual 2.5.4"},
    {"#include", ReferenceKind::Directive, "Reads a file in place: #include \"scale.h\".", "",
     "manual 2.5.6"},
};

// A system variable, and for an axis (slave) variable its X_ form as programs write it (2.1).
void add_variable(std::vector<ReferenceEntry>& out, std::string_view name, char access, bool slave,
                  uint32_t length) {
  const Meaning* m = meaning_of(name);
  ReferenceEntry e{std::string(name),
                   ReferenceKind::SystemVariable,
                   m->summary,
                   m->unit,
                   length > 1 ? "index 0 to " + std::to_string(length - 1) : std::string(),
                   access_of(access),
                   kVariablesSource,
                   ""};
  if (slave) {
    ReferenceEntry x = e;
    x.name = "X_" + e.name;
    x.summary = "Axis X's " + e.name + ": " + e.summary;
    out.push_back(std::move(x));
  }
  out.push_back(std::move(e));
}

}  // namespace

std::vector<dialect::ReferenceEntry> reference() {
  std::vector<ReferenceEntry> out;
#define SYSVAR(name, id, access, slave, length) add_variable(out, #name, access, slave, length);
#include "dialects/pdl/system_names.def"
#undef SYSVAR
#define STATE(name, number, writable)                                                            \
  out.push_back({#name, ReferenceKind::SystemVariable, meaning_of(#name)->summary, "", "0 or 1", \
                 (writable) ? "read/write (seton, setoff)" : "read only", kVariablesSource, ""});
#include "dialects/pdl/states.def"
#undef STATE
  for (const Word& w : kWords)
    out.push_back({w.name, w.kind, w.summary, "", "", "", w.source, w.signature});
  return out;
}

}  // namespace uprog::pdl
