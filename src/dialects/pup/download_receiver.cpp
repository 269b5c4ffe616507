// The firmware's side of ADownloadUProg (per connection) and AUploadUProg, and AProgInfo: a
// download is gathered, checked by length and CRC, then read, loaded and stored as one step.
#include <fmt/core.h>

#include "dialects/pup/cup_file.h"
#include "dialects/pup/download.h"
#include "dialects/pup/firmware.h"
#include "dialects/pup/message.h"

namespace uprog::pup {
namespace {

dialect::Answer answered(std::optional<dialect::Answer> fault) {
  return fault ? std::move(*fault) : dialect::Answer{};
}

}  // namespace

dialect::Answer Firmware::download_message(int32_t step, const std::optional<std::string>& argument,
                                           DownloadState& d) {
  if (!argument) return {"argument required", 9};
  const std::string& arg = *argument;
  dialect::DownloadReceiver& transfer = d.transfer;
  if (step == 1) {
    const auto n = parse_number(arg);
    transfer.abort();
    if (!n || *n < 0 || static_cast<size_t>(*n) > kMaxProgramBytes) return {"length", 41};
    if (running()) return {"user program running", 16};
    if (*n == 0) return {};  // drops a transfer
    return answered(transfer.begin(static_cast<size_t>(*n)));
  }
  if (!transfer.in_progress()) return {"download not begun", 40};
  if (step == 2) return answered(transfer.add_hex(arg));
  const auto crc = parse_number(arg);
  if (!crc) {
    transfer.abort();
    return {"argument wrong format", 6};
  }
  std::vector<uint8_t> bytes;
  if (auto fault = transfer.finish(bytes)) return std::move(*fault);
  const std::string cup(bytes.begin(), bytes.end());
  if (static_cast<uint32_t>(*crc) != expected_crc(cup)) return {"CRC", 43};
  const std::string why = install(cup, true);
  if (why.empty()) {
    runtime_.log(fmt::format("program downloaded ({} bytes)", cup.size()));
    return {};
  }
  // "error N: text"
  const int32_t code = std::atoi(why.c_str() + 6);
  return {why.substr(why.find(':') + 2), code == 0 ? 45 : code};
}

dialect::Answer Firmware::upload(int32_t offset) {
  if (!stored_) return {"no user program", 15};
  if (offset < 0 || static_cast<size_t>(offset) > stored_->size())
    return {"argument out of range", 7};
  return {to_hex(stored_->substr(static_cast<size_t>(offset), kMaxChunkBytes)), 0};
}

// CRC, date, name and the #information strings: an answer each.
std::vector<dialect::Answer> Firmware::info() {
  if (!stored_) return {{"no user program", 15}};
  std::vector<dialect::Answer> answers;
  const auto crc = declared_crc(*stored_);  // as the header writes it: 8 hex digits or 000000
  answers.push_back({crc && crc->checked ? stored_->substr(2, 8) : "000000", 0});
  answers.push_back({cup_program_.date, 0});
  answers.push_back({cup_program_.name, 0});
  for (const std::string& s : cup_program_.info) answers.push_back({s, 0});
  return answers;
}

}  // namespace uprog::pup
