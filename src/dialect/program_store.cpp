// The program store over the drive's flash (program_store.h).
#include "dialect/program_store.h"

namespace uprog::dialect {

std::optional<std::vector<uint8_t>> ProgramStore::read(Flash& flash, const Check& check,
                                                       std::vector<std::string>& messages,
                                                       std::string_view consequence) const {
  std::string error;
  auto bytes = flash.read(record_, &error);
  const std::string stored = "stored " + noun_ + " " + flash.where(record_);
  if (!bytes) {
    if (!error.empty()) messages.push_back(stored + " unreadable: " + error);
    return std::nullopt;
  }
  if (check) {
    const std::string why = check(*bytes);
    if (!why.empty()) {
      messages.push_back(stored + " refused: " + why + std::string(consequence));
      return std::nullopt;
    }
  }
  return bytes;
}

DownloadResult ProgramStore::store(Flash& flash, const std::vector<uint8_t>& bytes,
                                   const Check& check) const {
  DownloadResult r;
  if (check) {
    r.error = check(bytes);
    if (!r.error.empty()) return r;
  }
  std::string error;
  if (!flash.write(record_, bytes, &error)) {
    r.storage_failed = true;
    r.error = "could not store the " + noun_ + ": " + error;
    return r;
  }
  r.ok = true;
  return r;
}

}  // namespace uprog::dialect
