// The ST code generator: one image for the whole file. Globals in declaration order (the 32
// user variables first; a DLONG is two words), a routine per program and function with two
// scratch locals and one per FOR bound (none when it uses neither), a task record per
// program, an EOL after every statement and condition (the drive's line), the texts of PRINTF
// and COMMAND. PLCMAIN loops by itself and counts its passes in a last local of its own.
#pragma once
#include <string>
#include <string_view>

#include "bytecode/image.h"
#include "dialects/st/ast.h"
#include "preproc/source_locator.h"

namespace uprog::st {

// PLCMAIN's last local: the passes it has begun (the top of a pass adds one).
constexpr std::string_view kMainPassesLocal = "$PASSES";

bytecode::Image generate(const Program& program, const preproc::SourceLocator& locator,
                         const std::string& source_name);

}  // namespace uprog::st
