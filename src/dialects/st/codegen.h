// The ST code generator: one image for the whole file. Globals in declaration order (the 32
// user variables first; a DLONG is two words), a routine per program and function with two
// scratch locals and one per FOR bound, a task record per program, an EOL after every
// statement and condition (the drive's line), the texts of PRINTF and COMMAND.
#pragma once
#include <string>

#include "bytecode/image.h"
#include "dialects/st/ast.h"
#include "dialects/st/locator.h"

namespace uprog::st {

bytecode::Image generate(const Program& program, const Locator& locator, const std::string& source_name);

}  // namespace uprog::st
