// The compile-time pass over base code. It makes no fused instruction (the VM forms those when it
// loads an image, vm/fused.def): it writes a comparison and its JZ/JNZ as one compare-and-jump,
// drops a test against 0 before a branch, puts each line's end on the instruction before it (the
// line-end mark) or on the jump after it, drops code nothing reaches and threads jumps to jumps.
// An instruction is removed only when control cannot arrive at it except from the one before (no
// jump target, catch target, routine entry or source line's start); then every such place is
// relocated.
#include "bytecode/peephole.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

struct Instr {
  uint32_t pc;  // where it was; kept by the first instruction of a merged sequence
  Op op;
  uint32_t a;
  uint32_t b;
  bool ends_line = false;  // carries the line-end mark
};

bool decode(const std::vector<uint32_t>& code, std::vector<Instr>& out) {
  for (uint32_t pc = 0; pc < code.size();) {
    const uint32_t word = code[pc];
    if ((word & 0xFFu) >= kBaseOpCount) return false;
    const Op op = word_op(word);
    const uint32_t length = op_length(op);
    if (length > code.size() - pc) return false;
    out.push_back({pc, op, word_a(word), length == 2 ? code[pc + 1] : 0, word_ends_line(word)});
    pc += length;
  }
  return true;
}

bool is_branch(Op op) { return op == Op::JZ || op == Op::JNZ; }
// The branches a condition's line ends with: JZ, JNZ and the compare-and-jumps.
bool is_condition_branch(Op op) { return is_branch(op) || (op >= Op::JEQI && op <= Op::JNGEF); }

// The index of the instruction that starts at `pc`, or code.size().
size_t index_at(const std::vector<Instr>& code, uint32_t pc) {
  const auto at = std::lower_bound(code.begin(), code.end(), pc,
                                   [](const Instr& i, uint32_t p) { return i.pc < p; });
  return at != code.end() && at->pc == pc ? static_cast<size_t>(at - code.begin()) : code.size();
}

// "B T; EOL" with an EOL at T that starts no source line: a condition's line, whose end is an
// EOL on both paths. The branch with the line-end mark ends it on both (the mark's meaning for a
// branch) when it jumps past T's EOL: the instruction after that EOL, which the returned index
// names, then is a place control arrives at. code.size() when `k` is no such branch.
size_t past_target_eol(const std::vector<Instr>& code, size_t k, const std::vector<bool>& entered,
                       const std::vector<bool>& line_start) {
  const Instr& b = code[k];
  if (!is_condition_branch(b.op) || b.ends_line || k + 1 >= code.size() ||
      code[k + 1].op != Op::EOL || entered[code[k + 1].pc])
    return code.size();
  const size_t t = index_at(code, b.a);
  if (t + 1 >= code.size() || code[t].op != Op::EOL || line_start[code[t].pc]) return code.size();
  return t + 1;
}

// The branch of every condition's line above ends the line on both paths and jumps past its
// target's EOL; the EOL after it goes (nothing enters it), and the one at its target too once
// nothing else jumps there (drop_dead_code).
void end_condition_lines(std::vector<Instr>& code, const std::vector<bool>& entered,
                         const std::vector<bool>& line_start) {
  std::vector<Instr> out;
  out.reserve(code.size());
  for (size_t k = 0; k < code.size(); ++k) {
    out.push_back(code[k]);
    const size_t past = past_target_eol(code, k, entered, line_start);
    if (past == code.size() || !entered[code[past].pc]) continue;
    out.back().ends_line = true;
    out.back().a = code[past].pc;
    ++k;  // the EOL after the branch
  }
  code = std::move(out);
}
int32_t imm_of(const Instr& i) { return word_imm(a_field(i.a)); }

