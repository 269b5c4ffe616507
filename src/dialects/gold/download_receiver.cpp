// The DL command lines on the drive's side (download_receiver.h, docs/protocol.md "Download").
#include "dialects/gold/download_receiver.h"

#include <cctype>
#include <charconv>
#include <string>

#include "dialects/gold/download_protocol.h"
#include "dialects/gold/interpreter_errors.h"

namespace uprog::gold {
namespace {

// Upper case without blanks, as program-control lines are read.
std::string compact_upper(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != ' ' && c != '\t')
      out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

bool DownloadReceiver::is_download_command(std::string_view expression) {
  const std::string word = compact_upper(expression.substr(0, 16));
  return word.starts_with("DL##") || word.starts_with("DL=");
}

void DownloadReceiver::abort() {
  in_progress_ = false;
  announced_ = 0;
  bytes_.clear();
  bytes_.shrink_to_fit();  // an abandoned transfer must not keep its megabyte
}

Answer DownloadReceiver::fail(int32_t code, std::string why) {
  const bool was_running = in_progress_;
  abort();
  if (was_running) why += " (the transfer is dropped)";
  return Answer{std::move(why), code};
}

std::optional<Answer> DownloadReceiver::handle(std::string_view expression,
                                               std::vector<uint8_t>& finished) {
  const std::string word = compact_upper(expression);
  if (word.starts_with("DL=")) {
    if (!in_progress_) return fail(kErrorNoDownload, "DL= without DL##BEGIN");
    const std::string_view hex = std::string_view(word).substr(3);
    if (hex.empty() || hex.size() % 2 != 0) {
      return fail(kErrorDownloadChunk,
                  "DL= needs hex digit pairs, got " + std::to_string(hex.size()) + " digits");
    }
    if (bytes_.size() + hex.size() / 2 > announced_) {
      return fail(kErrorDownloadChunk,
                  "more bytes than the " + std::to_string(announced_) + " announced");
    }
    const std::size_t before = bytes_.size();
    for (std::size_t i = 0; i < hex.size(); i += 2) {
      const int high = hex_digit(hex[i]), low = hex_digit(hex[i + 1]);
      if (high < 0 || low < 0) {
        bytes_.resize(before);
        return fail(kErrorDownloadChunk, "DL= holds a character that is not a hex digit");
      }
      bytes_.push_back(static_cast<uint8_t>(high * 16 + low));
    }
    return std::nullopt;
  }
  if (word.starts_with("DL##BEGIN=")) {
    abort();  // a new BEGIN starts afresh: a host that lost its place can always retry
    const std::string_view number = std::string_view(word).substr(10);
    std::size_t size = 0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), size);
    if (number.empty() || ec != std::errc() || end != number.data() + number.size() || size == 0 ||
        size > kDownloadMaxBytes) {
      return fail(kErrorDownloadSize,
                  "DL##BEGIN=<bytes> needs a size from 1 to " + std::to_string(kDownloadMaxBytes));
    }
    in_progress_ = true;
    announced_ = size;
    return std::nullopt;
  }
  if (word == "DL##END") {
    if (!in_progress_) return fail(kErrorNoDownload, "DL##END without DL##BEGIN");
    if (bytes_.size() != announced_) {
      return fail(kErrorDownloadSize, "DL##END after " + std::to_string(bytes_.size()) +
                                          " of the " + std::to_string(announced_) +
                                          " bytes announced");
    }
    finished.swap(bytes_);
    abort();
    return std::nullopt;
  }
  if (word == "DL##ABORT") {
    abort();
    return std::nullopt;
  }
  return fail(kErrorSyntax,
              "Command syntax error: the download commands are DL##BEGIN=<bytes>, DL=<hex>, "
              "DL##END and DL##ABORT");
}

}  // namespace uprog::gold
