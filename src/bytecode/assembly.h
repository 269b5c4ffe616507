// The text form of an image (uprog assembly): disassemble() prints every part of an image so
// that assemble() rebuilds it exactly. The grammar is in docs/assembly.md.
#pragma once
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "support/diagnostic.h"

namespace uprog::bytecode {

std::string disassemble(const Image& image);

// Diagnostics use scheme "asm"; false when there was an error.
bool assemble(const std::string& text, const std::string& file, Image& out,
              std::vector<Diagnostic>& errors);

}  // namespace uprog::bytecode
