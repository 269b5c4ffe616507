// Peephole fusion over decoded instructions. A sequence is fused only when no instruction after
// its first is a jump target, catch target, routine entry or the start of a source line, so
// every place control can arrive at survives; then every such place is relocated.
#include "bytecode/peephole.h"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

struct Instr {
  uint32_t pc;  // where it was; kept by the first instruction of a fused sequence
  Op op;
  uint32_t a;
  uint32_t b;
  // A fused global comparison with an immediate (PUSHI k) compares with a constant: the
  // pass finds or adds the int constant k and puts its index into B's second half (or, for a
  // constant's store, STGK, into the whole of B).
  bool wants_constant = false;
  int32_t constant = 0;
  bool constant_is_b = false;
  bool ends_line = false;  // carries the line-end mark (mark_line_ends)
};

bool decode(const std::vector<uint32_t>& code, std::vector<Instr>& out) {
  for (uint32_t pc = 0; pc < code.size();) {
    const uint32_t word = code[pc];
    if ((word & 0xFFu) >= kOpCount) return false;
    const Op op = word_op(word);
    const uint32_t length = op_length(op);
    if (length > code.size() - pc) return false;
    out.push_back({pc, op, word_a(word), length == 2 ? code[pc + 1] : 0});
    pc += length;
  }
  return true;
}

// Int comparisons and the fused jumps taken when they are true; for JZ, their negation.
struct CompareFamily {
  Op compare, when_true, when_false, locals_true, locals_false, imm_true, imm_false, global_true,
      global_false;
};
constexpr CompareFamily kIntCompares[] = {
    {Op::EQI, Op::JEQI, Op::JNEI, Op::JEQLL, Op::JNELL, Op::JEQLK, Op::JNELK, Op::JEQGK, Op::JNEGK},
    {Op::NEI, Op::JNEI, Op::JEQI, Op::JNELL, Op::JEQLL, Op::JNELK, Op::JEQLK, Op::JNEGK, Op::JEQGK},
    {Op::LTI, Op::JLTI, Op::JGEI, Op::JLTLL, Op::JGELL, Op::JLTLK, Op::JGELK, Op::JLTGK, Op::JGEGK},
    {Op::LEI, Op::JLEI, Op::JGTI, Op::JLELL, Op::JGTLL, Op::JLELK, Op::JGTLK, Op::JLEGK, Op::JGTGK},
    {Op::GTI, Op::JGTI, Op::JLEI, Op::JGTLL, Op::JLELL, Op::JGTLK, Op::JLELK, Op::JGTGK, Op::JLEGK},
    {Op::GEI, Op::JGEI, Op::JLTI, Op::JGELL, Op::JLTLL, Op::JGELK, Op::JLTLK, Op::JGEGK, Op::JLTGK},
};
// Comparison k of kIntCompares (== != < <= > >=) fails exactly when this one holds.
constexpr uint32_t kNegatedCompare[] = {1, 0, 5, 4, 3, 2};
// Float comparisons fuse only with JZ: "jump unless" keeps NaN's answers exact.
struct FloatCompareFamily {
  Op compare, jump_unless, locals_unless, constant_unless, global_constant_unless, globals_unless;
};
constexpr FloatCompareFamily kFloatCompares[] = {
    {Op::EQF, Op::JNEQF, Op::JNEQFLL, Op::JNEQFLK, Op::JNEQFGK, Op::JNEQFGG},
    {Op::NEF, Op::JNNEF, Op::JNNEFLL, Op::JNNEFLK, Op::JNNEFGK, Op::JNNEFGG},
    {Op::LTF, Op::JNLTF, Op::JNLTFLL, Op::JNLTFLK, Op::JNLTFGK, Op::JNLTFGG},
    {Op::LEF, Op::JNLEF, Op::JNLEFLL, Op::JNLEFLK, Op::JNLEFGK, Op::JNLEFGG},
    {Op::GTF, Op::JNGTF, Op::JNGTFLL, Op::JNGTFLK, Op::JNGTFGK, Op::JNGTFGG},
    {Op::GEF, Op::JNGEF, Op::JNGEFLL, Op::JNGEFLK, Op::JNGEFGK, Op::JNGEFGG},
};

// Two globals' arithmetic: the plain operation, the form that pushes its result, and the
// three-address form that stores it into a global and ends the line.
constexpr std::array<std::array<Op, 3>, 5> kGlobalsArithmetic = {
    {{Op::ADDI, Op::ADDIGG, Op::ADDIGGEOL},
     {Op::SUBI, Op::SUBIGG, Op::SUBIGGEOL},
     {Op::ADDF, Op::ADDFGG, Op::ADDFGGEOL},
     {Op::SUBF, Op::SUBFGG, Op::SUBFGGEOL},
     {Op::MULF, Op::MULFGG, Op::MULFGGEOL}}};

// A branch's form that ends the line on both paths (opcodes.def), or nullopt.
std::optional<Op> ending_line_form(Op op) {
  const auto in = [&](Op first, Op last) { return op >= first && op <= last; };
  const auto shifted = [&](Op first, Op to) {
    return static_cast<Op>(static_cast<int>(to) + static_cast<int>(op) - static_cast<int>(first));
  };
  if (in(Op::JEQGK, Op::JGEGK)) return shifted(Op::JEQGK, Op::JEQGKEOL);
  if (in(Op::JNEQFGK, Op::JNGEFGK)) return shifted(Op::JNEQFGK, Op::JNEQFGKEOL);
  if (in(Op::JNEQF, Op::JNGEF)) return Op::JNCMPFEOL;  // the comparison into B
  if (in(Op::JNEQFGG, Op::JNGEFGG)) return shifted(Op::JNEQFGG, Op::JNEQFGGEOL);
  if (op == Op::JZG) return Op::JZGEOL;
  if (op == Op::JNZG) return Op::JNZGEOL;
  if (op == Op::JCMPGG) return Op::JCMPGGEOL;
  return std::nullopt;
}

// "Jcc T; EOL" with an EOL at T: a condition's line, ending after its branch on both paths.
// The instruction after T's EOL becomes a boundary, so that a fused branch can jump to it. An
// EOL that starts a source line stays where the branch goes: a breakpoint on it must be hit.
bool skippable_eol(const Instr& at_target, const std::vector<bool>& line_start) {
  return at_target.op == Op::EOL && !line_start[at_target.pc];
}