// The old code words control may arrive at other than from the instruction before: jump and
// catch targets in `code`, routine entries and line starts (a debugger may move a thread there).
std::vector<bool> entered_places(const std::vector<Instr>& code, const Image& image, size_t size) {
  std::vector<bool> entered(size + 1, false);
  for (const Instr& i : code)
    if (op_info(i.op).a == Operand::Target && i.a <= size) entered[i.a] = true;
  for (const Routine& r : image.routines)
    if (r.entry <= size) entered[r.entry] = true;
  for (const LineEntry& l : image.lines)
    if (l.code <= size) entered[l.code] = true;
  return entered;
}

class Merger {
 public:
  Merger(const std::vector<Instr>& in, const std::vector<bool>& entered)
      : in_(in), entered_(entered) {}

  // The one instruction that the sequence at `i` is, and how many it replaces.
  std::optional<std::pair<Instr, size_t>> match(size_t i) const {
    if (auto r = test_zero(i)) return r;
    if (auto r = compare_branch(i)) return r;
    if (auto r = local_increment(i)) return r;
    return eol_jump(i);
  }

 private:
  // Instructions i + 1 .. i + k exist and control arrives at none of them but from before.
  bool free(size_t i, size_t k) const {
    for (size_t j = 1; j <= k; ++j)
      if (i + j >= in_.size() || entered_[in_[i + j].pc]) return false;
    return true;
  }
  // No instruction of i .. i + k - 1 ends a line: a sequence that merges stays in its line.
  bool unmarked(size_t i, size_t k) const {
    for (size_t j = 0; j < k; ++j)
      if (in_[i + j].ends_line) return false;
    return true;
  }
  const Instr& at(size_t i) const { return in_[i]; }

  // CMPI r; JZ|JNZ T -> the int compare-and-jump of r or of its negation; CMPF r; JZ T -> the
  // float "jump unless r" (JZ only: NaN's answers stay exact)
  std::optional<std::pair<Instr, size_t>> compare_branch(size_t i) const {
    if (!free(i, 1) || !unmarked(i, 1) || !is_branch(at(i + 1).op)) return std::nullopt;
    const Instr& branch = at(i + 1);
    const uint32_t relation = at(i).a;
    if (relation >= kRelationCount) return std::nullopt;  // the verifier refuses it later
    Op jump;
    if (at(i).op == Op::CMPI)
      jump = int_jump(branch.op == Op::JNZ ? relation : negated_relation(relation));
    else if (at(i).op == Op::CMPF && branch.op == Op::JZ)
      jump = float_jump_unless(relation);
    else
      return std::nullopt;
    return std::pair{Instr{at(i).pc, jump, branch.a, 0, branch.ends_line}, size_t{2}};
  }

  // LDL a; PUSHI k; ADDI; STL a -> INCL a k: a local stepped by a constant (`n = n + 1`), one
  // instruction of every dialect's base set (ADDI and INCL both wrap).
  std::optional<std::pair<Instr, size_t>> local_increment(size_t i) const {
    if (!free(i, 3) || !unmarked(i, 3) || at(i).op != Op::LDL || at(i + 1).op != Op::PUSHI ||
        at(i + 2).op != Op::ADDI || at(i + 3).op != Op::STL || at(i + 3).a != at(i).a)
      return std::nullopt;
    const auto step = static_cast<uint32_t>(imm_of(at(i + 1)));
    return std::pair{Instr{at(i).pc, Op::INCL, at(i).a, step, at(i + 3).ends_line}, size_t{4}};
  }

  // PUSHI 0; CMPI != | ==; JZ|JNZ T — a test against zero is the branch itself.
  std::optional<std::pair<Instr, size_t>> test_zero(size_t i) const {
    if (!free(i, 2) || !unmarked(i, 2) || at(i).op != Op::PUSHI || imm_of(at(i)) != 0)
      return std::nullopt;
    const Instr& compare = at(i + 1);
    const Instr& branch = at(i + 2);
    if (compare.op != Op::CMPI || (compare.a != kRelNe && compare.a != kRelEq) ||
        !is_branch(branch.op))
      return std::nullopt;
    const bool jump_if_nonzero = (compare.a == kRelNe) == (branch.op == Op::JNZ);
    return std::pair{
        Instr{at(i).pc, jump_if_nonzero ? Op::JNZ : Op::JZ, branch.a, 0, branch.ends_line},
        size_t{3}};
  }

