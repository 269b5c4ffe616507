// The Gold drive's command table (shared/spec/gold-drive.md), one row per command.
// Ids are stable: they are stored in compiled images, so a row's id never changes or is reused;
// new commands take the next free number.
//
// Access: a command whose spec "access" column does not include "program" (SV, LD, RS, HP, XC,
// KL, CC, LS, DB) is kNotProgram, so a program using it fails with compile error 79. Rows 57 on
// are the Elmo reference's commands that real programs and host drivers send
// (docs/dialects/gold.md, "Commands from the reference"); where a command's range differs per
// index (HM, TR), the row holds the widest range and DriveCommands checks each index.
#include "dialects/gold/commands.h"

#include <array>
#include <cstdint>

namespace uprog::gold {
namespace {

constexpr double kIntMin = -2147483648.0;
constexpr double kIntMax = 2147483647.0;
constexpr double kFloatMax = 1e37;  // manual 1.3: floats lie strictly inside ±1e37

constexpr uint32_t kR = kReadOnly;
constexpr uint32_t kIx = kIndexed;
constexpr uint32_t kAct = kAction | kNotAssignable;
constexpr uint32_t kHostAct = kAction | kNotAssignable | kNotProgram;
constexpr ValueType kI = ValueType::Int;
constexpr ValueType kF = ValueType::Float;

constexpr std::array kCommands{
    // Motion
    CommandInfo{"MO", 1, kI, 0, 0, 0, 0, 1, "motor enable: 1 on, 0 off"},
    CommandInfo{"SO", 2, kI, kR, 0, 0, 0, 1, "servo on: 1 once the loop is closed after MO=1"},
    CommandInfo{"UM", 3, kI, kMotorOffOnly, 0, 0, 1, 5,
                "unit mode: 1 current, 2 velocity, 5 position"},
    CommandInfo{"PA", 4, kI, 0, 0, 0, kIntMin, kIntMax, "absolute target of the next move, counts"},
    CommandInfo{"PR", 5, kI, 0, 0, 0, kIntMin, kIntMax,
                "relative move: next target = previous target + PR"},
    CommandInfo{"SP", 6, kI, 0, 0, 0, 1, kIntMax, "speed of point-to-point moves, counts/s"},
    CommandInfo{"AC", 7, kI, 0, 0, 0, 1, kIntMax, "acceleration, counts/s^2"},
    CommandInfo{"DC", 8, kI, 0, 0, 0, 1, kIntMax, "deceleration, counts/s^2"},
    CommandInfo{"SD", 9, kI, 0, 0, 0, 1, kIntMax,
                "stop deceleration (limits, hard stop), counts/s^2"},
    CommandInfo{"SF", 10, kI, kIx | kIndexOptional, 1, 2, 0, 500,
                "smoothing: [1] (or SF) jerk-limit time, ms, 0 = trapezoid; [2] stored"},
    CommandInfo{"JV", 11, kI, 0, 0, 0, kIntMin, kIntMax, "jog velocity, counts/s"},
    CommandInfo{"BG", 12, kI, kAct, 0, 0, 0, 0, "begin the motion defined by PA, PR or JV"},
    CommandInfo{"ST", 13, kI, kAct, 0, 0, 0, 0, "stop: decelerate with SD"},
    CommandInfo{"TC", 14, kF, 0, 0, 0, -1000, 1000, "torque (current) command in UM=1, A"},
    CommandInfo{"PX", 15, kI, 0, 0, 0, kIntMin, kIntMax, "main position feedback, counts"},
    CommandInfo{"VX", 16, kI, kR, 0, 0, kIntMin, kIntMax, "main velocity feedback, counts/s"},
    CommandInfo{"PE", 17, kI, kR, 0, 0, kIntMin, kIntMax,
                "position error (reference - feedback), counts"},
    CommandInfo{"DV", 18, kI, kR | kIx, 2, 3, kIntMin, kIntMax,
                "desired values: [2] velocity, [3] position"},
    CommandInfo{"MS", 19, kI, kR, 0, 0, 0, 3,
                "motion status: 0 settled in TR, 1 stationary, 2 moving, 3 motor off"},
    CommandInfo{"ER", 20, kI, kIx, 2, 3, 1, kIntMax, "maximum error: [2] velocity, [3] position"},
    CommandInfo{"VH", 21, kI, kIx, 2, 3, kIntMin, kIntMax,
                "high limits: [2] velocity, [3] position"},
    CommandInfo{"VL", 22, kI, kIx, 2, 3, kIntMin, kIntMax,
                "low limits: [2] velocity, [3] position"},
    CommandInfo{"XM", 23, kI, kIx, 1, 2, kIntMin, kIntMax,
                "position modulo range [1]..[2]; equal = none"},
    CommandInfo{"KP", 24, kF, kIx, 1, 3, 0, 1e6,
                "proportional gains: [1] current, [2] velocity, [3] position"},
    CommandInfo{"KI", 25, kF, kIx, 1, 3, 0, 1e6,
                "integral gains, 1/s: [1] current, [2] velocity, [3] position"},
    CommandInfo{"KV", 26, kF, kIx, 1, 2, 0, 10, "feedforward: [1] velocity, [2] acceleration"},
    CommandInfo{"CL", 27, kF, kIx, 1, 1, 0, 100, "continuous current limit, A"},
    CommandInfo{"PL", 28, kF, kIx, 1, 1, 0, 100, "peak current limit, A"},
    // Inputs, outputs, status
    CommandInfo{"IL", 29, kI, kIx, 1, 6, 0, 23, "input logic: function and polarity of input n"},
    CommandInfo{"IP", 30, kI, kR, 0, 0, kIntMin, kIntMax,
                "input port: functions in bits 0..14, levels from bit 16"},
    CommandInfo{"IB", 31, kI, kR | kIx, 0, 31, 0, 1, "bit n of IP"},
    CommandInfo{"OP", 32, kI, 0, 0, 0, 0, 15, "output port: bit n-1 drives output n"},
    CommandInfo{"OB", 33, kI, kIx, 1, 4, 0, 1, "output bit n"},
    CommandInfo{"MF", 34, kI, kR, 0, 0, kIntMin, kIntMax, "motor fault bits; 0 = no fault"},
    CommandInfo{"SR", 35, kI, kR, 0, 0, kIntMin, kIntMax, "status register"},
    // Time, storage, program control
    CommandInfo{"TM", 36, kI, 0, 0, 0, kIntMin, kIntMax, "32-bit system time, us, wraps"},
    CommandInfo{"TS", 37, kI, 0, 0, 0, 25, 2000, "servo sampling time, us"},
    CommandInfo{"UI", 38, kI, kIx, 1, 24, kIntMin, kIntMax, "user integer n, saved by SV"},
    CommandInfo{"UF", 39, kF, kIx, 1, 24, -kFloatMax, kFloatMax, "user float n, saved by SV"},
    CommandInfo{"SV", 40, kI, kHostAct, 0, 0, 0, 0, "save parameters to non-volatile storage"},
    CommandInfo{"LD", 41, kI, kHostAct, 0, 0, 0, 0, "load parameters from non-volatile storage"},
    CommandInfo{"RS", 42, kI, kHostAct, 0, 0, 0, 0, "reset the drive; the stored program survives"},
    CommandInfo{"MI", 43, kI, 0, 0, 0, 0, 65535, "auto-routine mask"},
    CommandInfo{"XQ", 44, kI, kAct, 0, 0, 0, 0,
                "start the program at a function, label or auto-routine"},
    CommandInfo{"HP", 45, kI, kHostAct, 0, 0, 0, 0, "halt the program"},
    CommandInfo{"XC", 46, kI, kHostAct, 0, 0, 0, 0, "continue a halted program"},
    CommandInfo{"KL", 47, kI, kHostAct, 0, 0, 0, 0, "kill: halt and reset the program's stacks"},
    CommandInfo{"PS", 48, kI, kR, 0, 0, -2, 1,
                "program status: -2 none, -1 never run, 0 halted, 1 running"},
    CommandInfo{"CC", 49, kI, kHostAct, 0, 0, 0, 0, "load the stored program into RAM"},
    CommandInfo{"LS", 50, kI, kHostAct, 0, 0, 0, 0, "list the program (host only)"},
    CommandInfo{"EC", 51, kI, kR, 0, 0, 0, kIntMax, "code of the interpreter's last error"},
    CommandInfo{"DB", 52, kI, kHostAct, 0, 0, 0, 0,
                "DB##RV[n]=name: map a user variable to a recorder signal"},
    CommandInfo{"RV", 53, kI, kIx, 1, 8, 0, 1023,
                "recorder: the signal RC's bit n-1 records (recorder_signals.cpp)"},
    CommandInfo{"RL", 54, kI, 0, 0, 0, 1, 65536, "recorder length, samples"},
    CommandInfo{"RG", 55, kI, 0, 0, 0, 1, 4096, "recorder gap, time quanta (RP[0])"},
    CommandInfo{
        "RR", 56, kI, 0, 0, 0, -1, 3,
        "recorder: -1 invalidate, 0 kill, 1 on BG, 2 now, 3 on RP's trigger; reads its status"},
    // From the Elmo reference (docs/dialects/gold.md)
    CommandInfo{
        "HM", 57, kI, kIx, 1, 7, kIntMin, kIntMax,
        "homing: [1] arm, [2] value, [3] event, [4] action, [5] PX, [6] output, [7] capture"},
    CommandInfo{"CA", 58, kI, kIx | kMotorOffOnly, 1, 57, kIntMin, kIntMax,
                "commutation and feedback set-up; CA[18] counts per revolution"},
    CommandInfo{"QP", 59, kI, kIx, 1, 1024, kIntMin, kIntMax, "PT motion: position table"},
    CommandInfo{"TR", 60, kI, kIx, 1, 2, 0, 32000,
                "target: [1] radius, counts; [2] time, ms (MS=0)"},
    CommandInfo{"TI", 61, kI, kR | kIx, 1, 2, kIntMin, kIntMax,
                "temperature indications, degrees C"},
    CommandInfo{"WS", 62, kI, kR | kIx, 1, 99, kIntMin, kIntMax,
                "system words; WS[21] = PX modulo CA[18]"},
    CommandInfo{"EO", 63, kI, 0, 0, 0, 0, 1, "echo of the host's characters: 1 on, 0 off"},
    CommandInfo{"LL", 64, kI, kIx, 2, 3, kIntMin, kIntMax,
                "low feedback limits: [2] speed, [3] position (fault)"},
    CommandInfo{"HL", 65, kI, kIx, 2, 3, kIntMin, kIntMax,
                "high feedback limits: [2] speed, [3] position (fault)"},
    CommandInfo{"FP", 66, kI, kR | kIx, 1, 2, kIntMin, kIntMax,
                "feedback positions: [1] main (PX), [2] auxiliary (PY)"},
    CommandInfo{"FV", 67, kI, kR | kIx, 1, 2, kIntMin, kIntMax,
                "feedback velocities: [1] main (VX), [2] auxiliary"},
    CommandInfo{"VR", 68, kI, kR | kNotProgram | kText, 0, 0, 0, 0, "firmware version text"},
    CommandInfo{"SN", 69, kI, kR | kIx, 1, 4, kIntMin, kIntMax,
                "identity: [1] vendor, [2] product, [3] revision, [4] serial number"},
    CommandInfo{"MP", 70, kI, kIx, 1, 6, 0, 65535,
                "PT motion: [1] first, [2] last index, [3] cyclic, [4] cycles per point"},
    CommandInfo{"PT", 71, kI, 0, 0, 0, 1, 1024,
                "PT motion: the next BG starts at QP[PT]; reads the executing index"},
    CommandInfo{"PY", 72, kI, 0, 0, 0, kIntMin, kIntMax, "auxiliary position counter"},
    CommandInfo{"PM", 73, kI, 0, 0, 0, 0, 1, "profiler mode in UM=2: 1 ramps to JV, 0 steps"},
    CommandInfo{"IQ", 74, kF, kR, 0, 0, -1e6, 1e6, "active (torque) current, A"},
    CommandInfo{"HX", 75, kI, 0, 0, 0, 0, 1, "hexadecimal answers: 1 on, 0 off"},
    CommandInfo{"RC", 76, kI, 0, 0, 0, 0, 255, "recorder: bit n-1 records RV[n]"},
    CommandInfo{"RP", 77, kI, kIx, 0, 9, kIntMin, kIntMax,
                "recorder: [0] quantum, [1] trigger signal, [2] pre-trigger %, [3] trigger type, "
                "[4] [5] levels, [6] [7] input polarity and mask, [8] [9] upload range"},
    CommandInfo{"WI", 78, kI, kR | kIx, 21, 21, kIntMin, kIntMax,
                "WI[21]: samples per signal the recorder holds"},
    CommandInfo{"BH", 79, kI, kHostAct, 0, 0, 0, 0,
                "BH=n: upload the recorded signal RC&n, hexadecimal (command_line.cpp)"},
    // What a Gold host's preflight reads (issue 38; docs/dialects/gold.md, "Preflight")
    CommandInfo{"RM", 80, kI, kMotorOffOnly, 0, 0, 0, 1,
                "reference mode: 0 none, 1 external (SR bit 5)"},
    CommandInfo{"ID", 81, kF, kR, 0, 0, -1e6, 1e6,
                "reactive current, A (0: the motor model has none)"},
    CommandInfo{"FC", 82, kI, kIx | kMotorOffOnly, 1, 12, kIntMin, kIntMax,
                "feedback and gear configuration; 1 = unity"},
    CommandInfo{"BP", 83, kI, kIx, 1, 2, 0, 32000,
                "brake delays, ms: [1] engage, [2] release (stored)"},
    CommandInfo{"SC", 84, kI, kIx, 1, 16, kIntMin, kIntMax, "system configuration words (stored)"},
    CommandInfo{"FS", 85, kI, 0, 0, 0, kIntMin, kIntMax,
                "final speed of a point-to-point move, counts/s (stored)"},
    CommandInfo{"OV", 86, kI, kR | kIx, 2, 2, 0, 3,
                "OV[2]: the motion BG began: 0 none, 1 PTP, 2 PT, 3 jog"},
    CommandInfo{"LC", 87, kI, kR, 0, 0, 0, 1,
                "current limit: 1 limited to CL[1], 0 PL[1] or motor off"},
};

// find_command(id) indexes the table directly: row i must hold id i + 1.
constexpr bool ids_follow_rows() {
  for (size_t i = 0; i < kCommands.size(); ++i)
    if (kCommands[i].id != i + 1) return false;
  return true;
}
static_assert(ids_follow_rows(), "kCommands rows must be in id order, 1, 2, 3, ...");

char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (upper(a[i]) != upper(b[i])) return false;
  return true;
}

}  // namespace

const CommandInfo* find_command(std::string_view name) {
  for (const CommandInfo& c : kCommands)
    if (equal_ignoring_case(c.name, name)) return &c;
  return nullptr;
}

constinit const std::span<const CommandInfo> kCommandRows{kCommands};

std::span<const CommandInfo> all_commands() { return kCommands; }

}  // namespace uprog::gold
