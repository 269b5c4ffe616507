// The ST dialect behind dialect::Dialect: `.st` macro sources, stored as the source itself (the
// drive compiles it), the S300 firmware, PLCDL downloads and PLCRUN.
#include "dialects/st/dialect.h"

#include <fmt/core.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "dialects/st/compile.h"
#include "dialects/st/errors.h"
#include "dialects/st/firmware.h"
#include "dialects/st/names.h"
#include "dialects/st/outline.h"
#include "dialects/st/reference.h"

namespace uprog::st {
namespace {

constexpr std::string_view kExtensions[] = {".st"};
constexpr size_t kHexBytesPerLine = 100;

constexpr dialect::ErrorInfo kInterpreterErrors[] = {
#define EC(code, name, text) {code, #name, text},
#include "dialects/st/interpreter_errors.def"
#undef EC
};

std::vector<dialect::ErrorInfo> diagnostic_table() {
  size_t count = 0;
  const ErrorInfo* all = all_errors(count);
  std::vector<dialect::ErrorInfo> out;
  for (size_t i = 0; i < count; ++i) out.push_back({all[i].code, all[i].name, all[i].text});
  return out;
}

// `-D NAME=value` into the compiler's defines: a capital name (as #IF sees it) and a whole
// number; anything else is error 30 at the file, and nothing is compiled.
bool take_defines(const std::string& path, const dialect::CompileSettings& settings,
                  CompileOptions& options, std::vector<Diagnostic>& diagnostics) {
  for (const auto& [name, text] : settings.defines) {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    const bool number = !text.empty() && end != nullptr && *end == '\0' && errno == 0 &&
                        v >= INT32_MIN && v <= INT32_MAX;
    if (!number) {
      diagnostics.push_back(
          make_error(Error::BadDirective, Location{path, 0, 0},
                     fmt::format("-D {}={}: the value must be a whole number", name, text)));
      continue;
    }
    options.defines[upper(name)] = static_cast<int32_t>(v);
  }
  return diagnostics.empty();
}

class StDialect final : public dialect::Dialect {
 public:
  std::string_view name() const override { return "st"; }
  std::string_view description() const override {
    return "Kollmorgen S300/S700 macros (.st): structured text stored as source, compiled by the "
           "drive";
  }
  std::span<const std::string_view> source_extensions() const override { return kExtensions; }
  std::string_view stored_extension() const override { return ".st"; }

  dialect::CompileOutput compile_source(const SourceFile& source,
                                        const dialect::CompileSettings& settings) const override {
    CompileOptions options;
    options.check_only = settings.check_only;
    options.created_unix_s = settings.created_unix_s;
    dialect::CompileOutput out;
    if (!take_defines(source.name, settings, options, out.diagnostics)) return out;
    CompileResult r = st::compile(source, options);
    out.diagnostics = std::move(r.diagnostics);
    if (out.ok() && !settings.check_only) {
      // The stored form is the source: the drive compiles it itself.
      out.stored_form.assign(source.text.begin(), source.text.end());
      out.image = std::move(r.image);
      // The download carries the source alone: its file name goes to the drive beside it, so
      // that the drive compiles it under that name and breakpoints in it resolve.
      out.debug_map = nlohmann::json{{"source", source.name}}.dump(
          -1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    return out;
  }
  Diagnostic unreadable_source(const std::string& path, const std::string& why) const override {
    Diagnostic d = make_error(Error::Syntax, Location{path, 0, 0});
    d.message = "cannot read the file: " + why;
    return d;
  }

  std::span<const dialect::ErrorInfo> diagnostic_codes() const override {
    static const std::vector<dialect::ErrorInfo> table = diagnostic_table();
    return table;
  }
  std::span<const dialect::ErrorInfo> interpreter_errors() const override {
    return kInterpreterErrors;
  }

  std::unique_ptr<dialect::Firmware> make_firmware(
      dialect::Runtime& runtime, const dialect::FirmwareOptions& options) const override {
    return std::make_unique<Firmware>(runtime, options.wire_style);
  }

  // The drive's own wire: BEL `ERR n text`, the prompt `-->` after each line once PROMPT is 1.
  std::optional<dialect::PromptWire> host_prompt() const override {
    return dialect::PromptWire{"-->", "\aERR ", "PROMPT 1"};
  }

  std::vector<std::string> download_lines(const std::vector<uint8_t>& source) const override {
    std::vector<std::string> out{fmt::format("PLCDL BEGIN {}", source.size())};
    for (size_t i = 0; i < source.size(); i += kHexBytesPerLine) {
      std::string line = "PLCDL ";
      for (size_t k = i; k < source.size() && k < i + kHexBytesPerLine; ++k)
        line += fmt::format("{:02X}", source[k]);
      out.push_back(std::move(line));
    }
    out.push_back("PLCDL END");
    return out;
  }
  std::string load_line() const override { return "PLCRUN"; }
  std::size_t max_download_bytes() const override { return kMaxStoredSource; }
  const dialect::SampleProgram& sample_program() const override { return kSample; }
  std::vector<dialect::ReferenceEntry> reference() const override { return st::reference(); }
  // Keywords and the drive's names are case-insensitive (s300-drive.md, Program layout).
  bool names_ignore_case() const override { return true; }
  std::vector<dialect::SourceSymbol> outline(std::string_view text) const override {
    return st::outline(text);
  }
  dialect::WordSyntax word_syntax() const override { return st::word_syntax(); }

 private:
  // An unknown command is ERR 1 (tests/transcripts/st/interface.txt).
  static constexpr dialect::SampleProgram kSample{
      "sample.st",
      "LONG DONE ;\nPROGRAM PLCMAIN\n   DONE := 6 * 7;\nEND_PROGRAM\n",
      "",
      "DONE",
      "42",
      100,
      "LONG DONE ;\nPROGRAM PLCMAIN\n   DONE := 6 *;\nEND_PROGRAM\n",
      3,
      "NOSUCH"};
};

}  // namespace

const dialect::Dialect& dialect() {
  static const StDialect st;
  return st;
}

}  // namespace uprog::st
