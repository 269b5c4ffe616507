// Gold's entry in the dialect registry: its compiler, tables and firmware behind dialect::Dialect.
#include "dialects/gold/dialect.h"

#include "dialect/dl_lines.h"
#include "dialects/gold/compile.h"
#include "dialects/gold/errors.h"
#include "dialects/gold/firmware.h"
#include "dialects/gold/outline.h"
#include "dialects/gold/reference.h"

namespace uprog::gold {
namespace {

constexpr std::string_view kExtensions[] = {".ehl", ".gold"};

constexpr dialect::ErrorInfo kInterpreterErrors[] = {
#define EC(code, name, text) {code, #name, text},
#include "dialects/gold/interpreter_errors.def"
#undef EC
};

std::vector<dialect::ErrorInfo> diagnostic_table() {
  size_t count = 0;
  const ErrorInfo* all = all_errors(count);
  std::vector<dialect::ErrorInfo> out;
  for (size_t i = 0; i < count; ++i) out.push_back({all[i].code, all[i].name, all[i].text});
  return out;
}

class GoldDialect final : public dialect::Dialect {
 public:
  std::string_view name() const override { return "gold"; }
  std::string_view description() const override {
    return "Elmo Gold line: user programs (.ehl) compiled to images, the Gold command line";
  }
  std::span<const std::string_view> source_extensions() const override { return kExtensions; }
  std::string_view stored_extension() const override { return ".upi"; }

  dialect::CompileOutput compile_source(const SourceFile& source,
                                        const dialect::CompileSettings& settings) const override {
    CompileOptions options;
    options.check_only = settings.check_only;
    options.created_unix_s = settings.created_unix_s;
    CompileResult r = gold::compile(source, options);
    dialect::CompileOutput out;
    out.diagnostics = std::move(r.diagnostics);
    if (out.ok() && !settings.check_only) {
      out.stored_form = bytecode::encode(r.image);
      out.image = std::move(r.image);
    }
    return out;
  }
  Diagnostic unreadable_source(const std::string& path, const std::string& why) const override {
    return make_error(Error::OpenFileFailure, Location{path, 0, 0}, why);
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
    return std::make_unique<Firmware>(runtime, options);
  }

  std::vector<std::string> download_lines(const std::vector<uint8_t>& stored_form) const override {
    return dialect::download_lines(stored_form);
  }
  std::string load_line() const override { return "CC"; }
  std::optional<dialect::FramerOptions> host_framing() const override {
    dialect::FramerOptions framing = command_line_framing();
    framing.answer_empty_expressions = true;  // the drive form answers `PX;` CR twice
    return framing;
  }
  std::size_t max_download_bytes() const override { return dialect::kDownloadMaxBytes; }
  const dialect::SampleProgram& sample_program() const override { return kSample; }
  std::vector<dialect::ReferenceEntry> reference() const override { return gold::reference(); }
  bool names_ignore_case() const override { return true; }  // PX and px (commands.h)
  // The compiler's declarations; the word scanner's while the source does not parse.
  std::vector<dialect::SourceSymbol> outline(std::string_view text) const override {
    if (std::optional<std::vector<dialect::SourceSymbol>> s = gold::compiled_outline(text))
      return std::move(*s);
    return gold::outline(text);
  }
  dialect::WordSyntax word_syntax() const override { return gold::word_syntax(); }

 private:
  // AC must be positive (EC 21, the Elmo reference's "out of range").
  static constexpr dialect::SampleProgram kSample{
      "sample.ehl", "int done\nfunction main()\ndone = 6 * 7\nreturn\n", "main", "done", "42",
      100,          "int done\nfunction main()\ndone = 6 *\nreturn\n",   3,      "AC=-5"};
};

}  // namespace

const dialect::Dialect& dialect() {
  static const GoldDialect gold;
  return gold;
}

}  // namespace uprog::gold
