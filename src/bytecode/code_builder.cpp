// Instruction emission and label patching.
#include "bytecode/code_builder.h"

namespace uprog::bytecode {

void CodeBuilder::emit(Op op, uint32_t a, uint32_t b) {
  code_.push_back(make_word(op, a));
  if (op_length(op) == 2) code_.push_back(b);
}

CodeBuilder::Label CodeBuilder::new_label() {
  targets_.push_back(kUnbound);
  return Label{static_cast<uint32_t>(targets_.size() - 1)};
}

void CodeBuilder::bind(Label label) { targets_[label.id] = here(); }

void CodeBuilder::emit_to(Op op, Label label) {
  uses_.push_back({here(), label.id});
  emit(op, 0);
}

bool CodeBuilder::finish() {
  bool ok = true;
  for (const Use& use : uses_) {
    const uint32_t target = targets_[use.label];
    if (target == kUnbound) {
      ok = false;
      continue;
    }
    code_[use.pc] = make_word(word_op(code_[use.pc]), target);
  }
  uses_.clear();
  return ok;
}

}  // namespace uprog::bytecode
