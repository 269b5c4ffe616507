// What a drive's command line hands back for a host line, and what its firmware notes on its own:
// the values every dialect, the controller, the transports and the tools pass around.
#pragma once
#include <cstdint>
#include <string>

namespace uprog::dialect {

// One answer: a value as the drive prints it, or an error with the interpreter's code.
struct Answer {
  std::string text;   // "7", "3.600000"; for an error what went wrong ("the motor is off")
  int32_t error = 0;  // 0 for a value; else the dialect's interpreter error code
  bool is_error() const { return error != 0; }
  friend bool operator==(const Answer&, const Answer&) = default;
};

// Something the firmware did on its own, for `uprog run`, `uprog sim --log` and debuggers.
struct LogEntry {
  uint64_t time_us;
  std::string text;  // "AUTO_I1 entered", "run-time error 1 (division by zero) at f.ehl:3"
};

}  // namespace uprog::dialect
