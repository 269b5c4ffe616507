// One host's S300 command line: its own PLCDL download in progress (`PLCDL BEGIN n`, hex lines,
// `PLCDL END` stores atomically, `PLCDL ABORT`); every other line goes to the drive's command
// line, and each takes one axis step of virtual time after its answer.
#include <cctype>

#include "dialects/st/firmware.h"
#include "dialects/st/names.h"

namespace uprog::st {
namespace {

using dialect::Answer;

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
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
  std::vector<Answer> fail(int32_t code, std::string why) {
    active_ = false;
    bytes_.clear();
    return {Answer{std::move(why), code}};
  }

  std::vector<Answer> download(std::string_view rest) {
    const size_t b = rest.find_first_not_of(" \t");
    if (b == std::string_view::npos) return fail(kErrSyntax, "syntax error");
    rest = rest.substr(b);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.remove_suffix(1);
    const std::string word = upper(rest.substr(0, rest.find_first_of(" \t")));
    if (word == "BEGIN") {
      const std::string n(rest.substr(5));
      char* end = nullptr;
      const long size = std::strtol(n.c_str(), &end, 10);
      if (end == n.c_str() || *end != '\0' || size < 1 ||
          size > static_cast<long>(kMaxStoredSource))
        return fail(kErrDownloadSize, "PLCDL BEGIN needs a size from 1 to 61440");
      active_ = true;
      announced_ = static_cast<size_t>(size);
      bytes_.clear();
      return {};
    }
    if (word == "ABORT") {
      active_ = false;
      bytes_.clear();
      return {};
    }
    if (!active_) return fail(kErrNoDownload, "no download in progress (PLCDL BEGIN first)");
    if (word == "END") {
      if (bytes_.size() != announced_)
        return fail(kErrDownloadSize, "fewer bytes than PLCDL BEGIN announced");
      const dialect::DownloadResult r = firmware_.download(bytes_);
      active_ = false;
      bytes_.clear();
      if (!r.ok) return {Answer{r.error, kErrStorage}};
      return {};
    }
    if (rest.size() % 2 != 0) return fail(kErrDownloadData, "an odd number of hex digits");
    for (size_t i = 0; i < rest.size(); i += 2) {
      const int hi = hex_digit(rest[i]), lo = hex_digit(rest[i + 1]);
      if (hi < 0 || lo < 0) return fail(kErrDownloadData, "not hex digit pairs");
      bytes_.push_back(static_cast<uint8_t>(hi * 16 + lo));
    }
    if (bytes_.size() > announced_)
      return fail(kErrDownloadData, "more bytes than PLCDL BEGIN announced");
    return {};
  }

  Firmware& firmware_;
  bool active_ = false;
  size_t announced_ = 0;
  std::vector<uint8_t> bytes_;
};

}  // namespace

std::unique_ptr<dialect::Session> Firmware::open_session() {
  return std::make_unique<Session>(*this);
}

}  // namespace uprog::st