// The index of the instruction that starts at `pc`, or in.size().
size_t index_at(const std::vector<Instr>& in, uint32_t pc) {
  const auto at = std::lower_bound(in.begin(), in.end(), pc,
                                   [](const Instr& i, uint32_t p) { return i.pc < p; });
  return at != in.end() && at->pc == pc ? static_cast<size_t>(at - in.begin()) : in.size();
}

void mark_after_target_eols(const std::vector<Instr>& in, const std::vector<bool>& line_start,
                            std::vector<bool>& boundary) {
  for (size_t k = 0; k + 1 < in.size(); ++k) {
    if (op_info(in[k].op).flow != Flow::Branch || in[k + 1].op != Op::EOL) continue;
    const size_t t = index_at(in, in[k].a);
    if (t + 1 < in.size() && skippable_eol(in[t], line_start)) boundary[in[t + 1].pc] = true;
  }
}

bool fits_int16(int32_t v) { return v >= -32768 && v <= 32767; }
int32_t imm_of(const Instr& i) { return word_imm(a_field(i.a)); }

class Fuser {
 public:
  // room_for_constants: the pass may add int constants (one a fusion at most) and still index
  // every constant in 16 bits.
  Fuser(const std::vector<Instr>& in, const std::vector<bool>& boundary,
        const std::vector<bool>& line_start, bool room_for_constants)
      : in_(in),
        boundary_(boundary),
        line_start_(line_start),
        room_for_constants_(room_for_constants) {}

  // The fused instruction for the sequence at `i` and how many instructions it replaces.
  std::optional<std::pair<Instr, size_t>> match(size_t i) const {
    auto r = fuse(i);
    if (r) ending_line_branch(i, *r);
    return r;
  }

 private:
  std::optional<std::pair<Instr, size_t>> fuse(size_t i) const {
    for (auto m : {&Fuser::compare_locals,
                   &Fuser::arithmetic_locals,
                   &Fuser::local_constant,
                   &Fuser::two_locals,
                   &Fuser::store_constant,
                   &Fuser::test_global,
                   &Fuser::compare_global,
                   &Fuser::global_constant,
                   &Fuser::arithmetic_globals,
                   &Fuser::compare_globals,
                   &Fuser::float_global_constant,
                   &Fuser::two_globals,
                   &Fuser::add_global,
                   &Fuser::window_by_global,
                   &Fuser::stack_constant,
                   &Fuser::store_global_constant,
                   &Fuser::store_global_eol,
                   &Fuser::compare_branch,
                   &Fuser::test_zero,
                   &Fuser::line_ending_jump,
                   &Fuser::eol_jump,
                   &Fuser::wait_for_command}) {
      if (auto r = (this->*m)(i)) return r;
    }
    return std::nullopt;
  }

  // A fused branch at i of `n` instructions, followed by the EOL of its line, whose target is
  // an EOL too (mark_after_target_eols): one instruction that ends the line either way.
  void ending_line_branch(size_t i, std::pair<Instr, size_t>& fused) const {
    const std::optional<Op> form = ending_line_form(fused.first.op);
    if (!form || !free(i, fused.second) || at(i + fused.second).op != Op::EOL) return;
    const size_t target = index_at(in_, fused.first.a);
    if (target + 1 >= in_.size() || !skippable_eol(at(target), line_start_) ||
        !boundary_[at(target + 1).pc])
      return;
    if (*form == Op::JNCMPFEOL)
      fused.first.b = static_cast<uint32_t>(fused.first.op) - static_cast<uint32_t>(Op::JNEQF);
    fused.first.op = *form;
    fused.first.a = at(target + 1).pc;
    ++fused.second;
  }

  // Instruction i + k exists and control cannot arrive at it except from i + k - 1.
  bool free(size_t i, size_t k) const {
    for (size_t j = 1; j <= k; ++j)
      if (i + j >= in_.size() || boundary_[in_[i + j].pc]) return false;
    return true;
  }
  const Instr& at(size_t i) const { return in_[i]; }
  // Instruction i + k is an EOL that fuses with what is before it, and not with a JMP after it
  // (JMPEOL, which costs the same).
  bool lone_eol(size_t i, size_t k) const {
    return free(i, k) && at(i + k).op == Op::EOL &&
           !(free(i, k + 1) && at(i + k + 1).op == Op::JMP);
  }
  static bool is_branch(Op op) { return op == Op::JZ || op == Op::JNZ; }

  // LDL a; LDL b | PUSHI k; <int compare>; JZ/JNZ T
  // LDL a; LDL b | PUSHK k; <float compare>; JZ T
  std::optional<std::pair<Instr, size_t>> compare_locals(size_t i) const {
    if (!free(i, 3) || at(i).op != Op::LDL || !is_branch(at(i + 3).op)) return std::nullopt;
    const Instr& second = at(i + 1);
    // Both halves of a packed operand hold 16 bits: a local or a constant's index.
    const bool second_packs =
        (second.op == Op::LDL || second.op == Op::PUSHK) && second.a <= 0xFFFF;
    if (at(i).a > 0xFFFF) return std::nullopt;
    for (const auto& f : kFloatCompares) {
      if (at(i + 2).op != f.compare || at(i + 3).op != Op::JZ) continue;
      if (!second_packs) return std::nullopt;
      const Op fused = second.op == Op::LDL ? f.locals_unless : f.constant_unless;
      return std::pair{Instr{at(i).pc, fused, at(i + 3).a, pack_locals(at(i).a, second.a)},
                       size_t{4}};
    }
    for (const auto& f : kIntCompares) {
      if (at(i + 2).op != f.compare) continue;
      const bool jump_if_true = at(i + 3).op == Op::JNZ;
      const uint32_t local = at(i).a;
      if (second.op == Op::LDL && second_packs) {
        return std::pair{Instr{at(i).pc, jump_if_true ? f.locals_true : f.locals_false, at(i + 3).a,
                               pack_locals(local, second.a)},
                         size_t{4}};
      }
      if (second.op == Op::PUSHI && fits_int16(imm_of(second))) {
        return std::pair{Instr{at(i).pc, jump_if_true ? f.imm_true : f.imm_false, at(i + 3).a,
                               pack_local_imm(local, imm_of(second))},
                         size_t{4}};
      }
    }
    return std::nullopt;
  }

