// PUP's entry in the dialect registry: the PUP compiler (a .pup → its CUP text), CUP as the
// stored form, and the AG300 firmware.
#include "dialects/pup/dialect.h"

#include <filesystem>

#include "dialects/pup/errors.h"
#include "dialects/pup/pup_compiler.h"

namespace uprog::pup {
namespace {

constexpr std::string_view kExtensions[] = {".pup", ".cup"};

class PupDialect final : public dialect::Dialect {
 public:
  std::string_view name() const override { return "pup"; }
  std::string_view description() const override {
    return "Akribis AG300: PUP (.pup, .puh) compiled to CUP (.cup), threads, events";
  }
  std::span<const std::string_view> source_extensions() const override { return kExtensions; }
  std::string_view stored_extension() const override { return ".cup"; }

  dialect::CompileOutput compile_file(const std::string& path, const dialect::CompileSettings& settings) const override {
    dialect::CompileOutput out;
    PupOutput r = compile_pup_file(path, settings.created_unix_s);
    out.diagnostics = std::move(r.diagnostics);
    if (out.ok() && !settings.check_only) {
      const std::string cup = write_cup(r.program);
      out.stored_form.assign(cup.begin(), cup.end());
    }
    return out;
  }

  std::span<const dialect::ErrorInfo> diagnostic_codes() const override { return diagnostic_table(); }
  std::span<const dialect::ErrorInfo> interpreter_errors() const override { return {}; }
  std::unique_ptr<dialect::Firmware> make_firmware(dialect::Runtime&, const dialect::FirmwareOptions&) const override {
    return nullptr;
  }
  std::vector<std::string> download_lines(const std::vector<uint8_t>&) const override { return {}; }
  std::string load_line() const override { return ""; }
  std::size_t max_download_bytes() const override { return 262144; }
};

}  // namespace

const dialect::Dialect& dialect() {
  static const PupDialect pup;
  return pup;
}

}  // namespace uprog::pup
