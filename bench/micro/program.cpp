// Loads assembly or Gold source into a bare VM and runs main, for the micro-benchmarks.
#include "program.h"

#include "bytecode/assembly.h"
#include "dialects/gold/compile.h"
#include "support/diagnostic.h"

namespace uprog::bench {

vm::CommandStatus NullHost::read(uint32_t, int32_t, Value& out) {
  out = Value::of_int(0);
  return vm::kCommandOk;
}
vm::CommandStatus NullHost::write(uint32_t, int32_t, Value) { return vm::kCommandOk; }
vm::CommandStatus NullHost::execute(uint32_t, int32_t, const Value*, uint32_t) {
  return vm::kCommandOk;
}

std::string Program::load_assembly(const std::string& text) {
  bytecode::Image image;
  std::vector<Diagnostic> errors;
  if (!bytecode::assemble(text, "bench.s", image, errors)) return format_text(errors);
  return load(std::move(image));
}

std::string Program::load_gold(const std::string& source) {
  gold::CompileResult r = gold::compile(SourceFile{"bench.ehl", source});
  if (!r.ok()) return format_text(r.diagnostics);
  return load(std::move(r.image));
}

std::string Program::load(bytecode::Image image) {
  image_ = std::move(image);
  bytes_ = bytecode::encode(image_);
  bytecode::ImageView view;
  if (bytecode::load_image(bytes_.data(), bytes_.size(), view) != bytecode::LoadError::Ok)
    return "the image does not load";
  const vm::MachineConfig config;
  memory_.assign(vm::Machine::memory_needed(view, config) / 8 + 1, 0);
  const vm::LoadStatus st = machine_.load(bytes_.data(), bytes_.size(), config, memory_.data(),
                                          memory_.size() * 8, host_);
  if (!st.ok()) return "the VM refuses the image";
  const int r = image_.find_routine("main");
  if (r < 0) return "no routine main";
  main_ = static_cast<uint32_t>(r);
  return {};
}

bool Program::run_main() {
  machine_.start(0, main_);
  return machine_.run_slice(0, vm::Budget::unlimited()).end == vm::SliceEnd::Finished;
}

uint64_t Program::count_main() {
  machine_.start(0, main_);
  const vm::SliceResult r = machine_.run_slice(0, vm::Budget::of_instructions(UINT64_MAX / 2));
  return r.end == vm::SliceEnd::Finished ? r.executed : 0;
}

int32_t Program::global_int(const std::string& name) const {
  Value v = Value::of_int(0);
  const int g = image_.find_global(name);
  if (g >= 0) machine_.read_global(static_cast<uint32_t>(g), 0, v);
  return v.i;
}

}  // namespace uprog::bench
