// ST's reference (reference.h): every ASCII entry the compiler checks XREAD/XWRITE/COMMAND names
// against gets its entry from ascii_table(), with its meaning from shared/spec/s300-drive.md
// ("The ASCII interface") or, for the commands real hosts send, docs/dialects/st.md ("Host
// commands", citing Kollmorgen's ASCII reference pages); the language from "Program layout" and
// "Semantics".
#include "dialects/st/reference.h"

#include <string>
#include <string_view>

#include "dialects/st/ascii_table.h"

namespace uprog::st {
namespace {

using dialect::ReferenceEntry;
using dialect::ReferenceKind;

constexpr const char* kSpec = "shared/spec/s300-drive.md, The ASCII interface";
constexpr const char* kHost = "docs/dialects/st.md, Host commands (Kollmorgen ASCII reference)";

struct Meaning {
  std::string_view name;
  const char* summary;
  const char* unit;
  const char* source;
};

constexpr Meaning kMeanings[] = {
    {"EN", "Software enable: the output stage on unless a fault (8).", "", kSpec},
    {"DIS", "Software disable: the output stage off, motion aborted.", "", kSpec},
    {"ACTIVE", "1 while the output stage is on.", "", kSpec},
    {"OPMODE", "Operating mode: 0 velocity, 2 torque, 8 tasks; written disabled only.", "", kSpec},
    {"J", "J v [t]: jog at v rpm (for t ms); enabled, OPMODE 0.", "rpm", kSpec},
    {"T", "T a: torque setpoint in amperes; enabled, OPMODE 2.", "A", kSpec},
    {"ORDER", "ORDER nr p v c a d a2 d2 fn ft: defines motion task nr; ORDER nr lists it.", "",
     kSpec},
    {"MOVE", "MOVE nr starts motion task nr (OPMODE 8, enabled); MOVE reads the last.", "", kSpec},
    {"STOP", "Decelerates (the task's d, else DECSTOP).", "", kSpec},
    {"MTMUX", "The task (0, 192-255) that O_P ... O_FT edit; 0 at boot.", "", kSpec},
    {"O_P", "Position of the task MTMUX names.", "counts", kSpec},
    {"O_V", "Velocity of the task MTMUX names.", "", kSpec},
    {"O_C", "Control word of the task MTMUX names (bit 0 relative, bit 3 next, bit 13 user units).",
     "", kSpec},
    {"O_ACC1", "Acceleration ramp of the task MTMUX names.", "ms", kSpec},
    {"O_DEC1", "Deceleration ramp of the task MTMUX names.", "ms", kSpec},
    {"O_FN", "The next task of the task MTMUX names.", "", kSpec},
    {"O_FT", "The delay before the next task of the task MTMUX names.", "ms", kSpec},
    {"PGEARI", "Position resolution numerator (default 10000); written disabled only.", "", kSpec},
    {"PGEARO", "Position resolution denominator (default 65536); written disabled only.", "",
     kSpec},
    {"PFB", "Position feedback.", "counts x PGEARI/PGEARO", kSpec},
    {"PE", "Following error.", "counts x PGEARI/PGEARO", kSpec},
    {"PV", "Velocity.", "", kSpec},
    {"V", "Velocity (a float).", "rpm", kSpec},
    {"I", "The actual current, always positive (a float).", "A", kHost},
    {"ACC", "Acceleration: ms from 0 to VLIM, default 10.", "ms", kSpec},
    {"DEC", "Deceleration: ms from VLIM to 0, default 10.", "ms", kSpec},
    {"DECSTOP", "Stop deceleration: ms from VLIM to 0, default 10.", "ms", kSpec},
    {"VLIM", "Velocity limit, default 3000.", "rpm", kSpec},
    {"PEINPOS", "In-position window.", "counts", kSpec},
    {"PEMAX", "Following error limit (F03).", "counts", kSpec},
    {"INPOS", "1 while |target - PFB| <= PEINPOS.", "", kSpec},
    {"IN1", "Digital input 1 (logical).", "", kSpec},
    {"IN2", "Digital input 2 (logical).", "", kSpec},
    {"IN3", "Digital input 3 (logical).", "", kSpec},
    {"IN4", "Digital input 4 (logical).", "", kSpec},
    {"O1", "Digital output 1.", "", kSpec},
    {"O2", "Digital output 2.", "", kSpec},
    {"ERRCODE", "The faults in clear text: Fnn text a line each, or no error.", "", kSpec},
    {"STATUS",
     "Five hex status words: 1 enable and ready bits, 2 faults, 5 moving and in position.", "",
     kSpec},
    {"CLRFAULT", "Clears the faults whose cause is gone; programs stay stopped.", "", kSpec},
    {"SAVE", "Saves the parameters.", "", kSpec},
    {"LOAD", "Loads the saved parameters (disabled).", "", kSpec},
    {"RSTVAR", "Sets the parameters to their defaults.", "", kSpec},
    {"COLDSTART", "Reboots the drive.", "", kSpec},
    {"MSG", "Message level 0-2, default 0, saved: 1 and up print a refused command's error.", "",
     kSpec},
    {"PROMPT", "1 echoes input and prompts with -->, 0 neither.", "", kSpec},
    {"TASK", "The programs' load and their overruns.", "", kSpec},
    {"VER", "The firmware's version.", "", kSpec},
    {"PLCSTOP", "Stops all macro programs.", "", kSpec},
    {"PLC", "1 running, 0 stopped, -1 failed, -2 no source.", "", kSpec},
    {"PLCRUN", "Compiles the stored source and starts it (5 enabled, 11 failed).", "", kSpec},
    {"PLCSTART", "Compiles the stored source and starts it (5 enabled, 11 failed).", "", kSpec},
    {"PLCDL", "PLCDL BEGIN n / hex / END / ABORT: stores a source.", "", kSpec},
    {"PLIST", "The stored source, a line each.", "", kSpec},
    {"PLCSTAT", "A line per program: its name, state and where it stands.", "", kHost},
    {"PLCHOLD", "PLCHOLD [name]: holds the program (every program without a name).", "", kHost},
    {"PLCCONT", "PLCCONT [name]: lets a held program go on.", "", kHost},
    {"PLCSTEP", "PLCSTEP name: runs the held program's next line and holds it again.", "", kHost},
    {"VOSPD", "Overspeed threshold of F08, default 3600.", "rpm", kHost},
    {"ANCNFG",
     "Analog input configuration 0-14 (0 and 1: SW1 the velocity setpoint); written "
     "disabled, taken at boot.",
     "", kHost},
    {"MH", "Starts homing by NREF, DREF and VREF (OPMODE 8, enabled).", "", kHost},
    {"NREF", "Homing type 0-20, default 0 (0 takes the present position).", "", kHost},
    {"DREF", "Homing direction: 0 negative, 1 positive, 2 the nearer.", "", kHost},
    {"VREF", "Homing velocity, default 10000, at most VLIM.", "user units/s", kHost},
    {"ROFFS", "The reference point's position, default 0.", "user units", kHost},
    {"SETREF", "Makes the present position the reference point now.", "", kHost},
    {"SRND", "Start of the modulo range, default -2^31.", "user units", kHost},
    {"ERND", "End of the modulo range, default 2^31-1.", "user units", kHost},
    {"PRD", "The feedback's position within one turn, 0 to 1048575 (20 bits).", "", kHost},
    {"REFPOS",
     "Where the last homing saw its criterion, within one turn in 20 bits (as PRD counts).", "",
     kHost},
    {"VUNIT", "Velocity units: 0 and 1 (rpm for the speed loop, user units/s for tasks).", "",
     kHost},
    {"IN1MODE", "Input 1's function (2 PSTOP, 3 NSTOP, 12 reference switch); taken at boot.", "",
     kHost},
    {"IN2MODE", "Input 2's function (2 PSTOP, 3 NSTOP, 12 reference switch); taken at boot.", "",
     kHost},
    {"IN3MODE", "Input 3's function (2 PSTOP, 3 NSTOP, 12 reference switch); taken at boot.", "",
     kHost},
    {"IN4MODE", "Input 4's function (2 PSTOP, 3 NSTOP, 12 reference switch); taken at boot.", "",
     kHost},
    {"ANIN1", "Analog input SW1's level.", "mV", kHost},
    {"ANIN2", "Analog input SW2's level.", "mV", kHost},
    {"ANOFF1", "Analog input SW1's offset.", "mV", kHost},
    {"ANOFF2", "Analog input SW2's offset.", "mV", kHost},
    {"ANZERO1", "Zeroes analog input SW1's offset.", "", kHost},
    {"ANZERO2", "Zeroes analog input SW2's offset.", "", kHost},
    {"VSCALE1", "OPMODE 1's speed at 10 V on SW1, default 3000.", "rpm", kHost},
    {"VSCALE2", "OPMODE 1's speed at 10 V on SW2, default 3000.", "rpm", kHost},
};

const Meaning& meaning_of(std::string_view name) {
  static constexpr Meaning kNone{"", "", "", ""};  // the reference test names what lacks one
  for (const Meaning& m : kMeanings)
    if (m.name == name) return m;
  return kNone;
}

std::string access_of(const AsciiEntry& e) {
  std::string a = e.kind == AsciiKind::Command     ? "command"
                  : e.access == AsciiAccess::Read  ? "read only"
                  : e.access == AsciiAccess::Write ? "write only"
                                                   : "read/write";
  if (e.disabled_only) a += "; written with the output stage off (error 5)";
  if (e.saved) a += "; SAVE keeps it";
  return a;
}

struct Word {
  const char* name;
  ReferenceKind kind;
  const char* summary;
  const char* signature;
  const char* source;
};

constexpr const char* kLayout = "shared/spec/s300-drive.md, Program layout";
constexpr const char* kSemantics = "shared/spec/s300-drive.md, Semantics";

constexpr Word kWords[] = {
    {"IF", ReferenceKind::Keyword, "IF e THEN ... [ELSE ...] END_IF;", "", kLayout},
    {"THEN", ReferenceKind::Keyword, "Opens an IF's branch.", "", kLayout},
    {"ELSE", ReferenceKind::Keyword, "The other branch of an IF.", "", kLayout},
    {"END_IF", ReferenceKind::Keyword, "Ends an IF.", "", kLayout},
    {"WHILE", ReferenceKind::Keyword, "WHILE e DO ... END_WHILE; only in PLCMAIN (16).", "",
     kLayout},
    {"DO", ReferenceKind::Keyword, "Opens a WHILE's or FOR's body.", "", kLayout},
    {"END_WHILE", ReferenceKind::Keyword, "Ends a WHILE.", "", kLayout},
    {"REPEAT", ReferenceKind::Keyword, "REPEAT ... UNTIL e [END_REPEAT]; only in PLCMAIN (16).", "",
     kLayout},
    {"UNTIL", ReferenceKind::Keyword, "The condition that ends a REPEAT.", "", kLayout},
    {"END_REPEAT", ReferenceKind::Keyword, "Ends a REPEAT.", "", kLayout},
    {"FOR", ReferenceKind::Keyword,
     "FOR V := a TO b [BY constant] DO ... END_FOR; bounds evaluated once.", "", kLayout},
    {"TO", ReferenceKind::Keyword, "A FOR's last value.", "", kLayout},
    {"BY", ReferenceKind::Keyword, "A FOR's step, a constant other than 0.", "", kLayout},
    {"END_FOR", ReferenceKind::Keyword, "Ends a FOR.", "", kLayout},
    {"GOTO", ReferenceKind::Keyword, "GOTO L; to L: at a line start of the same program.", "",
     kLayout},
    {"RETURN", ReferenceKind::Keyword, "Ends a function, or this run of a program.", "", kLayout},
    {"PROGRAM", ReferenceKind::Keyword, "PROGRAM PLC1 ... END_PROGRAM: a program.", "", kLayout},
    {"END_PROGRAM", ReferenceKind::Keyword, "Ends a program.", "", kLayout},
    {"FUNCTION", ReferenceKind::Keyword,
     "FUNCTION NAME ... END_FUNCTION defines one; FUNCTION (NAME); calls it.", "", kLayout},
    {"END_FUNCTION", ReferenceKind::Keyword, "Ends a function.", "", kLayout},
    {"BYTE", ReferenceKind::Keyword, "An 8-bit global: read sign-extended, stores the low 8 bits.",
     "", kSemantics},
    {"WORD", ReferenceKind::Keyword, "A 16-bit global: read sign-extended, stores the low 16 bits.",
     "", kSemantics},
    {"LONG", ReferenceKind::Keyword, "A 32-bit global.", "", kSemantics},
    {"DLONG", ReferenceKind::Keyword, "A 64-bit global, only in the DLONG built-ins (22).", "",
     kSemantics},
    {"MOD", ReferenceKind::Keyword, "Remainder, signed like the dividend.", "", kSemantics},
    {"AND", ReferenceKind::Keyword, "Logical and: -1 or 0, both sides evaluated.", "", kSemantics},
    {"OR", ReferenceKind::Keyword, "Logical or: -1 or 0, both sides evaluated.", "", kSemantics},
    {"XOR", ReferenceKind::Keyword, "Logical exclusive or: -1 or 0.", "", kSemantics},
    {"NOT", ReferenceKind::Keyword, "Logical not: -1 or 0.", "", kSemantics},
    {"BNOT", ReferenceKind::Keyword, "Bitwise not.", "", kSemantics},
    {"TRUE", ReferenceKind::Keyword, "-1.", "", kLayout},
    {"FALSE", ReferenceKind::Keyword, "0.", "", kLayout},
    {"CLRDLONG", ReferenceKind::Function, "D := 0.", "CLRDLONG(D)", kSemantics},
    {"SETDLONG", ReferenceKind::Function, "D1 := D2.", "SETDLONG(D1, D2)", kSemantics},
    {"ADDDLONG", ReferenceKind::Function, "D1 := D2 + V, wrapping at 2^64.", "ADDDLONG(D1, D2, V)",
     kSemantics},
    {"SUBDLONG", ReferenceKind::Function, "D1 := D2 - V, wrapping at 2^64.", "SUBDLONG(D1, D2, V)",
     kSemantics},
    {"MULDIV", ReferenceKind::Function, "R := V1 * V2 / V3 in 64 bits, truncating.",
     "MULDIV(V1, V2, V3, R)", kSemantics},
    {"LIMITW", ReferenceKind::Function, "OUT := IN clamped to +-MAX.", "LIMITW(OUT, IN, MAX)",
     kSemantics},
    {"XREAD", ReferenceKind::Function, "Reads a drive parameter by name into V.",
     "XREAD('NAME', V)", kSemantics},
    {"XWRITE", ReferenceKind::Function, "Writes V to a drive parameter by name.",
     "XWRITE('NAME', V)", kSemantics},
    {"COMMAND", ReferenceKind::Function, "Sends a line to the ASCII interpreter.",
     "COMMAND('text')", kSemantics},
    {"PRINTF", ReferenceKind::Function, "Prints up to 3 LONG variables: %d %u %x %X %%.",
     "PRINTF('x=%d\\n', L1, L2, L3)", kSemantics},
    {"PLCINIT", ReferenceKind::Keyword, "The program run once at start.", "", kLayout},
    {"PLCMAIN", ReferenceKind::Keyword, "The background program, run again and again.", "",
     kLayout},
    {"PLC62", ReferenceKind::Keyword, "The program run every 62.5 us.", "", kLayout},
    {"PLC250", ReferenceKind::Keyword, "The program run every 250 us.", "", kLayout},
    {"PLC1", ReferenceKind::Keyword, "The program run every 1 ms.", "", kLayout},
    {"PLC4", ReferenceKind::Keyword, "The program run every 4 ms.", "", kLayout},
    {"PLC16", ReferenceKind::Keyword, "The program run every 16 ms.", "", kLayout},
};

}  // namespace

std::vector<dialect::ReferenceEntry> reference() {
  std::vector<ReferenceEntry> out;
  for (const AsciiEntry& e : ascii_table()) {
    const Meaning& m = meaning_of(e.name);
    out.push_back({std::string(e.name), ReferenceKind::Command, m.summary, m.unit,
                   e.kind == AsciiKind::Command ? "" : "default " + std::to_string(e.default_value),
                   access_of(e), m.source, ""});
  }
  for (int n = 1; n <= kUserVariables; ++n) {
    out.push_back({user_variable_name(n), ReferenceKind::SystemVariable,
                   "A user LONG variable, saved as a parameter.", "", "", "read/write; saved",
                   kSemantics, ""});
  }
  for (const Word& w : kWords)
    out.push_back({w.name, w.kind, w.summary, "", "", "", w.source, w.signature});
  return out;
}

}  // namespace uprog::st
