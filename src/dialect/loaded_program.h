// An image in RAM with the machine that runs it: the one way anything in uprog loads an image
// into a machine (container check, CRC, verifier, memory sized for the configuration).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "bytecode/image.h"
#include "vm/machine.h"

namespace uprog::dialect {

class LoadedProgram {
 public:
  // nullptr with `error` set when the bytes are not a sound image ("not a valid image: …", "the
  // verifier refused it: … at code word N"). With `decode`, image() holds the hosted form (names,
  // line table) for the command line and the debugger. With `dialect`, an image another
  // dialect's compiler made is refused too (a hand-made image names none and is taken).
  static std::unique_ptr<LoadedProgram> load(std::vector<uint8_t> bytes,
                                             const vm::MachineConfig& config, vm::Host& host,
                                             std::string* error, bool decode = true,
                                             std::string_view dialect = {});
  LoadedProgram(const LoadedProgram&) = delete;
  LoadedProgram& operator=(const LoadedProgram&) = delete;

  vm::Machine& machine() { return machine_; }
  const vm::Machine& machine() const { return machine_; }
  const bytecode::Image& image() const { return image_; }
  const std::vector<uint8_t>& bytes() const { return bytes_; }
  // The source place of code word `pc` ("f.ehl:12"), or "code word N" without a line table.
  std::string where(uint32_t pc) const;
  // where(pc) with the file's directories dropped ("f.ehl:12"): what a drive reports does not
  // depend on where the program was built.
  std::string place(uint32_t pc) const;

 private:
  LoadedProgram() = default;

  std::vector<uint8_t> bytes_;
  std::vector<uint64_t> memory_;
  bytecode::Image image_;
  vm::Machine machine_;
};

}  // namespace uprog::dialect
