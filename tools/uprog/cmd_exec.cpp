// `uprog exec FILE`: runs an image (binary, or assembly assembled on the fly) on the bare VM,
// with no drive, in virtual time, and prints how it ended and the values of its globals.
#include <fmt/core.h>

#include <cstring>
#include <memory>
#include <vector>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "commands.h"
#include "dialect/loaded_program.h"
#include "support/diagnostic.h"
#include "support/files.h"
#include "support/format_message.h"
#include "vm/machine.h"

namespace uprog::cli {
namespace {

// A host without a drive: commands are refused, time advances only by waits, messages are
// printed on a line of their own.
class BareHost final : public vm::Host {
 public:
  explicit BareHost(const std::vector<std::string>& texts) : texts_(texts) {}
  vm::CommandStatus read(uint32_t, int32_t, Value&) override { return kNoDrive; }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return kNoDrive; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override { return kNoDrive; }
  vm::CommandStatus message(uint32_t, uint32_t text, const Value* args, uint32_t count) override {
    if (text >= texts_.size()) return kNoDrive;  // the verifier keeps this from happening
    fmt::print("{}\n", format_message(texts_[text], args, count));
    return vm::kCommandOk;
  }
  uint32_t now_us() override { return now_us_; }
  void advance_to(uint32_t t) { now_us_ = t; }

 private:
  static constexpr vm::CommandStatus kNoDrive = 1;
  const std::vector<std::string>& texts_;
  uint32_t now_us_ = 0;
};

// As many as `uprog check` shows of a Gold source (gold::CompileOptions::max_errors).
constexpr size_t kMaxErrorsShown = 30;

std::string format_value(const bytecode::Global& g, Value v) {
  return g.type == ValueType::Float ? fmt::format("{:g}", v.f) : fmt::format("{}", v.i);
}

int run(const std::string& path, const std::string& entry) {
  std::string error;
  auto bytes = read_binary_file(path, &error);
  if (!bytes) {
    fmt::print(stderr, "uprog exec: {}\n", error);
    return 1;
  }
  bytecode::Image image;
  const bool is_binary = bytes->size() >= 4 && std::memcmp(bytes->data(), "UPRG", 4) == 0;
  if (is_binary) {
    if (!bytecode::decode(bytes->data(), bytes->size(), image, error)) {
      fmt::print(stderr, "uprog exec: {}: {}\n", path, error);
      return 1;
    }
  } else {
    std::vector<Diagnostic> errors;
    SourceFile source{path, std::string(bytes->begin(), bytes->end())};
    if (!bytecode::assemble(source.text, path, image, errors)) {
      // Any file that is not an image is read as assembly: a binary one gives an error a line.
      limit_errors(errors, kMaxErrorsShown);
      attach_source_lines(errors, source);
      fmt::print(stderr, "{}", format_text(errors));
      return 1;
    }
    *bytes = bytecode::encode(image);
  }
  const int routine = image.find_routine(entry);
  if (routine < 0) {
    fmt::print(stderr, "uprog exec: {}: no routine named '{}'\n", path, entry);
    return 1;
  }

  BareHost host(image.texts);
  const auto program =
      dialect::LoadedProgram::load(std::move(*bytes), vm::MachineConfig{}, host, &error, false);
  if (!program) {
    fmt::print(stderr, "uprog exec: {}: {}\n", path, error);
    return 1;
  }
  vm::Machine& machine = program->machine();
  machine.start(0, static_cast<uint32_t>(routine));
  vm::SliceResult r{};
  for (;;) {
    r = machine.run_slice(0, vm::Budget::unlimited());
    if (r.end == vm::SliceEnd::Waiting) {
      host.advance_to(host.now_us() + 1000);  // waits advance virtual time in 1 ms steps
      continue;
    }
    if (r.end != vm::SliceEnd::Yielded) break;
  }
  const bool failed = r.end == vm::SliceEnd::Error;
  if (failed) {
    fmt::print("{}: stopped by run-time error {} ({}) at code word {}\n", entry,
               static_cast<int>(machine.last_error(0)), vm::run_error_text(machine.last_error(0)),
               machine.pc(0));
  } else {
    fmt::print("{}: finished after {} µs of virtual time\n", entry, host.now_us());
  }
  for (uint32_t g = 0; g < image.globals.size(); ++g) {
    const auto& global = image.globals[g];
    std::string values;
    for (uint32_t k = 0; k < global.length && k < 16; ++k) {
      Value v;
      machine.read_global(g, k, v);
      values += (k ? " " : "") + format_value(global, v);
    }
    if (global.length > 16) values += " ...";
    fmt::print("  {} = {}\n", global.name, values);
  }
  return failed ? 1 : 0;
}

void add_exec(Options& cmd, Action& action) {
  auto input = std::make_shared<std::string>();
  auto entry = std::make_shared<std::string>("main");
  cmd.option("FILE", *input, "image (.upi) or assembly (.s)").required();
  cmd.option("--entry", *entry, "routine to start").show_default();
  cmd.on_chosen(
      [&action, input, entry] { action = [input, entry] { return run(*input, *entry); }; });
}

const Subcommand kExec("exec", "Run an image or assembly file on the bare VM", add_exec);

}  // namespace
}  // namespace uprog::cli
