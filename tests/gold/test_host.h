// A Host for the Gold tests: drive commands as a plain table of values, a clock the test moves.
#pragma once
#include <map>
#include <utility>
#include <vector>

#include "vm/host.h"

namespace uprog::gold_test {

class TestHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override;
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override;
  vm::CommandStatus execute(uint32_t command, int32_t index, const Value* args,
                            uint32_t arg_count) override;
  uint32_t now_us() override { return now; }

  uint32_t now = 0;
  std::map<std::pair<uint32_t, int32_t>, Value> values;
  std::vector<uint32_t> executed;
  uint32_t refuse_write = 0;  // a command id whose writes fail (0: none)
  ~TestHost() = default;
};

}  // namespace uprog::gold_test
