// The DL download lines (dl_lines.h).
#include "dialect/dl_lines.h"

#include <algorithm>
#include <cctype>

namespace uprog::dialect {
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

constexpr DownloadCodes kDlCodes{
    .not_begun = {kDlNoDownload},
    .bad_size = {kDlBadSize},
    .bad_data = {kDlBadChunk},
    .too_many = {kDlBadChunk},
    .too_few = {kDlBadSize},
};

}  // namespace

std::vector<std::string> download_lines(const std::vector<uint8_t>& image) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::vector<std::string> lines;
  lines.push_back("DL##BEGIN=" + std::to_string(image.size()));
  for (std::size_t at = 0; at < image.size(); at += kDownloadChunkBytes) {
    const std::size_t end = std::min(image.size(), at + kDownloadChunkBytes);
    std::string line = "DL=";
    for (std::size_t i = at; i < end; ++i) {
      line.push_back(kHex[image[i] >> 4]);
      line.push_back(kHex[image[i] & 0xF]);
    }
    lines.push_back(std::move(line));
  }
  lines.push_back("DL##END");
  return lines;
}

DlReceiver::DlReceiver() : transfer_(kDownloadMaxBytes, kDlCodes) {}

bool DlReceiver::is_download_command(std::string_view expression) {
  const std::string word = compact_upper(expression.substr(0, 16));
  return word.starts_with("DL##") || word.starts_with("DL=");
}

std::optional<Answer> DlReceiver::handle(std::string_view expression,
                                         std::vector<uint8_t>& finished) {
  const std::string word = compact_upper(expression);
  if (word.starts_with("DL=")) return transfer_.add_hex(std::string_view(word).substr(3));
  if (word.starts_with("DL##BEGIN=")) return transfer_.begin(std::string_view(word).substr(10));
  if (word == "DL##END") return transfer_.finish(finished);
  if (word == "DL##ABORT") {
    transfer_.abort();
    return std::nullopt;
  }
  transfer_.abort();
  return Answer{
      "Command syntax error: the download commands are DL##BEGIN=<bytes>, DL=<hex>, "
      "DL##END and DL##ABORT",
      kDlSyntax};
}

}  // namespace uprog::dialect
