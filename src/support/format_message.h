// The C-style formatter of what programs print (PDL's printl, ST's PRINTF): a format and the
// raw 32-bit words a MSG instruction sent. Hosted: the VM passes the words, the firmware calls
// this.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "support/value.h"

namespace uprog {

// C's conversions on 32-bit words: %d %i (int), %u %x %X (the word unsigned), %c (its low
// byte), %f %e %E %g %G (the word as a float32), each with flags (- + space # 0), a width and
// a precision (each capped at kMaxFormatWidth), and an optional, meaningless `l`; %% is a %.
// %s takes the words that the conversions after it leave, and prints their bytes, low byte
// first, up to a NUL. A missing word reads as 0; words left over are ignored; anything else
// after a % (%n, %p, %*d, an unknown letter) is printed as it stands.
std::string format_message(std::string_view format, const Value* args, size_t count);

constexpr int kMaxFormatWidth = 255;

}  // namespace uprog
