// The forms the drive's own compiler accepts, checked on a command's tokens before it is
// compiled: one operator per assignment (2.1), a built-in function's call as the whole right
// side with variables for arguments, the last of which may be a constant (2.1 form 7, 2.3), and
// a procedure's arguments constants or variables (1.4). Each refusal says how to split it.
#include "dialects/pdl/compiler.h"

namespace uprog::pdl {
namespace {

bool is_binary_operator(std::string_view op) {
  return op == "+" || op == "-" || op == "*" || op == "/" || op == "&" || op == "|" || op == "@" ||
         op == "%";
}

bool is_number(const Token& t) {
  return t.kind == Tok::Int || t.kind == Tok::Float || t.kind == Tok::Char;
}

}  // namespace

bool is_builtin_function(std::string_view name) {
  for (std::string_view b :
       {"max", "min", "abs", "sign", "sin", "cos", "sqrt", "divi", "shift", "bitset", "bitclr",
        "bittog", "sizeof", "memmin", "memmax", "memsum"}) {
    if (equal_ignoring_case(b, name)) return true;
  }
  return false;
}

size_t Compiler::command_end(size_t first) const {
  int depth = 0;
  for (size_t i = first; i < toks_.size(); ++i) {
    const Token& t = toks_[i];
    if (t.kind == Tok::End || (i > first && t.line_start)) return i;
    if (t.kind != Tok::Op) continue;
    if (t.text == "(" || t.text == "[") ++depth;
    if (t.text == ")" || t.text == "]") --depth;
    if (depth <= 0 && t.text == ";") return i;
  }
  return toks_.size() - 1;
}

size_t Compiler::closing(size_t open) const {
  int depth = 0;
  for (size_t i = open; i < toks_.size(); ++i) {
    const Token& t = toks_[i];
    if (t.kind == Tok::End || (i > open && t.line_start)) return i;
    if (t.kind != Tok::Op) continue;
    if (t.text == "(" || t.text == "[") ++depth;
    if ((t.text == ")" || t.text == "]") && --depth == 0) return i + 1;
  }
  return toks_.size() - 1;
}

bool Compiler::is_builtin_call(size_t at) const {
  const Token& t = toks_[at];
  return t.kind == Tok::Name && is_builtin_function(t.text) && at + 1 < toks_.size() &&
         toks_[at + 1].kind == Tok::Op && toks_[at + 1].text == "(" && !find_var(t.text);
}

bool Compiler::is_variable(size_t first, size_t end) const {
  size_t i = first;
  if (i < end && toks_[i].kind == Tok::Op && toks_[i].text == "*") ++i;
  if (i >= end || toks_[i].kind != Tok::Name || is_builtin_call(i)) return false;
  if (equal_ignoring_case(toks_[i].text, "sttovar")) return false;
  ++i;
  if (i < end && toks_[i].kind == Tok::Op && toks_[i].text == "[") i = closing(i);
  return i == end;
}

bool Compiler::is_constant(size_t first, size_t end) const {
  if (is_literal(first, end)) return true;
  // sizeof(v) is the array's size, known when compiling (2.1.4).
  return end == first + 4 && toks_[first].kind == Tok::Name &&
         equal_ignoring_case(toks_[first].text, "sizeof");
}

// 2.1.3: `v = sttovar …`, or a right side of states and bit tests (`var1 = s1 & var2->3`).
bool Compiler::is_state_logic(size_t first, size_t end) const {
  if (first < end && equal_ignoring_case(toks_[first].text, "sttovar")) return true;
  for (size_t i = first; i < end; ++i) {
    const Token& t = toks_[i];
    if (t.kind == Tok::Op && t.text == "->") return true;
    if (t.kind == Tok::Name && find_state(t.text) && !find_var(t.text)) return true;
  }
  return false;
}

std::string Compiler::tokens_text(size_t first, size_t end) const {
  std::string text;
  for (size_t i = first; i < end && i < toks_.size(); ++i) {
    const bool word = toks_[i].kind != Tok::Op;
    if (i > first && word && toks_[i - 1].kind != Tok::Op) text += ' ';
    text += toks_[i].kind == Tok::String ? "\"" + toks_[i].text + "\"" : toks_[i].text;
  }
  return text;
}

// The right side of `=` (tokens first..end) has at most one operator; of `op=`, none (2.1 forms
// 4, 6, 9). An index, a `<state>`, a call's arguments and a negative constant are no operators.
void Compiler::check_assignment_form(size_t first, size_t end, bool operation_assignment) {
  if (!strict_forms_ || is_state_logic(first, end)) return;
  int operators = 0;
  bool operand_expected = true;
  for (size_t i = first; i < end; ++i) {
    const Token& t = toks_[i];
    if (is_builtin_call(i) || (t.kind == Tok::Op && t.text == "[")) {
      i = (t.kind == Tok::Op ? closing(i) : closing(i + 1)) - 1;
      operand_expected = false;
      continue;
    }
    if (t.kind != Tok::Op) {
      operand_expected = false;
      continue;
    }
    if (t.text == "(" || t.text == ")") {
      operand_expected = t.text == "(";
      continue;
    }
    if (operand_expected && t.text == "<") {
      while (i + 1 < end && !(toks_[i].kind == Tok::Op && toks_[i].text == ">")) ++i;
      operand_expected = false;
      continue;
    }
    if (operand_expected && t.text == "-" && i + 1 < end && is_number(toks_[i + 1]))
      continue;  // -5
    const bool unary = operand_expected && (t.text == "-" || t.text == "~");
    if (!unary && !(is_binary_operator(t.text) && !operand_expected)) continue;  // &v, *p
    operand_expected = true;
    if (++operators <= (operation_assignment ? 0 : 1)) continue;
    if (operation_assignment) {
      error(Error::OneOperator, t.offset,
            "the right side of an operation assignment is a variable or a constant: assign '" +
                tokens_text(first, end) + "' to a variable of its own first");
    } else {
      error(Error::OneOperator, t.offset,
            "'" + t.text +
                "' is a second one: split the command into assignments of one operator "
                "each, computing a part into a variable of its own first (t = c * d; a = b + t;)");
    }
    return;
  }
}

// A built-in function's call is the whole right side of an assignment (2.1 form 7).
bool Compiler::check_call_alone(size_t at) {
  if (!strict_forms_ || (at == call_first_ && closing(at + 1) == call_end_)) return true;
  const std::string call = toks_[at].text + "(…)";
  error(Error::CallNotAlone, toks_[at].offset,
        "assign " + call + " to a variable in a command of its own, then use that variable here");
  return false;
}

// 2.3: "arg_1, …, arg_n must be local variables, and the last argument can be a constant".
void Compiler::check_function_argument(size_t first, size_t end, bool last) {
  if (!strict_forms_ || is_variable(first, end) || (last && is_constant(first, end))) return;
  const std::string what = tokens_text(first, end);
  if (is_constant(first, end)) {
    error(Error::FunctionArgument, toks_[first].offset,
          "only the last may be a constant: assign " + what +
              " to a variable first and pass the variable");
  } else {
    error(Error::FunctionArgument, toks_[first].offset,
          "assign '" + what + "' to a variable first and pass the variable");
  }
}

// 1.4: "Each argument can be a constant or a variable"; `&v` passes an output parameter.
void Compiler::check_proc_argument(size_t first, size_t end) {
  if (!strict_forms_ || is_variable(first, end) || is_constant(first, end)) return;
  if (first < end && toks_[first].kind == Tok::Op && toks_[first].text == "&" &&
      is_variable(first + 1, end))
    return;
  error(Error::ProcArgument, toks_[first].offset,
        "assign '" + tokens_text(first, end) + "' to a variable first and pass the variable");
}

}  // namespace uprog::pdl