  // EOL; JMP T — the jump that ends its line (the slice stops at T when the line's end spends
  // its budget, as after the EOL it would stop before the jump: nothing runs between).
  std::optional<std::pair<Instr, size_t>> eol_jump(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::EOL || at(i + 1).op != Op::JMP || at(i + 1).ends_line)
      return std::nullopt;
    return std::pair{Instr{at(i).pc, Op::JMP, at(i + 1).a, 0, true}, size_t{2}};
  }

  const std::vector<Instr>& in_;
  const std::vector<bool>& entered_;
};

// `PUSHI k; SUBI` is `PUSHI -k; ADDI` (both wrap), one form for the VM to fuse: its fused
// instructions of an immediate (ADDLK, ADDGK, ADDIK, ADDGKS, INCG, STEPMLK) take any immediate,
// so a subtraction of one needs none of its own. Only within a line and where nothing enters
// the SUBI: the pair stays where it was, its value the same.
void subtract_as_add(std::vector<Instr>& code, const std::vector<bool>& entered) {
  for (size_t i = 0; i + 1 < code.size(); ++i) {
    Instr& push = code[i];
    Instr& sub = code[i + 1];
    if (push.op != Op::PUSHI || sub.op != Op::SUBI || push.ends_line || entered[sub.pc]) continue;
    const int64_t negated = -static_cast<int64_t>(imm_of(push));
    if (!fits_imm(negated)) continue;
    push.a = static_cast<uint32_t>(negated) & kOperandMax;
    sub.op = Op::ADDI;
  }
}

// Code that follows an unconditional jump or a stop and that nothing enters (no target, routine
// entry or line start) is dropped; a jump to what then follows it falls through: a JMP goes, a
// JMP that ends its line is an EOL (but before a RET, which thread_jumps makes RETEOL of).
void drop_dead_code(std::vector<Instr>& code, const Image& image, size_t size) {
  const std::vector<bool> entered = entered_places(code, image, size);
  std::vector<Instr> live;
  live.reserve(code.size());
  bool reached = true;
  for (const Instr& i : code) {
    reached = reached || entered[i.pc];
    if (!reached) continue;
    live.push_back(i);
    const Flow flow = op_info(i.op).flow;
    reached = flow != Flow::Jump && flow != Flow::Stop;
  }
  code.clear();
  for (size_t k = 0; k < live.size(); ++k) {
    Instr i = live[k];
    const bool to_next = k + 1 < live.size() && i.op == Op::JMP && i.a == live[k + 1].pc;
    if (to_next && !i.ends_line && !entered[i.pc]) continue;
    if (to_next && i.ends_line && live[k + 1].op != Op::RET) i = Instr{i.pc, Op::EOL, 0, 0};
    code.push_back(i);
  }
}

// "X; EOL", X an instruction that goes on to the next and may carry the mark, the EOL neither
// entered nor a source line's start: X with the line-end mark, the line ending as it did
// without a dispatch of its own. (After a branch the EOL ends the line on one path only.)
void mark_line_ends(std::vector<Instr>& code, const std::vector<bool>& entered) {
  std::vector<Instr> out;
  out.reserve(code.size());
  for (const Instr& i : code) {
    Instr* last = out.empty() ? nullptr : &out.back();
    if (i.op == Op::EOL && last != nullptr && !entered[i.pc] &&
        op_info(last->op).flow == Flow::Next && may_end_line(last->op) && !last->ends_line) {
      last->ends_line = true;
      continue;
    }
    out.push_back(i);
  }
  code = std::move(out);
}

