// The compiler driver: preprocess, check line lengths, lex, parse, check, generate.
#include "dialects/gold/compile.h"

#include <sys/stat.h>

#include <cstdio>
#include <cstring>

#include "bytecode/image.h"
#include "bytecode/peephole.h"
#include "dialects/gold/lexer.h"
#include "dialects/gold/parser.h"
#include "dialects/gold/program_compiler.h"
#include "preproc/preprocess.h"
#include "support/files.h"

namespace uprog::gold {

namespace {

// Manual 2.7.2, error 51: a program line holds at most 128 characters.
constexpr size_t kMaxLineLength = 128;
// Manual 1.1: an interpreter expression holds at most 511 characters.
constexpr size_t kMaxCommandLine = 511;

// Stops after `limit` + 1: they come in the order of their places, so no later one is shown.
void check_line_lengths(const SourceFile& source, size_t limit, Reporter& reporter) {
  const std::string& t = source.text;
  int line = 1;
  size_t found = 0;
  for (size_t start = 0; start <= t.size() && found <= limit; ++line) {
    const void* nl = std::memchr(t.data() + start, '\n', t.size() - start);
    const size_t i =
        nl == nullptr ? t.size() : static_cast<size_t>(static_cast<const char*>(nl) - t.data());
    size_t end = i;
    if (end > start && t[end - 1] == '\r') --end;
    if (end - start > kMaxLineLength) {
      Location where{source.name, line, static_cast<int>(kMaxLineLength) + 1};
      reporter.add(make_error(Error::LineIsTooLong, where));
      ++found;
    }
    start = i + 1;
  }
}

}  // namespace

bool CompileResult::ok() const {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return false;
  return true;
}

bool CompiledLine::ok() const {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::Error) return false;
  return true;
}

CompileResult compile(const SourceFile& source, const CompileOptions& options) {
  CompileResult result;
  preproc::Preprocessed pre;
  DiagnosticList pre_diags;
  // Every directive starts with '#': without one the preprocessor would copy the text unchanged.
  const bool preprocess = options.preprocess && source.text.find('#') != std::string::npos;
  if (preprocess) {
    preproc::PreprocOptions po;
    po.scheme = "gold";
    // The preprocessor's own defaults map its errors onto Gold's codes (87-96).
    pre = preproc::preprocess(source, po, pre_diags);
  }
  const std::string& text = preprocess ? pre.text : source.text;
  Locator locator(source.name, text, preprocess ? &pre.map : nullptr);
  Reporter reporter(locator, options.max_errors);
  for (const Diagnostic& d : pre_diags.items()) reporter.add(d);
  check_line_lengths(source, options.max_errors, reporter);

  Lexer lexer(text, reporter);
  result.image = compile_program(lexer, reporter, locator, !options.check_only);
  if (!reporter.has_errors()) {
    result.image.source_name = source.name;
    result.image.created_unix_s = options.created_unix_s;
    if (options.optimize && !options.check_only) bytecode::optimize(result.image);
    if (options.max_program_bytes != 0 && !options.check_only) {
      const size_t bytes = text.size() + bytecode::encode(result.image).size();
      if (bytes > options.max_program_bytes) reporter.error(Error::ProgramIsTooLong, 0);
    }
  }
  result.diagnostics = reporter.finish();
  attach_source_lines(result.diagnostics, source);
  if (!result.ok() || options.check_only) result.image = bytecode::Image{};
  return result;
}

namespace {

// The whole file in one string of the right size: read_text_file() goes through a string stream,
// which copies a large file several times (and every new page costs a fault).
std::optional<std::string> read_source(const std::string& path, std::string* why) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  // Only a regular file's size is its length (a directory's "size" asked an exabyte string).
  struct stat st {};
  if (f != nullptr && ::fstat(::fileno(f), &st) == 0 && S_ISREG(st.st_mode) &&
      std::fseek(f, 0, SEEK_END) == 0) {
    const long size = std::ftell(f);
    std::string text;
    if (size >= 0 && std::fseek(f, 0, SEEK_SET) == 0) {
      text.resize(static_cast<size_t>(size));
      const size_t got = std::fread(text.data(), 1, text.size(), f);
      const bool whole = got == text.size() && std::fgetc(f) == EOF && !std::ferror(f);
      std::fclose(f);
      if (whole) return text;
      return read_text_file(path, why);  // the file changed size meanwhile
    }
  }
  if (f != nullptr) std::fclose(f);
  return read_text_file(path, why);  // not a seekable file (a pipe): and its own error text
}

}  // namespace

CompileResult compile_file(const std::string& path, const CompileOptions& options) {
  std::string why;
  std::optional<std::string> text = read_source(path, &why);
  if (!text) {
    CompileResult r;
    Diagnostic d = make_error(Error::OpenFileFailure, Location{path, 0, 0}, why);
    r.diagnostics.push_back(std::move(d));
    return r;
  }
  return compile(SourceFile{path, std::move(*text)}, options);
}

std::vector<KnownGlobal> known_globals(const bytecode::Image& program) {
  std::vector<KnownGlobal> out;
  for (const bytecode::Global& g : program.globals) {
    // Only what a program declared; a scalar has length 1 in the image.
    KnownGlobal k;
    k.name = g.name;
    k.type = g.type == ValueType::Int ? VarType::Int : VarType::Float;
    k.length = g.length == 1 ? 0 : static_cast<int32_t>(g.length);
    out.push_back(std::move(k));
  }
  return out;
}

CompiledLine compile_line(std::string_view line, const std::vector<KnownGlobal>& known) {
  CompiledLine result;
  const SourceFile source{"<command line>", std::string(line)};
  const std::string& text = source.text;
  Locator locator(source.name, text, nullptr);
  Reporter reporter(locator, CompileOptions{}.max_errors);
  if (text.size() > kMaxCommandLine) reporter.error(Error::ClauseIsTooLong, 0);
  Lexer lexer(text, reporter);
  AstArena arena;
  Block block = parse_line(lexer, reporter, arena);
  check_line(block, known, reporter);
  if (!reporter.has_errors())
    result.image = generate_line(block, known, locator, reporter, result.values);
  result.diagnostics = reporter.finish();
  attach_source_lines(result.diagnostics, source);
  if (!result.ok()) {
    result.image = bytecode::Image{};
    result.values.clear();
  }
  return result;
}

}  // namespace uprog::gold
