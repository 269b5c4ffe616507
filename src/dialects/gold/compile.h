// The Gold compiler's public API: a source file to an image with diagnostics, and a command
// line to a tiny image whose shown values keep their run-time type.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "bytecode/image.h"
#include "dialects/gold/checker.h"
#include "dialects/gold/codegen.h"
#include "support/diagnostic.h"
#include "support/source.h"

namespace uprog::gold {

struct CompileOptions {
  // Errors printed before "Too many errors" (46). The manual gives no number.
  size_t max_errors = 30;
  bool preprocess = true;
  uint64_t created_unix_s = 0;  // stored in the image; 0 keeps builds reproducible
  bool optimize = true;         // run the peephole pass (bytecode/peephole.h)
  // Diagnostics only (`uprog check`): the same diagnostics as a build, but no peephole pass,
  // no line table, and an empty image.
  bool check_only = false;
  // Manual 2.17: "Maximum length of user program text and non-text: 64 Kilobytes (Code,
  // symbols, variables)": the source text and the image's binary form together; beyond it a
  // build is error 36. 0: no limit (benchmarks of large programs).
  size_t max_program_bytes = 65536;
};

struct CompileResult {
  bytecode::Image image;                // empty when there are errors
  std::vector<Diagnostic> diagnostics;  // "file:line:col: error: <text> [gold <code>]"
  bool ok() const;
};

CompileResult compile(const SourceFile& source, const CompileOptions& options = {});
// Reads the file first: "Open file failure" (54) when it cannot.
CompileResult compile_file(const std::string& path, const CompileOptions& options = {});

// The globals of a compiled program, for the command line.
std::vector<KnownGlobal> known_globals(const bytecode::Image& program);

struct CompiledLine {
  bytecode::Image image;          // routine 0 runs the line
  std::vector<LineValue> values;  // what the line shows, in order
  std::vector<Diagnostic> diagnostics;
  bool ok() const;
};

// "PX=7; PX-3", "3+4", "myvar=5": statements of one interpreter line (1.1).
CompiledLine compile_line(std::string_view line, const std::vector<KnownGlobal>& known = {});

}  // namespace uprog::gold
