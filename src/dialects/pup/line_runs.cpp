// Fused copies of CUP code (line_runs.h).
#include "dialects/pup/line_runs.h"

#include <algorithm>
#include <set>

#include "bytecode/code_builder.h"
#include "bytecode/peephole.h"
#include "dialects/pup/cup_code.h"
#include "dialects/pup/cup_loader.h"
#include "vm/fused.h"
#include "vm/quicken.h"

namespace uprog::pup {
namespace {

using bytecode::CodeBuilder;
using bytecode::Op;

// A path ends after this many lines, and a copy takes a branch's both ways this many times at
// most (its other branches leave it when taken): the copies' size stays linear in the program's.
constexpr uint32_t kMostLines = 64;
constexpr uint32_t kMostForks = 8;
// All copies together take at most this many code words, and 4 a line more: a program whose
// every other line is a jump target would otherwise copy each stretch many times over.
constexpr size_t kCopyWords = 4096;
constexpr size_t kCopyWordsPerLine = 4;

bool is_gen_data(const Keyword* k) { return k != nullptr && k->id == KeywordId::GenData; }

// A line that a copy may hold: it reads and writes only AGenData and the stack, and can fail
// only by an index out of its window (the copy keeps that instruction's line). A division needs
// the line before it on the path to push a divisor other than 0 (`before` is null where the
// path arrives by a jump or starts).
bool may_copy(const LineOp& op, const LineOp* before) {
  const Message& m = op.msg;
  if (op.fails != 0) return false;
  if (m.tail == Message::Tail::Assign) return is_gen_data(op.key);
  switch (op.key->id) {
    case KeywordId::PushConstant:
    case KeywordId::Compare:
    case KeywordId::Jump:
      return true;
    case KeywordId::PushParam:
    case KeywordId::PopParam:
    case KeywordId::PushParamIdx:
    case KeywordId::PopParamIdx:
      return is_gen_data(op.name_key);
    case KeywordId::Math: {
      const int32_t n = m.target.index;
      if (n == 4 || n == 5) {
        return before != nullptr && before->key->id == KeywordId::PushConstant &&
               before->msg.value != 0;
      }
      return math_in_vm(n);
    }
    default:
      return false;
  }
}

// What the paths through a copy cost together: their instructions as the VM runs them, fused at
// load (vm/quicken.h), each with the JLINES before it, and the lines they run. Paths weigh the
// same.
struct PathCost {
  uint64_t instructions = 0, lines = 0;
  bool lost = false;  // code that does not end in a JMPLN: not a copy this file made
};

// One instruction of quickened code as a path sees it: its words, the lines it ends, its
// branch or jump (a fused one's, where its pattern has one), if any, and whether it leaves the
// copy (a JMPLN, alone or as a fused instruction's last) with how many lines that counts.
struct Step {
  uint32_t length = 1, ended = 0;
  bytecode::Flow flow = bytecode::Flow::Next;
  uint32_t target = 0;
  bool leaves = false;
  uint32_t leaving_lines = 0;
};
Step step_at(const std::vector<uint32_t>& code, uint32_t pc) {
  const uint32_t word = code[pc];
  Step s;
  s.ended = bytecode::word_ends_line(word) ? 1 : 0;
  const auto leaving = [&](Op op, uint32_t at) {
    if (op != Op::JMPLN) return;
    s.leaves = true;
    s.leaving_lines = code[at + 1];
  };
  if (!vm::is_fused(word)) {
    const Op op = bytecode::word_op(word);
    s.length = bytecode::op_length(op);
    s.ended += bytecode::ends_line_itself(op) ? 1 : 0;
    s.flow = bytecode::op_info(op).flow;
    s.target = bytecode::word_a(word);
    leaving(op, pc);
    return s;
  }
  const vm::FusedShape& shape = vm::kFusedShapes[vm::fused_of(word)];
  s.length = shape.length;
  for (uint32_t k = 0; k < shape.count; ++k) {
    const Op op = shape.ops[k];
    const uint32_t at = pc + vm::fused_offset(shape, k);
    s.ended += bytecode::ends_line_itself(op) ? 1 : 0;
    const bytecode::Flow flow = bytecode::op_info(op).flow;
    if (flow == bytecode::Flow::Branch || flow == bytecode::Flow::Jump) {
      s.flow = flow;
      s.target = bytecode::word_a(code[at]);
    }
    leaving(op, at);
  }
  return s;
}

void walk(const std::vector<uint32_t>& code, uint32_t pc, uint32_t instructions, uint32_t ended,
          PathCost& cost) {
  while (pc < code.size() && instructions < kMostLines * 4) {
    const Step s = step_at(code, pc);
    ++instructions;
    ended += s.ended;
    if (s.leaves) {
      cost.instructions += instructions + 1;
      cost.lines += s.leaving_lines + ended;
      return;
    }
    if (s.flow == bytecode::Flow::Branch) walk(code, s.target, instructions, ended, cost);
    pc = s.flow == bytecode::Flow::Jump ? s.target : pc + s.length;
  }
  cost.lost = true;
}

// The line a copy's path ends last, when its last instruction before the way out (JMPLN) is a
// store or another that falls through, ends in the JMPLN's count instead of that instruction's
// mark, so that the two may fuse at load (INCGJLN: a loop's step and the way out). The VM takes
// a copy only with more lines left in the slice than a path of it runs (JLINES), so no line
// budget runs out inside it, and where its lines are counted changes nothing else.
void count_last_line_in_exit(std::vector<uint32_t>& code) {
  std::vector<bool> entered(code.size(), false);
  for (uint32_t pc = 0; pc < code.size(); pc += bytecode::op_length(bytecode::word_op(code[pc]))) {
    const Op op = bytecode::word_op(code[pc]);
    const uint32_t target = bytecode::word_a(code[pc]);
    if (bytecode::op_info(op).a == bytecode::Operand::Target && target < code.size())
      entered[target] = true;
  }
  uint32_t before = UINT32_MAX;
  for (uint32_t pc = 0; pc < code.size(); pc += bytecode::op_length(bytecode::word_op(code[pc]))) {
    if (bytecode::word_op(code[pc]) == Op::JMPLN && before != UINT32_MAX && !entered[pc] &&
        bytecode::word_ends_line(code[before]) &&
        bytecode::op_info(bytecode::word_op(code[before])).flow == bytecode::Flow::Next &&
        !bytecode::ends_line_itself(bytecode::word_op(code[before]))) {
      code[before] &= ~bytecode::kLineEndBit;
      ++code[pc + 1];
    }
    before = pc;
  }
}

// The piece's code as the VM will run it: fused where nothing enters (its lines' starts are
// where it may fail, kept apart).
std::vector<uint32_t> quickened(const bytecode::Image& piece) {
  std::vector<uint32_t> code = piece.code;
  std::vector<uint32_t> entries = {0};
  for (const bytecode::LineEntry& e : piece.lines) entries.push_back(e.code);
  const auto size = static_cast<uint32_t>(code.size());
  std::vector<uint32_t> scratch(vm::quicken_scratch_words(size));
  vm::quicken(code.data(), size, entries, scratch.data());
  return code;
}

class Copier {
 public:
  Copier(const std::vector<LineOp>& ops, bytecode::Image& image)
      : ops_(ops), count_(static_cast<uint32_t>(ops.size()) - 1), image_(image) {}

