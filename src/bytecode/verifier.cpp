// Abstract interpretation of the code over stack depths: a worklist walks every path from every
// routine entry (and every catch block), checking operands against the routine that reaches
// them. An instruction reached by several routines is rechecked with the smallest local count.
#include "bytecode/verifier.h"

#include <algorithm>

#include "bytecode/intrinsics.h"
#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

constexpr int32_t kNotStart = -2;  // the word is an operand, not an instruction
constexpr int32_t kUnseen = -1;

struct Scratch {
  int32_t* depth;       // per code word: kNotStart, kUnseen, or the depth on entry
  uint32_t* local_cap;  // per code word: the fewest locals of any routine reaching it
  uint32_t* work;       // worklist of pcs
  uint32_t work_size = 0;
};

class Verifier {
 public:
  Verifier(const ImageView& image, const VerifyLimits& limits, Scratch s)
      : image_(image), limits_(limits), s_(s), size_(image.code.size()) {}

  VerifyResult run() {
    if (size_ == 0) return fail(VerifyError::EmptyCode, 0);
    if (VerifyResult r = decode(); !r.ok()) return r;
    for (uint32_t i = 0; i < image_.routines.size(); ++i) {
      if (VerifyResult r = walk(i); !r.ok()) return r;
    }
    VerifyResult ok;
    ok.max_depth = max_depth_;
    return ok;
  }

  // The depth on entry to `pc` on the paths of routine `routine` alone; -1 when none reaches it.
  int32_t depth_at(uint32_t routine, uint32_t pc) {
    if (size_ == 0 || routine >= image_.routines.size() || pc >= size_) return -1;
    if (!decode().ok() || !walk(routine).ok()) return -1;
    return s_.depth[pc];  // kNotStart and kUnseen are negative
  }

 private:
  // Every path from routine i's entry (and the catch blocks it enters).
  VerifyResult walk(uint32_t i) {
    const RoutineRecord r = image_.routines[i];
    if (s_.depth[r.entry] == kNotStart) return fail(VerifyError::BadEntry, r.entry);
    if (VerifyResult res = reach(r.entry, 0, r.locals, r.entry); !res.ok()) return res;
    while (s_.work_size > 0) {
      if (VerifyResult res = step(s_.work[--s_.work_size]); !res.ok()) return res;
    }
    return {};
  }

  VerifyResult fail(VerifyError e, uint32_t pc) const {
    VerifyResult r;
    r.error = e;
    r.pc = pc;
    return r;
  }

