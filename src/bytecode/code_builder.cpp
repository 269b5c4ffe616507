// Instruction emission and label patching.
#include "bytecode/code_builder.h"

namespace uprog::bytecode {

void CodeBuilder::emit(Op op, uint32_t a, uint32_t b) {
  last_ = here();
  code_.push_back(make_word(op, a));
  if (op_length(op) == 2) code_.push_back(b);
}

CodeBuilder::Label CodeBuilder::new_label() {
  targets_.push_back(kUnbound);
  return Label{static_cast<uint32_t>(targets_.size() - 1)};
}

void CodeBuilder::bind(Label label) { targets_[label.id] = last_bound_ = here(); }

void CodeBuilder::emit_to(Op op, Label label) {
  uses_.push_back({here(), label.id});
  emit(op, 0);
}

void CodeBuilder::end_line(uint32_t line_start) {
  if (last_ != kUnbound && last_ >= line_start && last_bound_ != here() &&
      may_end_line(word_op(code_[last_])) && !word_ends_line(code_[last_])) {
    code_[last_] |= kLineEndBit;
    return;
  }
  emit(Op::EOL);
}

bool CodeBuilder::finish() {
  bool ok = true;
  for (const Use& use : uses_) {
    const uint32_t target = targets_[use.label];
    if (target == kUnbound) {
      ok = false;
      continue;
    }
    code_[use.pc] = with_a(code_[use.pc], target);
  }
  uses_.clear();
  return ok;
}

}  // namespace uprog::bytecode
