// CUP's operations as VM instructions (cup_code.h).
#include "dialects/pup/cup_code.h"

#include <map>
#include <optional>

#include "dialects/pup/cup_math.h"

namespace uprog::pup {

using bytecode::Op;

namespace {

// One opcode for AMath[n] (ADDI for 1 …), or nullopt where it takes several or the firmware.
std::optional<Op> native_math(int32_t n) {
  static const std::map<int32_t, Op> kNative = {
      {1, Op::ADDI},  {2, Op::MULI},  {3, Op::SUBI},  {4, Op::DIVI}, {5, Op::REMI},
      {6, Op::NEGI},  {7, Op::ABSI},  {10, Op::ANDI}, {11, Op::ORI}, {12, Op::XORI},
      {13, Op::NOTI}, {14, Op::SHLI}, {15, Op::SHRI}, {22, Op::LNOT}};
  if (auto it = kNative.find(n); it != kNative.end()) return it->second;
  return std::nullopt;
}

bool is_logical(int32_t n) { return n == 20 || n == 21; }

}  // namespace

bool math_in_vm(int32_t n) { return native_math(n).has_value() || is_logical(n); }

bool emit_math(bytecode::CodeBuilder& b, int32_t n) {
  if (auto op = native_math(n)) {
    b.emit(*op);
    return true;
  }
  if (const auto f = intrinsic_of(n)) {
    b.emit(Op::INTRIN, static_cast<uint32_t>(*f));
    return true;
  }
  if (!is_logical(n)) return false;
  // Logical and/or: both operands to 0/1 first.
  b.emit_imm(Op::PUSHI, 0), b.emit(Op::CMPI, bytecode::kRelNe), b.emit(Op::SWAP),
      b.emit_imm(Op::PUSHI, 0), b.emit(Op::CMPI, bytecode::kRelNe);
  b.emit(n == 20 ? Op::ANDI : Op::ORI);
  return true;
}

void emit_condition(bytecode::CodeBuilder& b, int32_t c) {
  using namespace bytecode;
  static constexpr uint32_t kRelations[] = {kRelEq, kRelNe, kRelGt, kRelGe, kRelLt, kRelLe};
  if (c >= 3 && c <= 8) return b.emit(Op::CMPI, kRelations[c - 3]);
  b.emit_imm(Op::PUSHI, 0);
  b.emit(Op::CMPI, c == 2 ? kRelGt : c == 9 ? kRelEq : kRelNe);
}

}  // namespace uprog::pup
