// Emits instructions into an image's code, with labels that may be bound after they are used.
// The assembler and every dialect's code generator build code through it.
#pragma once
#include <cstdint>
#include <vector>

#include "bytecode/opcodes.h"

namespace uprog::bytecode {

class CodeBuilder {
 public:
  struct Label {
    uint32_t id;
  };

  explicit CodeBuilder(std::vector<uint32_t>& code) : code_(code) {}

  uint32_t here() const { return static_cast<uint32_t>(code_.size()); }

  // `a` must fit its operand kind (23 bits; signed for Imm). `b` is the second word when the
  // opcode has one.
  void emit(Op op, uint32_t a = 0, uint32_t b = 0);
  void emit_imm(Op op, int32_t a, uint32_t b = 0) { emit(op, static_cast<uint32_t>(a), b); }

  Label new_label();
  void bind(Label label);
  bool bound(Label label) const { return targets_[label.id] != kUnbound; }
  uint32_t target(Label label) const { return targets_[label.id]; }
  // An instruction whose A operand is the label's address (JMP, JZ, JNZ, TRY).
  void emit_to(Op op, Label label);

  // Ends the source line whose code starts at `line_start`: with the line-end mark on its last
  // instruction when that may carry it and nothing jumps to the place after it, else with an EOL.
  void end_line(uint32_t line_start);

  // Patches every use; false when a used label was never bound.
  bool finish();

 private:
  static constexpr uint32_t kUnbound = UINT32_MAX;
  struct Use {
    uint32_t pc;
    uint32_t label;
  };
  std::vector<uint32_t>& code_;
  uint32_t last_ = kUnbound;        // where the last instruction emitted starts
  uint32_t last_bound_ = kUnbound;  // where the last label was bound
  std::vector<uint32_t> targets_;
  std::vector<Use> uses_;
};

}  // namespace uprog::bytecode