  // <compare>; JZ/JNZ T
  std::optional<std::pair<Instr, size_t>> compare_branch(size_t i) const {
    if (!free(i, 1) || !is_branch(at(i + 1).op)) return std::nullopt;
    const bool jump_if_true = at(i + 1).op == Op::JNZ;
    for (const auto& f : kIntCompares) {
      if (at(i).op == f.compare)
        return std::pair{Instr{at(i).pc, jump_if_true ? f.when_true : f.when_false, at(i + 1).a, 0},
                         size_t{2}};
    }
    if (jump_if_true) return std::nullopt;
    for (const auto& f : kFloatCompares) {
      if (at(i).op == f.compare)
        return std::pair{Instr{at(i).pc, f.jump_unless, at(i + 1).a, 0}, size_t{2}};
    }
    return std::nullopt;
  }

  // PUSHI 0; NEI|EQI; JZ|JNZ T — a test against zero is the branch itself.
  std::optional<std::pair<Instr, size_t>> test_zero(size_t i) const {
    if (!free(i, 2) || at(i).op != Op::PUSHI || imm_of(at(i)) != 0) return std::nullopt;
    const Op compare = at(i + 1).op;
    const Op branch = at(i + 2).op;
    if ((compare != Op::NEI && compare != Op::EQI) || !is_branch(branch)) return std::nullopt;
    const bool jump_if_nonzero = (compare == Op::NEI) == (branch == Op::JNZ);
    return std::pair{Instr{at(i).pc, jump_if_nonzero ? Op::JNZ : Op::JZ, at(i + 2).a, 0},
                     size_t{3}};
  }

  // LDL a; PUSHI k; ADDI|SUBI|REMI
  std::optional<std::pair<Instr, size_t>> local_constant(size_t i) const {
    if (!free(i, 2) || at(i).op != Op::LDL || at(i + 1).op != Op::PUSHI) return std::nullopt;
    const int32_t k = imm_of(at(i + 1));
    const Op op = at(i + 2).op;
    if (op == Op::ADDI || op == Op::SUBI) {
      const int32_t addend = op == Op::ADDI ? k : -k;  // |k| < 2^23: no overflow
      return std::pair{Instr{at(i).pc, Op::ADDLK, at(i).a, static_cast<uint32_t>(addend)},
                       size_t{3}};
    }
    if (op == Op::REMI && k != 0)
      return std::pair{Instr{at(i).pc, Op::REMLK, at(i).a, static_cast<uint32_t>(k)}, size_t{3}};
    return std::nullopt;
  }

  // LDL a; LDL b; ADDI|SUBI|ADDF|SUBF|MULF [; STL c]
  std::optional<std::pair<Instr, size_t>> arithmetic_locals(size_t i) const {
    if (!free(i, 2) || at(i).op != Op::LDL || at(i + 1).op != Op::LDL) return std::nullopt;
    if (at(i).a > 0xFFFF || at(i + 1).a > 0xFFFF) return std::nullopt;
    static constexpr std::array<std::array<Op, 3>, 5> kForms = {
        {{Op::ADDI, Op::ADDILL, Op::ADDILLS},
         {Op::SUBI, Op::SUBILL, Op::SUBILLS},
         {Op::ADDF, Op::ADDFLL, Op::ADDFLLS},
         {Op::SUBF, Op::SUBFLL, Op::SUBFLLS},
         {Op::MULF, Op::MULFLL, Op::MULFLLS}}};
    const uint32_t pair = pack_locals(at(i).a, at(i + 1).a);
    for (const auto& [plain, push, store] : kForms) {
      if (at(i + 2).op != plain) continue;
      if (free(i, 3) && at(i + 3).op == Op::STL)
        return std::pair{Instr{at(i).pc, store, at(i + 3).a, pair}, size_t{4}};
      return std::pair{Instr{at(i).pc, push, 0, pair}, size_t{3}};
    }
    return std::nullopt;
  }

  // LDL a; LDL b | LDL a; STL b | LDL a; PUSHK k | PUSHK k; LDL a — unless the second
  // instruction starts a longer pattern of its own.
  std::optional<std::pair<Instr, size_t>> two_locals(size_t i) const {
    if (!free(i, 1)) return std::nullopt;
    const Instr& first = at(i);
    const Instr& second = at(i + 1);
    if (second.op == Op::LDL &&
        (arithmetic_locals(i + 1) || compare_locals(i + 1) || local_constant(i + 1)))
      return std::nullopt;
    if (first.op == Op::LDL && second.op == Op::LDL)
      return std::pair{Instr{first.pc, Op::LDL2, first.a, second.a}, size_t{2}};
    if (first.op == Op::LDL && second.op == Op::STL)
      return std::pair{Instr{first.pc, Op::MOVL, second.a, first.a}, size_t{2}};
    if (first.op == Op::LDL && second.op == Op::PUSHK)
      return std::pair{Instr{first.pc, Op::LDLK, first.a, second.a}, size_t{2}};
    if (first.op == Op::PUSHK && second.op == Op::LDL)
      return std::pair{Instr{first.pc, Op::LDKL, first.a, second.a}, size_t{2}};
    return std::nullopt;
  }

