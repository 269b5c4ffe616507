// PUP's entry in the dialect registry: the PUP compiler (a .pup → its CUP text), CUP as the
// stored form, and the AG300 firmware.
#include "dialects/pup/dialect.h"

#include <filesystem>

#include "dialects/pup/cup_loader.h"
#include "dialects/pup/debug_map.h"
#include "dialects/pup/download.h"
#include "dialects/pup/errors.h"
#include "dialects/pup/firmware.h"
#include "dialects/pup/outline.h"
#include "dialects/pup/pup_compiler.h"
#include "dialects/pup/reference.h"
#include "support/files.h"

namespace uprog::pup {
namespace {

constexpr std::string_view kExtensions[] = {".pup", ".cup"};

bool is_cup(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".cup" || ext == ".CUP";
}

// A refusal of a .cup, with the download's code for it ("[cup 45]").
Diagnostic cup_diagnostic(int32_t code, const std::string& why, const std::string& path) {
  Diagnostic d;
  d.scheme = "cup";
  d.code = code;
  d.message = why;
  d.where = Location{path, 0, 0};
  return d;
}

// A hand-written .cup: read leniently, checked by the loader (a refusal names its line), and
// written again with CR line ends and a fresh header.
PupOutput rebuild_cup(const std::string& path, const std::string& text, uint64_t created_unix_s) {
  PupOutput out;
  std::string why;
  out.program = read_cup_text(text, std::filesystem::path(path).stem().string());
  out.program.date = cup_date(created_unix_s);
  if (!load_cup(out.program, &why)) out.diagnostics.push_back(cup_diagnostic(45, why, path));
  // The flash sector (ADownloadUProg[1]'s 262 144 characters); 41 is the download's "length".
  if (const std::string too_large = out.ok() ? flash_refusal(write_cup(out.program).size()) : "";
      !too_large.empty()) {
    out.diagnostics.push_back(cup_diagnostic(41, too_large, path));
  }
  return out;
}

class PupDialect final : public dialect::Dialect {
 public:
  std::string_view name() const override { return "pup"; }
  std::string_view description() const override {
    return "Akribis AG300: PUP (.pup, .puh) compiled to CUP (.cup), threads, events";
  }
  std::span<const std::string_view> source_extensions() const override { return kExtensions; }
  std::string_view stored_extension() const override { return ".cup"; }
  // X.pup → X.cup, as the PC Suite names it; a .cup is rewritten in place (checked, fresh header).
  std::string stored_path(const std::string& source) const override {
    return std::filesystem::path(source).replace_extension(".cup").string();
  }

  dialect::CompileOutput compile_source(const SourceFile& source,
                                        const dialect::CompileSettings& settings) const override {
    dialect::CompileOutput out;
    const bool cup = is_cup(source.name);
    PupOutput r =
        cup ? rebuild_cup(source.name, source.text, settings.created_unix_s)
            : compile_pup(source.name, source.text, settings.created_unix_s, settings.includes);
    out.diagnostics = std::move(r.diagnostics);
    if (out.ok() && !settings.check_only) {
      const std::string text = write_cup(r.program);
      out.stored_form.assign(text.begin(), text.end());
      if (!cup) out.debug_map = write_debug_map(r.places, r.vars);
    }
    return out;
  }
  Diagnostic unreadable_source(const std::string& path, const std::string& why) const override {
    return make_error(Error::IncludeNotFound, Location{path, 0, 0}, why);
  }

  std::span<const dialect::ErrorInfo> diagnostic_codes() const override {
    return diagnostic_table();
  }
  std::span<const dialect::ErrorInfo> interpreter_errors() const override {
    return interpreter_error_table();
  }
  std::unique_ptr<dialect::Firmware> make_firmware(
      dialect::Runtime& runtime, const dialect::FirmwareOptions& options) const override {
    return std::make_unique<Firmware>(runtime, options);
  }
  std::vector<std::string> download_lines(const std::vector<uint8_t>& cup) const override {
    return pup::download_lines(cup);
  }
  std::string load_line() const override { return ""; }  // ADownloadUProg[3] stores and loads
  std::size_t max_download_bytes() const override { return kMaxProgramBytes; }
  const dialect::SampleProgram& sample_program() const override { return kSample; }
  std::vector<dialect::ReferenceEntry> reference() const override { return pup::reference(); }
  // Controller keywords are case-insensitive (keywords.h); statements are matched exactly first.
  bool names_ignore_case() const override { return true; }
  std::vector<dialect::SourceSymbol> outline(std::string_view text) const override {
    return pup::outline(text);
  }

 private:
  // An unknown keyword is 1 (akribis-drive.md, "Errors"; tests/transcripts/pup/command_line.txt).
  static constexpr dialect::SampleProgram kSample{
      "sample.pup",
      "#definevar Done AGenData[1]\nAProgTask[1]\nDone = 6 * 7\nAProgHalt[1]\n",
      "",
      "AGenData[1]",
      "42",
      100,
      "#definevar Done AGenData[1]\nAProgTask[1]\nDone = 6 *\nAProgHalt[1]\n",
      3,
      "ANoSuchThing"};
};

}  // namespace

const dialect::Dialect& dialect() {
  static const PupDialect pup;
  return pup;
}

}  // namespace uprog::pup
