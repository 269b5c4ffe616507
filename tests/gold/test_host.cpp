// The Gold tests' Host.
#include "test_host.h"

namespace uprog::gold_test {

vm::CommandStatus TestHost::read(uint32_t command, int32_t index, Value& out) {
  auto it = values.find({command, index});
  out = it == values.end() ? Value::of_int(0) : it->second;
  return vm::kCommandOk;
}

vm::CommandStatus TestHost::write(uint32_t command, int32_t index, Value value) {
  if (command == refuse_write) return 21;
  values[{command, index}] = value;
  return vm::kCommandOk;
}

vm::CommandStatus TestHost::execute(uint32_t command, int32_t, const Value*, uint32_t) {
  executed.push_back(command);
  return vm::kCommandOk;
}

}  // namespace uprog::gold_test