  // PUSHK k; STL a
  std::optional<std::pair<Instr, size_t>> store_constant(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::PUSHK || at(i + 1).op != Op::STL) return std::nullopt;
    return std::pair{Instr{at(i).pc, Op::STLK, at(i + 1).a, at(i).a}, size_t{2}};
  }

  // The global forms, for dialects whose variables are globals (element 0 of a scalar; the
  // opcodes read and write what LDG and STG do). A packed operand holds a global in 16 bits.
  bool packs_global(const Instr& i) const { return i.op == Op::LDG && i.a <= 0xFFFF; }

  // LDG g; PUSHK k | PUSHI k; <int compare>; JZ/JNZ T
  // LDG g; PUSHK k; <float compare>; JZ T
  std::optional<std::pair<Instr, size_t>> compare_global(size_t i) const {
    if (!free(i, 3) || !packs_global(at(i)) || !is_branch(at(i + 3).op)) return std::nullopt;
    const Instr& second = at(i + 1);
    const bool constant = second.op == Op::PUSHK && second.a <= 0xFFFF;
    const bool immediate = second.op == Op::PUSHI && room_for_constants_;
    if (!constant && !immediate) return std::nullopt;
    for (const auto& f : kFloatCompares) {
      if (at(i + 2).op != f.compare) continue;
      if (at(i + 3).op != Op::JZ || !constant) return std::nullopt;
      return std::pair{
          Instr{at(i).pc, f.global_constant_unless, at(i + 3).a, pack_locals(at(i).a, second.a)},
          size_t{4}};
    }
    for (const auto& f : kIntCompares) {
      if (at(i + 2).op != f.compare) continue;
      const Op fused = at(i + 3).op == Op::JNZ ? f.global_true : f.global_false;
      Instr out{at(i).pc, fused, at(i + 3).a, pack_locals(at(i).a, constant ? second.a : 0)};
      if (immediate) {
        out.wants_constant = true;
        out.constant = imm_of(second);
      }
      return std::pair{out, size_t{4}};
    }
    return std::nullopt;
  }

  // LDG g; JZ|JNZ T, and LDG g; PUSHI 0; NEI|EQI; JZ|JNZ T
  std::optional<std::pair<Instr, size_t>> test_global(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::LDG) return std::nullopt;
    if (is_branch(at(i + 1).op)) {
      const Op fused = at(i + 1).op == Op::JNZ ? Op::JNZG : Op::JZG;
      return std::pair{Instr{at(i).pc, fused, at(i + 1).a, at(i).a}, size_t{2}};
    }
    if (!free(i, 3) || at(i + 1).op != Op::PUSHI || imm_of(at(i + 1)) != 0) return std::nullopt;
    const Op compare = at(i + 2).op;
    const Op branch = at(i + 3).op;
    if ((compare != Op::NEI && compare != Op::EQI) || !is_branch(branch)) return std::nullopt;
    const bool jump_if_nonzero = (compare == Op::NEI) == (branch == Op::JNZ);
    return std::pair{Instr{at(i).pc, jump_if_nonzero ? Op::JNZG : Op::JZG, at(i + 3).a, at(i).a},
                     size_t{4}};
  }

  // LDG g; PUSHI k; ADDI|SUBI; STG g; EOL; JMPLN L n — fused code's loop step on its way out.
  std::optional<std::pair<Instr, size_t>> loop_step(size_t i, uint32_t addend) const {
    const auto step = static_cast<int32_t>(addend);
    if (!free(i, 5) || at(i + 4).op != Op::EOL || at(i + 5).op != Op::JMPLN || at(i).a > 0xFFFF ||
        step < -128 || step > 127 || at(i + 5).b >= 255)
      return std::nullopt;
    return std::pair{
        Instr{at(i).pc, Op::INCGJMPLN, at(i + 5).a, pack_loop_step(at(i).a, step, at(i + 5).b + 1)},
        size_t{6}};
  }

  // LDG g; PUSHI k; ADDI|SUBI [; STG g [; EOL]] | LDG g; PUSHI k; REMI
  std::optional<std::pair<Instr, size_t>> global_constant(size_t i) const {
    if (!free(i, 2) || at(i).op != Op::LDG || at(i + 1).op != Op::PUSHI) return std::nullopt;
    const int32_t k = imm_of(at(i + 1));
    const Op op = at(i + 2).op;
    if (op == Op::ADDI || op == Op::SUBI) {
      const auto addend = static_cast<uint32_t>(op == Op::ADDI ? k : -k);  // |k| < 2^23
      if (free(i, 3) && at(i + 3).op == Op::STG && at(i + 3).a == at(i).a) {
        if (auto r = loop_step(i, addend)) return r;
        if (lone_eol(i, 4))
          return std::pair{Instr{at(i).pc, Op::INCGEOL, at(i).a, addend}, size_t{5}};
        return std::pair{Instr{at(i).pc, Op::INCG, at(i).a, addend}, size_t{4}};
      }
      return std::pair{Instr{at(i).pc, Op::ADDGK, at(i).a, addend}, size_t{3}};
    }
    if (op != Op::REMI || k == 0) return std::nullopt;
    const bool stored = free(i, 3) && at(i + 3).op == Op::STG && lone_eol(i, 4);
    if (stored && fits_int16(k) && at(i).a <= 0xFFFF)
      return std::pair{Instr{at(i).pc, Op::REMGKEOL, at(i + 3).a, pack_local_imm(at(i).a, k)},
                       size_t{5}};
    return std::pair{Instr{at(i).pc, Op::REMGK, at(i).a, static_cast<uint32_t>(k)}, size_t{3}};
  }

  // LDG a; LDG b; ADDI|SUBI|ADDF|SUBF|MULF [; STG c; EOL]
  std::optional<std::pair<Instr, size_t>> arithmetic_globals(size_t i) const {
    if (!free(i, 2) || !packs_global(at(i)) || !packs_global(at(i + 1))) return std::nullopt;
    const uint32_t pair = pack_locals(at(i).a, at(i + 1).a);
    for (const auto& [plain, push, store] : kGlobalsArithmetic) {
      if (at(i + 2).op != plain) continue;
      if (free(i, 3) && at(i + 3).op == Op::STG && lone_eol(i, 4))
        return std::pair{Instr{at(i).pc, store, at(i + 3).a, pair}, size_t{5}};
      return std::pair{Instr{at(i).pc, push, 0, pair}, size_t{3}};
    }
    return std::nullopt;
  }

  // LDG a; LDG b; <int compare>; JZ|JNZ T | LDG a; LDG b; <int compare's jump> T
  std::optional<std::pair<Instr, size_t>> compare_int_globals(size_t i) const {
    if (!free(i, 2) || at(i).op != Op::LDG || at(i + 1).op != Op::LDG ||
        at(i).a > kGlobalsTestMax || at(i + 1).a > kGlobalsTestMax)
      return std::nullopt;
    for (uint32_t how = 0; how < std::size(kIntCompares); ++how) {
      const CompareFamily& f = kIntCompares[how];
      if (at(i + 2).op == f.when_true)
        return std::pair{
            Instr{at(i).pc, Op::JCMPGG, at(i + 2).a, pack_globals_test(at(i).a, at(i + 1).a, how)},
            size_t{3}};
      if (at(i + 2).op != f.compare || !free(i, 3) || !is_branch(at(i + 3).op)) continue;
      const uint32_t holds = at(i + 3).op == Op::JNZ ? how : kNegatedCompare[how];
      return std::pair{
          Instr{at(i).pc, Op::JCMPGG, at(i + 3).a, pack_globals_test(at(i).a, at(i + 1).a, holds)},
          size_t{4}};
    }
    return std::nullopt;
  }

  // LDG a; LDG b; <float compare>; JZ T
  std::optional<std::pair<Instr, size_t>> compare_globals(size_t i) const {
    if (auto r = compare_int_globals(i)) return r;
    if (!free(i, 3) || !packs_global(at(i)) || !packs_global(at(i + 1)) || at(i + 3).op != Op::JZ)
      return std::nullopt;
    for (const auto& f : kFloatCompares) {
      if (at(i + 2).op == f.compare)
        return std::pair{
            Instr{at(i).pc, f.globals_unless, at(i + 3).a, pack_locals(at(i).a, at(i + 1).a)},
            size_t{4}};
    }
    return std::nullopt;
  }

  // LDG g; PUSHK k; ADDF|SUBF|MULF | PUSHK k; LDG g; MULF — the operands in their order.
  std::optional<std::pair<Instr, size_t>> float_global_constant(size_t i) const {
    if (!free(i, 2)) return std::nullopt;
    const Instr& first = at(i);
    const Instr& second = at(i + 1);
    const Op op = at(i + 2).op;
    const auto constant = [](const Instr& k) { return k.op == Op::PUSHK && k.a <= 0xFFFF; };
    if (packs_global(first) && constant(second)) {
      const Op fused = op == Op::ADDF   ? Op::ADDFGK
                       : op == Op::SUBF ? Op::SUBFGK
                       : op == Op::MULF ? Op::MULFGK
                                        : Op::NOP;
      if (fused != Op::NOP)
        return std::pair{Instr{first.pc, fused, 0, pack_locals(first.a, second.a)}, size_t{3}};
    }
    if (constant(first) && packs_global(second) && op == Op::MULF)
      return std::pair{Instr{first.pc, Op::MULFKG, 0, pack_locals(second.a, first.a)}, size_t{3}};
    return std::nullopt;
  }

  // LDG a; STG b | LDG a; LDG b — unless the second starts a longer pattern of its own.
  std::optional<std::pair<Instr, size_t>> two_globals(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::LDG) return std::nullopt;
    if (at(i + 1).op == Op::STG)
      return std::pair{Instr{at(i).pc, Op::MOVG, at(i + 1).a, at(i).a}, size_t{2}};
    if (at(i + 1).op != Op::LDG) return std::nullopt;
    if (arithmetic_globals(i + 1) || compare_global(i + 1) || test_global(i + 1) ||
        global_constant(i + 1) || compare_globals(i + 1) || float_global_constant(i + 1) ||
        add_global(i + 1))
      return std::nullopt;
    return std::pair{Instr{at(i).pc, Op::LDG2, at(i).a, at(i + 1).a}, size_t{2}};
  }

  // LDG g; ADDI — a global added to what is on the stack.
  std::optional<std::pair<Instr, size_t>> add_global(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::LDG || at(i + 1).op != Op::ADDI) return std::nullopt;
    return std::pair{Instr{at(i).pc, Op::ADDIG, at(i).a, 0}, size_t{2}};
  }

  // LDG g; LDGW a w | LDG g; STGW a w — a window of a global indexed by another global.
  std::optional<std::pair<Instr, size_t>> window_by_global(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::LDG || at(i).a > 0xFFu) return std::nullopt;
    const Op op = at(i + 1).op;
    const uint32_t first = window_first(at(i + 1).b), size = window_size(at(i + 1).b);
    if ((op != Op::LDGW && op != Op::STGW) || first > kGlobalWindowMax || size > kGlobalWindowMax)
      return std::nullopt;
    return std::pair{Instr{at(i).pc, op == Op::LDGW ? Op::LDGWG : Op::STGWG, at(i + 1).a,
                           pack_global_window(first, size, at(i).a)},
                     size_t{2}};
  }

  // PUSHI k; MULI | PUSHI k; REMI (k != 0) — the stack's int with an immediate.
  std::optional<std::pair<Instr, size_t>> stack_constant(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::PUSHI) return std::nullopt;
    if (at(i + 1).op == Op::MULI)
      return std::pair{Instr{at(i).pc, Op::MULIK, at(i).a, 0}, size_t{2}};
    if (at(i + 1).op == Op::REMI && imm_of(at(i)) != 0)
      return std::pair{Instr{at(i).pc, Op::REMIK, at(i).a, 0}, size_t{2}};
    return std::nullopt;
  }

  // PUSHK k | PUSHI k; STG g [; EOL]
  std::optional<std::pair<Instr, size_t>> store_global_constant(size_t i) const {
    const bool immediate = at(i).op == Op::PUSHI && room_for_constants_;
    if (!free(i, 1) || (at(i).op != Op::PUSHK && !immediate) || at(i + 1).op != Op::STG)
      return std::nullopt;
    const bool eol = lone_eol(i, 2);
    Instr out{at(i).pc, eol ? Op::STGKEOL : Op::STGK, at(i + 1).a, at(i).a};
    if (immediate) {  // an int constant of its own (`R3 := 0`)
      out.wants_constant = out.constant_is_b = true;
      out.constant = imm_of(at(i));
    }
    return std::pair{out, size_t{eol ? 3u : 2u}};
  }

  // STG g; EOL; JMP T | STG g; JMPEOL T | STG g; EOL — the end of an assignment's line.
  std::optional<std::pair<Instr, size_t>> store_global_eol(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::STG) return std::nullopt;
    const Instr& next = at(i + 1);
    if (next.op == Op::JMPEOL)
      return std::pair{Instr{at(i).pc, Op::STGJEOL, next.a, at(i).a}, size_t{2}};
    if (next.op != Op::EOL) return std::nullopt;
    if (free(i, 2) && at(i + 2).op == Op::JMP)
      return std::pair{Instr{at(i).pc, Op::STGJEOL, at(i + 2).a, at(i).a}, size_t{3}};
    return std::pair{Instr{at(i).pc, Op::STGEOL, at(i).a, 0}, size_t{2}};
  }

  // INCL a k | STL a; EOL; JMP T — a loop's step, or the last assignment of an if arm.
  std::optional<std::pair<Instr, size_t>> line_ending_jump(size_t i) const {
    if (!free(i, 2) || at(i + 1).op != Op::EOL || at(i + 2).op != Op::JMP) return std::nullopt;
    const Instr& first = at(i);
    const uint32_t target = at(i + 2).a;
    if (first.op == Op::STL)
      return std::pair{Instr{first.pc, Op::STLJEOL, target, first.a}, size_t{3}};
    const int32_t step = static_cast<int32_t>(first.b);
    if (first.op == Op::INCL && first.a <= 0xFFFF && fits_int16(step))
      return std::pair{Instr{first.pc, Op::INCLJEOL, target, pack_local_imm(first.a, step)},
                       size_t{3}};
    return std::nullopt;
  }

  // CMDGET c n; [PUSHI k; <int compare>;] JZ|JNZ T; YIELD; JMP back to the CMDGET, with T
  // right after the JMP: a wait for the command, as UNTILCK, whose test holds where the jump to
  // T was taken (without a comparison the value is tested against 0).
  std::optional<std::pair<Instr, size_t>> wait_for_command(size_t i) const {
    if (at(i).op != Op::CMDGET || at(i).b > 0xFFu) return std::nullopt;
    size_t n = 1;
    uint32_t how = 1;  // !=
    int32_t k = 0;
    if (free(i, 2) && at(i + 1).op == Op::PUSHI) {
      const Op compare = at(i + 2).op;
      const auto f = std::find_if(std::begin(kIntCompares), std::end(kIntCompares),
                                  [&](const CompareFamily& c) { return c.compare == compare; });
      k = imm_of(at(i + 1));
      if (f == std::end(kIntCompares) || k < -(1 << 19) || k >= (1 << 19)) return std::nullopt;
      how = static_cast<uint32_t>(f - std::begin(kIntCompares));
      n = 3;
    }
    if (!free(i, n + 2) || !is_branch(at(i + n).op) || at(i + n + 1).op != Op::YIELD ||
        at(i + n + 2).op != Op::JMP || at(i + n + 2).a != at(i).pc || i + n + 3 >= in_.size() ||
        at(i + n).a != at(i + n + 3).pc)
      return std::nullopt;
    if (at(i + n).op == Op::JZ) how = kNegatedCompare[how];
    const uint32_t test = pack_command_test(at(i).b, how, k);
    return std::pair{Instr{at(i).pc, Op::UNTILCK, at(i).a, test}, n + 3};
  }

  // EOL; JMP T
  std::optional<std::pair<Instr, size_t>> eol_jump(size_t i) const {
    if (!free(i, 1) || at(i).op != Op::EOL || at(i + 1).op != Op::JMP) return std::nullopt;
    return std::pair{Instr{at(i).pc, Op::JMPEOL, at(i + 1).a, 0}, size_t{2}};
  }

  const std::vector<Instr>& in_;
  const std::vector<bool>& boundary_;
  const std::vector<bool>& line_start_;
  bool room_for_constants_;
};

