// What a dialect offers: its name and file extensions, its compiler (source file → the stored
// form the drive keeps, with diagnostics), its registered error tables, and its firmware. The
// one list of dialects is src/dialects/registry.def; nothing registers itself.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bytecode/image.h"
#include "dialect/firmware.h"
#include "dialect/outline.h"
#include "dialect/reference.h"
#include "dialect/runtime.h"
#include "support/diagnostic.h"
#include "support/include_search.h"
#include "support/source.h"

namespace uprog::dialect {

// One registered code of a list (a compile diagnostic, an interpreter error).
struct ErrorInfo {
  int32_t code;
  std::string_view name;
  std::string_view text;
};

struct CompileSettings {
  bool check_only = false;      // diagnostics only (`uprog check`): no stored form is built
  uint64_t created_unix_s = 0;  // stored where the form has a date; 0 keeps builds reproducible
  // `uprog check -D NAME=value`: names the preprocessor sees with a value (ST: a drive parameter's
  // value for #IF instead of its default); a dialect without such names ignores them.
  std::vector<std::pair<std::string, std::string>> defines;
  // #include (PDL, PUP): folders searched after the includer's, and an editor's unsaved texts.
  IncludeSearch includes;
};

struct CompileOutput {
  std::vector<uint8_t> stored_form;      // what is downloaded and stored; empty on errors
  std::optional<bytecode::Image> image;  // the image it loads into, where the compiler has it
  std::vector<Diagnostic> diagnostics;
  // The debug map of a stored form that carries no line table of its own (PUP's X.cup.json: the
  // source place of each CUP line, the variables' names), in the dialect's own JSON; empty for
  // none.
  std::string debug_map;
  bool ok() const {
    for (const Diagnostic& d : diagnostics)
      if (d.severity == Severity::Error) return false;
    return true;
  }
};

// A small program of the dialect and what a drive does with it: every registered dialect gives
// one, and every registered dialect passes the same checks with it (tests/dialect/
// conformance_test.cpp: compile, download as a host does, run, step cycle by cycle, refusals);
// its fuzzers start from it.
struct SampleProgram {
  std::string_view file_name;      // "sample.ehl": a name with one of the dialect's extensions
  std::string_view source;         // compiles clean; started, it makes `query` answer `answer`
  std::string_view entry;          // what Firmware::start() takes ("" for the dialect's own start)
  std::string_view query;          // a host line that reads what the program did
  std::string_view answer;         // its one answer once the program did it, and not before
  uint32_t max_cycles;             // the firmware cycles the program may take to do it
  std::string_view bad_source;     // a program the compiler refuses
  uint32_t bad_source_line;        // the line its first error names
  std::string_view bad_host_line;  // a line the command line refuses with a registered error
};

class Dialect {
 public:
  virtual ~Dialect() = default;
  virtual std::string_view name() const = 0;         // "gold": what --dialect and `dialect` take
  virtual std::string_view description() const = 0;  // one line for `uprog dialects`
  // Source extensions, with the dot (".ehl"); the first is the usual one.
  virtual std::span<const std::string_view> source_extensions() const = 0;
  // The extension of the stored form as `uprog build` writes it (".upi").
  virtual std::string_view stored_extension() const = 0;
  // Where `uprog build SOURCE` writes the stored form by default: SOURCE plus the extension
  // ("f.ehl.upi"); a dialect whose stored form replaces the source's extension says so.
  virtual std::string stored_path(const std::string& source) const {
    return source + std::string(stored_extension());
  }
  // The front end over a source in memory: preprocess, compile, build the stored form.
  // `source.name` places the diagnostics and resolves includes (relative to its folder).
  virtual CompileOutput compile_source(const SourceFile& source,
                                       const CompileSettings& settings) const = 0;
  // The same from a file: the one compile driver (dialect/compile_driver.h) reads it and calls
  // compile_source(); a file that cannot be read gets unreadable_source()'s diagnostic.
  CompileOutput compile_file(const std::string& path, const CompileSettings& settings) const;
  // The dialect's diagnostic for a source file that cannot be read (its own scheme and code).
  virtual Diagnostic unreadable_source(const std::string& path, const std::string& why) const = 0;
  virtual std::span<const ErrorInfo> diagnostic_codes() const = 0;
  virtual std::span<const ErrorInfo> interpreter_errors() const = 0;
  virtual std::unique_ptr<Firmware> make_firmware(Runtime& runtime,
                                                  const FirmwareOptions& options) const = 0;

  // The host's side: the command lines that download a stored form into a running drive, and
  // the one that then loads it to run ("" when storing is enough).
  virtual std::vector<std::string> download_lines(
      const std::vector<uint8_t>& stored_form) const = 0;
  virtual std::string load_line() const = 0;
  // How the drive splits a host's lines into expressions when it answers each of them once and
  // marks no line end (Gold's drive form): a host counts its answers with it. nullopt (the
  // default): the drive ends the answers to each line with the wire's line end.
  virtual std::optional<FramerOptions> host_framing() const { return std::nullopt; }
  // How a host reads the drive's own wire when the drive ends each line with a prompt (ST's
  // `-->`); nullopt (the default): the semicolon wire or host_framing().
  virtual std::optional<PromptWire> host_prompt() const { return std::nullopt; }
  // The largest stored form a drive takes over the wire.
  virtual std::size_t max_download_bytes() const = 0;
  // The dialect's sample program (SampleProgram above).
  virtual const SampleProgram& sample_program() const = 0;
  // Its reference for editors (dialect/reference.h): the language server's hover and
  // completion. Whether names are matched ignoring case, as the dialect's compiler does.
  virtual std::vector<ReferenceEntry> reference() const { return {}; }
  virtual bool names_ignore_case() const { return false; }
  // The declarations of a source as written (dialect/outline.h), for an editor's outline, go to
  // definition, references, rename and completion; none by default.
  virtual std::vector<SourceSymbol> outline(std::string_view /*text*/) const { return {}; }
  // How its comments and strings are written, for the words an editor looks at.
  virtual WordSyntax word_syntax() const { return {}; }
};

}  // namespace uprog::dialect
