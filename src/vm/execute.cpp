// The execute loop: computed-goto dispatch over the verified code.
//
// Invariants:
// - ip, sp and locals live in registers while instructions run; the thread's pc and sp are
//   written back (SAVE) before anything that may look at the thread: a host call (the host
//   may ask where the thread stands), a call or return, an error, the end of the slice.
// - The verifier has proven every operand index, jump target and stack depth of the code, and
//   enter() has checked that the new frame's stack fits, so no instruction checks them again.
//   Only values can be wrong at run time: array indices, divisors, host refusals.
// - A slice stops only between instructions: at a budget check (before an instruction), after
//   EOL, YIELD or WAIT, or at an end of the program, a breakpoint or an uncaught error.
#include <cmath>
#include <cstring>

// Computed goto (labels as values) is a GNU extension that g++ and clang both support.
#pragma GCC diagnostic ignored "-Wpedantic"

#include "bytecode/opcodes.h"
#include "support/arith.h"
#include "vm/budget_count.h"
#include "vm/fused.h"
#include "vm/intrinsic.h"
#include "vm/machine.h"

namespace uprog::vm {

using bytecode::Op;
namespace arith = uprog::arith;
// The line budget in units of a word's line-end mark (vm/budget_count.h).
using LineCount = CountIn<bytecode::kLineEndBit>;

namespace {

TypedValue read_pair(const Value* at) {
  return {at[0], at[1].i == 0 ? ValueType::Int : ValueType::Float};
}
void write_pair(Value* at, TypedValue v) {
  at[0] = v.value;
  at[1] = Value::of_int(v.is_float() ? 1 : 0);
}
// A call's words copied or set to 0: frames mostly have a few, which a call of memcpy or memset
// (what a plain loop compiles to) or a jump table would cost more than. 3 or 4 words are two
// 8-byte moves that may overlap; 2 cleared are one. 2 is the likely count, kept on the call's
// straight path: every CALLFEOL copies two stack registers (limit and base) and most clear two
// (ret and goto); laid out as GCC chose, each went out of the way and back, four taken jumps a
// call. Those two are copied a word at a time, not as one 8-byte load: a call's arguments were
// pushed a word at a time just before, and a load that spans two stores still in flight waits
// until both reach the cache (store-to-load forwarding fails): PDL's fib(29), 31 runs
// alternated, 0.0422 -> 0.0405 s least CPU time. Clearing may store 8 bytes at once: a
// narrower load inside one store is forwarded.
void copy_words(Value* to, const Value* from, uint32_t n) {
  if (n == 2) [[likely]] {  // PDL's limit and base; a call's two arguments or locals
    const Value first = from[0], second = from[1];
    to[0] = first;
    to[1] = second;
  } else if (n - 3 <= 1) {
    uint64_t head = 0, tail = 0;
    std::memcpy(&head, from, sizeof head);
    std::memcpy(&tail, from + n - 2, sizeof tail);
    std::memcpy(static_cast<void*>(to), &head, sizeof head);
    std::memcpy(static_cast<void*>(to + n - 2), &tail, sizeof tail);
  } else if (n == 1) {
    to[0] = from[0];
  } else if (n != 0) {
    std::memcpy(static_cast<void*>(to), from, n * sizeof(Value));
  }
}
void zero_words(Value* to, uint32_t n) {
  if (n == 2) [[likely]] {
    const uint64_t zero = 0;
    std::memcpy(static_cast<void*>(to), &zero, sizeof zero);
  } else if (n - 3 <= 1) {
    const uint64_t zero = 0;
    std::memcpy(static_cast<void*>(to), &zero, sizeof zero);
    std::memcpy(static_cast<void*>(to + n - 2), &zero, sizeof zero);
  } else if (n == 1) {
    to[0].bits = 0;
  } else if (n != 0) {
    std::memset(static_cast<void*>(to), 0, n * sizeof(Value));
  }
}
// A 64-bit value on the stack or in memory: two words, the low one first (deeper).
uint64_t read_wide(const Value* at) {
  return static_cast<uint64_t>(at[0].bits) | (static_cast<uint64_t>(at[1].bits) << 32);
}
void write_wide(Value* at, uint64_t v) {
  at[0].bits = static_cast<uint32_t>(v);
  at[1].bits = static_cast<uint32_t>(v >> 32);
}

}  // namespace

SliceResult Machine::run_other_slice(uint32_t thread, const Budget& budget) {
  if (!loaded_ || thread >= thread_count_) return {SliceEnd::NotRunning, 0};
  Thread& t = threads_[thread];
  switch (t.status) {
    case ThreadStatus::Idle:
      return {SliceEnd::NotRunning, 0};
    case ThreadStatus::Error:
      return {SliceEnd::Error, 0};
    case ThreadStatus::Halted:
      return {SliceEnd::Halted, 0};
    case ThreadStatus::AtBreakpoint:
      return {SliceEnd::Breakpoint, 0};
    case ThreadStatus::Waiting:
      if (sleeping(thread)) return {SliceEnd::Waiting, 0};
      set_status(t, ThreadStatus::Running);
      break;
    case ThreadStatus::Running:
      break;
  }
  if (t.step_over) return step_over_breakpoint(t, budget);
  return execute(t, budget);
}

// Resumed at a breakpoint: run the original instruction once, then re-arm the trap. Out of
// line, so that the usual slice's entry saves no registers for it.
[[gnu::noinline]] SliceResult Machine::step_over_breakpoint(Thread& t, const Budget& budget) {
  t.step_over = false;
  const Breakpoint* b = find_breakpoint(t.pc);
  if (b == nullptr) return execute(t, budget);
  const uint32_t at = t.pc;
  const uint32_t trap = code_[at];
  code_[at] = b->original;
  const SliceResult first = execute(t, Budget{1, budget.lines, budget.back_jumps});
  code_[at] = trap;
  if (first.end != SliceEnd::BudgetSpent || budget.instructions == 1) return first;
  Budget rest = budget;
  if (rest.instructions != 0) rest.instructions -= 1;
  if (rest.lines != 0) rest.lines -= first.lines;  // the first instruction may end a line
  SliceResult more = execute(t, rest);
  more.executed += first.executed;
  more.lines += first.lines;
  return more;
}

// One loop for both kinds of slice: a slice with an instruction budget dispatches through a
// table whose every entry counts first, so that a slice without one pays nothing per instruction
// for counting and the loop's code is there once (a copy for each kind did not leave the
// embeddable core room for more instructions).
SliceResult Machine::execute(Thread& start, const Budget& budget, Round* round) {
  static const void* const kDispatch[] = {
#define OP(name, a, b, pop, push, flow, meaning) &&op_##name,
#include "bytecode/opcodes.def"
#undef OP
#define FUSED(name, pattern, when, meaning, ...) &&fused_##name,
#define FUSED_PER_RELATION(name, pattern, when, meaning, ...)                     \
  &&fused_##name##_0, &&fused_##name##_1, &&fused_##name##_2, &&fused_##name##_3, \
      &&fused_##name##_4, &&fused_##name##_5,
#include "vm/fused.def"
#undef FUSED_PER_RELATION
#undef FUSED
  };
  static const void* const kCountThenDispatch[] = {
#define OP(name, a, b, pop, push, flow, meaning) &&count_then_dispatch,
#include "bytecode/opcodes.def"
#undef OP
#define FUSED(name, pattern, when, meaning, ...) &&count_then_dispatch,
#define FUSED_PER_RELATION(name, pattern, when, meaning, ...)                                 \
  &&count_then_dispatch, &&count_then_dispatch, &&count_then_dispatch, &&count_then_dispatch, \
      &&count_then_dispatch, &&count_then_dispatch,
#include "vm/fused.def"
#undef FUSED_PER_RELATION
#undef FUSED
  };
  static_assert(sizeof(kDispatch) / sizeof(kDispatch[0]) == kFirstFused + kFusedOpcodeCount);
  const bool counted = budget.instructions != 0;
  const void* const* const dispatch = counted ? kCountThenDispatch : kDispatch;

  const uint32_t* const code = code_;
  Thread* tp = &start;
  // A round of one-line turns (run_round) goes on from thread to thread at their line ends.
  // No round, or a line of it called the host (which may have changed who runs next): the
  // slice ends at its line end.
  bool round_ends = round == nullptr;
  const uint32_t* ip = code + tp->pc;
  Value* sp = tp->sp;
  Value* locals = tp->frames[tp->frame_count - 1].locals;
  BudgetCount steps = BudgetCount::of(budget.instructions);
  LineCount lines = LineCount::of(budget.lines);
  BudgetCount back_jumps = BudgetCount::of(budget.back_jumps);
  const LineCount lines_each = lines;  // a round's next slice
  const BudgetCount back_jumps_each = back_jumps;
  // A call may start a frame at or below this stack position (see enter()).
  const uint32_t call_room = config_.stack - max_depth_;  // in a thread's stack
  const Value* call_limit = tp->stack + call_room;
  uint32_t word = 0;
  RunError error = RunError::None;
  int32_t detail = 0;
  SliceEnd end = SliceEnd::BudgetSpent;

// Line ends passed so far; a budget of 0 (no limit) counts nothing.
#define LINES_ENDED() (budget.lines != 0 ? budget.lines - lines.left() : 0)
#define SAVE() (tp->pc = static_cast<uint32_t>(ip - code), tp->sp = sp)
#define LOAD() (ip = code + tp->pc, sp = tp->sp, locals = tp->frames[tp->frame_count - 1].locals)
// The next instruction, once the one in `word` has run: the line it ends is counted first.
// `word` is 0 before the first instruction and after an error, which end no line.
#define DISPATCH_COUNTING_MARK()               \
  do {                                         \
    lines.now -= word & bytecode::kLineEndBit; \
    if (lines.now == 0) goto out_of_lines;     \
    DISPATCH_NEXT();                           \
  } while (0)
#define DISPATCH() DISPATCH_COUNTING_MARK()
// After an instruction that leaves a value for the rest of its expression, which ends a line
// only where a statement is that expression alone: the line's count off the straight path.
// Every other instruction takes its line by subtracting its word's mark, with no branch on the
// mark: statements end lines, and in PDL, ST and CUP nearly every instruction is a statement.
// Gold's g_bits (mostly loads and operators) ran 7-14 % slower with the subtraction alone.
#define DISPATCH_VALUE()                               \
  do {                                                 \
    if (bytecode::word_ends_line(word)) [[unlikely]] { \
      if (lines.take_one()) goto out_of_lines;         \
    }                                                  \
    DISPATCH_NEXT();                                   \
  } while (0)
  // A call, a return, RESET and EOL carry no mark (the verifier refuses one): the next at once.
  static_assert(
      !bytecode::may_end_line(bytecode::Op::CALL) && !bytecode::may_end_line(bytecode::Op::RET) &&
      !bytecode::may_end_line(bytecode::Op::RETEOL) &&
      !bytecode::may_end_line(bytecode::Op::RESET) && !bytecode::may_end_line(bytecode::Op::EOL));
#define DISPATCH_NEXT()           \
  do {                            \
    word = *ip;                   \
    goto* dispatch[word & 0xFFu]; \
  } while (0)
// Every jump goes through here: one going back counts against the slice's back_jumps. When
// they run out it goes to `spent`, which continues as the jump's instruction would.
#define JUMP_OR(target, spent)               \
  do {                                       \
    const uint32_t* const to = (target);     \
    if (to <= ip && --back_jumps.now == 0) { \
      ip = to;                               \
      goto spent;                            \
    }                                        \
    ip = to;                                 \
  } while (0)
#define JUMP_TO(target) JUMP_OR(target, out_of_back_jumps)
// What counts as a jump back without being one: a call, a restart, a catch (each may enter code
// before it, or a call tree that never jumps back). The slice may end where control went.
#define COUNT_JUMP_BACK() \
  if (--back_jumps.now == 0) goto out_of_back_jumps
#define A() bytecode::word_a(word)
#define IMM() bytecode::word_imm(word)
#define B() (ip[1])
#define FAIL(e)       \
  do {                \
    error = (e);      \
    goto raise_error; \
  } while (0)
// `word`, the data memory's word at an address (an int, taken unsigned); outside the memory it
// is BadAddress.
#define MEMORY_WORD(word, address)                                 \
  const auto word##_address = static_cast<uint32_t>(address);      \
  if (word##_address >= memory_words_) FAIL(RunError::BadAddress); \
  Value& word = memory_[word##_address]
// `word`, the word of a frame in the data memory at a local's address plus an offset, wrapping
// as ADDLK does.
#define FRAME_WORD(word, local, offset) \
  MEMORY_WORD(word, static_cast<uint32_t>(locals[local].i) + (offset))
#define INT_BINARY(expr)        \
  {                             \
    const int32_t a = sp[-2].i; \
    const int32_t b = sp[-1].i; \
    sp[-2].i = (expr);          \
    --sp;                       \
    ++ip;                       \
    DISPATCH_VALUE();           \
  }
#define FLOAT_BINARY(expr)    \
  {                           \
    const float a = sp[-2].f; \
    const float b = sp[-1].f; \
    sp[-2].f = (expr);        \
    --sp;                     \
    ++ip;                     \
    DISPATCH_VALUE();         \
  }
#define COMPARE(type, field)                      \
  {                                               \
    const type a = sp[-2].field;                  \
    const type b = sp[-1].field;                  \
    sp[-2].i = relation_holds(A(), a, b) ? 1 : 0; \
    --sp;                                         \
    ++ip;                                         \
    DISPATCH_VALUE();                             \
  }
#define UNARY(expr)         \
  {                         \
    const Value a = sp[-1]; \
    sp[-1] = (expr);        \
    ++ip;                   \
    DISPATCH_VALUE();       \
  }
// A call to the host. Refused, it raises CommandRefused before the instruction has any
// effect. Done with kCommandEndSlice, the instruction completes and the slice ends as at YIELD.
#define HOST_CALL(call, effect)                                       \
  {                                                                   \
    round_ends = true;                                                \
    SAVE();                                                           \
    detail = (call);                                                  \
    if (detail != kCommandOk) {                                       \
      if (detail != kCommandEndSlice) FAIL(RunError::CommandRefused); \
      detail = 0;                                                     \
      effect;                                                         \
      lines.now -= word & bytecode::kLineEndBit;                      \
      end = SliceEnd::Yielded;                                        \
      goto stop;                                                      \
    }                                                                 \
    effect;                                                           \
    DISPATCH();                                                       \
  }

  DISPATCH();

op_NOP:
  ++ip;
  DISPATCH();
op_PUSHI:
  (sp++)->i = IMM();
  ++ip;
  DISPATCH_VALUE();
op_PUSHK:
  *sp++ = constants_[A()];
  ++ip;
  DISPATCH_VALUE();
op_POP:
  --sp;
  ++ip;
  DISPATCH();
op_DUP:
  sp[0] = sp[-1];
  ++sp;
  ++ip;
  DISPATCH_VALUE();
op_SWAP : {
  const Value top = sp[-1];
  sp[-1] = sp[-2];
  sp[-2] = top;
  ++ip;
  DISPATCH();
}

op_LDL:
  *sp++ = locals[A()];
  ++ip;
  DISPATCH_VALUE();
op_STL:
  locals[A()] = *--sp;
  ++ip;
  DISPATCH();
op_LDG:
  *sp++ = global_data_[A()][0];
  ++ip;
  DISPATCH_VALUE();
op_STG:
  global_data_[A()][0] = *--sp;
  ++ip;
  DISPATCH();
op_LDGE:
  *sp++ = global_data_[A()][B()];
  ip += 2;
  DISPATCH();
op_STGE:
  global_data_[A()][B()] = *--sp;
  ip += 2;
  DISPATCH();
// The fused copy of a run of lines, when no count or breakpoint can stop the slice inside it
// (the drive's one-line slices, stepping and the debugger take the lines one by one).
op_JLINES:
  if (!counted && breakpoint_count_ == 0 && lines.more_than(B())) {
    JUMP_TO(code + A());
    DISPATCH_NEXT();
  }
  ip += 2;
  DISPATCH_NEXT();
// The way out of such fused code, counting the lines its path ran.
op_JMPLN:
  if (!lines.spend(B())) {
    ip = code + A();
    end = SliceEnd::LineEnd;
    goto stop;
  }
  JUMP_TO(code + A());
  word = *ip;
  // Into the next copy, as a loop's back edge goes: JLINES's test and jump without a dispatch
  // of its own. Only a copy ends in these jumps, and its JLINES found no count and no breakpoint
  // set, which nothing in a copy changes.
  if (bytecode::word_op(word) == Op::JLINES && lines.more_than(B())) {
    JUMP_TO(code + A());
    word = *ip;
  }
  goto* dispatch[word & 0xFFu];
op_LDGX : {
  const auto index = static_cast<uint32_t>(sp[-1].i);
  if (index >= global_length_[A()]) FAIL(RunError::IndexOutOfRange);
  sp[-1] = global_data_[A()][index];
  ++ip;
  DISPATCH();
}
op_STGX : {
  const auto index = static_cast<uint32_t>(sp[-2].i);
  if (index >= global_length_[A()]) FAIL(RunError::IndexOutOfRange);
  global_data_[A()][index] = sp[-1];
  sp -= 2;
  ++ip;
  DISPATCH();
}
op_LDGW : {
  const uint32_t b = B();
  const uint32_t i = static_cast<uint32_t>(sp[-1].i) - 1u;  // 1..size: 0..size - 1
  if (i >= bytecode::window_size(b)) FAIL(RunError::IndexOutOfRange);
  sp[-1] = global_data_[A()][bytecode::window_first(b) + i];
  ip += 2;
  DISPATCH();
}
op_STGW : {
  const uint32_t b = B();
  const uint32_t i = static_cast<uint32_t>(sp[-1].i) - 1u;
  if (i >= bytecode::window_size(b)) FAIL(RunError::IndexOutOfRange);
  global_data_[A()][bytecode::window_first(b) + i] = sp[-2];
  sp -= 2;
  ip += 2;
  DISPATCH();
}
op_INCL:
  locals[A()].i = arith::wrap_add(locals[A()].i, static_cast<int32_t>(B()));
  ip += 2;
  DISPATCH();

op_ADDI:
  INT_BINARY(arith::wrap_add(a, b))
op_SUBI:
  INT_BINARY(arith::wrap_sub(a, b))
op_MULI:
  INT_BINARY(arith::wrap_mul(a, b))
op_DIVI:
  if (sp[-1].i == 0) FAIL(RunError::DivisionByZero);
  INT_BINARY(arith::int_div(a, b))
op_REMI:
  if (sp[-1].i == 0) FAIL(RunError::DivisionByZero);
  INT_BINARY(arith::int_rem(a, b))
op_NEGI:
  UNARY(Value::of_int(arith::saturating_neg(a.i)))
op_ANDI:
  INT_BINARY(a & b)
op_ORI:
  INT_BINARY(a | b)
op_XORI:
  INT_BINARY(a ^ b)
op_NOTI:
  UNARY(Value::of_int(~a.i))
op_SHLI:
  INT_BINARY(arith::shift_left(a, b))
op_SHRI:
  INT_BINARY(arith::shift_right(a, b))
op_ABSI:
  UNARY(Value::of_int(arith::saturating_abs(a.i)))
op_SIGNI:
  UNARY(Value::of_int(arith::sign_of(a.i)))

op_ADDF:
  FLOAT_BINARY(a + b)
op_SUBF:
  FLOAT_BINARY(a - b)
op_MULF:
  FLOAT_BINARY(a * b)
op_DIVF:
  if (sp[-1].f == 0.0f) FAIL(RunError::DivisionByZero);
  FLOAT_BINARY(a / b)
op_NEGF:
  UNARY(Value::of_float(-a.f))
op_ABSF:
  UNARY(Value::of_float(std::fabs(a.f)))
op_SIGNF:
  UNARY(Value::of_int(arith::sign_of(a.f)))
op_SINF:
  UNARY(Value::of_float(std::sin(a.f)))
op_COSF:
  UNARY(Value::of_float(std::cos(a.f)))
op_SQRTF:
  UNARY(Value::of_float(a.f > 0.0f ? std::sqrt(a.f) : 0.0f))

op_CMPI:
  COMPARE(int32_t, i)
op_CMPF:
  COMPARE(float, f)
op_LNOT:
  UNARY(Value::of_int(a.i == 0 ? 1 : 0))
op_TRUTHF:
  UNARY(Value::of_int(a.f != 0.0f ? 1 : 0))

op_I2F:
  UNARY(Value::of_float(static_cast<float>(a.i)))
op_I2F2:
  sp[-2] = Value::of_float(static_cast<float>(sp[-2].i));
  ++ip;
  DISPATCH();
op_F2IR:
  UNARY(Value::of_int(arith::round_to_int(a.f)))
op_F2IT:
  UNARY(Value::of_int(arith::trunc_to_int(a.f)))

op_MULID : {
  const arith::PromotedProduct p = arith::promoting_mul(sp[-2].i, sp[-1].i);
  write_pair(sp - 2, p.is_float ? TypedValue::of_float(p.f) : TypedValue::of_int(p.i));
  goto next_1;
}
op_I2D:
  (sp++)->i = 0;
  goto next_1;
op_F2D:
  (sp++)->i = 1;
  goto next_1;
op_D2F:
  --sp;
  if (sp[0].i == 0) sp[-1] = Value::of_float(static_cast<float>(sp[-1].i));
  goto next_1;
op_D2IR:
  --sp;
  if (sp[0].i != 0) sp[-1] = Value::of_int(arith::round_to_int(sp[-1].f));
  goto next_1;
op_D2IT:
  --sp;
  if (sp[0].i != 0) sp[-1] = Value::of_int(arith::trunc_to_int(sp[-1].f));
  goto next_1;
op_ADDD:
op_SUBD:
op_MULD:
op_DIVD : {
  const TypedValue a = read_pair(sp - 4);
  const TypedValue b = read_pair(sp - 2);
  const Op op = bytecode::word_op(word);
  TypedValue r;
  if (!a.is_float() && !b.is_float()) {
    const int32_t x = a.value.i, y = b.value.i;
    if (op == Op::ADDD) {
      r = TypedValue::of_int(arith::wrap_add(x, y));
    } else if (op == Op::SUBD) {
      r = TypedValue::of_int(arith::wrap_sub(x, y));
    } else if (op == Op::MULD) {
      const arith::PromotedProduct p = arith::promoting_mul(x, y);
      r = p.is_float ? TypedValue::of_float(p.f) : TypedValue::of_int(p.i);
    } else {
      if (y == 0) FAIL(RunError::DivisionByZero);
      r = TypedValue::of_int(arith::int_div(x, y));
    }
  } else {
    const float x = a.as_float(), y = b.as_float();
    if (op == Op::ADDD) {
      r = TypedValue::of_float(x + y);
    } else if (op == Op::SUBD) {
      r = TypedValue::of_float(x - y);
    } else if (op == Op::MULD) {
      r = TypedValue::of_float(x * y);
    } else {
      if (y == 0.0f) FAIL(RunError::DivisionByZero);
      r = TypedValue::of_float(x / y);
    }
  }
  sp -= 2;
  write_pair(sp - 2, r);
  goto next_1;
}
op_NEGD : {
  const TypedValue a = read_pair(sp - 2);
  write_pair(sp - 2, a.is_float() ? TypedValue::of_float(-a.value.f)
                                  : TypedValue::of_int(arith::saturating_neg(a.value.i)));
  goto next_1;
}
op_ABSD : {
  const TypedValue a = read_pair(sp - 2);
  write_pair(sp - 2, a.is_float() ? TypedValue::of_float(std::fabs(a.value.f))
                                  : TypedValue::of_int(arith::saturating_abs(a.value.i)));
  goto next_1;
}
op_CMPD : {
  const TypedValue a = read_pair(sp - 4);
  const TypedValue b = read_pair(sp - 2);
  const bool r = !a.is_float() && !b.is_float() ? relation_holds(A(), a.value.i, b.value.i)
                                                : relation_holds(A(), a.as_float(), b.as_float());
  sp -= 3;
  sp[-1] = Value::of_int(r ? 1 : 0);
  goto next_1;
}

op_JMP:
  JUMP_TO(code + A());
  DISPATCH();
op_JZ:
  if ((--sp)->i == 0)
    JUMP_TO(code + A());
  else
    ++ip;
  DISPATCH();
op_JNZ:
  if ((--sp)->i != 0)
    JUMP_TO(code + A());
  else
    ++ip;
  DISPATCH();
// A call counts as a jump back: a call tree of forward calls (each routine calling the next
// twice) runs exponentially long without jumping back, and never past a frame's depth without
// a call. The slice may end at the callee's entry, as a jump's ends at its target.
op_CALL : {
  // The common case inline; enter() handles the rest and reports which limit was hit.
  const RoutineInfo& r = routines_[A()];
  Value* base = sp - r.inputs;
  Value* callee = tp->locals_top;
  if (tp->frame_count < config_.frames &&
      r.locals <= static_cast<size_t>(tp->locals_end - callee) && base <= call_limit) {
    Frame& f = tp->frames[tp->frame_count++];
    f.return_pc = static_cast<uint32_t>(ip - code) + 2;
    f.routine = A();
    f.locals = callee;
    f.stack_base = base;
    f.nargout = static_cast<uint8_t>(B());
    f.kind = FrameKind::Call;
    for (uint32_t i = 0; i < r.inputs; ++i) callee[i] = base[i];
    // Most routines have a local or two beyond their inputs: a memset call would cost more.
    Value* rest = callee + r.inputs;
    switch (r.locals - r.inputs) {
      case 2:
        rest[1].bits = 0;
        [[fallthrough]];
      case 1:
        rest[0].bits = 0;
        [[fallthrough]];
      case 0:
        break;
      default:
        std::memset(static_cast<void*>(rest), 0, (r.locals - r.inputs) * sizeof(Value));
    }
    tp->locals_top = callee + r.locals;
    sp = base;
    locals = callee;
    ip = code + r.entry;
    COUNT_JUMP_BACK();
    DISPATCH_NEXT();
  }
  SAVE();
  if (!enter(*tp, A(), tp->pc + 2, static_cast<uint8_t>(B()), FrameKind::Call, error))
    goto raise_error;
  LOAD();
  COUNT_JUMP_BACK();
  DISPATCH_NEXT();
}
op_CALLFEOL : {
  // A frame in the data memory at the memory stack's pointer (local 0), below its limit (local
  // 1): the arguments into it, its other words after them to 0, the line's end, then the call.
  // Each step reads again what it needs (B, local 0, the routine's record) rather than keep it
  // across the step before: the loop's registers hold its own state, and what was kept went
  // through the stack. So the return pc counts from code_, not from the loop's copy `code`:
  // with it the compiler shared `ip - code` with the errors' SAVE, computed before the checks.
  const RoutineInfo* const r = routines_ + A();
  {
    const uint32_t shape = B();
    const auto at = static_cast<uint32_t>(locals[0].i);
    const uint64_t frame_end = uint64_t{at} + bytecode::memory_frame_words(shape);  // no wrap
    if (frame_end > memory_words_) [[unlikely]]
      FAIL(RunError::BadAddress);
    if (frame_end > static_cast<uint32_t>(locals[1].i)) [[unlikely]]
      FAIL(RunError::CallDepth);
    if (tp->frame_count >= config_.frames) [[unlikely]]
      FAIL(RunError::CallDepth);
    if (r->locals > static_cast<size_t>(tp->locals_end - tp->locals_top)) [[unlikely]]
      FAIL(RunError::LocalsExhausted);
    if (sp - bytecode::memory_frame_arguments(shape) > call_limit) [[unlikely]]
      FAIL(RunError::StackOverflow);
  }
  {
    const uint32_t shape = B();
    const uint32_t arguments = bytecode::memory_frame_arguments(shape);
    const uint32_t first = bytecode::memory_frame_first(shape);
    const auto at = static_cast<uint32_t>(locals[0].i);
    Value* const parameters = memory_ + at + first;
    sp -= arguments;
    copy_words(parameters, sp, arguments);
    zero_words(parameters + arguments, bytecode::memory_frame_words(shape) - first - arguments);
    tp->locals_top[0].i = static_cast<int32_t>(at + bytecode::memory_frame_words(shape));
  }
  {
    const uint32_t inputs = r->inputs;
    Value* const callee = tp->locals_top;
    callee[inputs - 1].i = locals[0].i;
    copy_words(callee + 1, locals + 1, inputs - 2);
    zero_words(callee + inputs, r->locals - inputs);
  }
  {
    const uint32_t depth = tp->frame_count;
    Frame& f = tp->frames[depth];
    Value* const callee = tp->locals_top;
    f.return_pc = static_cast<uint32_t>(ip + 2 - code_);
    f.routine = A();
    f.locals = callee;
    f.stack_base = sp;
    f.nargout = 0;
    f.kind = FrameKind::Call;
    tp->frame_count = depth + 1;
    tp->locals_top = callee + r->locals;
    locals = callee;
    ip = code + r->entry;
  }
  if (--back_jumps.now == 0) goto out_of_back_jumps_at_line_end;
  if (lines.take_one()) goto out_of_lines;
  DISPATCH_NEXT();
}
op_RET : {
  const uint32_t depth = tp->frame_count - 1;  // the frames that stay
  const Frame* const f = tp->frames + depth;
  tp->frame_count = depth;
  tp->locals_top = f->locals;
  while (tp->handler_count > 0 && tp->handlers[tp->handler_count - 1].frame_count > depth)
    tp->handler_count--;
  // A call's frame that wants no outputs (every procedure's): its two bytes side by side, one
  // test.
  static_assert(static_cast<uint32_t>(FrameKind::Call) == 0, "a call's frame is kind 0");
  if ((f->nargout | (static_cast<uint32_t>(f->kind) << 8)) == 0 && depth != 0) {
    sp = f->stack_base;
    ip = code + f->return_pc;
    locals = f[-1].locals;  // the caller's frame, just below
  } else if (f->kind == FrameKind::Event) {
    sp = f->stack_base;
    ip = code + f->return_pc;
    locals = f[-1].locals;
    set_status(*tp, f->saved_status);
    tp->wake_us = f->saved_wake_us;
    if (tp->status == ThreadStatus::Waiting) {
      end = SliceEnd::Waiting;
      goto stop;
    }
    if (tp->status == ThreadStatus::Halted) {
      end = SliceEnd::Halted;
      goto stop;
    }
  } else {
    Value* base = f->stack_base;
    const uint32_t nargout = f->nargout;
    if (nargout != 0) {  // a function's call (Gold's)
      const Value* outputs = f->locals + routines_[f->routine].inputs;
      if (nargout == 1) {
        base[0] = outputs[0];
      } else {
        for (uint32_t i = 0; i < nargout; ++i) base[i] = outputs[i];
      }
    }
    sp = base + nargout;
    if (depth == 0) goto finished;
    ip = code + f->return_pc;
    locals = f[-1].locals;
  }
  if (lines.now == 0) goto out_of_lines;
  DISPATCH_NEXT();
}
op_NARGOUT:
  (sp++)->i = tp->frames[tp->frame_count - 1].nargout;
  goto next_1;
op_EXIT:
  goto finished;
op_RESET:
  tp->frame_count = 0;
  tp->handler_count = 0;
  tp->sp = tp->stack;
  tp->locals_top = tp->locals;
  if (!enter(*tp, A(), 0, 0, FrameKind::Call, error)) {
    ip = code + tp->pc;
    sp = tp->sp;
    goto raise_error;
  }
  LOAD();
  COUNT_JUMP_BACK();  // a restart is a loop's iteration too
  DISPATCH_NEXT();
op_EOL:
  ++ip;
  if (lines.take_one()) goto out_of_lines;
  DISPATCH_NEXT();
op_RAISE:
  if (!run_error_from_code(A(), error) || error == RunError::None) error = RunError::Raised;
  goto raise_error;
op_YIELD:
  ++ip;
  end = SliceEnd::Yielded;
  goto stop;
op_WAIT : {
  int64_t duration_us = static_cast<int64_t>((--sp)->i) * static_cast<int64_t>(A());
  if (duration_us < 0) duration_us = 0;
  if (duration_us > INT32_MAX) duration_us = INT32_MAX;  // the clock's signed horizon
  tp->wake_us = host_->now_us() + static_cast<uint32_t>(duration_us);
  set_status(*tp, ThreadStatus::Waiting);
  ++ip;
  end = SliceEnd::Waiting;
  goto stop;
}
op_TRY:
op_TRYALL : {
  if (tp->handler_count >= config_.handlers) FAIL(RunError::TryDepth);
  tp->handlers[tp->handler_count++] = {A(), tp->frame_count, sp, tp->locals_top,
                                       bytecode::word_op(word) == Op::TRYALL};
  goto next_1;
}
op_ENDTRY:
  if (tp->handler_count == 0) FAIL(RunError::TryMismatch);
  tp->handler_count--;
  goto next_1;
op_ERRCODE:
  (sp++)->i = static_cast<int32_t>(tp->last_error);
  goto next_1;
op_CLOCK:
  (sp++)->i = static_cast<int32_t>(host_->now_us());
  goto next_1;

// The compare-and-jumps: a comparison and its branch in one. Float ones jump "unless": NaN
// compares false and falls through.
#define JUMP_COMPARE(type, field, cond) \
  {                                     \
    const type a = sp[-2].field;        \
    const type b = sp[-1].field;        \
    sp -= 2;                            \
    if (cond)                           \
      JUMP_TO(code + A());              \
    else                                \
      ++ip;                             \
    DISPATCH();                         \
  }
op_JEQI:
  JUMP_COMPARE(int32_t, i, a == b)
op_JNEI:
  JUMP_COMPARE(int32_t, i, a != b)
op_JLTI:
  JUMP_COMPARE(int32_t, i, a < b)
op_JLEI:
  JUMP_COMPARE(int32_t, i, a <= b)
op_JGTI:
  JUMP_COMPARE(int32_t, i, a > b)
op_JGEI:
  JUMP_COMPARE(int32_t, i, a >= b)
op_JNEQF:
  JUMP_COMPARE(float, f, !(a == b))
op_JNNEF:
  JUMP_COMPARE(float, f, !(a != b))
op_JNLTF:
  JUMP_COMPARE(float, f, !(a < b))
op_JNLEF:
  JUMP_COMPARE(float, f, !(a <= b))
op_JNGTF:
  JUMP_COMPARE(float, f, !(a > b))
op_JNGEF:
  JUMP_COMPARE(float, f, !(a >= b))
#undef JUMP_COMPARE
op_RETEOL:
  // The line ends here; the return is the line's last instruction, so a slice whose line
  // budget runs out at this end of line stops after the return, in the caller.
  lines.take_one();  // RET stops when that was the last
  goto op_RET;

// The fused instructions (vm/fused.def), formed at load: each reads its operands in the base
// words of its pattern, where they stay, and goes on past them. Their dispatch is the same as
// every other instruction's: the fused word carries the line-end mark of its pattern's last.
// The first word is `word` itself (its operand bits are the base instruction's): no load.
#define WORD_AT(k) ((k) == 0 ? word : ip[fused_offset(kShape, k)])
#define A_AT(k) bytecode::word_a(WORD_AT(k))
#define IMM_AT(k) bytecode::word_imm(WORD_AT(k))
#define B_AT(k) (ip[fused_offset(kShape, k) + 1])
// A folded family's relation: in a FUSED_PER_RELATION family the constant of the handler the
// quickener chose for the site, elsewhere read from the compare-and-jump's opcode.
#define RELATION_AT(k)                                                           \
  (kRelation != kNoRelation                                                      \
       ? kRelation                                                               \
       : static_cast<uint32_t>(bytecode::word_op(ip[fused_offset(kShape, k)])) - \
             static_cast<uint32_t>(kShape.ops[k]))
#define NEXT()                            \
  do {                                    \
    ip += kShape.length;                  \
    if constexpr (leaves_value(kShape)) { \
      DISPATCH_VALUE();                   \
    } else {                              \
      DISPATCH();                         \
    }                                     \
  } while (0)
#define BRANCH_IF(condition, k) \
  do {                          \
    if (condition)              \
      JUMP_TO(code + A_AT(k));  \
    else                        \
      ip += kShape.length;      \
    DISPATCH();                 \
  } while (0)
// The rest runs as written from the pattern's k-th instruction, by that instruction's handler.
#define GO_ON_AT(k, handler)       \
  do {                             \
    ip += fused_offset(kShape, k); \
    word = *ip;                    \
    goto handler;                  \
  } while (0)
#define FUSED(name, pattern, when, meaning, ...)                        \
  fused_##name : {                                                      \
    [[maybe_unused]] static constexpr FusedShape kShape =               \
        fused_detail::kShapes[static_cast<uint32_t>(Fused::name)];      \
    [[maybe_unused]] static constexpr uint32_t kRelation = kNoRelation; \
    __VA_ARGS__;                                                        \
  }
#define FUSED_MEMBER(name, relation, ...)                          \
  fused_##name##_##relation : {                                    \
    static constexpr FusedShape kShape =                           \
        fused_detail::kShapes[static_cast<uint32_t>(Fused::name)]; \
    static constexpr uint32_t kRelation = relation;                \
    __VA_ARGS__;                                                   \
  }
// Not clang-formatted: it formats this macro differently each time it runs.
// clang-format off
#define FUSED_PER_RELATION(name, pattern, when, meaning, ...)                                     \
  FUSED_MEMBER(name, 0, __VA_ARGS__) FUSED_MEMBER(name, 1, __VA_ARGS__)                           \
  FUSED_MEMBER(name, 2, __VA_ARGS__) FUSED_MEMBER(name, 3, __VA_ARGS__)                           \
  FUSED_MEMBER(name, 4, __VA_ARGS__) FUSED_MEMBER(name, 5, __VA_ARGS__)
// clang-format on
#include "vm/fused.def"
#undef FUSED_PER_RELATION
#undef FUSED_MEMBER
#undef FUSED
#undef BRANCH_IF
#undef GO_ON_AT
#undef NEXT
#undef A_AT
#undef WORD_AT
#undef IMM_AT
#undef B_AT
#undef RELATION_AT

op_CMDGET : {
  Value v;
  HOST_CALL(host_->read(A(), static_cast<int32_t>(B()), v), (*sp++ = v, ip += 2))
}
op_CMDGETX : {
  Value v;
  HOST_CALL(host_->read(A(), sp[-1].i, v), (sp[-1] = v, ++ip))
}
op_CMDSET:
  HOST_CALL(host_->write(A(), static_cast<int32_t>(B()), sp[-1]), (--sp, ip += 2))
op_CMDSETX:
  HOST_CALL(host_->write(A(), sp[-2].i, sp[-1]), (sp -= 2, ++ip))
op_CMDRUN:
op_CMDRUNX : {
  // CMDRUN is CMDRUNX at index 0, with no index on the stack.
  const uint32_t count = B();
  const bool indexed = bytecode::word_op(word) == Op::CMDRUNX;
  Value* const args = sp - count;
  HOST_CALL(host_->execute(A(), indexed ? args[-1].i : 0, args, count),
            (sp = args - (indexed ? 1 : 0), ip += 2))
}
op_MSG : {
  const uint32_t count = B();
  const auto thread = static_cast<uint32_t>(tp - threads_);
  HOST_CALL(host_->message(thread, A(), sp - count, count), (sp -= count, ip += 2))
}

op_LDM : {
  MEMORY_WORD(w, sp[-1].i);
  sp[-1] = w;
  ++ip;
  DISPATCH();
}
op_STM : {
  MEMORY_WORD(w, sp[-2].i);
  w = sp[-1];
  sp -= 2;
  ++ip;
  DISPATCH();
}

op_SEXT:
  UNARY(Value::of_int(arith::sign_extend(a.i, A())))
op_ZEXT:
  UNARY(Value::of_int(arith::zero_extend(a.i, A())))
op_SHRU:
  INT_BINARY(arith::shift_right_logical(a, b))
op_CMPU : {
  // Unsigned order is signed order with the sign bits flipped.
  const bool r = relation_holds(A(), sp[-2].i ^ INT32_MIN, sp[-1].i ^ INT32_MIN);
  --sp;
  sp[-1] = Value::of_int(r ? 1 : 0);
  ++ip;
  DISPATCH();
}
op_I2W:
  sp[0] = Value::of_int(sp[-1].i < 0 ? -1 : 0);
  ++sp;
  goto next_1;
op_ADDW:
  write_wide(sp - 4, read_wide(sp - 4) + read_wide(sp - 2));
  sp -= 2;
  goto next_1;
op_SUBW:
  write_wide(sp - 4, read_wide(sp - 4) - read_wide(sp - 2));
  sp -= 2;
  goto next_1;
op_MULDIV : {
  if (sp[-1].i == 0) FAIL(RunError::DivisionByZero);
  int32_t q;
  if (!arith::mul_div(sp[-3].i, sp[-2].i, sp[-1].i, q)) FAIL(RunError::Overflow);
  sp -= 2;
  sp[-1] = Value::of_int(q);
  goto next_1;
}
op_INTRIN : {
  // Every function pushes one int; it pops one or two (intrinsics.def).
  const auto function = static_cast<bytecode::Intrinsic>(A());
  const bool binary = bytecode::kIntrinsicInfo[A()].pop == 2;
  const IntrinsicResult r =
      binary ? apply_intrinsic(function, sp[-2].i, sp[-1].i) : apply_intrinsic(function, sp[-1].i);
  if (r.error != RunError::None) FAIL(r.error);
  if (binary) --sp;
  sp[-1] = Value::of_int(r.value);
  goto next_1;
}

op_BREAK:
  set_status(*tp, ThreadStatus::AtBreakpoint);
  end = SliceEnd::Breakpoint;
  goto stop;

// The shared end of the instructions that are seldom hot: one copy of the dispatch for them
// keeps the embeddable core within 32 KiB.
next_1:
  ++ip;
  DISPATCH();

// A slice that counts instructions counts base ones: a fused instruction runs as the first of
// its pattern, and the rest follow one by one (their words were never changed).
count_then_dispatch:
  if (steps.now-- == 0) goto out_of_budget;
  word = base_word(word);
  goto* kDispatch[word & 0xFFu];

// A spent 32-bit count takes the next chunk of its budget and the slice goes on as if nothing
// happened; only when the whole budget is spent does the slice end.
out_of_budget:  // `word` is the instruction not yet run: counted again, not its line
  if (steps.refill()) DISPATCH_NEXT();
  steps.now = 0;
  end = SliceEnd::BudgetSpent;
  goto stop;

out_of_back_jumps:
  if (back_jumps.refill()) DISPATCH();
  end = SliceEnd::BudgetSpent;
  goto stop;

out_of_back_jumps_at_line_end:  // a line-ending jump: the line is still to be counted
  if (!back_jumps.refill()) {
    end = SliceEnd::BudgetSpent;
    goto stop;
  }
  if (lines.take_one()) goto out_of_lines;
  DISPATCH_NEXT();

out_of_lines:
  if (lines.refill()) DISPATCH_NEXT();
  end = SliceEnd::LineEnd;
  if (!round_ends) {
    SAVE();
    if (Thread* const next = next_in_round(*round, bytecode::word_op(*ip), tp->frame_count)) {
      tp = next;
      LOAD();
      call_limit = tp->stack + call_room;
      lines = lines_each;
      back_jumps = back_jumps_each;
      DISPATCH_NEXT();
    }
  }
  goto stop;

finished:
  SAVE();
  reset_thread(*tp);
  tp->last_error = RunError::None;
  return {SliceEnd::Finished, counted ? budget.instructions - steps.left() : 0, LINES_ENDED()};

raise_error:
  SAVE();
  if (raise(*tp, error, detail)) {
    error = RunError::None;
    detail = 0;
    word = 0;  // the failed instruction ended no line
    LOAD();
    // A catch block may lie before its try: catching is a loop's iteration too.
    COUNT_JUMP_BACK();
    DISPATCH();
  }
  return {SliceEnd::Error, counted ? budget.instructions - steps.left() : 0, LINES_ENDED()};

stop:
  SAVE();
  return {end, counted ? budget.instructions - steps.left() : 0, LINES_ENDED()};

#undef LINES_ENDED
#undef JUMP_TO
#undef JUMP_OR
#undef COUNT_JUMP_BACK
#undef SAVE
#undef LOAD
#undef DISPATCH
#undef DISPATCH_NEXT
#undef DISPATCH_VALUE
#undef DISPATCH_COUNTING_MARK
#undef A
#undef IMM
#undef B
#undef FAIL
#undef FRAME_WORD
#undef MEMORY_WORD
#undef INT_BINARY
#undef FLOAT_BINARY
#undef COMPARE
#undef UNARY
#undef HOST_CALL
}

}  // namespace uprog::vm
