// The S300 ASCII table (ascii_table.h).
#include "dialects/st/ascii_table.h"

#include <cctype>
#include <charconv>

namespace uprog::st {
namespace {

using K = AsciiKind;
using A = AsciiAccess;

constexpr AsciiEntry kTable[] = {
    // name, kind, access, default, disabled only, saved
    {"EN", K::Command, A::Write, 0, false, false},
    {"DIS", K::Command, A::Write, 0, false, false},
    {"ACTIVE", K::Int, A::Read, 0, false, false},
    {"OPMODE", K::Int, A::ReadWrite, 8, true, true},
    {"J", K::Command, A::Write, 0, false, false},
    {"T", K::Command, A::Write, 0, false, false},
    {"ORDER", K::Command, A::Write, 0, false, false},
    {"MOVE", K::Int, A::ReadWrite, 0, false, false},
    {"STOP", K::Command, A::Write, 0, false, false},
    {"MTMUX", K::Int, A::ReadWrite, 0, false, false},
    {"O_P", K::Int, A::ReadWrite, 0, false, false},
    {"O_V", K::Int, A::ReadWrite, 0, false, false},
    {"O_C", K::Int, A::ReadWrite, 0, false, false},
    {"O_ACC1", K::Int, A::ReadWrite, 0, false, false},
    {"O_DEC1", K::Int, A::ReadWrite, 0, false, false},
    {"O_FN", K::Int, A::ReadWrite, 0, false, false},
    {"O_FT", K::Int, A::ReadWrite, 0, false, false},
    {"PGEARI", K::Int, A::ReadWrite, 10000, true, true},
    {"PGEARO", K::Int, A::ReadWrite, 65536, true, true},
    {"PFB", K::Int, A::Read, 0, false, false},
    {"PE", K::Int, A::Read, 0, false, false},
    {"PV", K::Int, A::Read, 0, false, false},
    {"V", K::Float, A::Read, 0, false, false},
    {"I", K::Float, A::Read, 0, false, false},
    {"ACC", K::Int, A::ReadWrite, 10, false, true},
    {"DEC", K::Int, A::ReadWrite, 10, false, true},
    {"DECSTOP", K::Int, A::ReadWrite, 10, false, true},
    {"VLIM", K::Int, A::ReadWrite, 3000, false, true},
    {"PEINPOS", K::Int, A::ReadWrite, 4000, false, true},
    {"PEMAX", K::Int, A::ReadWrite, 262144, false, true},
    {"INPOS", K::Int, A::Read, 0, false, false},
    {"IN1", K::Int, A::Read, 0, false, false},
    {"IN2", K::Int, A::Read, 0, false, false},
    {"IN3", K::Int, A::Read, 0, false, false},
    {"IN4", K::Int, A::Read, 0, false, false},
    {"O1", K::Int, A::ReadWrite, 0, false, false},
    {"O2", K::Int, A::ReadWrite, 0, false, false},
    {"ERRCODE", K::Text, A::Read, 0, false, false},
    {"STATUS", K::Text, A::Read, 0, false, false},
    {"CLRFAULT", K::Command, A::Write, 0, false, false},
    {"SAVE", K::Command, A::Write, 0, false, false},
    {"LOAD", K::Command, A::Write, 0, false, false},
    {"RSTVAR", K::Command, A::Write, 0, false, false},
    {"COLDSTART", K::Command, A::Write, 0, false, false},
    {"MSG", K::Int, A::ReadWrite, 0, false, true},
    {"PROMPT", K::Int, A::ReadWrite, 1, false, true},
    {"TASK", K::Text, A::Read, 0, false, false},
    {"VER", K::Text, A::Read, 0, false, false},
    {"PLCSTOP", K::Command, A::Write, 0, false, false},
    {"PLC", K::Int, A::Read, 0, false, false},
    {"PLCRUN", K::Command, A::Write, 0, false, false},
    {"PLCSTART", K::Command, A::Write, 0, false, false},
    {"PLCDL", K::Command, A::Write, 0, false, false},
    {"PLIST", K::Text, A::Read, 0, false, false},
    {"PLCSTAT", K::Text, A::Read, 0, false, false},
    {"PLCHOLD", K::Command, A::Write, 0, false, false},
    {"PLCCONT", K::Command, A::Write, 0, false, false},
    {"PLCSTEP", K::Command, A::Write, 0, false, false},
    // Commands real hosts send (docs/dialects/st.md, "Host commands"; the SERVOSTAR-family
    // ASCII reference's defaults). Appended: a compiled program names entries by their index.
    {"VOSPD", K::Int, A::ReadWrite, 3600, false, true},
    {"ANCNFG", K::Int, A::ReadWrite, 0, true, true},
    {"MH", K::Command, A::Write, 0, false, false},
    {"NREF", K::Int, A::ReadWrite, 0, false, true},
    {"DREF", K::Int, A::ReadWrite, 0, false, true},
    {"VREF", K::Int, A::ReadWrite, 10000, false, true},
    {"ROFFS", K::Int, A::ReadWrite, 0, false, true},
    {"SETREF", K::Command, A::Write, 0, false, false},
    {"SRND", K::Int, A::ReadWrite, INT32_MIN, false, true},
    {"ERND", K::Int, A::ReadWrite, INT32_MAX, false, true},
    {"PRD", K::Int, A::Read, 0, false, false},
    {"VUNIT", K::Int, A::ReadWrite, 0, false, true},
    // The digital inputs' functions (reference, "IN1MODE"…: written disabled, taken at the next
    // boot): 2 PSTOP, 3 NSTOP, 12 the reference switch, for MH's switch types.
    {"IN1MODE", K::Int, A::ReadWrite, 0, true, true},
    {"IN2MODE", K::Int, A::ReadWrite, 0, true, true},
    {"IN3MODE", K::Int, A::ReadWrite, 0, true, true},
    {"IN4MODE", K::Int, A::ReadWrite, 0, true, true},
    // The analog inputs SW1 and SW2 (reference, "ANIN1", "ANOFF1", "ANZERO1", "VSCALE1"): the
    // level in mV, its offset, the offset's zeroing, OPMODE 1's rpm at 10 V.
    {"ANIN1", K::Int, A::Read, 0, false, false},
    {"ANIN2", K::Int, A::Read, 0, false, false},
    {"ANOFF1", K::Int, A::ReadWrite, 0, false, true},
    {"ANOFF2", K::Int, A::ReadWrite, 0, false, true},
    {"ANZERO1", K::Command, A::Write, 0, false, false},
    {"ANZERO2", K::Command, A::Write, 0, false, false},
    {"VSCALE1", K::Int, A::ReadWrite, 3000, false, true},
    {"VSCALE2", K::Int, A::ReadWrite, 3000, false, true},
    // Where the last homing saw its criterion, within one turn in 20 bits (reference, "REFPOS").
    {"REFPOS", K::Int, A::Read, 0, false, false},
};

bool same_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) !=
        std::toupper(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

// The user variables are entries too, after the table, so a compiled XREAD may name them.
constexpr size_t kFixed = sizeof kTable / sizeof kTable[0];
struct UserEntries {
  std::string names[kUserVariables];
  AsciiEntry entries[kUserVariables];
  UserEntries() {
    for (int n = 1; n <= kUserVariables; ++n) {
      names[n - 1] = user_variable_name(n);
      entries[n - 1] = {names[n - 1], K::Int, A::ReadWrite, 0, false, true};
    }
  }
};
const UserEntries& user_entries() {
  static const UserEntries e;
  return e;
}

}  // namespace

std::span<const AsciiEntry> ascii_table() { return kTable; }

std::optional<int> user_variable_number(std::string_view name) {
  std::string_view digits;
  int low = 0, high = 0;
  if (name.size() > 6 && same_ignoring_case(name.substr(0, 6), "DPRVAR"))
    digits = name.substr(6), low = 1, high = 16;
  else if (name.size() > 3 && same_ignoring_case(name.substr(0, 3), "DPV"))
    digits = name.substr(3), low = 17, high = 32;
  else
    return std::nullopt;
  int n = 0;
  const auto [p, e] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (e != std::errc() || p != digits.data() + digits.size() || digits[0] == '0' || n < low ||
      n > high)
    return std::nullopt;
  return n;
}

std::string user_variable_name(int n) { return (n <= 16 ? "DPRVAR" : "DPV") + std::to_string(n); }

bool reserves_name(const AsciiEntry& e) { return e.name != "I"; }

const AsciiEntry* find_ascii(std::string_view name) {
  for (const AsciiEntry& e : kTable)
    if (same_ignoring_case(e.name, name)) return &e;
  if (auto n = user_variable_number(name)) return &user_entries().entries[*n - 1];
  return nullptr;
}

uint32_t ascii_id(const AsciiEntry& entry) {
  if (&entry >= kTable && &entry < kTable + kFixed) return static_cast<uint32_t>(&entry - kTable);
  return static_cast<uint32_t>(kFixed + static_cast<size_t>(&entry - user_entries().entries));
}

const AsciiEntry* ascii_by_id(uint32_t id) {
  if (id < kFixed) return &kTable[id];
  if (id - kFixed < kUserVariables) return &user_entries().entries[id - kFixed];
  return nullptr;
}

bool readable(const AsciiEntry& e) { return e.access != AsciiAccess::Write; }
bool writable(const AsciiEntry& e) { return e.access != AsciiAccess::Read; }

}  // namespace uprog::st
