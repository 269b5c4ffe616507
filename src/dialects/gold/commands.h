// The Gold drive's command table (shared/spec/gold-drive.md): one entry per command, used by the
// compiler (types, "not program", "not assign") and by the command line (ranges, motor-off rules).
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

#include "support/value.h"

namespace uprog::gold {

enum CommandFlag : uint32_t {
  kReadOnly = 1u << 0,       // a read-only status (VX, MS, SO, ...): assignment refused
  kNotAssignable = 1u << 1,  // an action (BG, ST, SV, ...): "not assign" flag, compile error 82
  kNotProgram = 1u << 2,     // host only (LS, ...): "not program" flag, compile error 79
  kMotorOffOnly = 1u << 3,   // assignable only while MO=0 (UM, ...)
  kAction = 1u << 4,         // executed, not read or written (BG, ST, SV, LD, RS, ...)
  kIndexed = 1u << 5,        // takes an index: UI[3], IL[2]
  kText = 1u << 6,           // answers text, not a number (VR): DriveCommands::text()
  kIndexOptional = 1u << 7,  // kIndexed, and without an index it is its first (SF is SF[1])
};

struct CommandInfo {
  std::string_view name;  // upper case as the manual writes it: "PX", "UI"
  uint16_t id;            // stable number stored in images; never reused
  ValueType type;
  uint32_t flags;
  int32_t min_index;  // for kIndexed commands, the valid index range
  int32_t max_index;
  double min_value;  // the range a write accepts
  double max_value;
  std::string_view meaning;  // one line, for `--help` and listings
};

// Case-insensitive lookup; nullptr when no command has that name.
const CommandInfo* find_command(std::string_view name);
std::span<const CommandInfo> all_commands();
// The table's rows, row i holding id i + 1 (commands.cpp checks it).
extern const std::span<const CommandInfo> kCommandRows;
// Inline: every drive command a program reads or writes comes through here (MS in
// `until (MS == 0)` once per background pass), a direct index.
inline const CommandInfo* find_command(uint16_t id) {
  return id >= 1 && id <= kCommandRows.size() ? &kCommandRows[id - 1u] : nullptr;
}

}  // namespace uprog::gold
