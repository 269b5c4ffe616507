// The PUP compiler: a .pup file and the .puh files it includes → a CUP program (cup_file.h),
// with the PUP place of every CUP line for the debug map, and the diagnostics.
#pragma once
#include <string>
#include <vector>

#include "dialects/pup/cup_file.h"
#include "dialects/pup/pup_expr.h"
#include "support/diagnostic.h"
#include "support/include_search.h"

namespace uprog::pup {

struct PupOutput {
  CupProgram program;
  std::vector<Location> places;  // per CUP line, where in the PUP sources it came from
  VarTable vars;                 // the #definevar names, for the debug map
  std::vector<Diagnostic> diagnostics;
  bool ok() const;
};

// `text` is the file's content; `path` names it (for diagnostics and #include).
// `includes`: where #include looks after the includer's and the .pup's folders, and what an
// editor holds open unsaved (the command line's default: the disk only).
PupOutput compile_pup(const std::string& path, const std::string& text, uint64_t created_unix_s,
                      const IncludeSearch& includes = {});
PupOutput compile_pup_file(const std::string& path, uint64_t created_unix_s);

}  // namespace uprog::pup
