// Quickening (quicken.h): a forward pass over the base code, longest pattern first.
#include "vm/quicken.h"

#include "vm/fused.h"
#include "vm/run_error.h"  // a pattern's RAISE code in fused.def

namespace uprog::vm {
namespace {

using bytecode::Op;

// Pattern f as kFusedBases holds it: what the quickener reads at load.
struct Pattern {
  const uint8_t* ops;
  uint32_t count;
  uint32_t length;
  uint32_t relation_at;
  bool per_relation;
  bytecode::Op op(uint32_t k) const { return static_cast<bytecode::Op>(ops[k]); }
  uint32_t offset(uint32_t k) const { return words_before(ops, k); }  // of the k-th, in words
};
Pattern pattern(uint32_t f) {
  const uint32_t start = kFusedBases.pattern_start[f];
  const uint32_t first = kFusedBases.first_opcode[f];
  const uint32_t next = f + 1 < kFusedCount ? kFusedBases.first_opcode[f + 1] : kFusedOpcodeCount;
  return {kFusedBases.pattern_ops + start, kFusedBases.pattern_start[f + 1] - start,
          kFusedBases.length[first], kFusedBases.relation_at[f], next - first > 1};
}
// A pattern's offsets where its WHEN reads them: constants, so that no table of kShapes is kept.
template <uint32_t f, uint32_t k>
constexpr uint32_t kOffset = fused_offset(fused_detail::kShapes[f], k);

class Quickener {
 public:
  Quickener(uint32_t* code, uint32_t size, uint32_t* entered)
      : code_(code), size_(size), entered_(entered) {}

  void mark_entered(uint32_t pc) {
    if (pc < size_) entered_[pc / 32] |= 1u << (pc % 32);
  }
  bool entered(uint32_t pc) const { return (entered_[pc / 32] >> (pc % 32)) & 1u; }

  // The fused instruction the base code at `pc` may become (the one of most instructions), or
  // kFusedCount.
  uint32_t match(uint32_t pc) const {
    uint32_t best = kFusedCount;
    for (uint32_t f = 0; f < kFusedCount; ++f) {
      const Pattern p = pattern(f);
      if (p.ops[0] != static_cast<uint8_t>(bytecode::word_op(code_[pc]))) continue;
      if (best != kFusedCount && pattern(best).count >= p.count) continue;
      if (fits(pc, p) && holds(static_cast<Fused>(f), code_ + pc, pc)) best = f;
    }
    return best;
  }

  // Forms the fused instruction f at pc: its opcode (of a FUSED_PER_RELATION family, the one for
  // the relation of its compare-and-jump), and the mark of its last word.
  void form(uint32_t pc, uint32_t f) {
    const Pattern p = pattern(f);
    const uint32_t last = code_[pc + p.offset(p.count - 1u)];
    uint32_t relation = 0;
    if (p.per_relation) {
      const auto jump =
          static_cast<uint32_t>(bytecode::word_op(code_[pc + p.offset(p.relation_at)]));
      relation = jump - p.ops[p.relation_at];
    }
    code_[pc] = (code_[pc] & ~0x1FFu) | fused_number(static_cast<Fused>(f), relation) |
                (last & bytecode::kLineEndBit);
  }

 private:
  bool fits(uint32_t pc, const Pattern& p) const {
    if (p.length > size_ - pc) return false;
    uint32_t at = pc;
    for (uint32_t k = 0; k < p.count; at += bytecode::op_length(p.op(k++))) {
      // The k-th instruction: its opcode, or any of the six relations where the pattern takes one.
      const auto op = static_cast<uint32_t>(bytecode::word_op(code_[at]));
      if (k == p.relation_at ? op - p.ops[k] >= kFamilyMembers : op != p.ops[k]) return false;
      if (k > 0 && entered(at)) return false;
      if (k + 1 < p.count && bytecode::word_ends_line(code_[at])) return false;
    }
    return true;
  }

