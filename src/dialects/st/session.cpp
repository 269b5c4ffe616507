// One host's S300 command line: its own PLCDL download in progress (`PLCDL BEGIN n`, hex lines,
// `PLCDL END` stores atomically, `PLCDL ABORT`); every other line goes to the drive's command
// line, and each takes one axis step of virtual time after its answer.
#include <optional>

#include "dialect/download_receiver.h"
#include "dialects/st/firmware.h"
#include "dialects/st/names.h"

namespace uprog::st {
namespace {

using dialect::Answer;

// The PLCDL lines' faults in the spec's codes (shared/spec/s300-drive.md: Gold's 210-213 as
// 12-14).
constexpr dialect::DownloadCodes kPlcdlCodes{
    .not_begun = {kErrNoDownload, "no download in progress (PLCDL BEGIN first)"},
    .bad_size = {kErrDownloadSize, "PLCDL BEGIN needs a size from 1 to 61440"},
    .bad_data = {kErrDownloadData, "not hex digit pairs"},
    .too_many = {kErrDownloadData, "more bytes than PLCDL BEGIN announced"},
    .too_few = {kErrDownloadSize, "fewer bytes than PLCDL BEGIN announced"},
};

std::string_view trimmed(std::string_view s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

class Session final : public dialect::Session {
 public:
  explicit Session(Firmware& firmware) : firmware_(firmware) {}

  // The line is answered as it arrives; the axis step it takes passes after the answer.
  std::vector<Answer> send(std::string_view line) override {
    const size_t b = line.find_first_not_of(" \t");
    std::vector<Answer> answers = b != std::string_view::npos && upper(line.substr(b, 5)) == "PLCDL"
                                      ? download(line.substr(b + 5))
                                      : firmware_.command_line(line);
    firmware_.spend_line_time();
    return answers;
  }

 private:
  static std::vector<Answer> answered(std::optional<Answer> fault) {
    if (!fault) return {};
    return {std::move(*fault)};
  }

  std::vector<Answer> download(std::string_view rest) {
    // The transfer is in the drive's RAM: a reboot (COLDSTART) since BEGIN dropped it.
    if (transfer_boot_ != firmware_.boot_count()) {
      transfer_.abort();
      transfer_boot_ = firmware_.boot_count();
    }
    rest = trimmed(rest);
    if (rest.empty()) return {Answer{"syntax error", kErrSyntax}};
    const std::string word = upper(rest.substr(0, rest.find_first_of(" \t")));
    // The page: "If the amplifier is not enabled the program can be modified and recompiled".
    if ((word == "BEGIN" || word == "END") && firmware_.stage_on()) {
      transfer_.abort();
      return {Answer{"needs disabled", kErrNeedsDisabled}};
    }
    if (word == "BEGIN") return answered(transfer_.begin(trimmed(rest.substr(5))));
    if (word == "ABORT") {
      transfer_.abort();
      return {};
    }
    if (word != "END") return answered(transfer_.add_hex(rest));
    std::vector<uint8_t> source;
    if (auto fault = transfer_.finish(source)) return {std::move(*fault)};
    const dialect::DownloadResult r = firmware_.download(source);
    if (!r.ok) return {Answer{r.error, kErrStorage}};
    return {};
  }

  Firmware& firmware_;
  dialect::DownloadReceiver transfer_{kMaxStoredSource, kPlcdlCodes};
  uint64_t transfer_boot_ = 0;  // the boot the transfer began in
};

}  // namespace

std::unique_ptr<dialect::Session> Firmware::open_session() {
  return std::make_unique<Session>(*this);
}

}  // namespace uprog::st