  bool may_start(uint32_t l) const { return l <= count_ && may_copy(ops_[l], nullptr); }

  // The copy from line `first`; `exits` gets the lines it leaves to. Empty when no shorter.
  LineRun copy(uint32_t first, std::set<uint32_t>& exits) {
    bytecode::Image piece;
    CodeBuilder b(piece.code);
    first_ = first;
    forks_ = 0;
    most_ = 0;
    pushed_global_at_ = UINT32_MAX;  // an earlier copy's place means nothing in this one
    exits_ = &exits;
    piece_ = &piece;
    piece.lines.push_back({0, "", first});
    path(b, first, 0, 0);
    b.finish();
    piece.constants = image_.constants;  // with the lines' own, as are the globals
    piece.globals = image_.globals;
    bytecode::Routine r;
    r.name = "copy";
    piece.routines.push_back(r);
    bytecode::optimize(piece);
    count_last_line_in_exit(piece.code);
    PathCost cost;
    walk(quickened(piece), 0, 0, 0, cost);
    if (cost.lost || cost.instructions >= cost.lines) return {};
    LineRun run{first, most_, piece.code, {}};
    for (const bytecode::LineEntry& e : piece.lines) run.lines.emplace_back(e.code, e.line);
    return run;
  }

 private:
  // The code of one path from line l, `ran` lines run before it, `ended` of them ended by the
  // copy's own EOLs; a branch's taken side is emitted after its other side, as a path of its own.
  void path(CodeBuilder& b, uint32_t l, uint32_t ran, uint32_t ended) {
    const LineOp* before = nullptr;
    while (l <= count_ && ran < kMostLines && may_copy(ops_[l], before)) {
      const LineOp& op = ops_[l];
      ++ran;
      if (op.key->id != KeywordId::Jump) {
        ended += line(b, op, l) ? 1 : 0;
        before = &op;
        ++l;
        continue;
      }
      const int32_t c = op.msg.target.index;
      if (c == 1) {
        // The copy's own loop goes on into its next turn while a whole turn more fits in a path:
        // one way out and back in (JMPLN, then JLINES) for several turns. Not a turn of more than
        // two branches (its test and an `if`), whose forks would spend on its first turns the few
        // that a copy follows.
        if (op.target != first_ || ran + (l + 1 - first_) > kMostLines || branches(first_, l) > 2)
          return leave(b, op.target, ran, ended);
        l = first_;
        before = nullptr;
        continue;
      }
      const auto taken = b.new_label();
      if (c == 9) {
        b.emit_to(Op::JZ, taken);
      } else {
        if (c != 10) emit_condition(b, c);
        b.emit_to(Op::JNZ, taken);
      }
      path(b, l + 1, ran, ended);
      b.bind(taken);
      if (op.target <= l || forks_ == kMostForks) return leave(b, op.target, ran, ended);
      ++forks_;
      l = op.target;
      before = nullptr;
    }
    leave(b, l, ran, ended);
  }

