// The PDL compiler's entry points: a source file (or text) to an image with diagnostics.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "dialects/pdl/debug_info.h"
#include "support/diagnostic.h"
#include "support/include_search.h"
#include "support/source.h"

namespace uprog::pdl {

struct CompileOptions {
  bool check_only = false;
  uint64_t created_unix_s = 0;
  size_t max_errors = 30;
  // #include reads files from disk (regular files up to kMaxIncludeBytes); false: none is read
  // (every #include is [pdl 102]), for fuzzing and for text that is not the user's.
  bool read_includes = true;
  // Where #include looks after the includer's folder, and what an editor holds open unsaved.
  IncludeSearch includes;
};

constexpr uintmax_t kMaxIncludeBytes = 1u << 20;

struct CompileResult {
  bytecode::Image image;
  std::vector<Diagnostic> diagnostics;
  bool ok() const;
};

CompileResult compile(const SourceFile& source, const CompileOptions& options = {});
CompileResult compile_file(const std::string& path, const CompileOptions& options = {});

// For the debugger: one expression, condition or assignment (`set PLACE = value`, `x += 1`) in
// the variables of `program` and of a procedure frame (`frame`, null in task code), compiled into
// an image with the program's globals whose routine 0 leaves the value in its last global.
struct EvaluationCode {
  bool ok = false;
  bytecode::Image image;
  bool is_float = false;
  std::string error;  // the first diagnostic's text, when !ok
};
EvaluationCode compile_evaluation(std::string_view text, const bytecode::Image& program,
                                  const ProcInfo* frame);

}  // namespace uprog::pdl
