// A program loaded into a bare VM for the micro-benchmarks: built from uprog assembly or Gold
// source, run from `main` to its end with an unlimited budget on a Host that does nothing.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "vm/machine.h"

namespace uprog::bench {

class NullHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t, int32_t, Value& out) override;
  vm::CommandStatus write(uint32_t, int32_t, Value) override;
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override;
  uint32_t now_us() override { return 0; }
  ~NullHost() = default;
};

class Program {
 public:
  // Returns an error text, empty on success.
  std::string load_assembly(const std::string& text);
  std::string load_gold(const std::string& source);
  // Runs main to its end with no budget, as a drive runs a program between waits (the VM's
  // uncounted loop); false when it did not finish.
  bool run_main();
  // Runs main once under an instruction budget to count its instructions (0: did not finish).
  uint64_t count_main();
  int32_t global_int(const std::string& name) const;

 private:
  std::string load(bytecode::Image image);

  bytecode::Image image_;
  std::vector<uint8_t> bytes_;
  std::vector<uint64_t> memory_;
  NullHost host_;
  vm::Machine machine_;
  uint32_t main_ = 0;
};

}  // namespace uprog::bench