  // The conditional jumps among lines [from, to).
  uint32_t branches(uint32_t from, uint32_t to) const {
    uint32_t n = 0;
    for (uint32_t k = from; k < to; ++k)
      n += ops_[k].key->id == KeywordId::Jump && ops_[k].msg.target.index != 1 ? 1 : 0;
    return n;
  }

  // JMPLN counts the path's lines that no EOL of the copy has ended.
  void leave(CodeBuilder& b, uint32_t line, uint32_t ran, uint32_t ended) {
    b.emit(Op::JMPLN, kRunExit + line, ran - ended);
    most_ = std::max(most_, ran);
    exits_->insert(line);
  }

  // The line as a compiler gives it to the peephole pass: a branch is a comparison and JNZ, a
  // store ends its statement with an EOL (so that the forms that store and end a line apply,
  // `T = A + B` one ADDIGGEOL). True when it ended a line so.
  bool line(CodeBuilder& b, const LineOp& op, uint32_t l) {
    const Message& m = op.msg;
    if (m.tail == Message::Tail::Assign) {
      push(b, m.value);
      return store(b, m.target.index);
    }
    switch (op.key->id) {
      case KeywordId::PushConstant:
        push(b, m.value);
        break;
      case KeywordId::PushParam:
        pushed_global_at_ = b.here();
        b.emit(Op::LDG, gen_data_element_global(image_, m.name.index));
        break;
      case KeywordId::PopParam:
        return store(b, m.name.index);
      case KeywordId::PushParamIdx:
        may_fail(b, l);
        b.emit(Op::LDGW, gen_data_global(image_), gen_data_window(m));
        break;
      case KeywordId::PopParamIdx:
        may_fail(b, l);
        b.emit(Op::STGW, gen_data_global(image_), gen_data_window(m));
        b.emit(Op::EOL);
        return true;
      case KeywordId::Math:
        emit_math(b, m.target.index);
        break;
      case KeywordId::Compare:
        emit_condition(b, m.target.index);
        break;
      default:
        break;
    }
    return false;
  }
  bool store(CodeBuilder& b, int32_t n) {
    b.emit(Op::STG, gen_data_element_global(image_, n));
    b.emit(Op::EOL);
    return true;
  }
  // An instruction that may fail starts a line of the piece: the peephole keeps it apart, and
  // the line table says where it went. An index pushed from a global just before starts it
  // instead, so that the two may fuse (LDGWG, STGWG) into what fails.
  void may_fail(const CodeBuilder& b, uint32_t l) {
    const bool index_pushed = pushed_global_at_ + 1 == b.here();
    piece_->lines.push_back({index_pushed ? pushed_global_at_ : b.here(), "", l});
  }
  void push(CodeBuilder& b, int32_t v) {
    if (bytecode::fits_imm(v)) return b.emit_imm(Op::PUSHI, v);
    b.emit(Op::PUSHK, image_.constant_index({ValueType::Int, static_cast<uint32_t>(v)}));
  }

