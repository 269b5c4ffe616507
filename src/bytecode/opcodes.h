// The opcode enum, names, operand kinds, stack effects and control flow, all generated from
// opcodes.def. An instruction is one 32-bit word (opcode in bits 0..7, the line-end mark in bit
// 8, operand A in bits 9..31) followed by one more word when the opcode has a B operand.
#pragma once
#include <cstdint>

namespace uprog::bytecode {

enum class Operand : uint8_t {
  None,
  Imm,
  Const,
  Local,
  Global,
  Routine,
  Target,
  Count,
  Command,
  Unit,
  LocalPair,
  LocalImm,
  LocalConst,
  Width,
  Text,
  GlobalPair,
  GlobalConst,
  GlobalImm,
  Element,
  Lines,
  Window,
  GlobalsTest,
  LoopStep,
  GlobalWindow,
  MemoryFrame,
  FrameTest,
  OffsetImm,
  Comparison,
  PointerTest
};

// The packed B operands of the fused comparisons and arithmetic (LocalConst, GlobalPair,
// GlobalConst pack like LocalPair: 16 bits each; GlobalImm like LocalImm).
constexpr uint32_t pack_locals(uint32_t first, uint32_t second) { return first | (second << 16); }
constexpr uint32_t pack_local_imm(uint32_t local, int32_t imm) {
  return local | (static_cast<uint32_t>(imm) << 16);
}
constexpr uint32_t packed_first(uint32_t b) { return b & 0xFFFFu; }
constexpr uint32_t packed_second(uint32_t b) { return b >> 16; }
constexpr int32_t packed_imm(uint32_t b) { return static_cast<int32_t>(b) >> 16; }
// LDGW's and STGW's B: the window's first element and its size, 16 bits each.
constexpr uint32_t pack_window(uint32_t first, uint32_t size) { return first | (size << 16); }
constexpr uint32_t window_first(uint32_t b) { return b & 0xFFFFu; }
constexpr uint32_t window_size(uint32_t b) { return b >> 16; }
// UNTILCK's B: the command's index (0..255) in bits 0-7, the comparison (0..5: == != < <= > >=)
// in bits 8-11, the immediate (-2^19..2^19-1) in bits 12-31.
constexpr uint32_t pack_command_test(uint32_t index, uint32_t how, int32_t imm) {
  return index | (how << 8) | (static_cast<uint32_t>(imm) << 12);
}
constexpr uint32_t command_test_index(uint32_t b) { return b & 0xFFu; }
constexpr uint32_t command_test_how(uint32_t b) { return (b >> 8) & 0xFu; }
constexpr int32_t command_test_imm(uint32_t b) { return static_cast<int32_t>(b) >> 12; }
// JCMPGG's B: two globals below 2^13 in bits 0-12 and 13-25, the comparison (0..5: == != < <=
// > >=) in bits 26-28.
constexpr uint32_t kGlobalsTestMax = (1u << 13) - 1;
constexpr uint32_t pack_globals_test(uint32_t first, uint32_t second, uint32_t how) {
  return first | (second << 13) | (how << 26);
}
constexpr uint32_t globals_test_first(uint32_t b) { return b & kGlobalsTestMax; }
constexpr uint32_t globals_test_second(uint32_t b) { return (b >> 13) & kGlobalsTestMax; }
constexpr uint32_t globals_test_how(uint32_t b) { return b >> 26; }
// INCGJMPLN's B: the global in bits 0-15, the step (-128..127) in bits 16-23, the line ends it
// counts (0..255) in bits 24-31.
constexpr uint32_t pack_loop_step(uint32_t global, int32_t step, uint32_t lines) {
  return global | ((static_cast<uint32_t>(step) & 0xFFu) << 16) | (lines << 24);
}
constexpr uint32_t loop_step_global(uint32_t b) { return b & 0xFFFFu; }
constexpr int32_t loop_step_step(uint32_t b) { return static_cast<int8_t>((b >> 16) & 0xFFu); }
constexpr uint32_t loop_step_lines(uint32_t b) { return b >> 24; }
// LDGWG's and STGWG's B: the window's first element in bits 0-11, its size in bits 12-23, the
// global holding the index (below 256) in bits 24-31.
constexpr uint32_t kGlobalWindowMax = (1u << 12) - 1;
constexpr uint32_t pack_global_window(uint32_t first, uint32_t size, uint32_t index_global) {
  return first | (size << 12) | (index_global << 24);
}
constexpr uint32_t global_window_first(uint32_t b) { return b & kGlobalWindowMax; }
constexpr uint32_t global_window_size(uint32_t b) { return (b >> 12) & kGlobalWindowMax; }
constexpr uint32_t global_window_index(uint32_t b) { return b >> 24; }
enum class Flow : uint8_t { Next, Jump, Branch, Call, Stop };

constexpr int kVar = -1;  // a stack effect that the operands decide

enum class Op : uint8_t {
#define OP(name, a, b, pop, push, flow, meaning) name,
#include "bytecode/opcodes.def"
#undef OP
};

struct OpInfo {
  Operand a;
  Operand b;
  int8_t pop;
  int8_t push;
  Flow flow;
};

// What the verifier and the VM need; names and meanings are apart so firmware need not carry them.
inline constexpr OpInfo kOpInfo[] = {
#define OP(name, a, b, pop, push, flow, meaning) {Operand::a, Operand::b, pop, push, Flow::flow},
#include "bytecode/opcodes.def"
#undef OP
};
inline constexpr const char* kOpNames[] = {
#define OP(name, a, b, pop, push, flow, meaning) #name,
#include "bytecode/opcodes.def"
#undef OP
};
inline constexpr const char* kOpMeanings[] = {
#define OP(name, a, b, pop, push, flow, meaning) meaning,
#include "bytecode/opcodes.def"
#undef OP
};

inline constexpr uint32_t kOpCount = sizeof(kOpInfo) / sizeof(kOpInfo[0]);
static_assert(kOpCount <= 256, "an opcode is one byte");

// ADDMLK's B packs like LocalImm, an offset (0..65535) in place of the local.
// JCMPMKEOL's B: the local holding the frame's address (0..15) in bits 0-3, the word's offset
// (0..4095) in bits 4-15, the comparison (0..5: == != < <= > >=) in bits 16-18, the immediate
// (-8192..8191) in bits 19-31.
constexpr uint32_t kFrameTestLocalMax = 15;
constexpr uint32_t kFrameTestOffsetMax = 4095;
constexpr int32_t kFrameTestImmMin = -8192;
constexpr int32_t kFrameTestImmMax = 8191;
constexpr uint32_t pack_frame_test(uint32_t local, uint32_t offset, uint32_t how, int32_t imm) {
  return local | (offset << 4) | (how << 16) | (static_cast<uint32_t>(imm) << 19);
}
constexpr uint32_t frame_test_local(uint32_t b) { return b & 0xFu; }
constexpr uint32_t frame_test_offset(uint32_t b) { return (b >> 4) & kFrameTestOffsetMax; }
constexpr uint32_t frame_test_how(uint32_t b) { return (b >> 16) & 0x7u; }
constexpr int32_t frame_test_imm(uint32_t b) { return static_cast<int32_t>(b) >> 19; }
// LDPMLK's B: the local holding the frame's address (0..15) in bits 0-3, the word's offset
// (0..255) in bits 4-11, the bound below which an address passes (0..4095) in bits 12-23, the
// window's local (0..15) in bits 24-27 and its size's power of two (0..15) in bits 28-31.
constexpr uint32_t kPointerTestLocalMax = 15;
constexpr uint32_t kPointerTestOffsetMax = 255;
constexpr uint32_t kPointerTestBoundMax = 4095;
constexpr uint32_t kPointerTestSizeMax = 15;
constexpr uint32_t pack_pointer_test(uint32_t local, uint32_t offset, uint32_t bound,
                                     uint32_t window_local, uint32_t size_power) {
  return local | (offset << 4) | (bound << 12) | (window_local << 24) | (size_power << 28);
}
constexpr uint32_t pointer_test_local(uint32_t b) { return b & 0xFu; }
constexpr uint32_t pointer_test_offset(uint32_t b) { return (b >> 4) & kPointerTestOffsetMax; }
constexpr uint32_t pointer_test_bound(uint32_t b) { return (b >> 12) & kPointerTestBoundMax; }
constexpr uint32_t pointer_test_window_local(uint32_t b) { return (b >> 24) & 0xFu; }
constexpr uint32_t pointer_test_window(uint32_t b) { return 1u << (b >> 28); }
// CALLFEOL's B: the frame's words (1..4095) in bits 0-11, the arguments in bits 12-19, the
// frame word the first goes to in bits 20-27.
constexpr uint32_t kMemoryFrameMax = (1u << 12) - 1;
constexpr uint32_t pack_memory_frame(uint32_t words, uint32_t arguments, uint32_t first) {
  return words | (arguments << 12) | (first << 20);
}
constexpr uint32_t memory_frame_words(uint32_t b) { return b & kMemoryFrameMax; }
constexpr uint32_t memory_frame_arguments(uint32_t b) { return (b >> 12) & 0xFFu; }
constexpr uint32_t memory_frame_first(uint32_t b) { return (b >> 20) & 0xFFu; }
constexpr const OpInfo& op_info(Op op) { return kOpInfo[static_cast<uint8_t>(op)]; }
constexpr const char* op_name(Op op) { return kOpNames[static_cast<uint8_t>(op)]; }
constexpr uint32_t op_length(Op op) { return op_info(op).b == Operand::None ? 1u : 2u; }
// The instructions whose A is a catch block rather than a jump.
constexpr bool enters_try(Op op) { return op == Op::TRY || op == Op::TRYALL; }
// The instructions that pop B values for the host (and CMDRUNX an index below them).
constexpr bool pops_host_arguments(Op op) {
  return op == Op::CMDRUN || op == Op::CMDRUNX || op == Op::MSG;
}

// The A field: 23 bits, sign-extended for immediates.
constexpr int32_t kImmMin = -(1 << 22);
constexpr int32_t kImmMax = (1 << 22) - 1;
constexpr uint32_t kOperandMax = (1u << 23) - 1;
constexpr bool fits_imm(int64_t v) { return v >= kImmMin && v <= kImmMax; }

// The line-end mark: the source line ends once the instruction has run, on every path it takes,
// as an EOL after it would (and for a branch, at its target too) -- a line costs no dispatch
// of its own.
constexpr uint32_t kLineEndBit = 1u << 8;

constexpr Op word_op(uint32_t word) { return static_cast<Op>(word & 0xFFu); }
constexpr uint32_t word_a(uint32_t word) { return word >> 9; }
constexpr int32_t word_imm(uint32_t word) { return static_cast<int32_t>(word) >> 9; }
constexpr bool word_ends_line(uint32_t word) { return (word & kLineEndBit) != 0; }
// Operand A placed in its field of an instruction word.
constexpr uint32_t a_field(uint32_t a) { return (a & kOperandMax) << 9; }
constexpr uint32_t make_word(Op op, uint32_t a) { return static_cast<uint32_t>(op) | a_field(a); }
// The word with another operand A; its opcode and line-end mark stay.
constexpr uint32_t with_a(uint32_t word, uint32_t a) {
  return (word & ~a_field(kOperandMax)) | a_field(a);
}

// The instructions that end their line themselves: EOL and the fused forms named ...EOL.
constexpr bool ends_line_itself(Op op) {
  const char* name = op_name(op);
  uint32_t n = 0;
  while (name[n] != '\0') ++n;
  return n >= 3 && name[n - 3] == 'E' && name[n - 2] == 'O' && name[n - 1] == 'L';
}
// The superinstructions of the peephole pass, whose dispatch does not look for the mark (it would
// cost the dialects that fuse most, PDL above all, without a line to end), but the compare-and-
// jumps on the stack, which the CUP loader makes of AJump[c].
constexpr bool is_superinstruction(Op op) {
  const auto in = [op](Op first, Op last) { return op >= first && op <= last; };
  return (in(Op::ADDLK, Op::MULFLLS) && !in(Op::JEQI, Op::JGEI)) || in(Op::STGEOL, Op::JULTLK) ||
         in(Op::MULIK, Op::INCGJMPLN) || op == Op::ADDMLK || op == Op::INCMLKEOL;
}
// The instructions that may carry the line-end mark: those that run to completion and go on in
// the same slice. Not a call or a return (the line would end in another frame), nor one that
// ends its line itself, stops the slice (YIELD, WAIT) or runs apart from the loop (UNTILCK),
// nor a superinstruction. A table made at compile time, so that firmware carries no names.
struct LineEndTable {
  bool may[256];
};
constexpr LineEndTable make_line_end_table() {
  LineEndTable t{};
  for (uint32_t i = 0; i < kOpCount; ++i) {
    const Op op = static_cast<Op>(i);
    const Flow flow = op_info(op).flow;
    t.may[i] = (flow == Flow::Next || flow == Flow::Jump || flow == Flow::Branch) &&
               !ends_line_itself(op) && !is_superinstruction(op) && op != Op::YIELD &&
               op != Op::WAIT && op != Op::UNTILCK && op != Op::BREAK && op != Op::JLINES &&
               op != Op::JMPLN;
  }
  return t;
}
inline constexpr LineEndTable kLineEndTable = make_line_end_table();
constexpr bool may_end_line(Op op) { return kLineEndTable.may[static_cast<uint8_t>(op)]; }
static_assert(ends_line_itself(Op::EOL) && ends_line_itself(Op::JMPEOL) &&
              !ends_line_itself(Op::JMP) && may_end_line(Op::JZ) && !may_end_line(Op::RETEOL) &&
              may_end_line(Op::JGTI) && may_end_line(Op::LDGE) && !may_end_line(Op::REMLK) &&
              !may_end_line(Op::STMLK) && !may_end_line(Op::MULIK) && !may_end_line(Op::JCMPGG));

}  // namespace uprog::bytecode
