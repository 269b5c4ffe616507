// The text form of an image (uprog assembly): disassemble() prints every part of an image so
// that assemble() rebuilds it exactly. The grammar is in docs/assembly.md.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "support/diagnostic.h"

namespace uprog::bytecode {

// `notes`, when given, has a note for each code word ("" for none) that ends the instruction
// starting there as a comment (`uprog build --emit asm --quickened`: the VM's fused instruction).
std::string disassemble(const Image& image, std::span<const std::string> notes = {});

// Diagnostics use scheme "asm"; false when there was an error.
bool assemble(const std::string& text, const std::string& file, Image& out,
              std::vector<Diagnostic>& errors);

}  // namespace uprog::bytecode