  const std::vector<LineOp>& ops_;
  const uint32_t count_;
  bytecode::Image& image_;
  bytecode::Image* piece_ = nullptr;
  uint32_t first_ = 0, forks_ = 0, most_ = 0;
  uint32_t pushed_global_at_ = UINT32_MAX;  // where the last LDG of a pushed AGenData[n] is
  std::set<uint32_t>* exits_ = nullptr;
};

}  // namespace

std::vector<LineRun> fuse_line_runs(const std::vector<LineOp>& ops,
                                    const std::vector<int32_t>& depth,
                                    const std::vector<bool>& entered, bytecode::Image& image) {
  std::vector<LineRun> runs;
  const auto count = static_cast<uint32_t>(ops.size()) - 1;
  if (count + 1 >= kRunExit) return runs;
  Copier copier(ops, image);
  // A copy starts where control arrives other than from a line a copy holds, and where a copy
  // leaves to (its path too long, or its branch taken past the forks it may follow).
  std::set<uint32_t> starts;
  for (uint32_t l = 1; l <= count; ++l) {
    const bool after_copied =
        l > 1 && may_copy(ops[l - 1], l > 2 ? &ops[l - 2] : nullptr) && ops[l - 1].falls_through;
    if (depth[l] >= 0 && copier.may_start(l) && (entered[l] || !after_copied)) starts.insert(l);
  }
  std::set<uint32_t> done;
  size_t words = 0;
  const size_t most_words = kCopyWords + kCopyWordsPerLine * count;
  while (!starts.empty()) {
    const uint32_t l = *starts.begin();
    starts.erase(starts.begin());
    if (!done.insert(l).second) continue;
    std::set<uint32_t> exits;
    LineRun run = copier.copy(l, exits);
    if (run.code.empty() || words + run.code.size() > most_words) continue;
    words += run.code.size();
    runs.push_back(std::move(run));
    for (uint32_t e : exits)
      if (e <= count && depth[e] >= 0 && copier.may_start(e) && done.count(e) == 0)
        starts.insert(e);
  }
  std::sort(runs.begin(), runs.end(),
            [](const LineRun& a, const LineRun& b) { return a.first < b.first; });
  return runs;
}

}  // namespace uprog::pup
