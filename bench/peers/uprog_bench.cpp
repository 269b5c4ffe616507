// The peers' bench driver: compiles a Gold (or PDL) file, runs `main` to its end with an unlimited
// budget on the bare VM (a fake Host, no drive simulation), prints the globals named by --then. A
// .pup file is compiled to CUP and loaded as the AG300 loads it; it runs task 1 on a host that
// keeps AGenData[1..1000] (--then AGenData[N]), every other keyword reading 0.
// --histogram counts executed opcodes and opcode pairs instead (one instruction per slice);
// A .s file (uprog assembly, e.g. hand-edited --asm output) is assembled and run through the
// same peephole pass, to measure a code-generation change before the compiler makes it.
// A .st file (ST) runs PLCMAIN, which restarts by itself when it ends: give --histogram a
// --limit (its --asm shows the code).
// --check only compiles (the compile-speed comparison while `uprog check` does not exist).
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bytecode/assembly.h"
#include "bytecode/image.h"
#include "bytecode/opcodes.h"
#include "bytecode/peephole.h"
#include "dialects/gold/compile.h"
#include "dialects/pdl/compile.h"
#include "dialects/pdl/layout.h"
#include "dialects/pup/cup_loader.h"
#include "dialects/pup/pup_compiler.h"
#include "dialects/st/compile.h"
#include "support/diagnostic.h"
#include "vm/machine.h"

namespace {

using uprog::Value;
namespace bc = uprog::bytecode;
namespace vm = uprog::vm;

// No drive: commands read 0 and succeed; the clock moves only when the program waits.
class FakeHost final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t, int32_t, Value& out) override {
    out = Value::of_int(0);
    return vm::kCommandOk;
  }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return vm::kCommandOk; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override {
    return vm::kCommandOk;
  }
  uint32_t now_us() override { return now; }
  uint32_t now = 0;
  ~FakeHost() = default;
};

// The AG300's general data as the firmware keeps it, for a CUP image: the image's AGenData global
// placed on it (bind_gen_data), and the indexed accesses (APushParamIdx/APopParamIdx) of the
// loaded program.
class PupHost final : public vm::Host {
 public:
  explicit PupHost(const std::vector<uprog::pup::IndexedAccess>& indexed) : indexed_(indexed) {}
  vm::CommandStatus read(uint32_t command, int32_t index, Value& out) override {
    const Value* cell = at(command, index);
    out = cell != nullptr ? *cell : Value::of_int(0);
    return vm::kCommandOk;
  }
  vm::CommandStatus write(uint32_t command, int32_t index, Value value) override {
    if (Value* cell = at(command, index)) *cell = value;
    return vm::kCommandOk;
  }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override {
    return vm::kCommandOk;
  }
  uint32_t now_us() override { return now; }
  uint32_t now = 0;
  std::array<Value, uprog::pup::kGenDataSize> gen_data{};

 private:
  Value* at(uint32_t command, int32_t index) {
    int32_t n = index;
    if (command >= uprog::pup::kIndexedBase &&
        command - uprog::pup::kIndexedBase < indexed_.size()) {
      const uprog::pup::IndexedAccess& a = indexed_[command - uprog::pup::kIndexedBase];
      if (a.key != uprog::pup::KeywordId::GenData || index < 1 || index > a.size) return nullptr;
      n = a.base + index - 1;
    } else if (command != static_cast<uint32_t>(uprog::pup::KeywordId::GenData)) {
      return nullptr;
    }
    return n >= 1 && n <= static_cast<int32_t>(gen_data.size())
               ? &gen_data[static_cast<size_t>(n - 1)]
               : nullptr;
  }
  const std::vector<uprog::pup::IndexedAccess>& indexed_;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_histogram(const std::vector<uint64_t>& ops, const std::vector<uint64_t>& pairs,
                     uint64_t total) {
  std::vector<std::pair<uint64_t, std::string>> rows;
  for (size_t op = 0; op < bc::kOpCount; ++op)
    if (ops[op] != 0) rows.emplace_back(ops[op], bc::kOpNames[op]);
  std::sort(rows.rbegin(), rows.rend());
  std::printf("executed %llu instructions\nopcode            count      share\n",
              static_cast<unsigned long long>(total));
  for (const auto& [n, name] : rows)
    std::printf("%-12s %12llu  %5.1f%%\n", name.c_str(), static_cast<unsigned long long>(n),
                100.0 * static_cast<double>(n) / static_cast<double>(total));
  rows.clear();
  for (size_t p = 0; p < pairs.size(); ++p)
    if (pairs[p] != 0)
      rows.emplace_back(pairs[p], std::string(bc::kOpNames[p / 256]) + " " + bc::kOpNames[p % 256]);
  std::sort(rows.rbegin(), rows.rend());
  std::printf("\nopcode pair                 count      share\n");
  for (size_t i = 0; i < rows.size() && i < 25; ++i)
    std::printf("%-22s %12llu  %5.1f%%\n", rows[i].second.c_str(),
                static_cast<unsigned long long>(rows[i].first),
                100.0 * static_cast<double>(rows[i].first) / static_cast<double>(total));
}

}  // namespace

