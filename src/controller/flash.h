// The drive's flash (dialect::Flash): one file per record in the state directory, each replaced
// atomically; without a state directory, records in memory for the life of the drive.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "dialect/runtime.h"

namespace uprog::controller {

class StateFlash final : public dialect::Flash {
 public:
  // Creates `state_dir` when it does not exist; "" keeps everything in memory.
  explicit StateFlash(std::string state_dir);
  std::optional<std::vector<uint8_t>> read(std::string_view name, std::string* error) override;
  bool write(std::string_view name, std::span<const uint8_t> bytes, std::string* error) override;
  std::string where(std::string_view name) const override;

 private:
  std::string dir_;
  std::map<std::string, std::vector<uint8_t>, std::less<>> memory_;
};

}  // namespace uprog::controller