// The stack effect of an instruction that writes nothing and never jumps (it may fail, as
// LDMLK and LDM may): what an accumulation's expression may be, and what may stand between an
// address and the STM that stores at it. nullopt for any other.
std::optional<int> pure_effect(Op op) {
  switch (op) {
    case Op::LDG:
    case Op::LDL:
    case Op::PUSHI:
    case Op::PUSHK:
    case Op::LDMLK:
    case Op::ADDIGG:
    case Op::SUBIGG:
    case Op::ADDFGG:
    case Op::SUBFGG:
    case Op::MULFGG:
    case Op::ADDGK:
    case Op::REMGK:
    case Op::ADDLK:
    case Op::REMLK:
    case Op::ADDMLK:
    case Op::ADDILL:
    case Op::SUBILL:
    case Op::ADDFLL:
    case Op::SUBFLL:
    case Op::MULFLL:
    case Op::ADDFGK:
    case Op::SUBFGK:
    case Op::MULFGK:
    case Op::MULFKG:
      return 1;
    case Op::MULIK:
    case Op::REMIK:
    case Op::ADDIG:
      return 0;
    case Op::LDL2:
    case Op::LDG2:
      return 2;
    case Op::ADDI:
    case Op::SUBI:
    case Op::MULI:
      return -1;
    default:
      return std::nullopt;
  }
}

