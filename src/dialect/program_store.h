// The one way a dialect's firmware keeps its program's stored form in the drive's flash: checked
// before it is stored, stored atomically (a kill leaves the old form or the new one whole, and no
// temporary: support/files.h), read once at power-up and checked again before it is trusted.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dialect/firmware.h"
#include "dialect/runtime.h"

namespace uprog::dialect {

class ProgramStore {
 public:
  // "" when a stored form is sound, else why not (the verifier's finding, a parse error).
  using Check = std::function<std::string(const std::vector<uint8_t>&)>;

  // `record`: the flash record ("program.upi"); `noun`: what the messages call its contents
  // ("program", "PLC source").
  ProgramStore(std::string_view record, std::string_view noun) : record_(record), noun_(noun) {}

  std::string_view record() const { return record_; }

  // At power-up: the stored form, when the flash holds one and `check` (if any) finds it sound.
  // A record that cannot be read or is refused adds a message ("stored program state/program.upi
  // refused: WHY" + `consequence`) and gives nullopt; an absent record gives nullopt silently.
  std::optional<std::vector<uint8_t>> read(Flash& flash, const Check& check,
                                           std::vector<std::string>& messages,
                                           std::string_view consequence = "") const;

  // A download: `check` (if any) first, then the atomic store. On a refusal or a failed store
  // the stored form in the flash is unchanged and the result says why.
  DownloadResult store(Flash& flash, const std::vector<uint8_t>& bytes,
                       const Check& check = nullptr) const;

 private:
  std::string record_;
  std::string noun_;
};

}  // namespace uprog::dialect