// A jump to a JMP goes straight to its target; a jump that ends its line to a RET becomes
// RETEOL. Targets are followed a bounded number of steps, so a cycle of jumps stays a cycle.
void thread_jumps(std::vector<uint32_t>& code) {
  const auto final_target = [&](uint32_t target) {
    for (int hops = 0; hops < 8 && target < code.size() && word_op(code[target]) == Op::JMP &&
                       !word_ends_line(code[target]);
         ++hops)
      target = word_a(code[target]);
    return target;
  };
  for (uint32_t pc = 0; pc < code.size(); pc += op_length(word_op(code[pc]))) {
    const Op op = word_op(code[pc]);
    if (op_info(op).a != Operand::Target || enters_try(op) || op == Op::JLINES) continue;
    const uint32_t target = final_target(word_a(code[pc]));
    if (op == Op::JMP && word_ends_line(code[pc]) && target < code.size() &&
        word_op(code[target]) == Op::RET) {
      code[pc] = make_word(Op::RETEOL, 0);
      continue;
    }
    code[pc] = with_a(code[pc], target);
  }
}

}  // namespace

PeepholeStats optimize(Image& image) {
  PeepholeStats stats;
  stats.words_before = stats.words_after = static_cast<uint32_t>(image.code.size());
  std::vector<Instr> in;
  if (!decode(image.code, in)) return stats;

  const size_t size = image.code.size();
  std::vector<bool> entered = entered_places(in, image, size);
  std::vector<bool> line_start(size + 1, false);
  for (const LineEntry& l : image.lines)
    if (l.code <= size) line_start[l.code] = true;
  // Where a condition's line may jump past its target's EOL (end_condition_lines), control will
  // arrive: nothing merges into it.
  for (size_t k = 0; k < in.size(); ++k)
    if (const size_t past = past_target_eol(in, k, entered, line_start); past < in.size())
      entered[in[past].pc] = true;
  subtract_as_add(in, entered);
  std::vector<Instr> out;
  const Merger merger(in, entered);
  for (size_t i = 0; i < in.size();) {
    if (auto m = merger.match(i)) {
      out.push_back(m->first);
      i += m->second;
      ++stats.fused;
    } else {
      out.push_back(in[i++]);
    }
  }
  end_condition_lines(out, entered, line_start);
  // A jump dropped may leave the place it went to unentered: again until nothing changes.
  for (size_t before = out.size() + 1; out.size() < before;) {
    before = out.size();
    drop_dead_code(out, image, size);
  }
  mark_line_ends(out, entered);

  // Old instruction starts (and the end) to new ones.
  std::vector<uint32_t> relocated(size + 1, UINT32_MAX);
  std::vector<uint32_t> code;
  for (const Instr& i : out) {
    relocated[i.pc] = static_cast<uint32_t>(code.size());
    code.push_back(make_word(i.op, i.a) | (i.ends_line ? kLineEndBit : 0u));
    if (op_length(i.op) == 2) code.push_back(i.b);
  }
  relocated[size] = static_cast<uint32_t>(code.size());
  const auto move = [&](uint32_t old) { return old <= size ? relocated[old] : UINT32_MAX; };
  // A place that was inside a merged sequence cannot be referenced (nothing entered it), so
  // every lookup below finds a relocated start; an out-of-range one is left to the verifier.
  for (uint32_t pc = 0; pc < code.size(); pc += op_length(word_op(code[pc]))) {
    const Op op = word_op(code[pc]);
    if (op_info(op).a != Operand::Target) continue;
    const uint32_t target = move(word_a(code[pc]));
    if (target != UINT32_MAX) code[pc] = with_a(code[pc], target);
  }
  thread_jumps(code);
  for (Routine& r : image.routines)
    if (move(r.entry) != UINT32_MAX) r.entry = move(r.entry);
  for (LineEntry& l : image.lines)
    if (move(l.code) != UINT32_MAX) l.code = move(l.code);
  image.code = std::move(code);
  stats.words_after = static_cast<uint32_t>(image.code.size());
  return stats;
}

}  // namespace uprog::bytecode
