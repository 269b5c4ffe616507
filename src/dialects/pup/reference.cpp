// PUP's reference (reference.h): every controller keyword gets its entry from keywords.def, the
// table the compiler, the CUP loader and the command line read; its meaning and unit are
// shared/spec/akribis-drive.md's (Messages, CUP keywords, Threads and events, Program control).
#include "dialects/pup/reference.h"

#include <string>
#include <string_view>

#include "dialects/pup/builtin_header.h"
#include "dialects/pup/keywords.h"

namespace uprog::pup {
namespace {

using dialect::ReferenceEntry;
using dialect::ReferenceKind;

struct Meaning {
  std::string_view name;
  const char* summary;
  const char* unit;
  const char* section;  // akribis-drive.md's
};

constexpr const char* kAxis = "Messages";
constexpr const char* kCup = "CUP keywords and type numbers";
constexpr const char* kControl = "Program control";
constexpr const char* kThreads = "Threads and events";

constexpr Meaning kMeanings[] = {
    {"AMotorOn", "Motor enable (Gold's MO); =1 fails with 23 on a fault cause, 24 on inhibit.", "",
     kAxis},
    {"AMotorReady", "The servo loop is closed (Gold's SO).", "", kAxis},
    {"AMotionMode",
     "What ABegin does: 0 move to AAbsTrgt, 1 by ARelTrgt, 2 jog, 3 velocity loop, "
     "4 current ACurrCmd; changing loop needs the motor off (22).",
     "", kAxis},
    {"AAbsTrgt", "Absolute target of the next move (Gold's PA).", "counts", kAxis},
    {"ARelTrgt", "Relative target of the next move (Gold's PR).", "counts", kAxis},
    {"ACurrCmd", "Current command in mode 4 (Gold's TC).", "mA", kAxis},
    {"APos", "Position feedback (Gold's PX); not set during motion.", "counts", kAxis},
    {"ASpeed", "Speed: nonzero, |v| <= 2e6; moves use |v|, modes 2 and 3 its sign.", "counts/s",
     kAxis},
    {"AAccel", "Acceleration, > 0 (Gold's AC).", "counts/s^2", kAxis},
    {"ADecel", "Deceleration, > 0 (Gold's DC); AStop uses it.", "counts/s^2", kAxis},
    {"AStopDecel", "Stop deceleration, > 0 (Gold's SD).", "counts/s^2", kAxis},
    {"ASmooth", "Smoothing time (Gold's SF).", "ms", kAxis},
    {"ABegin", "Starts the motion AMotionMode names (21 with the motor off).", "", kAxis},
    {"AStop", "Stops with ADecel.", "", kAxis},
    {"AVel", "Velocity feedback (Gold's VX).", "counts/s", kAxis},
    {"APosErr", "Position error (Gold's PE).", "counts", kAxis},
    {"APosRef", "Reference position (Gold's DV[3]).", "counts", kAxis},
    {"AInMotion", "1 while the profiler moves.", "", kAxis},
    {"AInPos", "1 in position (Gold's MS = 0).", "", kAxis},
    {"APosMax", "High software position limit (Gold's VH[3]).", "counts", kAxis},
    {"APosMin", "Low software position limit (Gold's VL[3]).", "counts", kAxis},
    {"AMaxPosErr", "Largest position error before a fault (Gold's ER[3]).", "counts", kAxis},
    {"AMotorFault", "Fault bits (Gold's MF).", "", kAxis},
    {"AClearFault", "Clears the fault once its cause is gone (23 while it is there).", "", kAxis},
    {"ADinPort", "Digital inputs: bit n-1 is input n (1..6); the same as AInPort.", "", kAxis},
    {"AInPort", "Digital inputs: bit n-1 is input n (1..6); the same as ADinPort.", "", kAxis},
    {"ADoutPort", "Digital outputs: bit n-1 is output n (1..4); the same as AOutPort.", "", kAxis},
    {"AOutPort", "Digital outputs: bit n-1 is output n (1..4); the same as ADoutPort.", "", kAxis},
    {"AInFunc",
     "Input n's function: 0 general, 1/2 forward/reverse limit, 3 inhibit, 4 hard "
     "stop; active high.",
     "", kAxis},
    {"AAINPort", "The analog input.", "mV", kAxis},
    {"AAINFactor", "Analog input factor, kept for programs (default 1).", "", kAxis},
    {"AAINOffset", "Analog input offset, kept for programs (default 0).", "", kAxis},
    {"AGenData", "General data for programs, n <= 1000, 0 at boot.", "", kAxis},
    {"ATimer", "Timer n <= 4: counts down by 1 each ms to 0 (event 18-21 at 0).", "ms", kAxis},
    {"ATime", "Time since boot.", "ms", kAxis},
    {"AWaitTime", "AWaitTime,ms: the thread waits; in a program only.", "ms", kAxis},
    {"AErrLog",
     "Error log n <= 16, newest first: code,source,line (source 0 the host, else the "
     "thread).",
     "", kAxis},
    {"APushConstant", "APushConstant,n pushes n on the thread's expression stack.", "", kCup},
    {"APushParam", "APushParam,AKey pushes the parameter's value.", "", kCup},
    {"APopParam", "APopParam,AKey pops into the parameter (an assignment, with its checks).", "",
     kCup},
    {"APushParamIdx", "APushParamIdx[S],AKey[N] pops i (1..S, else 4) and pushes AKey[N+i-1].", "",
     kCup},
    {"APopParamIdx",
     "APopParamIdx[S],AKey[N] pops i (1..S, else 4), then pops into "
     "AKey[N+i-1].",
     "", kCup},
    {"AMath", "AMath[n]: an operation on the stack (1 ADD ... 42 EXP); 2nd op 1st.", "", kCup},
    {"ACompare",
     "ACompare[c] pushes 1 or 0: 2 POS, 3 EQ, 4 NE, 5 GT, 6 GE, 7 LT, 8 LE, 9 Z, 10 NZ.", "", kCup},
    {"AGetStatus", "AGetStatus[s],v pushes 1 or 0 as status s holds for v.", "", kCup},
    {"AJump", "AJump[c],line jumps when condition c holds (1 always).", "", kCup},
    {"AProgFuncCall", "AProgFuncCall,f calls function f (28 past 30 frames).", "", kCup},
    {"AProgCallFunc", "The same as AProgFuncCall.", "", kCup},
    {"AReturn", "Returns from a function or an event (29 without a call).", "", kCup},
    {"AWaitStatus", "AWaitStatus[s],v waits until status s holds for v.", "", kCup},
    {"AProgTask", "Marks where task n (1..64) starts; not executed.", "", kCup},
    {"AProgFunc", "Marks where function n (1..256) starts; not executed.", "", kCup},
    {"AProgRun", "AProgRun[t],n starts task n in thread t; n = -1 continues a halted thread.", "",
     kControl},
    {"AProgHalt", "Halts thread t.", "", kControl},
    {"AProgHaltAll", "Halts every thread.", "", kControl},
    {"AProgResetAll",
     "Halts and resets every thread: stacks, pointers, errors, breakpoints, "
     "priorities, mask, events.",
     "", kControl},
    {"AProgStatus",
     "Thread t: 0 idle, 1 running, 2 waiting, 3 halted, 4 breakpoint, 5 error, "
     "6 held.",
     "", kThreads},
    {"AProgError", "Thread t's last run-time error.", "", kControl},
    {"AProgPointer", "Thread t's next CUP line, 0 idle; set only halted or idle.", "", kControl},
    {"AProgSingle",
     "AProgSingle[t],k steps a halted thread: k = 0 one line, else over calls and "
     "waits.",
     "", kControl},
    {"AProgBreaks", "Thread t's breakpoint lines: =n adds, =-n removes, =0 clears; at most 16.", "",
     kControl},
    {"AProgCallStack", "Thread t's return lines, innermost first.", "", kControl},
    {"AProgExpStack", "Thread t's expression stack.", "", kControl},
    {"AProgClrCall", "Clears thread t's call stack (17 while it runs).", "", kControl},
    {"AProgClrExp", "Clears thread t's expression stack (17 while it runs).", "", kControl},
    {"AProgEventMask", "Bit ID enables event ID (default 0x00FFFFFF); bit 31 lets events nest.", "",
     kThreads},
    {"AProgPriority", "Thread t runs every k-th cycle, k = 1..1000 (default 1).", "", kThreads},
    {"AProgInfo", "The program's CRC, date, name and #information strings, an answer each.", "",
     kControl},
    {"ADownloadUProg", "Downloads a CUP program over the line.", "", "The CUP file"},
    {"AUploadUProg", "Uploads the stored CUP program.", "", "The CUP file"},
};

const Meaning& meaning_of(std::string_view name) {
  static constexpr Meaning kNone{"", "", "", ""};  // the reference test names what lacks one
  for (const Meaning& m : kMeanings)
    if (m.name == name) return m;
  return kNone;
}

std::string access_of(const Keyword& k) {
  std::string a;
  switch (k.kind) {
    case KeywordKind::Param:
      a = "read/write";
      break;
    case KeywordKind::ReadOnly:
      a = "read only";
      break;
    case KeywordKind::Command:
      a = "command";
      break;
    case KeywordKind::Cup:
      a = "CUP stack or flow keyword";
      break;
    case KeywordKind::Marker:
      a = "marker";
      break;
  }
  a += (k.attrs & kOverLine) != 0 ? "; over the line" : "; not over the line (13)";
  a += (k.attrs & kInProgram) != 0 ? "; in a program" : "; not in a program (14)";
  if ((k.attrs & kNeedsProgram) != 0) a += "; needs a program (15)";
  if ((k.attrs & kNotInMotion) != 0) a += "; not during motion (20)";
  return a;
}

struct Word {
  const char* name;
  ReferenceKind kind;
  const char* summary;
  const char* signature;
};

// akribis-drive.md, "PUP": the statements, math functions (in thousandths and mrad, as CUP's
// AMath) and directives.
constexpr Word kWords[] = {
    {"if", ReferenceKind::Keyword, "if (cond) ... else ... end", ""},
    {"else", ReferenceKind::Keyword, "The other branch of an if.", ""},
    {"end", ReferenceKind::Keyword, "Ends an if, while, for or switch.", ""},
    {"while", ReferenceKind::Keyword, "while (cond) ... end", ""},
    {"for", ReferenceKind::Keyword, "for (init; cond; step) ... end, as C's.", ""},
    {"switch", ReferenceKind::Keyword, "switch (v) case n: ... default: ... end, as C's.", ""},
    {"case", ReferenceKind::Keyword, "A switch branch.", ""},
    {"default", ReferenceKind::Keyword, "The switch branch no case took.", ""},
    {"break", ReferenceKind::Keyword, "Leaves the innermost loop or switch.", ""},
    {"continue", ReferenceKind::Keyword, "Goes on with the innermost loop's next turn.", ""},
    {"return", ReferenceKind::Keyword, "Returns from a function (Return, AReturn too).", ""},
    {"GoTo", ReferenceKind::Keyword, "GoTo, n: jumps to task n (AJump[1]).", ""},
    {"sin", ReferenceKind::Function, "Sine, the angle in mrad, the result in thousandths.",
     "sin(a)"},
    {"cos", ReferenceKind::Function, "Cosine, the angle in mrad, the result in thousandths.",
     "cos(a)"},
    {"tan", ReferenceKind::Function, "Tangent, the angle in mrad, the result in thousandths.",
     "tan(a)"},
    {"asin", ReferenceKind::Function, "Arc sine in mrad of thousandths; beyond +-1000: 31.",
     "asin(x)"},
    {"acos", ReferenceKind::Function, "Arc cosine in mrad of thousandths; beyond +-1000: 31.",
     "acos(x)"},
    {"atan", ReferenceKind::Function, "Arc tangent in mrad of thousandths.", "atan(x)"},
    {"atan2", ReferenceKind::Function, "Arc tangent of y/x in mrad.", "atan2(y, x)"},
    {"log", ReferenceKind::Function, "Natural logarithm in thousandths; x <= 0: 31.", "log(x)"},
    {"log10", ReferenceKind::Function, "Base-10 logarithm in thousandths; x <= 0: 31.", "log10(x)"},
    {"exp", ReferenceKind::Function, "e to the x, in thousandths.", "exp(x)"},
    {"power", ReferenceKind::Function, "a to the b, saturating; a negative operand: 31.",
     "power(a, b)"},
    {"abs", ReferenceKind::Function, "Absolute value.", "abs(x)"},
    {"sqrt", ReferenceKind::Function, "The integer square root; a negative operand: 31.",
     "sqrt(x)"},
    {"#define", ReferenceKind::Directive, "Replaces whole identifiers from its line on.", ""},
    {"#definevar", ReferenceKind::Directive,
     "#definevar Arr[S] AGenData[N]: Arr[i] is AGenData[N+i-1].", ""},
    {"#include", ReferenceKind::Directive,
     "Reads a .puh beside the includer, then the compiler's akribis.puh.", ""},
    {"#event", ReferenceKind::Directive, "#event ID Function links event ID to a function.", ""},
    {"#information", ReferenceKind::Directive, "A text AProgInfo answers.", ""},
};

// The names `#include akribis.puh` gives (builtin_header.h, the compiler's own header): each
// with its number and the table the number is for, the header's groups in their order.
void add_builtin_header(std::vector<ReferenceEntry>& out) {
  static constexpr std::pair<std::string_view, const char*> kGroups[] = {
      {"ADD", "a Math[] operation"},
      {"ALWAYS", "a Compare[]/Jump[] condition"},
      {"MOTION_ENDED", "an AWaitStatus[] condition"},
      {"EV_FAULT", "an event ID (#event)"}};
  const char* group = kGroups[0].second;
  std::string_view text = kBuiltinHeader;
  while (!text.empty()) {
    const size_t eol = text.find('\n');
    std::string_view line = text.substr(0, eol);
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    if (!line.starts_with("#define ")) continue;
    line.remove_prefix(8);
    const size_t space = line.find(' ');
    const std::string_view name = line.substr(0, space);
    const std::string_view value = space == std::string_view::npos ? "" : line.substr(space + 1);
    for (const auto& [first, what] : kGroups)
      if (name == first) group = what;
    out.push_back({std::string(name), ReferenceKind::Constant,
                   std::string(name) + " is " + std::string(value) + ": " + group +
                       ", as `#include akribis.puh` names it.",
                   "", "", "",
                   "akribis.puh, built into the compiler (docs/dialects/pup.md, builtin_header.h); "
                   "shared/spec/akribis-drive.md, #include",
                   ""});
  }
}

}  // namespace

std::vector<dialect::ReferenceEntry> reference() {
  std::vector<ReferenceEntry> out;
  for (size_t i = 0; i < static_cast<size_t>(KeywordId::kCount); ++i) {
    const Keyword& k = keyword(static_cast<KeywordId>(i));
    const Meaning& m = meaning_of(k.name);
    std::string range;
    if (k.indexed())
      range = "index " + std::to_string(k.index_min) + " to " + std::to_string(k.index_max);
    out.push_back({std::string(k.name),
                   k.kind == KeywordKind::Param || k.kind == KeywordKind::ReadOnly
                       ? ReferenceKind::SystemVariable
                       : ReferenceKind::Command,
                   m.summary, m.unit, range, access_of(k),
                   m.section[0] == '\0' ? ""
                                        : std::string("shared/spec/akribis-drive.md, ") +
                                              m.section + "; AG300 manual (seed 002)",
                   ""});
  }
  for (const Word& w : kWords) {
    out.push_back(
        {w.name, w.kind, w.summary, "", "", "", "shared/spec/akribis-drive.md, PUP", w.signature});
  }
  add_builtin_header(out);
  return out;
}

}  // namespace uprog::pup