  // Marks instruction starts; checks opcodes and the operands that need no context.
  VerifyResult decode() {
    for (uint32_t pc = 0; pc < size_; ++pc) s_.depth[pc] = kNotStart;
    uint32_t pc = 0;
    while (pc < size_) {
      const uint32_t word = image_.code[pc];
      if ((word & 0xFFu) >= kOpCount) return fail(VerifyError::BadOpcode, pc);
      const Op op = word_op(word);
      if (op == Op::BREAK) return fail(VerifyError::BreakInImage, pc);
      if (word_ends_line(word) && !may_end_line(op)) return fail(VerifyError::BadLineEnd, pc);
      const uint32_t length = op_length(op);
      if (length > size_ - pc) return fail(VerifyError::Truncated, pc);
      s_.depth[pc] = kUnseen;
      s_.local_cap[pc] = UINT32_MAX;
      pc += length;
    }
    for (pc = 0; pc < size_; pc += op_length(word_op(image_.code[pc]))) {
      const uint32_t word = image_.code[pc];
      const OpInfo& info = op_info(word_op(word));
      const uint32_t a = word_a(word);
      switch (info.a) {
        case Operand::Const:
          if (a >= image_.constants.size()) return fail(VerifyError::BadConstant, pc);
          break;
        case Operand::Global:
          if (a >= image_.globals.size()) return fail(VerifyError::BadGlobal, pc);
          break;
        case Operand::Routine:
          if (a >= image_.routines.size()) return fail(VerifyError::BadRoutine, pc);
          break;
        case Operand::Target:
          if (a >= size_ || s_.depth[a] == kNotStart) return fail(VerifyError::BadTarget, pc);
          break;
        case Operand::Unit:
          if (a == 0) return fail(VerifyError::BadOperand, pc);
          break;
        case Operand::Width:
          if (a == 0 || a > 31) return fail(VerifyError::BadOperand, pc);
          break;
        case Operand::Text:
          if (a >= image_.texts.size()) return fail(VerifyError::BadOperand, pc);
          break;
        default:
          break;
      }
      if (names_relation(word_op(word)) && a >= kRelationCount)
        return fail(VerifyError::BadOperand, pc);
      if (info.a == Operand::Intrinsic && a >= kIntrinsicCount)
        return fail(VerifyError::BadOperand, pc);
      if (info.b == Operand::Const && image_.code[pc + 1] >= image_.constants.size())
        return fail(VerifyError::BadConstant, pc);
      if (info.b != Operand::None) {
        if (VerifyResult r = check_global_b(info.b, image_.code[pc + 1], pc); !r.ok()) return r;
      }
      if (info.b == Operand::Element && image_.code[pc + 1] >= image_.globals[a].length)
        return fail(VerifyError::BadOperand, pc);
      if (info.b == Operand::Window &&
          window_first(image_.code[pc + 1]) + window_size(image_.code[pc + 1]) >
              image_.globals[a].length)
        return fail(VerifyError::BadOperand, pc);
      if (info.b == Operand::Lines && image_.code[pc + 1] == 0)
        return fail(VerifyError::BadOperand, pc);
      if (word_op(word) == Op::CALL) {
        const RoutineRecord callee = image_.routines[a];
        if (image_.code[pc + 1] > callee.outputs) return fail(VerifyError::BadOperand, pc);
      }
      // A restart drops every frame and starts its routine with nothing on the stack: a routine
      // with inputs would take them from below the stack.
      if (word_op(word) == Op::RESET && image_.routines[a].inputs != 0)
        return fail(VerifyError::BadOperand, pc);
      if (word_op(word) == Op::CALLFEOL) {
        const uint32_t b = image_.code[pc + 1];
        if (image_.routines[a].inputs < 2 || b > pack_memory_frame(kMemoryFrameMax, 0xFF, 0xFF) ||
            memory_frame_first(b) + memory_frame_arguments(b) > memory_frame_words(b))
          return fail(VerifyError::BadOperand, pc);
      }
      if (pops_host_arguments(word_op(word)) && image_.code[pc + 1] > limits_.max_stack)
        return fail(VerifyError::BadOperand, pc);
    }
    return {};
  }

  // A B operand that names globals (and a constant): every index in range. The image's
  // globals all have at least one element (the loader refuses a length of 0), so element 0,
  // which these opcodes read and write, exists.
  VerifyResult check_global_b(Operand kind, uint32_t b, uint32_t pc) const {
    const size_t globals = image_.globals.size();
    switch (kind) {
      case Operand::Global:
        if (b >= globals) return fail(VerifyError::BadGlobal, pc);
        break;
      default:
        break;
    }
    return {};
  }

  // Records that `pc` is reached with `depth` by a routine with `locals` locals.
  VerifyResult reach(uint32_t pc, int32_t depth, uint32_t locals, uint32_t from) {
    if (pc >= size_) return fail(VerifyError::FallsOffEnd, from);
    int32_t& seen = s_.depth[pc];
    if (seen == kNotStart) return fail(VerifyError::BadTarget, from);
    if (seen == kUnseen) {
      seen = depth;
    } else if (seen != depth) {
      return fail(VerifyError::StackMismatch, pc);
    } else if (locals >= s_.local_cap[pc]) {
      return {};  // already checked under a tighter local count
    }
    s_.local_cap[pc] = locals;
    if (s_.work_size >= size_) return fail(VerifyError::NoScratch, pc);
    s_.work[s_.work_size++] = pc;
    return {};
  }

