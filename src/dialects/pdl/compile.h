// The PDL compiler's entry points: a source file (or text) to an image with diagnostics.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "support/diagnostic.h"
#include "support/source.h"

namespace uprog::pdl {

struct CompileOptions {
  bool check_only = false;
  uint64_t created_unix_s = 0;
  size_t max_errors = 30;
  // #include reads files from disk (regular files up to kMaxIncludeBytes); false: none is read
  // (every #include is [pdl 102]), for fuzzing and for text that is not the user's.
  bool read_includes = true;
};

constexpr uintmax_t kMaxIncludeBytes = 1u << 20;

struct CompileResult {
  bytecode::Image image;
  std::vector<Diagnostic> diagnostics;
  bool ok() const;
};

CompileResult compile(const SourceFile& source, const CompileOptions& options = {});
CompileResult compile_file(const std::string& path, const CompileOptions& options = {});

}  // namespace uprog::pdl
