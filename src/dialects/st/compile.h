// The ST compiler's driver: the source limits (61 440 bytes, 255 characters a line), the shared
// preprocessor (#DEFINE #IF #IFDEF #IFNDEF #ELSE #ENDIF, drive parameters in #IF), lexer,
// parser, whole-file checks and code generation. The drive runs it at boot and on PLCRUN;
// `uprog check` and the tools run it on files.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bytecode/image.h"
#include "dialects/st/checker.h"
#include "support/diagnostic.h"
#include "support/source.h"

namespace uprog::st {

constexpr size_t kMaxSourceBytes = 61'440;
constexpr size_t kMaxLineLength = 255;

struct CompileOptions {
  bool check_only = false;
  uint64_t created_unix_s = 0;
  // A drive parameter's value at compile time, for #IF (the drive's: its current values;
  // `uprog check`: the table's defaults). Null: the defaults.
  std::function<std::optional<int32_t>(std::string_view name)> parameter;
  // `uprog check -D NAME=value`: a parameter's value instead of its default, or a name of its
  // own (as a #DEFINE) for #IF and #IFDEF.
  std::map<std::string, int32_t, std::less<>> defines;
};

struct CompileResult {
  bytecode::Image image;  // empty on errors or with check_only
  std::vector<Diagnostic> diagnostics;
  CheckResult sizes;  // the programs present and the load factor (also with errors after parsing)
  // Each image global's width in bits (8 BYTE, 16 WORD, 32 LONG, 64 DLONG): a host's write
  // into a variable is cut to its type as the program's own store is.
  std::vector<uint8_t> global_bits;
  bool ok() const;
};

CompileResult compile(const SourceFile& source, const CompileOptions& options = {});
CompileResult compile_file(const std::string& path, const CompileOptions& options = {});

}  // namespace uprog::st
