// Quickening: the fused instructions of vm/fused.def formed in place in verified base code when
// a machine loads an image (Machine::load), and the base instruction a word was (fused.h).
#pragma once
#include <cstdint>
#include <span>

#include "bytecode/image_view.h"

namespace uprog::vm {

// The words of the bitmap quicken() needs for code of `code_size` words.
constexpr uint32_t quicken_scratch_words(uint32_t code_size) { return (code_size + 31) / 32; }

// Rewrites the first word of every sequence that matches a fused instruction's pattern, where
// no instruction after the first is a place control arrives at (a jump or catch target, a
// routine's entry, a line's start) and no word but the last ends a line. `code` is `image`'s
// verified code, copied; `scratch` has quicken_scratch_words(size) words. Returns how many
// instructions it formed.
uint32_t quicken(uint32_t* code, uint32_t size, const bytecode::ImageView& image,
                 uint32_t* scratch);
// The same for code that is no image's (a loader's piece): `entries` are its routines' entries
// and its lines' starts.
uint32_t quicken(uint32_t* code, uint32_t size, std::span<const uint32_t> entries,
                 uint32_t* scratch);

}  // namespace uprog::vm
