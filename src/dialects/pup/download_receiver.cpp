// The firmware's side of ADownloadUProg (per connection) and AUploadUProg, and AProgInfo: a
// download is gathered, checked by length and CRC, then read, loaded and stored as one step.
#include <fmt/core.h>

#include "dialects/pup/cup_file.h"
#include "dialects/pup/download.h"
#include "dialects/pup/firmware.h"
#include "dialects/pup/message.h"

namespace uprog::pup {
namespace {

dialect::Answer fail(DownloadState& d, int32_t code, std::string text) {
  d.open = false;
  d.dropped = true;
  d.data.clear();
  return {std::move(text), code};
}

}  // namespace

dialect::Answer Firmware::download_message(int32_t step, const std::optional<std::string>& argument,
                                           DownloadState& d) {
  if (!argument) return {"argument required", 9};
  const std::string& arg = *argument;
  if (step == 1) {
    const auto n = parse_number(arg);
    if (!n || *n < 0 || static_cast<size_t>(*n) > kMaxProgramBytes) return fail(d, 41, "length");
    if (running()) return fail(d, 16, "user program running");
    d = DownloadState{};
    if (*n == 0) return {};  // drops a transfer
    d.open = true;
    d.expected = static_cast<size_t>(*n);
    return {};
  }
  if (!d.open) return {"download not begun", 40};
  if (step == 2) {
    std::string bytes;
    if (!from_hex(arg, bytes) || bytes.size() > kMaxChunkBytes || bytes.empty())
      return fail(d, 42, "data");
    if (d.data.size() + bytes.size() > d.expected) return fail(d, 41, "length");
    d.data += bytes;
    return {};
  }
  const auto crc = parse_number(arg);
  if (!crc) return fail(d, 6, "argument wrong format");
  if (d.data.size() != d.expected) return fail(d, 41, "length");
  const std::string cup = std::move(d.data);
  d = DownloadState{};
  if (static_cast<uint32_t>(*crc) != expected_crc(cup)) return fail(d, 43, "CRC");
  const std::string why = install(cup, true);
  if (why.empty()) {
    runtime_.log(fmt::format("program downloaded ({} bytes)", cup.size()));
    return {};
  }
  // "error N: text"
  const int32_t code = std::atoi(why.c_str() + 6);
  return fail(d, code == 0 ? 45 : code, why.substr(why.find(':') + 2));
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
