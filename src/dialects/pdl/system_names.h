// The names the drive defines (system_names.def, states.def) and the command numbers the
// compiler's CMDGET/CMDSET/CMDRUN use to reach them: shared by the compiler and the firmware.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

namespace uprog::pdl {

struct SystemVariable {
  std::string_view name;
  uint32_t id;
  char access;  // 'r', 'w' or 'b'
  bool slave;
  uint32_t length;
  bool readable() const { return access != 'w'; }
  bool writable() const { return access != 'r'; }
};

struct StateName {
  std::string_view name;
  int32_t number;
  bool writable;
};

// Commands beyond the variables: a state by number (index), and the task actions.
constexpr uint32_t kStateCommand = 100;
constexpr uint32_t kLockCommand = 101;
constexpr uint32_t kUnlockCommand = 102;
constexpr uint32_t kRunCommand = 103;       // index: the task; argument: the routine
constexpr uint32_t kKillCommand = 104;      // index: the task
constexpr uint32_t kEndPhaseCommand = 105;  // spends the rest of the turn (a yield the host counts)
constexpr int32_t kStateCount = 32 * 4;     // status[0..3]

constexpr uint32_t kMaxAxes = 4;

// Case-insensitive look-ups; `X_name` finds a slave variable with `axis_zero` set.
const SystemVariable* find_system_variable(std::string_view name, bool* axis_zero = nullptr);
const SystemVariable* system_variable_by_id(uint32_t id);
const StateName* find_state(std::string_view name);
bool equal_ignoring_case(std::string_view a, std::string_view b);

}  // namespace uprog::pdl