// "name" or "name[k]": the global's name and the element the user wrote (AGenData counts
// from 1, a program's own arrays from 0, as each dialect's command line reads them); -1 for an
// index that is not a number.
std::pair<std::string, int> split_index(const std::string& name) {
  const size_t open = name.find('[');
  if (open == std::string::npos || name.back() != ']') return {name, 0};
  const std::string digits = name.substr(open + 1, name.size() - open - 2);
  const bool number = !digits.empty() && digits.size() < 9 &&
                      digits.find_first_not_of("0123456789") == std::string::npos;
  return {name.substr(0, open), number ? std::stoi(digits) : -1};
}

int main(int argc, char** argv) {
  std::string file;
  std::vector<std::string> then;
  uint64_t limit = 0;  // --histogram: stop after this many instructions (0: run to the end)
  bool histogram = false, emit_asm = false, timing = false, check = false, peephole = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--then" && i + 1 < argc)
      then.emplace_back(argv[++i]);
    else if (arg == "--histogram")
      histogram = true;
    else if (arg == "--asm")
      emit_asm = true;
    else if (arg == "--timing")
      timing = true;
    else if (arg == "--check")
      check = true;
    else if (arg == "--no-peephole")
      peephole = false;
    else if (arg == "--limit" && i + 1 < argc)
      limit = std::stoull(argv[++i]);
    else
      file = arg;
  }
  if (file.empty()) {
    std::fprintf(stderr,
                 "usage: uprog_bench FILE.ehl|FILE.s [--then GLOBAL]... [--asm] [--no-peephole] "
                 "[--check] [--histogram [--limit N]] [--timing]\n");
    return 2;
  }
  const auto compile_start = std::chrono::steady_clock::now();
  uprog::gold::CompileResult compiled;
  std::optional<uprog::pup::LoadedCup> pup_loaded;
  if (file.size() > 2 && file.compare(file.size() - 2, 2, ".s") == 0) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    if (!bc::assemble(text.str(), file, compiled.image, compiled.diagnostics)) {
      std::fprintf(stderr, "%s", uprog::format_text(compiled.diagnostics).c_str());
      return 1;
    }
    if (peephole) bc::optimize(compiled.image);
  } else if (file.size() > 4 && file.compare(file.size() - 4, 4, ".pdl") == 0) {
    uprog::pdl::CompileResult pdl = uprog::pdl::compile_file(file);
    compiled.image = std::move(pdl.image);
    compiled.diagnostics = std::move(pdl.diagnostics);
  } else if (file.size() > 3 && file.compare(file.size() - 3, 3, ".st") == 0) {
    uprog::st::CompileResult st = uprog::st::compile_file(file);
    compiled.image = std::move(st.image);
    compiled.diagnostics = std::move(st.diagnostics);
  } else if (file.size() > 4 && file.compare(file.size() - 4, 4, ".pup") == 0) {
    uprog::pup::PupOutput pup = uprog::pup::compile_pup_file(file, 0);
    compiled.diagnostics = std::move(pup.diagnostics);
    std::string why;
    if (compiled.ok()) {
      pup_loaded = uprog::pup::load_cup(pup.program, &why);
      if (!pup_loaded) {
        std::fprintf(stderr, "%s: the loader refuses it: %s\n", file.c_str(), why.c_str());
        return 1;
      }
      compiled.image = pup_loaded->image;
    }
  } else {
    uprog::gold::CompileOptions options;
    options.optimize = peephole;
    options.max_program_bytes = 0;  // the workloads are larger than a drive's 64 KB (2.17)
    compiled = uprog::gold::compile_file(file, options);
  }
  if (!compiled.ok()) {
    std::fprintf(stderr, "%s", uprog::format_text(compiled.diagnostics).c_str());
    return 1;
  }
  const double compile_s = seconds_since(compile_start);
  if (check) {
    if (timing) std::fprintf(stderr, "compile %.6f s\n", compile_s);
    return 0;
  }
  const bc::Image& image = compiled.image;
  if (emit_asm) {
    std::printf("%s", bc::disassemble(image).c_str());
    return 0;
  }
  const std::vector<uint8_t> bytes = bc::encode(image);
  bc::ImageView view;
  if (bc::load_image(bytes.data(), bytes.size(), view) != bc::LoadError::Ok) {
    std::fprintf(stderr, "the image does not load\n");
    return 1;
  }
  const vm::MachineConfig config;
  std::vector<uint64_t> memory(vm::Machine::memory_needed(view, config) / 8 + 1);
  FakeHost fake_host;
  static const std::vector<uprog::pup::IndexedAccess> kNoAccess;
  PupHost pup_host(pup_loaded ? pup_loaded->indexed : kNoAccess);
  vm::Host& vm_host =
      pup_loaded ? static_cast<vm::Host&>(pup_host) : static_cast<vm::Host&>(fake_host);
  uint32_t& now = pup_loaded ? pup_host.now : fake_host.now;
  vm::Machine machine;
  const vm::LoadStatus status =
      machine.load(bytes.data(), bytes.size(), config, memory.data(), memory.size() * 8, vm_host);
  if (!status.ok()) {
    std::fprintf(stderr, "the VM refuses the image (verify error %d at pc %u)\n",
                 static_cast<int>(status.verify), status.pc);
    return 1;
  }
  if (pup_loaded) {
    if (!uprog::pup::bind_gen_data(machine, *pup_loaded, pup_host.gen_data)) {
      std::fprintf(stderr, "AGenData cannot be placed\n");
      return 1;
    }
    const int32_t task = pup_loaded->task_routine.size() > 1 ? pup_loaded->task_routine[1] : -1;
    if (task < 0) {
      std::fprintf(stderr, "no AProgTask[1]\n");
      return 1;
    }
    machine.start(0, static_cast<uint32_t>(task));
  } else if (image.dialect == "pdl") {
    // A PDL program runs from the start of its code with task 1's stack registers.
    namespace pdl = uprog::pdl;
    const int32_t base = pdl::stack_base(1);
    const auto args = pdl::stack_registers(1, Value::of_int(base), base);
    machine.start(0, 0, args.data(), pdl::kEntryInputs);
  } else {
    const int main_routine = image.find_routine(image.dialect == "st" ? "PLCMAIN" : "main");
    if (main_routine < 0) {
      std::fprintf(stderr, "no function main\n");
      return 1;
    }
    machine.start(0, static_cast<uint32_t>(main_routine));
  }

  const auto run_start = std::chrono::steady_clock::now();
  // Only --histogram counts: a 512 KiB table zeroed in every run would be in the time measured.
  std::vector<uint64_t> ops(histogram ? 256 : 0), pairs(histogram ? 256 * 256 : 0);
  uint64_t executed = 0;
  uint32_t previous = UINT32_MAX;
  vm::SliceResult r{vm::SliceEnd::NotRunning, 0};
  for (;;) {
    if (histogram) {
      const uint32_t op = image.code[machine.pc(0)] & 0xFFu;
      r = machine.run_slice(0, vm::Budget::of_instructions(1));
      if (r.executed != 0) {
        ++ops[op];
        if (previous != UINT32_MAX) ++pairs[previous * 256 + op];
        previous = op;
      }
    } else {
      r = machine.run_slice(0, vm::Budget::unlimited());
    }
    executed += r.executed;
    if (r.end == vm::SliceEnd::Finished || (limit != 0 && executed >= limit)) break;
    if (r.end == vm::SliceEnd::Error) {
      std::fprintf(stderr, "run-time error %d at pc %u\n", static_cast<int>(machine.last_error(0)),
                   machine.pc(0));
      return 1;
    }
    if (r.end == vm::SliceEnd::Waiting) now += 1000;
  }
  const double run_s = seconds_since(run_start);
  if (histogram) print_histogram(ops, pairs, executed);
  if (timing)
    std::fprintf(stderr, "compile %.6f s, run %.6f s, %llu instructions\n", compile_s, run_s,
                 static_cast<unsigned long long>(executed));
  for (const std::string& name : then) {
    const auto [base, index] = split_index(name);
    if (pup_loaded && base == "AGenData") {
      if (index < 1 || index > static_cast<int32_t>(uprog::pup::kGenDataSize)) {
        std::fprintf(stderr, "no %s\n", name.c_str());
        return 1;
      }
      std::printf("%s=%d\n", name.c_str(), pup_host.gen_data[static_cast<size_t>(index - 1)].i);
      continue;
    }
    const int g = image.find_global(base);
    Value v = Value::of_int(0);
    if (g < 0 || index < 0 ||
        !machine.read_global(static_cast<uint32_t>(g), static_cast<uint32_t>(index), v)) {
      std::fprintf(stderr, "no global %s\n", name.c_str());
      return 1;
    }
    if (image.globals[static_cast<size_t>(g)].type == uprog::ValueType::Float)
      std::printf("%s=%.9g\n", name.c_str(), static_cast<double>(v.f));
    else
      std::printf("%s=%d\n", name.c_str(), v.i);
  }
  return 0;
}