// "LDG g; e; ADDI|ADDF|SUBF; STGEOL g", with e one fused instruction (`p = p + a * b;`), is e
// and the accumulation ADDxGEOL g: the global stays the left operand, and e writes nothing, so
// reading g after it reads the same. Over the fused code, since e is what the fusion made.
void fold_accumulations(std::vector<Instr>& code, const std::vector<bool>& boundary) {
  std::vector<Instr> folded;
  folded.reserve(code.size());
  for (size_t k = 0; k < code.size(); ++k) {
    const bool shaped = k + 3 < code.size() && code[k].op == Op::LDG &&
                        pure_effect(code[k + 1].op) == 1 && code[k + 3].op == Op::STGEOL &&
                        code[k + 3].a == code[k].a && !boundary[code[k + 1].pc] &&
                        !boundary[code[k + 2].pc] && !boundary[code[k + 3].pc];
    const Op combine = shaped ? code[k + 2].op : Op::NOP;
    const Op accumulate = combine == Op::ADDI   ? Op::ADDIGEOL
                          : combine == Op::ADDF ? Op::ADDFGEOL
                          : combine == Op::SUBF ? Op::SUBFGEOL
                                                : Op::NOP;
    if (accumulate == Op::NOP) {
      folded.push_back(code[k]);
      continue;
    }
    Instr expression = code[k + 1];
    expression.pc = code[k].pc;  // where the line's code starts
    folded.push_back(expression);
    folded.push_back(Instr{code[k + 2].pc, accumulate, code[k].a, 0});
    k += 3;
  }
  code = std::move(folded);
}

// Where the STM is that stores at the address ADDLK pushes at k, with pure pushes of one value
// between them (at most four, none of them a place control can enter); 0 when there is none.
size_t stored_at(const std::vector<Instr>& code, size_t k, const std::vector<bool>& boundary) {
  int depth = 0;
  for (size_t j = k + 1; j < code.size() && j <= k + 4 && !boundary[code[j].pc]; ++j) {
    const std::optional<int> effect = pure_effect(code[j].op);
    if (!effect || depth + *effect < 1) return 0;
    depth += *effect;
    if (depth == 1 && j + 1 < code.size() && code[j + 1].op == Op::STM && !boundary[code[j + 1].pc])
      return j + 1;
  }
  return 0;
}

// Instructions k + 1 .. k + n of the fused code exist and control enters none of them.
bool unentered(const std::vector<Instr>& code, size_t k, size_t n,
               const std::vector<bool>& boundary) {
  if (k + n >= code.size()) return false;
  for (size_t j = 1; j <= n; ++j)
    if (boundary[code[k + j].pc]) return false;
  return true;
}

