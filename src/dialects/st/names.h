// The words of the language: keywords (case-insensitive), built-ins, program names, the words
// that are not implemented, and the rules a user's name must follow.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "dialects/st/ast.h"
#include "dialects/st/errors.h"

namespace uprog::st {

std::string upper(std::string_view s);
bool is_keyword(std::string_view upper_word);
bool is_unsupported_word(std::string_view upper_word);  // ELSIF, CASE, EXIT, ARRAY, REAL, …
std::optional<Builtin> builtin_of(std::string_view upper_word);
std::optional<ProgramKind> program_of(std::string_view upper_word);
std::string_view program_name(ProgramKind kind);
// The period of a real-time program in ns (0 for PLCINIT, PLCMAIN) and its load factor.
uint32_t period_ns(ProgramKind kind);
uint32_t load_factor(ProgramKind kind);

// What is wrong with `name` as a user's name, checked in the spec's order (7, 8, 2, 9); none
// when it may be used.
std::optional<Error> name_problem(std::string_view name);

}  // namespace uprog::st
