// The words of the language (names.h).
#include "dialects/st/names.h"

#include <cctype>

#include "dialects/st/ascii_table.h"

namespace uprog::st {
namespace {

constexpr std::string_view kKeywords[] = {
    "IF",      "THEN",        "ELSE",     "END_IF",       "WHILE", "DO",      "END_WHILE", "REPEAT",
    "UNTIL",   "END_REPEAT",  "FOR",      "TO",           "BY",    "END_FOR", "GOTO",      "RETURN",
    "PROGRAM", "END_PROGRAM", "FUNCTION", "END_FUNCTION", "BYTE",  "WORD",    "LONG",      "DLONG",
    "MOD",     "AND",         "OR",       "XOR",          "NOT",   "BNOT",    "TRUE",      "FALSE",
};
constexpr std::string_view kUnsupported[] = {
    "ELSIF", "CASE",  "OF",  "END_CASE", "EXIT", "ARRAY",
    "REAL",  "LREAL", "INT", "DINT",     "BOOL", "CONTINUE",
};
struct BuiltinName {
  std::string_view name;
  Builtin builtin;
};
constexpr BuiltinName kBuiltins[] = {
    {"CLRDLONG", Builtin::Clrdlong}, {"SETDLONG", Builtin::Setdlong},
    {"ADDDLONG", Builtin::Adddlong}, {"SUBDLONG", Builtin::Subdlong},
    {"MULDIV", Builtin::Muldiv},     {"LIMITW", Builtin::Limitw},
    {"XREAD", Builtin::Xread},       {"XWRITE", Builtin::Xwrite},
    {"COMMAND", Builtin::Command},   {"PRINTF", Builtin::Printf},
};
struct ProgramInfo {
  std::string_view name;
  ProgramKind kind;
  uint32_t period_ns;
  uint32_t factor;
};
constexpr ProgramInfo kPrograms[] = {
    {"PLCINIT", ProgramKind::Init, 0, 0},         {"PLC62", ProgramKind::Plc62, 62'500, 256},
    {"PLC250", ProgramKind::Plc250, 250'000, 64}, {"PLC1", ProgramKind::Plc1, 1'000'000, 16},
    {"PLC4", ProgramKind::Plc4, 4'000'000, 4},    {"PLC16", ProgramKind::Plc16, 16'000'000, 1},
    {"PLCMAIN", ProgramKind::Main, 0, 0},
};

const ProgramInfo* info_of(ProgramKind kind) {
  for (const ProgramInfo& p : kPrograms)
    if (p.kind == kind) return &p;
  return nullptr;
}

}  // namespace

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool is_keyword(std::string_view w) {
  for (std::string_view k : kKeywords)
    if (k == w) return true;
  return false;
}

bool is_unsupported_word(std::string_view w) {
  for (std::string_view k : kUnsupported)
    if (k == w) return true;
  return false;
}

std::optional<Builtin> builtin_of(std::string_view w) {
  for (const BuiltinName& b : kBuiltins)
    if (b.name == w) return b.builtin;
  return std::nullopt;
}

std::optional<ProgramKind> program_of(std::string_view w) {
  for (const ProgramInfo& p : kPrograms)
    if (p.name == w) return p.kind;
  return std::nullopt;
}

std::string_view program_name(ProgramKind kind) {
  const ProgramInfo* p = info_of(kind);
  return p ? p->name : "FUNCTION";
}
uint32_t period_ns(ProgramKind kind) {
  const ProgramInfo* p = info_of(kind);
  return p ? p->period_ns : 0;
}
uint32_t load_factor(ProgramKind kind) {
  const ProgramInfo* p = info_of(kind);
  return p ? p->factor : 0;
}

std::optional<Error> name_problem(std::string_view name) {
  if (name.size() > 10) return Error::NameTooLong;
  for (char c : name)
    if (std::islower(static_cast<unsigned char>(c))) return Error::NotCapitals;
  for (char c : name)
    if (c == '_') return Error::BadCharacter;
  const std::string u = upper(name);
  if (is_keyword(u) || is_unsupported_word(u) || builtin_of(u) || program_of(u))
    return Error::ReservedName;
  if (const AsciiEntry* e = find_ascii(u);
      e != nullptr && !user_variable_number(u) && reserves_name(*e))
    return Error::ReservedName;
  return std::nullopt;
}

}  // namespace uprog::st
