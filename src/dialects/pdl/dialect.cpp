// PDL's entry in the dialect registry: its compiler, tables and firmware behind dialect::Dialect,
// and each host's session (its level and its download in progress).
#include "dialects/pdl/dialect.h"

#include "dialect/dl_lines.h"
#include "dialects/pdl/compile.h"
#include "dialects/pdl/errors.h"
#include "dialects/pdl/firmware.h"
#include "dialects/pdl/outline.h"
#include "dialects/pdl/reference.h"

namespace uprog::pdl {
namespace {

constexpr std::string_view kExtensions[] = {".pdl"};

constexpr dialect::ErrorInfo kHostErrors[] = {
#define EC(code, name, text) {code, #name, text},
#include "dialects/pdl/interpreter_errors.def"
#undef EC
};

std::vector<dialect::ErrorInfo> diagnostic_table() {
  size_t count = 0;
  const ErrorEntry* all = all_errors(count);
  std::vector<dialect::ErrorInfo> out;
  for (size_t i = 0; i < count; ++i) out.push_back({all[i].code, all[i].name, all[i].text});
  return out;
}

class Session final : public dialect::Session {
 public:
  explicit Session(Firmware& firmware) : firmware_(firmware) {}
  std::vector<dialect::Answer> send(std::string_view line) override {
    return firmware_.host_line(line, level_, &download_, true);
  }

 private:
  Firmware& firmware_;
  int32_t level_ = 0;  // level/n; 0 at connect
  dialect::DlReceiver download_;
};

class PdlDialect final : public dialect::Dialect {
 public:
  std::string_view name() const override { return "pdl"; }
  std::string_view description() const override {
    return "HIWIN D-series PDL: four tasks switched every phase, pointers, procedures, printl "
           "events";
  }
  std::span<const std::string_view> source_extensions() const override { return kExtensions; }
  std::string_view stored_extension() const override { return ".pdi"; }
  dialect::CompileOutput compile_source(const SourceFile& source,
                                        const dialect::CompileSettings& settings) const override {
    CompileOptions options;
    options.check_only = settings.check_only;
    options.created_unix_s = settings.created_unix_s;
    options.includes = settings.includes;
    CompileResult r = pdl::compile(source, options);
    dialect::CompileOutput out;
    out.diagnostics = std::move(r.diagnostics);
    if (out.ok() && !settings.check_only) {
      out.stored_form = bytecode::encode(r.image);
      out.image = std::move(r.image);
    }
    return out;
  }
  Diagnostic unreadable_source(const std::string& path, const std::string& why) const override {
    return make_diagnostic(Error::Syntax, Location{path, 0, 0}, "cannot read: " + why);
  }
  std::span<const dialect::ErrorInfo> diagnostic_codes() const override {
    static const std::vector<dialect::ErrorInfo> table = diagnostic_table();
    return table;
  }
  std::span<const dialect::ErrorInfo> interpreter_errors() const override { return kHostErrors; }
  std::unique_ptr<dialect::Firmware> make_firmware(
      dialect::Runtime& runtime, const dialect::FirmwareOptions& options) const override {
    return std::make_unique<Firmware>(runtime, options);
  }
  std::vector<std::string> download_lines(const std::vector<uint8_t>& stored_form) const override {
    return dialect::download_lines(stored_form);
  }
  std::string load_line() const override { return "reset"; }
  std::size_t max_download_bytes() const override { return dialect::kDownloadMaxBytes; }
  const dialect::SampleProgram& sample_program() const override { return kSample; }
  std::vector<dialect::ReferenceEntry> reference() const override { return pdl::reference(); }
  // The drive's names are found ignoring case (system_names.h); the user's are not.
  bool names_ignore_case() const override { return true; }
  std::vector<dialect::SourceSymbol> outline(std::string_view text) const override {
    return pdl::outline(text);
  }

 private:
  // A command the host protocol does not know is 1 (tests/transcripts/pdl/host_protocol.txt).
  static constexpr dialect::SampleProgram kSample{
      "sample.pdl", "#long done\n#task/1;\ndone = 6 * 7;\nhalt;\n", "", "done",          "42",
      100,          "#long done\n#task/1;\ndone = 6 *;\nhalt;\n",   3,  "frobnicate now"};
};

}  // namespace

std::unique_ptr<dialect::Session> Firmware::open_session() {
  return std::make_unique<Session>(*this);
}

const dialect::Dialect& dialect() {
  static const PdlDialect pdl;
  return pdl;
}

}  // namespace uprog::pdl
