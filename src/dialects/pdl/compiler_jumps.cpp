// A command's condition as jumps (`if`, `while`, `till`): `a & b` jumps past on a false `a`
// without computing b, `|` on a true one, `~` is the other jump, as a compiled C condition does;
// the value form computes every relation's 0 or 1, their AND or OR, and one jump. Taken only
// when every token after the first relation is quiet (numbers, the program's own variables and
// states by name, the relations, + and -, & | ~ and parentheses): no part that may be skipped
// can raise an error or act, so that skipping it once the outcome is known cannot be told from
// computing it.
#include "dialects/pdl/compiler.h"
#include "dialects/pdl/system_names.h"

namespace uprog::pdl {
namespace {

bool is_op(const Token& t, std::string_view op) { return t.kind == Tok::Op && t.text == op; }

}  // namespace

bool Compiler::quiet_condition(size_t first, size_t end) const {
  static constexpr std::string_view kQuietOps[] = {"=", "<>", "<", "<=", ">", ">=", "&",
                                                   "|", "~",  "(", ")",  "+", "-"};
  for (size_t i = first; i < end; ++i) {
    const Token& t = toks_[i];
    if (t.kind == Tok::Int || t.kind == Tok::Float) continue;
    if (t.kind == Tok::Name) {  // a variable's own value (`*p` and `v[i]` are not quiet)
      if (find_var(t.text) == nullptr && find_state(t.text) == nullptr) return false;
      continue;
    }
    if (t.kind != Tok::Op) return false;
    bool quiet = false;
    for (std::string_view op : kQuietOps) quiet = quiet || t.text == op;
    if (!quiet) return false;
  }
  return true;
}

// The next `op` outside parentheses in [first, end), or end.
size_t Compiler::next_outside_parentheses(size_t first, size_t end, std::string_view op) const {
  int depth = 0;
  for (size_t i = first; i < end; ++i) {
    const Token& t = toks_[i];
    if (is_op(t, "(")) ++depth;
    if (is_op(t, ")")) --depth;
    if (depth == 0 && is_op(t, op)) return i;
  }
  return end;
}

void Compiler::jump_on_condition(bool when, CodeBuilder::Label target) {
  const size_t first = pos_, end = closing(first - 1) - 1;  // the `)` of the command's `(`
  // The first relation runs first and whole either way (`v[i] <> 0 & i < n`): only what may be
  // skipped after it must be quiet.
  size_t rest = first;
  while (rest < end && !is_op(toks_[rest], "&") && !is_op(toks_[rest], "|")) ++rest;
  if (first >= end || !is_op(toks_[end], ")") || !quiet_condition(rest, end)) {
    condition();
    code_.emit_to(when ? Op::JNZ : Op::JZ, target);
    return;
  }
  jump_on_either(first, end, when, target);
  pos_ = end;
}

// Terms joined by `|`, each factors joined by `&`: a truth decided by one part jumps there;
// the last part alone decides the jump to `target`.
void Compiler::jump_on_either(size_t first, size_t end, bool when, CodeBuilder::Label target) {
  jump_on_chain(first, end, "|", true, when, target);
}

void Compiler::jump_on_chain(size_t first, size_t end, std::string_view op, bool decides, bool when,
                             CodeBuilder::Label target) {
  const CodeBuilder::Label past = code_.new_label();
  bool past_used = false;      // bound only then: a label here would keep the line's end apart
  for (size_t at = first;;) {  // an empty part (`a &)`) is read, and refused, as the rest
    const size_t part_end = next_outside_parentheses(at, end, op);
    const bool last = part_end == end;
    // A part equal to `decides` settles the chain: to the target when that is the jump's
    // truth, else past the rest.
    const bool to_target = last || decides == when;
    const bool on = last ? when : decides;
    past_used = past_used || !to_target;
    if (op == "|")
      jump_on_chain(at, part_end, "&", false, on, to_target ? target : past);
    else
      jump_on_factor(at, part_end, on, to_target ? target : past);
    if (last) break;
    at = part_end + 1;
  }
  if (past_used) code_.bind(past);
}

void Compiler::jump_on_factor(size_t first, size_t end, bool when, CodeBuilder::Label target) {
  if (is_op(toks_[first], "~")) return jump_on_factor(first + 1, end, !when, target);
  if (is_op(toks_[first], "(") && closing(first) == end)
    return jump_on_either(first + 1, end - 1, when, target);
  pos_ = first;
  cond_atom();
  if (pos_ != end) expect_op(")");  // what the value form reports of a part it cannot read
  pos_ = end;
  code_.emit_to(when ? Op::JNZ : Op::JZ, target);
}

}  // namespace uprog::pdl
