// Where things live in a PDL program's data memory and its machine, shared by the compiler and
// the firmware: the data memory's words are the program's addresses, 400 words of user memory
// from 0 and each task's 256-word stack from 0x1000 * t, the words between unused; the locals
// every entry routine has (the task's stack registers, then scratch words).
#pragma once
#include <array>
#include <cstdint>

#include "support/value.h"

namespace uprog::pdl {

constexpr int32_t kUserWords = 400;
constexpr int32_t kStackWords = 256;
constexpr uint32_t kTasks = 3;
constexpr int32_t kFloatAddressBit = 1 << 29;  // &f of a float (manual 2.5.2)
constexpr int32_t kTaskAddressUnit = 0x1000;   // &local of task t: 0x1000*t + word

// The first word of task t's stack (t = 1..3): its address as a program sees it, and its word of
// the data memory, so that a pointer needs no translation, only a check.
constexpr int32_t stack_base(uint32_t task) {
  return static_cast<int32_t>(task) * kTaskAddressUnit;
}
constexpr int32_t kMemoryWords = stack_base(kTasks) + kStackWords;

// Locals of every entry routine; the first kEntryInputs are set by the firmware at start, or
// by a procedure call for the procedure's routine (which has the first kFirstScratch and the
// scratch words it uses).
// sp and limit are locals 0 and 1, fp the last input, as the VM's CALLFEOL takes them.
enum EntryLocal : uint32_t {
  kSp = 0,     // address of the next free stack word
  kLimit = 1,  // one past the stack's last word
  kBase = 2,   // address of its first word
  kFp = 3,     // address of the current procedure's frame (its first reserved word)
  kEntryInputs = 4,
  kRetId = 4,  // the return site a ret or a procedure's end goes back to
  kGotoN = 5,  // the slot offset of an indirect goto
  kFirstScratch = 6,
  kEntryLocals = 16,
};

// The stack registers a task's code starts with (the entry inputs): fp at the stack's base when
// no procedure's frame is given.
inline std::array<Value, kEntryInputs> stack_registers(uint32_t task, Value sp, int32_t fp) {
  const int32_t base = stack_base(task);
  return {sp, Value::of_int(base + kStackWords), Value::of_int(base), Value::of_int(fp)};
}

// A procedure's frame: a return id's and a saved fp's words (reserved, pdl-drive.md), then its
// parameters and locals.
constexpr uint32_t kMinFrameWords = 2;

constexpr uint32_t kMaxTasksNumber = 3;
constexpr uint32_t kPdlCodeBytes = 32 * 1024;

}  // namespace uprog::pdl
