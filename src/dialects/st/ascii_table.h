// The S300's ASCII parameters and commands (shared/spec/s300-drive.md, "The ASCII interface"):
// name, kind, access and default. The compiler checks XREAD/XWRITE/COMMAND names and reserved
// names against it; the firmware's command line answers them.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace uprog::st {

enum class AsciiKind : uint8_t { Int, Float, Text, Command };
enum class AsciiAccess : uint8_t { Read, ReadWrite, Write };

struct AsciiEntry {
  std::string_view name;
  AsciiKind kind;
  AsciiAccess access;
  int32_t default_value;  // what #IF reads at compile time without a drive, and RSTVAR sets
  bool disabled_only;     // writes need the output stage off (error 5)
  bool saved;             // SAVE keeps it
};

std::span<const AsciiEntry> ascii_table();
// Case-insensitive; DPRVAR1…16 and DPV17…32 included. nullptr when there is none.
const AsciiEntry* find_ascii(std::string_view name);
// An entry's number (its index in the table): what CMDGET/CMDSET carry in a compiled program.
uint32_t ascii_id(const AsciiEntry& entry);
// False for `I` (the actual current), a name programs use for their loop counters: a program may
// declare it, and its global then hides the drive's `I` from the command line.
bool reserves_name(const AsciiEntry& entry);
const AsciiEntry* ascii_by_id(uint32_t id);
bool readable(const AsciiEntry& e);
bool writable(const AsciiEntry& e);

// The command number of COMMAND('…') (CMDRUN with the text's index as its argument).
constexpr uint32_t kCommandAction = 0xFFF0;

// "DPRVAR7" → 7, "DPV20" → 20; nullopt for any other name.
std::optional<int> user_variable_number(std::string_view name);
constexpr int kUserVariables = 32;
std::string user_variable_name(int n);  // 1..16 DPRVARn, 17..32 DPVn

}  // namespace uprog::st
