// How the Gold command line shows a number (manual 1.3.2), as one rule: integers in decimal;
// floats whole and below 1e7 with one decimal ("3.0"), others with six ("3.600000"), and from
// 1e7 up in e-notation with a two-digit unsigned exponent ("1.234568e07").
#pragma once
#include <cstdint>
#include <string>

namespace uprog::gold {

std::string format_gold_int(int32_t value);
std::string format_gold_float(float value);

}  // namespace uprog::gold