  VerifyResult step(uint32_t pc) {
    const uint32_t word = image_.code[pc];
    const Op op = word_op(word);
    const OpInfo& info = op_info(op);
    const uint32_t a = word_a(word);
    const uint32_t locals = s_.local_cap[pc];
    const int32_t depth = s_.depth[pc];

    if (info.a == Operand::Local && a >= locals) return fail(VerifyError::BadLocal, pc);
    if (info.b == Operand::Local && image_.code[pc + 1] >= locals)
      return fail(VerifyError::BadLocal, pc);

    int32_t pop = info.pop;
    int32_t push = info.push;
    if (op == Op::CALL) {
      pop = static_cast<int32_t>(image_.routines[a].inputs);
      push = static_cast<int32_t>(image_.code[pc + 1]);
    } else if (op == Op::CALLFEOL) {
      // The callee's inputs but the last are the caller's first locals, and 0 and 1 are read.
      if (std::max<uint32_t>(image_.routines[a].inputs - 1, 2) > locals)
        return fail(VerifyError::BadLocal, pc);
      pop = static_cast<int32_t>(memory_frame_arguments(image_.code[pc + 1]));
    } else if (op == Op::INTRIN) {
      pop = kIntrinsicInfo[a].pop;
      push = kIntrinsicInfo[a].push;
    } else if (pops_host_arguments(op)) {
      pop = static_cast<int32_t>(image_.code[pc + 1]) + (op == Op::CMDRUNX ? 1 : 0);
    }
    if (depth < pop) return fail(VerifyError::StackUnderflow, pc);
    const int32_t after = depth - pop + push;
    const int32_t peak = depth > after ? depth : after;
    if (peak > static_cast<int32_t>(limits_.max_stack)) return fail(VerifyError::StackOverflow, pc);
    if (static_cast<uint32_t>(peak) > max_depth_) max_depth_ = static_cast<uint32_t>(peak);

    const uint32_t next = pc + op_length(op);
    switch (info.flow) {
      case Flow::Next:
      case Flow::Call:
        if (enters_try(op)) {
          if (VerifyResult r = reach(a, after, locals, pc); !r.ok()) return r;
        }
        return reach(next, after, locals, pc);
      case Flow::Jump:
        return reach(a, after, locals, pc);
      case Flow::Branch: {
        if (VerifyResult r = reach(a, after, locals, pc); !r.ok()) return r;
        return reach(next, after, locals, pc);
      }
      case Flow::Stop:
        if (op == Op::RET && depth != 0) return fail(VerifyError::ReturnWithValues, pc);
        return {};
    }
    return {};
  }

  const ImageView& image_;
  VerifyLimits limits_;
  Scratch s_;
  uint32_t size_;
  uint32_t max_depth_ = 0;
};

}  // namespace

const char* verify_error_text(VerifyError e) {
  switch (e) {
    case VerifyError::Ok:
      return "ok";
    case VerifyError::EmptyCode:
      return "the image has no code";
    case VerifyError::BadOpcode:
      return "unknown opcode";
    case VerifyError::Truncated:
      return "an instruction runs past the end of the code";
    case VerifyError::BreakInImage:
      return "a breakpoint instruction in an image";
    case VerifyError::BadConstant:
      return "constant index out of range";
    case VerifyError::BadGlobal:
      return "global index out of range";
    case VerifyError::BadLocal:
      return "local index out of range for the routine";
    case VerifyError::BadRoutine:
      return "routine index out of range";
    case VerifyError::BadTarget:
      return "jump target is not an instruction";
    case VerifyError::BadOperand:
      return "operand out of range";
    case VerifyError::BadEntry:
      return "routine entry is not an instruction";
    case VerifyError::StackUnderflow:
      return "expression stack underflow";
    case VerifyError::StackOverflow:
      return "expression stack deeper than the limit";
    case VerifyError::StackMismatch:
      return "paths join with different stack depths";
    case VerifyError::FallsOffEnd:
      return "a path falls off the end of the code";
    case VerifyError::ReturnWithValues:
      return "return with values left on the stack";
    case VerifyError::NoScratch:
      return "verifier scratch memory too small";
    case VerifyError::BadLineEnd:
      return "a line end on an instruction that cannot end a line";
  }
  return "unknown verifier error";
}

size_t verify_scratch_size(const ImageView& image) {
  return static_cast<size_t>(image.code.size()) * (sizeof(int32_t) + 2 * sizeof(uint32_t));
}

namespace {

Scratch scratch_of(const ImageView& image, void* scratch) {
  const size_t n = image.code.size();
  auto* words = static_cast<uint32_t*>(scratch);
  return {reinterpret_cast<int32_t*>(words), words + n, words + 2 * n};
}

}  // namespace

VerifyResult verify(const ImageView& image, const VerifyLimits& limits, void* scratch,
                    size_t scratch_size) {
  if (scratch == nullptr || scratch_size < verify_scratch_size(image)) {
    VerifyResult r;
    r.error = image.code.size() == 0 ? VerifyError::EmptyCode : VerifyError::NoScratch;
    return r;
  }
  return Verifier(image, limits, scratch_of(image, scratch)).run();
}

bool stack_depth_at(const ImageView& image, const VerifyLimits& limits, uint32_t routine,
                    uint32_t pc, void* scratch, size_t scratch_size, uint32_t& depth) {
  if (scratch == nullptr || scratch_size < verify_scratch_size(image)) return false;
  const int32_t d = Verifier(image, limits, scratch_of(image, scratch)).depth_at(routine, pc);
  if (d < 0) return false;
  depth = static_cast<uint32_t>(d);
  return true;
}

}  // namespace uprog::bytecode
