// The compiler's own akribis.puh: names for the numbers of Math[], Compare[]/Jump[],
// WaitStatus[] and the event IDs, found by `#include akribis.puh` when no file of that name
// lies beside the includer.
#pragma once
#include <string_view>

namespace uprog::pup {

constexpr std::string_view kBuiltinHeaderName = "akribis.puh";
constexpr std::string_view kBuiltinHeader =
    "// akribis.puh: the numbers of the AG300's type tables\n"
    "#define ADD 1\n#define MULTIPLY 2\n#define SUBTRACT 3\n#define DIVIDE 4\n#define MODULO 5\n"
    "#define NEGATE 6\n#define ABS 7\n#define SQRT 8\n#define POWER 9\n#define BITWISE_AND 10\n"
    "#define BITWISE_OR 11\n#define BITWISE_XOR 12\n#define BITWISE_NOT 13\n#define SHIFT_LEFT 14\n"
    "#define SHIFT_RIGHT 15\n#define LOGICAL_AND 20\n#define LOGICAL_OR 21\n#define LOGICAL_NOT "
    "22\n"
    "#define SIN 30\n#define COS 31\n#define TAN 32\n#define ASIN 33\n#define ACOS 34\n#define "
    "ATAN 35\n"
    "#define ATAN2 36\n#define LOG 40\n#define LOG10 41\n#define EXP 42\n"
    "#define ALWAYS 1\n#define POS 2\n#define EQ 3\n#define NE 4\n#define GT 5\n#define GE "
    "6\n#define LT 7\n"
    "#define LE 8\n#define Z 9\n#define NZ 10\n"
    "#define MOTION_ENDED 1\n#define IN_POSITION 2\n#define INPUT_HIGH 3\n#define INPUT_LOW 4\n"
    "#define FLAG_SET 5\n#define FLAG_CLEAR 6\n#define TIMER_ZERO 7\n#define MOTOR_READY 8\n"
    "#define THREAD_STOPPED 9\n"
    "#define EV_FAULT 0\n#define EV_FWD_LIMIT 1\n#define EV_REV_LIMIT 2\n#define EV_POS_MAX 3\n"
    "#define EV_POS_MIN 4\n#define EV_MOTION_END 5\n#define EV_INPUT1_RISE 6\n#define "
    "EV_INPUT1_FALL 12\n"
    "#define EV_TIMER1_ZERO 18\n#define EV_THREAD_ERROR 22\n#define EV_COMM_ERROR 23\n";

}  // namespace uprog::pup
