// The transfer every dialect's download shares (download_receiver.h).
#include "dialect/download_receiver.h"

#include <charconv>

namespace uprog::dialect {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

bool append_hex_bytes(std::string_view hex, std::vector<uint8_t>& out) {
  if (hex.size() % 2 != 0) return false;
  const std::size_t before = out.size();
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    const int high = hex_value(hex[i]), low = hex_value(hex[i + 1]);
    if (high < 0 || low < 0) {
      out.resize(before);
      return false;
    }
    out.push_back(static_cast<uint8_t>(high * 16 + low));
  }
  return true;
}

DownloadReceiver::DownloadReceiver(std::size_t max_bytes, DownloadCodes codes,
                                   std::size_t max_line_bytes)
    : max_bytes_(max_bytes), codes_(codes), max_line_bytes_(max_line_bytes) {}

void DownloadReceiver::abort() {
  in_progress_ = false;
  announced_ = 0;
  bytes_.clear();
  bytes_.shrink_to_fit();  // an abandoned transfer must not keep its megabyte
}

Answer DownloadReceiver::fail(DownloadFaultAnswer answer, std::string description) {
  const bool was_running = in_progress_;
  abort();
  if (answer.text != nullptr) return Answer{answer.text, answer.code};
  if (was_running) description += " (the transfer is dropped)";
  return Answer{std::move(description), answer.code};
}

std::optional<Answer> DownloadReceiver::begin(std::string_view decimal_size) {
  std::size_t size = 0;
  const char* const end = decimal_size.data() + decimal_size.size();
  const auto [stop, ec] = std::from_chars(decimal_size.data(), end, size);
  if (decimal_size.empty() || ec != std::errc() || stop != end) size = 0;
  return begin(size);
}

std::optional<Answer> DownloadReceiver::begin(std::size_t size) {
  abort();
  if (size == 0 || size > max_bytes_)
    return fail(codes_.bad_size, "the size must be 1 to " + std::to_string(max_bytes_) + " bytes");
  in_progress_ = true;
  announced_ = size;
  return std::nullopt;
}

std::optional<Answer> DownloadReceiver::add_hex(std::string_view hex) {
  if (!in_progress_) return fail(codes_.not_begun, "no download begun");
  if (hex.empty() || hex.size() / 2 > max_line_bytes_ || !append_hex_bytes(hex, bytes_)) {
    std::string why = "the bytes must be hex digit pairs";
    if (max_line_bytes_ != SIZE_MAX)
      why += ", at most " + std::to_string(max_line_bytes_) + " a line";
    return fail(codes_.bad_data, std::move(why));
  }
  if (bytes_.size() > announced_)
    return fail(codes_.too_many,
                "more bytes than the " + std::to_string(announced_) + " announced");
  return std::nullopt;
}

std::optional<Answer> DownloadReceiver::finish(std::vector<uint8_t>& finished) {
  if (!in_progress_) return fail(codes_.not_begun, "no download begun");
  if (bytes_.size() != announced_) {
    return fail(codes_.too_few, "the end after " + std::to_string(bytes_.size()) + " of the " +
                                    std::to_string(announced_) + " bytes announced");
  }
  finished.swap(bytes_);
  abort();
  return std::nullopt;
}

}  // namespace uprog::dialect
