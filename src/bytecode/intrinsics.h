// The intrinsic functions' enum, arities and names, generated from intrinsics.def: what the
// verifier needs of INTRIN's operand, and the names for tools.
#pragma once
#include <cstdint>

namespace uprog::bytecode {

enum class Intrinsic : uint8_t {
#define INTRINSIC(name, pop, push, meaning) name,
#include "bytecode/intrinsics.def"
#undef INTRINSIC
};

struct IntrinsicInfo {
  int8_t pop;
  int8_t push;
};
inline constexpr IntrinsicInfo kIntrinsicInfo[] = {
#define INTRINSIC(name, pop, push, meaning) {pop, push},
#include "bytecode/intrinsics.def"
#undef INTRINSIC
};
inline constexpr const char* kIntrinsicNames[] = {
#define INTRINSIC(name, pop, push, meaning) #name,
#include "bytecode/intrinsics.def"
#undef INTRINSIC
};
inline constexpr const char* kIntrinsicMeanings[] = {
#define INTRINSIC(name, pop, push, meaning) meaning,
#include "bytecode/intrinsics.def"
#undef INTRINSIC
};
inline constexpr uint32_t kIntrinsicCount = sizeof(kIntrinsicInfo) / sizeof(kIntrinsicInfo[0]);

}  // namespace uprog::bytecode
