// The 32-bit Value every layer passes around: an int32 or a float32, untagged.
// Whoever holds a Value knows its type (the compiler, an image's type bytes, a tag beside it).
#pragma once
#include <cstdint>
#include <cstring>

namespace uprog {

enum class ValueType : uint8_t { Int = 0, Float = 1 };

union Value {
  int32_t i;
  float f;
  uint32_t bits;

  static constexpr Value of_int(int32_t v) {
    Value x{};
    x.i = v;
    return x;
  }
  static Value of_float(float v) {
    Value x{};
    x.f = v;
    return x;
  }
  static constexpr Value of_bits(uint32_t v) {
    Value x{};
    x.bits = v;
    return x;
  }
};
static_assert(sizeof(Value) == 4, "a Value is one 32-bit word");

// A value with its type beside it, for the places where the type is known only at run time.
struct TypedValue {
  Value value;
  ValueType type;

  static constexpr TypedValue of_int(int32_t v) { return {Value::of_int(v), ValueType::Int}; }
  static TypedValue of_float(float v) { return {Value::of_float(v), ValueType::Float}; }
  bool is_float() const { return type == ValueType::Float; }
  float as_float() const { return is_float() ? value.f : static_cast<float>(value.i); }
};

}  // namespace uprog