// A frame's word with a constant: "ADDLK l k; LDM; PUSHI c; ADDI|SUBI" is ADDMLK, and "ADDLK l k;
// LDM; PUSHI c; J<cmp>I T; EOL" with a skippable EOL at T (mark_after_target_eols) is JCMPMKEOL,
// which jumps past it: a condition on a parameter or local, ending its line either way. With the
// length of the sequence, or nullopt.
std::optional<std::pair<Instr, size_t>> frame_word_with_constant(
    const std::vector<Instr>& code, size_t k, const std::vector<bool>& boundary,
    const std::vector<bool>& line_start) {
  const auto free = [&](size_t n) { return unentered(code, k, n, boundary); };
  const Instr& address = code[k];
  if (address.op != Op::ADDLK || !free(3) || code[k + 1].op != Op::LDM ||
      code[k + 2].op != Op::PUSHI)
    return std::nullopt;
  const auto offset = static_cast<int32_t>(address.b);
  const int32_t c = imm_of(code[k + 2]);
  const Op use = code[k + 3].op;
  if ((use == Op::ADDI || use == Op::SUBI) && offset >= 0 && offset <= 0xFFFF && fits_int16(c) &&
      fits_int16(-c)) {
    const int32_t addend = use == Op::ADDI ? c : -c;
    return std::pair{Instr{address.pc, Op::ADDMLK, address.a,
                           pack_local_imm(static_cast<uint32_t>(offset), addend)},
                     size_t{4}};
  }
  if (use < Op::JEQI || use > Op::JGEI || !free(4) || code[k + 4].op != Op::EOL ||
      address.a > kFrameTestLocalMax || offset < 0 ||
      offset > static_cast<int32_t>(kFrameTestOffsetMax) || c < kFrameTestImmMin ||
      c > kFrameTestImmMax)
    return std::nullopt;
  const size_t target = index_at(code, code[k + 3].a);
  if (target + 1 >= code.size() || !skippable_eol(code[target], line_start) ||
      !boundary[code[target + 1].pc])
    return std::nullopt;
  const auto how = static_cast<uint32_t>(use) - static_cast<uint32_t>(Op::JEQI);
  return std::pair{Instr{address.pc, Op::JCMPMKEOL, code[target + 1].pc,
                         pack_frame_test(address.a, static_cast<uint32_t>(offset), how, c)},
                   size_t{5}};
}

// A pointer read from a frame's word and its two common checks to one place: "LDMLK l k;
// JULTK T bound; JULTLK T (w, 2^n)" is LDPMLK T, where its fields fit.
void fuse_pointer_tests(std::vector<Instr>& code, const std::vector<bool>& boundary) {
  std::vector<Instr> fused;
  fused.reserve(code.size());
  for (size_t k = 0; k < code.size(); ++k) {
    const Instr& load = code[k];
    if (load.op == Op::LDMLK && unentered(code, k, 2, boundary) && code[k + 1].op == Op::JULTK &&
        code[k + 2].op == Op::JULTLK && code[k + 1].a == code[k + 2].a &&
        load.a <= kPointerTestLocalMax && load.b <= kPointerTestOffsetMax &&
        code[k + 1].b <= kPointerTestBoundMax) {
      const uint32_t window_local = packed_first(code[k + 2].b);
      const int32_t window = packed_imm(code[k + 2].b);
      uint32_t power = 0;
      while (power < kPointerTestSizeMax && (1 << power) < window) ++power;
      if (window_local <= kPointerTestLocalMax && window > 0 && (1 << power) == window) {
        fused.push_back(
            Instr{load.pc, Op::LDPMLK, code[k + 1].a,
                  pack_pointer_test(load.a, load.b, code[k + 1].b, window_local, power)});
        k += 2;
        continue;
      }
    }
    fused.push_back(load);
  }
  code = std::move(fused);
}

// A frame's word stepped by a constant, ending its line: "ADDMLK l (k, c); STMLK l k; EOL" is
// INCMLKEOL l (k, c) (`n--;` of a parameter kept in the data memory).
void fuse_frame_steps(std::vector<Instr>& code, const std::vector<bool>& boundary) {
  std::vector<Instr> fused;
  fused.reserve(code.size());
  for (size_t k = 0; k < code.size(); ++k) {
    const Instr& add = code[k];
    if (add.op == Op::ADDMLK && unentered(code, k, 2, boundary) && code[k + 1].op == Op::STMLK &&
        code[k + 1].a == add.a && code[k + 1].b == packed_first(add.b) &&
        code[k + 2].op == Op::EOL) {
      fused.push_back(Instr{add.pc, Op::INCMLKEOL, add.a, add.b});
      k += 2;
      continue;
    }
    fused.push_back(add);
  }
  code = std::move(fused);
}

// An address of a frame in the data memory and its use: "ADDLK l k; LDM" is LDMLK, and
// "ADDLK l k; <pure pushes of one value>; STM" is the pushes and STMLK (the address computed
// after the value, which changes nothing, since the pushes write nothing). An address's
// unsigned range tests that keep it: "DUP; PUSHI k; CMPU <; JNZ T" is JULTK, and "DUP; LDL l;
// SUBI; PUSHI k; CMPU <; JNZ T" is JULTLK. Over the fused code; nothing control can enter is
// inside a sequence.
void fuse_memory_frames(std::vector<Instr>& code, const std::vector<bool>& boundary,
                        const std::vector<bool>& line_start) {
  constexpr uint32_t kBelow = 2;  // CMPU's "<"
  const auto inside_free = [&](size_t k, size_t n) { return unentered(code, k, n, boundary); };
  const auto is = [&](size_t k, Op op) { return code[k].op == op; };
  const auto below_then_jump = [&](size_t k) {  // PUSHI k; CMPU <; JNZ
    return is(k, Op::PUSHI) && is(k + 1, Op::CMPU) && code[k + 1].a == kBelow && is(k + 2, Op::JNZ);
  };
  std::vector<Instr> fused;
  fused.reserve(code.size());
  for (size_t k = 0; k < code.size(); ++k) {
    const Instr& i = code[k];
    if (auto with_constant = frame_word_with_constant(code, k, boundary, line_start)) {
      fused.push_back(with_constant->first);
      k += with_constant->second - 1;
    } else if (i.op == Op::ADDLK && inside_free(k, 1) && is(k + 1, Op::LDM)) {
      fused.push_back(Instr{i.pc, Op::LDMLK, i.a, i.b});
      k += 1;
    } else if (i.op == Op::DUP && inside_free(k, 3) && below_then_jump(k + 1) &&
               imm_of(code[k + 1]) >= 0) {
      fused.push_back(
          Instr{i.pc, Op::JULTK, code[k + 3].a, static_cast<uint32_t>(imm_of(code[k + 1]))});
      k += 3;
    } else if (i.op == Op::DUP && inside_free(k, 5) && is(k + 1, Op::LDL) &&
               code[k + 1].a <= 0xFFFF && is(k + 2, Op::SUBI) && below_then_jump(k + 3) &&
               fits_int16(imm_of(code[k + 3])) && imm_of(code[k + 3]) >= 0) {
      fused.push_back(Instr{i.pc, Op::JULTLK, code[k + 5].a,
                            pack_local_imm(code[k + 1].a, imm_of(code[k + 3]))});
      k += 5;
    } else {
      fused.push_back(i);
    }
  }
  code.clear();
  for (size_t k = 0; k < fused.size(); ++k) {
    const size_t store = fused[k].op == Op::ADDLK ? stored_at(fused, k, boundary) : 0;
    if (store == 0) {
      code.push_back(fused[k]);
      continue;
    }
    const Instr& address = fused[k];
    for (size_t j = k + 1; j < store; ++j) code.push_back(fused[j]);
    code[code.size() - (store - k - 1)].pc =
        address.pc;  // the sequence starts where the address did
    code.push_back(Instr{fused[store].pc, Op::STMLK, address.a, address.b});
    k = store;
  }
  fuse_pointer_tests(code, boundary);
  fuse_frame_steps(code, boundary);
}

