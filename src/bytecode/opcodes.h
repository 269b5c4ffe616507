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
  Width,
  Text,
  Element,
  Lines,
  Window,
  MemoryFrame,
  Intrinsic
};

// LDGW's and STGW's B: the window's first element and its size, 16 bits each.
constexpr uint32_t pack_window(uint32_t first, uint32_t size) { return first | (size << 16); }
constexpr uint32_t window_first(uint32_t b) { return b & 0xFFFFu; }
constexpr uint32_t window_size(uint32_t b) { return b >> 16; }
enum class Flow : uint8_t { Next, Jump, Branch, Call, Stop };

// The relation a comparison's A names (CMPI, CMPF, CMPU, CMPD); the compare-and-jumps JEQI..JGEI
// and JNEQF..JNGEF are in this order too.
constexpr uint32_t kRelEq = 0, kRelNe = 1, kRelLt = 2, kRelLe = 3, kRelGt = 4, kRelGe = 5;
constexpr uint32_t kRelationCount = 6;
// The relation that holds exactly when `r` does not (of ints: floats have NaN).
constexpr uint32_t negated_relation(uint32_t r) {
  constexpr uint32_t kNegation[kRelationCount] = {kRelNe, kRelEq, kRelGe, kRelGt, kRelLe, kRelLt};
  return kNegation[r];
}

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

// Every opcode of this table: the base set and BREAK, its last. The base set is [0, kBaseOpCount):
// what an image may hold. The VM's fused instructions are numbered from kOpCount (vm/fused.def).
inline constexpr uint32_t kOpCount = sizeof(kOpInfo) / sizeof(kOpInfo[0]);
inline constexpr uint32_t kBaseOpCount = static_cast<uint32_t>(Op::BREAK);
static_assert(kBaseOpCount + 1 == kOpCount, "BREAK follows the base set");

// The compare-and-jump of an int relation; the "jump unless" of a float relation.
constexpr Op int_jump(uint32_t relation) {
  return static_cast<Op>(static_cast<uint32_t>(Op::JEQI) + relation);
}
constexpr Op float_jump_unless(uint32_t relation) {
  return static_cast<Op>(static_cast<uint32_t>(Op::JNEQF) + relation);
}
static_assert(int_jump(kRelGe) == Op::JGEI && float_jump_unless(kRelGe) == Op::JNGEF &&
              int_jump(kRelLt) == Op::JLTI && float_jump_unless(kRelNe) == Op::JNNEF);
static_assert(kOpCount <= 256, "an opcode is one byte");

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
// The comparisons whose A is a relation (kRelEq..kRelGe).
constexpr bool names_relation(Op op) {
  return op == Op::CMPI || op == Op::CMPF || op == Op::CMPU || op == Op::CMPD;
}
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

// The instructions that end their line themselves, so carry no mark: EOL, RETEOL and CALLFEOL.
constexpr bool ends_line_itself(Op op) {
  return op == Op::EOL || op == Op::RETEOL || op == Op::CALLFEOL;
}
// The instructions that may carry the line-end mark: those that run to completion and go on in
// the same slice. Not a call or a return (the line would end in another frame), nor one that
// ends its line itself or stops the slice (YIELD, WAIT), nor the copies' JLINES and JMPLN (the
// way out counts its lines itself). A table made at compile time, so that firmware carries no
// names: a bit for each opcode.
struct LineEndTable {
  uint32_t may[8];
};
constexpr LineEndTable make_line_end_table() {
  LineEndTable t{};
  for (uint32_t i = 0; i < kOpCount; ++i) {
    const Op op = static_cast<Op>(i);
    const Flow flow = op_info(op).flow;
    const bool may = (flow == Flow::Next || flow == Flow::Jump || flow == Flow::Branch) &&
                     !ends_line_itself(op) && op != Op::YIELD && op != Op::WAIT &&
                     op != Op::BREAK && op != Op::JLINES && op != Op::JMPLN;
    if (may) t.may[i / 32] |= 1u << (i % 32);
  }
  return t;
}
inline constexpr LineEndTable kLineEndTable = make_line_end_table();
constexpr bool may_end_line(Op op) {
  const auto i = static_cast<uint8_t>(op);
  return (kLineEndTable.may[i / 32] >> (i % 32)) & 1u;
}
static_assert(ends_line_itself(Op::EOL) && !ends_line_itself(Op::JMP) && may_end_line(Op::JZ) &&
              may_end_line(Op::JMP) && !may_end_line(Op::RETEOL) && may_end_line(Op::JGTI) &&
              may_end_line(Op::LDGE) && !may_end_line(Op::CALL) && !may_end_line(Op::YIELD));

}  // namespace uprog::bytecode