  // The pattern's condition on its operands (fused.def's WHEN).
  static bool holds(Fused f, const uint32_t* at, [[maybe_unused]] uint32_t pc) {
#define PC_AT(k) (pc + kOffset<index, k>)
#define A_AT(k) bytecode::word_a(at[kOffset<index, k>])
#define IMM_AT(k) bytecode::word_imm(at[kOffset<index, k>])
#define B_AT(k) (at[kOffset<index, k> + 1])
#define OP_AT(k) static_cast<uint32_t>(bytecode::word_op(at[kOffset<index, k>]))
    switch (f) {
#define FUSED(name, pattern, when, meaning, ...)                                \
  case Fused::name: {                                                           \
    [[maybe_unused]] constexpr auto index = static_cast<uint32_t>(Fused::name); \
    return (when);                                                              \
  }
#include "vm/fused.def"
#undef FUSED
    }
#undef PC_AT
#undef A_AT
#undef IMM_AT
#undef B_AT
#undef OP_AT
    return false;
  }

  uint32_t* code_;
  uint32_t size_;
  uint32_t* entered_;
};

}  // namespace

namespace {

// Whether the instruction at pc is a check's way past its error: a conditional jump over one
// RAISE to the instruction after it. Its target is not entered from elsewhere by that jump: a
// pattern that holds the target past its first word holds the RAISE before it and the jump,
// and its WHEN demands that the jump goes there (PC_AT).
bool jumps_over_raise(const uint32_t* code, uint32_t size, uint32_t pc) {
  static_assert(bytecode::op_length(bytecode::Op::JZ) == 1 &&
                bytecode::op_length(bytecode::Op::JNZ) == 1 &&
                bytecode::op_length(bytecode::Op::RAISE) == 1);
  const bytecode::Op op = bytecode::word_op(code[pc]);
  return (op == bytecode::Op::JZ || op == bytecode::Op::JNZ) && pc + 1 < size &&
         bytecode::word_op(code[pc + 1]) == bytecode::Op::RAISE &&
         bytecode::word_a(code[pc]) == pc + 2;
}

// Marks every jump and catch target of the code; the caller marks the entries and line starts.
Quickener entered_targets(uint32_t* code, uint32_t size, uint32_t* scratch) {
  for (uint32_t i = 0; i < quicken_scratch_words(size); ++i) scratch[i] = 0;
  Quickener q(code, size, scratch);
  for (uint32_t pc = 0; pc < size; pc += bytecode::op_length(bytecode::word_op(code[pc]))) {
    const bytecode::OpInfo& info = bytecode::op_info(bytecode::word_op(code[pc]));
    if (info.a == bytecode::Operand::Target && !jumps_over_raise(code, size, pc))
      q.mark_entered(bytecode::word_a(code[pc]));
  }
  return q;
}

uint32_t form_all(Quickener& q, uint32_t* code, uint32_t size) {
  uint32_t formed = 0;
  for (uint32_t pc = 0; pc < size;) {
    const uint32_t length = bytecode::op_length(bytecode::word_op(code[pc]));
    uint32_t f = q.match(pc);
    // A pair gives way to a longer pattern that starts at its second instruction (LDL x; LDL a;
    // PUSHI k; JLTI: x stays, JLTLK follows).
    if (f != kFusedCount && pattern(f).count == 2 && pc + length < size) {
      const uint32_t next = q.match(pc + length);
      if (next != kFusedCount && pattern(next).count > 2) f = kFusedCount;
    }
    if (f == kFusedCount) {
      pc += length;
      continue;
    }
    q.form(pc, f);
    ++formed;
    pc += pattern(f).length;
  }
  return formed;
}

}  // namespace

uint32_t quicken(uint32_t* code, uint32_t size, const bytecode::ImageView& image,
                 uint32_t* scratch) {
  Quickener q = entered_targets(code, size, scratch);
  for (uint32_t i = 0; i < image.routines.size(); ++i) q.mark_entered(image.routines[i].entry);
  for (uint32_t i = 0; i < image.lines.size(); ++i) q.mark_entered(image.lines[i].code);
  return form_all(q, code, size);
}

uint32_t quicken(uint32_t* code, uint32_t size, std::span<const uint32_t> entries,
                 uint32_t* scratch) {
  Quickener q = entered_targets(code, size, scratch);
  for (const uint32_t pc : entries) q.mark_entered(pc);
  return form_all(q, code, size);
}

}  // namespace uprog::vm