// The old code words control may arrive at other than from the instruction before: jump
// targets in `code`, routine entries and line starts (a debugger may move a thread there).
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

// Appends `i`, merged into the instruction before it when nothing enters `i`: an EOL into the
// store or step whose line it ends (`R3 := 0;` in an IF, once the jump over the ELSE side's EOL
// falls through), a global's store that ends a line into two globals' arithmetic before it.
void append_merging(std::vector<Instr>& code, const Instr& i, const std::vector<bool>& entered) {
  static constexpr std::array<std::array<Op, 2>, 3> kEnding = {
      {{Op::STG, Op::STGEOL}, {Op::STGK, Op::STGKEOL}, {Op::INCG, Op::INCGEOL}}};
  if (!code.empty() && !entered[i.pc]) {
    const Instr last = code.back();
    std::optional<Instr> merged;
    for (const auto& [plain, ending] : kEnding)
      if (i.op == Op::EOL && last.op == plain) merged = Instr{last.pc, ending, last.a, last.b};
    for (const auto& [plain, push, store] : kGlobalsArithmetic)
      if (i.op == Op::STGEOL && last.op == push) merged = Instr{last.pc, store, i.a, last.b};
    if (merged) {
      code.pop_back();
      append_merging(code, *merged, entered);  // a store that now ends a line may merge again
      return;
    }
  }
  code.push_back(i);
}

// After the fusions a branch may jump past an EOL that then nothing reaches (PDL's and ST's
// `if` without `else`: "JZ f; EOL; body; JMP end; f: EOL; end:" becomes "JZGEOL end; body;
// STGJEOL end; EOL; end:"). Code that follows an unconditional jump or a stop and that nothing
// enters (no target, routine entry or line start) is dropped; a jump to what then follows it
// falls through: `JMP` goes, `JMPEOL` is an EOL (but before a RET, which thread_jumps makes
// RETEOL of), `STGJEOL g` is `STGEOL g`, and what they end merges (append_merging).
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
    const bool to_next =
        k + 1 < live.size() && op_info(i.op).a == Operand::Target && i.a == live[k + 1].pc;
    if (to_next && i.op == Op::JMP && !entered[i.pc]) continue;
    // Before a RET the jump stays: thread_jumps makes it one RETEOL.
    if (to_next && i.op == Op::JMPEOL && live[k + 1].op != Op::RET) i = Instr{i.pc, Op::EOL, 0, 0};
    if (to_next && i.op == Op::STGJEOL) i = Instr{i.pc, Op::STGEOL, i.b, 0};
    append_merging(code, i, entered);
  }
}

// "X; EOL", X an instruction that goes on to the next and may carry the mark, the EOL neither
// entered nor a source line's start: X with the line-end mark, the line ending as it did
// without a dispatch of its own. (After a branch the EOL ends the line on one path only.)
void mark_line_ends(std::vector<Instr>& code, const std::vector<bool>& entered,
                    const std::vector<bool>& line_start) {
  std::vector<Instr> out;
  out.reserve(code.size());
  for (const Instr& i : code) {
    Instr* last = out.empty() ? nullptr : &out.back();
    if (i.op == Op::EOL && last != nullptr && !entered[i.pc] && !line_start[i.pc] &&
        op_info(last->op).flow == Flow::Next && may_end_line(last->op) && !last->ends_line) {
      last->ends_line = true;
      continue;
    }
    out.push_back(i);
  }
  code = std::move(out);
}

// A jump to a JMP goes straight to its target; a jump-and-end-of-line to a RET becomes
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
    if (op_info(op).a != Operand::Target || enters_try(op)) continue;
    const uint32_t target = final_target(word_a(code[pc]));
    if (op == Op::JMPEOL && target < code.size() && word_op(code[target]) == Op::RET) {
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
  // Line-end marks put each line's end on its own instruction (a CUP loader's one instruction a
  // line); fusing would merge lines, so such code stays as it is.
  for (const Instr& i : in)
    if (word_ends_line(image.code[i.pc])) return stats;

  const size_t size = image.code.size();
  std::vector<bool> boundary = entered_places(in, image, size);
  std::vector<bool> line_start(size + 1, false);
  for (const LineEntry& l : image.lines)
    if (l.code <= size) line_start[l.code] = true;
  mark_after_target_eols(in, line_start, boundary);

  // One pass, longest patterns first.
  std::vector<Instr> out;
  const Fuser fuser(in, boundary, line_start, image.constants.size() + in.size() <= 0xFFFF);
  for (size_t i = 0; i < in.size();) {
    if (auto m = fuser.match(i)) {
      if (m->first.wants_constant) {
        const Constant k{ValueType::Int, static_cast<uint32_t>(m->first.constant)};
        const uint32_t index = image.constant_index(k);
        m->first.b = m->first.constant_is_b ? index : pack_locals(packed_first(m->first.b), index);
      }
      out.push_back(m->first);
      i += m->second;
      ++stats.fused;
    } else {
      out.push_back(in[i++]);
    }
  }

  fold_accumulations(out, boundary);
  fuse_memory_frames(out, boundary, line_start);
  // A jump dropped may leave the place it went to unentered: again until nothing changes.
  for (size_t before = out.size() + 1; out.size() < before;) {
    before = out.size();
    drop_dead_code(out, image, size);
  }
  mark_line_ends(out, boundary, line_start);

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
  // A place that was inside a fused sequence cannot be referenced (it was no boundary), so
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
