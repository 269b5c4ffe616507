// The PDL compiler driver: the shared preprocessor with PDL's options, the tokenizer, the
// one-pass compiler, then the peephole pass.
#include "dialects/pdl/compile.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <tuple>

#include "bytecode/peephole.h"
#include "dialects/pdl/compiler.h"
#include "preproc/preprocess.h"
#include "preproc/source_locator.h"
#include "support/files.h"

namespace uprog::pdl {
namespace {

int preproc_code(preproc::PreprocError e) {
  if (e == preproc::PreprocError::IncludeNotFound) return static_cast<int>(Error::IncludeNotFound);
  if (e == preproc::PreprocError::IncludeTooDeep) return static_cast<int>(Error::IncludeTooDeep);
  return static_cast<int>(Error::PreprocDirective);
}

const char* preproc_text(preproc::PreprocError e) {
  using P = preproc::PreprocError;
  switch (e) {
    case P::IdentifierMissing:
      return "#define needs a name";
    case P::InvalidIdentifier:
      return "not a valid macro name";
    case P::AlreadyDefined:
      return "macro already defined";
    case P::ConditionMissing:
      return "condition missing";
    case P::MisplacedElse:
      return "#else outside #ifdef/#ifndef, or twice";
    case P::NotDefined:
      return "#undef of a name that is not defined";
    case P::MismatchedType:
      return "condition of the wrong type";
    case P::TooManyDefines:
      return "too many #define directives";
    case P::MisplacedEndif:
      return "#endif without #ifdef/#ifndef";
    case P::UnterminatedIf:
      return "#ifdef/#ifndef without #endif";
    case P::TooManyElseifs:
      return "too many branches";
    case P::UnknownDirective:
      return "directive not supported";
    case P::DivisionByZero:
      return "division by zero";
    case P::ExpansionTooComplex:
      return "macro expansion too deep or too long";
    case P::IncludeNotFound:
      return "cannot include the file";
    case P::IncludeTooDeep:
      return "#include nested more than 20 deep";
  }
  return "preprocessor error";
}

// An included file: a regular file of at most kMaxIncludeBytes (not a device or a pipe, which
// might never end).
std::optional<std::string> read_include(const std::string& path, std::string* why) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    *why = std::filesystem::exists(path, ec) ? "not a regular file" : "no such file";
    return std::nullopt;
  }
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxIncludeBytes) {
    *why = "larger than " + std::to_string(kMaxIncludeBytes) + " bytes";
    return std::nullopt;
  }
  return read_text_file(path, why);
}

std::optional<std::string> no_include(const std::string&, std::string* why) {
  *why = "this compilation reads no files";
  return std::nullopt;
}

}  // namespace

bool CompileResult::ok() const {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return false;
  return true;
}

CompileResult compile(const SourceFile& source, const CompileOptions& options) {
  CompileResult result;
  preproc::PreprocOptions po;
  po.scheme = "pdl";
  po.code_of = preproc_code;
  po.text_of = preproc_text;
  po.star_star_comments = false;
  po.undefined_identifier_is_zero = true;
  po.undef_of_undefined_ignored = true;  // 2.5.3 (11): the directives are C's
  po.identical_redefinition_allowed = true;
  po.unknown_hash_lines_pass_through = true;
  po.max_name_length = 24;
  po.allow_elifdef = true;
  po.allow_function_macros = true;
  po.allow_include = true;
  po.max_include_depth = 20;  // 1.1
  po.backslash_separates = true;
  po.read_file = no_include;
  if (options.read_includes) {
    po.include_folders = options.includes.folders;
    po.read_file = [&includes = options.includes](const std::string& path, std::string* why) {
      return includes.read(path, why, read_include);
    };
  }
  DiagnosticList pre_diags;
  const bool preprocess = source.text.find('#') != std::string::npos;
  preproc::Preprocessed pre;
  if (preprocess) pre = preproc::preprocess(source, po, pre_diags);
  const std::string& text = preprocess ? pre.text : source.text;
  std::vector<Diagnostic> diags = pre_diags.items();
  for (Diagnostic& d : diags) d.scheme = "pdl";

  std::vector<LexError> lex_errors;
  std::vector<Token> tokens = tokenize(text, lex_errors);
  const preproc::SourceLocator locator(source.name, text, preprocess ? &pre.map : nullptr);
  const auto locate = [&locator](size_t offset) { return locator.locate(offset); };
  for (const LexError& e : lex_errors)
    diags.push_back(make_diagnostic(e.error, locate(e.offset), e.detail));
  Compiler compiler(std::move(tokens), locate, source.name);
  bytecode::Image image;
  const bool ok = compiler.compile(image) && diags.empty();
  // A line whose characters did not lex gets no second error from the parser.
  std::vector<std::pair<std::string, int>> bad_lines;
  for (const Diagnostic& d : diags) bad_lines.emplace_back(d.where.file, d.where.line);
  for (Diagnostic& d : compiler.diagnostics()) {
    const std::pair<std::string, int> line{d.where.file, d.where.line};
    if (std::find(bad_lines.begin(), bad_lines.end(), line) == bad_lines.end())
      diags.push_back(std::move(d));
  }
  // By place: the source's own first, then each included file's, by name.
  std::stable_sort(diags.begin(), diags.end(), [&source](const Diagnostic& a, const Diagnostic& b) {
    const auto key = [&source](const Diagnostic& d) {
      const bool included = d.where.file != source.name;
      return std::tuple<bool, const std::string&, int, int>(included, d.where.file, d.where.line,
                                                            d.where.column);
    };
    return key(a) < key(b);
  });
  limit_errors(diags, options.max_errors);
  result.diagnostics = std::move(diags);
  if (ok && result.ok() && !options.check_only) {
    image.source_name = source.name;
    image.created_unix_s = options.created_unix_s;
    // The peephole pass moves code words and keeps routine entries where they go: the debug
    // info's code words ride along as routines for the time of the pass (they are all jump
    // targets already, so nothing fuses differently).
    DebugInfo info = compiler.debug_info();
    const std::vector<uint32_t*> words = info.code_words();
    const size_t routines = image.routines.size();
    for (uint32_t* word : words) {
      bytecode::Routine carrier;
      carrier.name = "(debug)";
      carrier.entry = *word;
      image.routines.push_back(std::move(carrier));
    }
    bytecode::optimize(image);
    for (size_t i = 0; i < words.size(); ++i) *words[i] = image.routines[routines + i].entry;
    image.routines.resize(routines);
    for (std::string& line : info.info_lines()) image.info.push_back(std::move(line));
    result.image = std::move(image);
  }
  attach_source_lines(result.diagnostics, source);
  return result;
}

CompileResult compile_file(const std::string& path, const CompileOptions& options) {
  std::string why;
  std::optional<std::string> text = read_text_file(path, &why);
  if (!text) {
    CompileResult r;
    r.diagnostics.push_back(
        make_diagnostic(Error::Syntax, Location{path, 0, 0}, "cannot read: " + why));
    return r;
  }
  return compile(SourceFile{path, std::move(*text)}, options);
}

}  // namespace uprog::pdl
