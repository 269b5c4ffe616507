// The C-like preprocessor every dialect shares (#define, #undef, #if/#elseif/#else/#endif,
// #ifdef/#ifndef, #include where a dialect has it), with per-dialect options. Its output keeps
// a map back to the original text, so a diagnostic points at the file, line and column the
// user wrote.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/diagnostic.h"
#include "support/source.h"

namespace uprog::preproc {

// What went wrong, independent of any dialect; PreprocOptions maps each to the dialect's code.
enum class PreprocError {
  IdentifierMissing,    // #define without a name (Gold 87)
  InvalidIdentifier,    // #define 2PI (Gold 88)
  AlreadyDefined,       // #define NUM twice (Gold 89)
  ConditionMissing,     // #if without a condition (Gold 90)
  MisplacedElse,        // #else/#elseif outside #if, twice, or not last (Gold 92)
  NotDefined,           // #undef of an unknown name (Gold 93)
  MismatchedType,       // a condition that is neither int nor float (Gold 94)
  TooManyDefines,       // more than max_defines (Gold 95)
  MisplacedEndif,       // #endif without #if (Gold 96)
  UnterminatedIf,       // end of file inside #if
  TooManyElseifs,       // more than max_elseifs in one #if block
  UnknownDirective,     // a directive this dialect does not have (or that is switched off)
  DivisionByZero,       // #if 1/0 (Gold 86)
  ExpansionTooComplex,  // macro expansion deeper than max_expansion_depth or longer than
                        // max_expansion_chars (Gold 39, "Code is too complex")
  IncludeNotFound,      // #include of a file that cannot be read, or without a "name" / <name>
  IncludeTooDeep,       // #include nested deeper than max_include_depth (a file including itself)
};

// Gold's code and text for each PreprocError: the defaults when PreprocOptions leaves them null.
int gold_code_of(PreprocError e);
const char* gold_text_of(PreprocError e);

// What a dialect's preprocessor accepts. The defaults are Gold's (manual 2.8-2.10).
struct PreprocOptions {
  std::string scheme = "gold";  // the diagnostics' scheme
  int max_defines = 100;        // #define directives per program (Gold 95 beyond)
  int max_elseifs = 50;         // #elseif directives per #if block
  size_t max_name_length = 32;  // characters in a #define name
  // The dialect's code and text for each PreprocError (null: gold_code_of / gold_text_of).
  int (*code_of)(PreprocError) = nullptr;
  const char* (*text_of)(PreprocError) = nullptr;

  // Where identifiers are not replaced: the dialect's comments and strings.
  bool slash_slash_comments = true;  // `// to end of line`
  bool star_star_comments = true;    // `** to end of line` (Gold's interpreter comment marker)
  bool block_comments = true;        // `/* ... */`, may span lines
  char string_quote = '"';           // 0: the dialect has no string literals

  // An identifier in #if/#elseif that is not defined with a value: false gives Gold 94
  // (manual 2.10 allows only numbers and #define values); true counts it as 0, as C does.
  bool undefined_identifier_is_zero = false;
  // C's rules (C17 6.10.3 p2, 6.10.3.5 p2), where the dialect's manual says its directives are
  // C's (HIWIN PDL 2.5.3): `#undef` of a name not defined is ignored, and a `#define` that repeats
  // a macro's definition (the same parameters and body, whitespace aside) is accepted. Gold's
  // manual makes both errors (93, 89).
  bool undef_of_undefined_ignored = false;
  bool identical_redefinition_allowed = false;
  // A `#word` line that is no directive: Gold has labels (`#start`, manual 2.6), so it passes
  // to the dialect untouched; false reports UnknownDirective.
  bool unknown_hash_lines_pass_through = true;
  // Bounds that keep hostile input finite (`#define A B B`, `#define B C C`, ...).
  int max_expansion_depth = 64;
  size_t max_expansion_chars = 1 << 16;  // per use of a macro in the text

  // Names the dialect knows before the source (ST: the drive's parameters and the program's
  // variables): true when `name` is one, with its value where it has one (#if reads it, #ifdef
  // finds it). Null: none.
  // `line` is the asking directive's (a name the source declares may count only below it).
  std::function<bool(std::string_view name, std::optional<int32_t>& value, int line)> predefined;

  // Extension points for later dialects. Each switch names a directive; while it is off the
  // directive is UnknownDirective. Switching one on whose handler is not written yet in
  // preprocess.cpp's directive table still gives UnknownDirective ("not implemented").
  bool allow_include = false;  // #include "file" / <file> (HIWIN PDL): implemented
  // #include: files nested at most this deep (the source itself is depth 0), found beside the
  // file that includes them (or as given, when absolute); read_file reads one (null: from disk).
  int max_include_depth = 20;
  bool backslash_separates = false;  // `#include "..\common.h"` (HIWIN's manual, 2.5.6)
  std::function<std::optional<std::string>(const std::string& path, std::string* why)> read_file;
  // Folders where a relative #include name not found beside its includer is looked for next.
  std::vector<std::string> include_folders;
  bool allow_function_macros = false;  // #define F(a, b) ... with `\` continuation (HIWIN PDL)
  bool allow_elifdef = false;          // #elifdef / #elifndef (HIWIN PDL): implemented
  bool allow_definevar = false;        // #definevar NAME GenData[N] (Akribis PUP)
  bool allow_information = false;      // #information text (Akribis PUP)
};

// One stretch of output text that came from a macro expansion. A string macro's replacement is
// rescanned; names it expands are part of the outermost use's stretch, not expansions of their own.
struct Expansion {
  size_t begin = 0, end = 0;  // output offsets [begin, end)
  std::string macro;
  Location used_at;     // where the identifier stood in the source
  Location defined_at;  // the #define line
};

class SourceMap {
 public:
  // The original place of output offset `offset` (inside an expansion: where it was used).
  // Two binary searches; columns count bytes from 1. Past the end: the end of the last line.
  Location locate(size_t offset) const;
  // The expansion that produced `offset`, or nullptr.
  const Expansion* expansion_at(size_t offset) const;

  // Filled by the preprocessor. A segment per source line at least, so it holds no file name,
  // only an index (0: `file`, k: included[k - 1]): no string is built per line.
  struct Segment {
    size_t out_begin;  // output offset where this segment starts
    int line, column;  // original place of its first character; columns advance one by one
    uint32_t file = 0;
  };
  std::string file;
  std::vector<std::string> included;  // the #include'd files, as their diagnostics name them
  std::vector<Segment> segments;      // sorted by out_begin
  const std::string& file_name(uint32_t index) const {
    return index == 0 ? file : included[index - 1];
  }
  std::vector<Expansion> expansions;
};

struct Preprocessed {
  std::string text;  // what the dialect's lexer reads: directives removed, macros expanded
  SourceMap map;
};

Preprocessed preprocess(const SourceFile& source, const PreprocOptions& options,
                        DiagnosticList& diagnostics);

}  // namespace uprog::preproc
