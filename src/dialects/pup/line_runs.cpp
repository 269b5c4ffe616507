// Runs of CUP lines and their fused copies (line_runs.h).
#include "dialects/pup/line_runs.h"

#include <fmt/core.h>

#include "bytecode/code_builder.h"
#include "bytecode/peephole.h"
#include "dialects/pup/cup_code.h"

namespace uprog::pup {
namespace {

using bytecode::Op;

bool is_gen_data(const Keyword* k) { return k != nullptr && k->id == KeywordId::GenData; }

// A line that a run may hold: it reads and writes only AGenData and the stack and cannot fail.
// A division needs the line before it in the run to push a divisor other than 0 (`before` is
// null for a run's first line).
bool may_run(const LineOp& op, const LineOp* before) {
  const Message& m = op.msg;
  if (m.tail == Message::Tail::Assign) return is_gen_data(op.key);
  switch (op.key->id) {
    case KeywordId::PushConstant: case KeywordId::Compare: case KeywordId::Jump: return true;
    case KeywordId::PushParam: case KeywordId::PopParam: return is_gen_data(op.name_key);
    case KeywordId::Math: {
      const int32_t n = m.target.index;
      if (n == 4 || n == 5) {
        return before != nullptr && before->key->id == KeywordId::PushConstant &&
               before->msg.value != 0;
      }
      return native_math(n).has_value() || n == 20 || n == 21;
    }
    default: return false;
  }
}

class Fuser {
 public:
  explicit Fuser(bytecode::Image& image) : image_(image) {}

  // The copy of lines first..last, or an empty run when it would not be shorter.
  LineRun fuse(const std::vector<LineOp>& ops, uint32_t first, uint32_t last) {
    bytecode::Image piece;
    bytecode::CodeBuilder b(piece.code);
    for (uint32_t l = first; l <= last; ++l) line(b, ops[l], l);
    if (ops[last].key->id != KeywordId::Jump) b.emit(Op::JMP, kRunExit + last + 1);
    piece.constants = image_.constants;  // with the lines' own, as are the globals
    piece.globals = image_.globals;
    bytecode::Routine r;
    r.name = "run";
    piece.routines.push_back(r);
    bytecode::optimize(piece);

    LineRun run{first, last, 0, piece.code};
    uint32_t instructions = 0, ended = 0;
    bool branched = false;
    for (uint32_t pc = 0; pc < run.code.size(); pc += bytecode::op_length(bytecode::word_op(run.code[pc]))) {
      const Op op = bytecode::word_op(run.code[pc]);
      const bool ends = bytecode::word_ends_line(run.code[pc]) || bytecode::ends_line_itself(op);
      if (ends && branched) return {};  // a line end some path would miss: the count would be wrong
      ended += ends ? 1 : 0;
      branched = branched || bytecode::op_info(op).flow == bytecode::Flow::Branch;
      ++instructions;
    }
    const uint32_t lines = last - first + 1;
    if (ended > lines || instructions + 1 >= lines) return {};
    image_.constants = piece.constants;  // with those the fusions added
    run.counted = lines - ended;
    return run;
  }

 private:
  // The line in the shape a compiler gives the peephole pass: a value's store ends a statement
  // (an EOL, so that the three-address forms that end a line apply), a branch is a comparison
  // and JNZ.
  void line(bytecode::CodeBuilder& b, const LineOp& op, uint32_t l) {
    const Message& m = op.msg;
    if (m.tail == Message::Tail::Assign) {
      push(b, m.value);
      return store(b, m.target.index);
    }
    switch (op.key->id) {
      case KeywordId::PushConstant: return push(b, m.value);
      case KeywordId::PushParam: return b.emit(Op::LDG, element(m.name.index));
      case KeywordId::PopParam: return store(b, m.name.index);
      case KeywordId::Math: emit_math(b, m.target.index); return;
      case KeywordId::Compare: return emit_condition(b, m.target.index);
      case KeywordId::Jump: {
        const int32_t c = m.target.index;
        if (c == 1) return b.emit(Op::JMP, kRunExit + op.target);
        if (c == 9) {
          b.emit(Op::JZ, kRunExit + op.target);
        } else {
          if (c != 10) emit_condition(b, c);
          b.emit(Op::JNZ, kRunExit + op.target);
        }
        return b.emit(Op::JMP, kRunExit + l + 1);
      }
      default: return;
    }
  }
  void store(bytecode::CodeBuilder& b, int32_t index) {
    b.emit(Op::STG, element(index));
    b.emit(Op::EOL);
  }
  void push(bytecode::CodeBuilder& b, int32_t v) {
    if (bytecode::fits_imm(v)) return b.emit_imm(Op::PUSHI, v);
    b.emit(Op::PUSHK, image_.constant_index({ValueType::Int, static_cast<uint32_t>(v)}));
  }
  // The global "AGenData[n]", added the first time.
  uint32_t element(int32_t n) {
    const std::string name = fmt::format("AGenData[{}]", n);
    if (const int g = image_.find_global(name); g >= 0) return static_cast<uint32_t>(g);
    image_.globals.push_back({name, ValueType::Int, 1});
    return static_cast<uint32_t>(image_.globals.size() - 1);
  }

  bytecode::Image& image_;
};

}  // namespace

std::vector<LineRun> fuse_line_runs(const std::vector<LineOp>& ops, const std::vector<int32_t>& depth,
                                    const std::vector<bool>& entered, bytecode::Image& image) {
  std::vector<LineRun> runs;
  Fuser fuser(image);
  const uint32_t count = static_cast<uint32_t>(ops.size()) - 1;
  for (uint32_t first = 1; first <= count;) {
    uint32_t last = first;
    const auto in_run = [&](uint32_t l) {
      return depth[l] >= 0 && may_run(ops[l], l > first ? &ops[l - 1] : nullptr);
    };
    if (!in_run(first)) {
      ++first;
      continue;
    }
    while (ops[last].key->id != KeywordId::Jump && last < count && !entered[last + 1] && in_run(last + 1)) ++last;
    if (last > first) {
      if (LineRun run = fuser.fuse(ops, first, last); !run.code.empty()) runs.push_back(std::move(run));
    }
    first = last + 1;
  }
  return runs;
}

}  // namespace uprog::pup
