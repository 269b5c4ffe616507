// The S300 firmware's lifecycle and its PLC (firmware.h): boot, the stored source, compiling with
// the MSG report, starting the cyclic tasks, F31/F32, and the Host the VM calls.
#include "dialects/st/firmware.h"

#include <fmt/core.h>

#include "bytecode/image.h"
#include "dialect/program_store.h"
#include "dialects/st/codegen.h"
#include "dialects/st/names.h"
#include "drive/axis.h"
#include "support/format_message.h"
#include "vm/run_error.h"

namespace uprog::st {
namespace {

const dialect::ProgramStore kSourceStore{"program.st", "PLC source"};
constexpr uint64_t kCostlyCallLines = 625;  // XREAD, XWRITE, COMMAND, PRINTF

vm::MachineConfig machine_config() {
  vm::MachineConfig c;
  c.threads = 7;  // one per program
  c.stack = 512;  // an expression may nest 200 deep (parser.cpp)
  return c;
}

// PLCMAIN's pass counter (codegen.h): its routine's last local.
uint32_t passes_local_of(const bytecode::ImageView& image, uint32_t routine) {
  const bytecode::RoutineRecord r = image.routines[routine];
  if (r.locals == 0) return scheduling::CyclicTasks::kNoLocal;
  const bytecode::LocalRecord l = image.locals[r.first_local + r.locals - 1];
  return image.string(l.name) == kMainPassesLocal ? r.locals - 1
                                                  : scheduling::CyclicTasks::kNoLocal;
}

}  // namespace

Firmware::Firmware(dialect::Runtime& runtime, dialect::WireStyle wire_style)
    : runtime_(runtime), wire_(prompt_, wire_style) {
  defaults();
}

void Firmware::boot(std::vector<std::string>& messages) {
  ++boots_;
  axis_ = &runtime_.axis();
  axis_->set_period_us(static_cast<int32_t>(kStepNs / 1000));
  stop_plc();
  faults_.clear();
  run_error_ = vm::RunError::None;
  compile_failed_ = false;
  enabled_ = false;
  tasks_.clear();
  mtmux_ = last_move_ = 0;
  next_pending_ = false;
  jog_until_ns_ = 0;
  deferred_ = Deferred{};  // a J or MOVE that waited for EN's delay is gone with the reboot
  reference_set_ = false;
  defaults();
  load();
  apply_limits();
  end_homing();
  // The inputs' functions are read at boot only (the reference's IN1MODE: "switched off and
  // then on again after an alteration").
  for (size_t n = 0; n < input_modes_.size(); ++n)
    input_modes_[n] = values_.at("IN" + std::to_string(n + 1) + "MODE");
  ancnfg_ = values_.at("ANCNFG");  // also a configuration the reference takes at boot
  analog_rpm_.reset();
  source_.reset();
  // Checked when it compiles (compile_and_start), as the drive compiles it at every boot.
  if (auto bytes = kSourceStore.read(runtime_.flash(), nullptr, messages))
    source_ = std::string(bytes->begin(), bytes->end());
  compile_and_start();
}

bool Firmware::stage_on() const { return axis_ != nullptr && axis_->motor_on(); }

std::string Firmware::source_name() const {
  if (source_ && !source_name_.empty() && *source_ == named_source_) return source_name_;
  return std::string(kSourceStore.record());
}

dialect::DownloadResult Firmware::download(const std::vector<uint8_t>& source) {
  dialect::DownloadResult r;
  if (source.size() > kMaxStoredSource) {
    r.error = "the source is over 61440 bytes";
    return r;
  }
  r = kSourceStore.store(runtime_.flash(), source);
  if (!r.ok) return r;
  source_ = std::string(source.begin(), source.end());
  r.ok = true;
  runtime_.log("PLC source stored (" + std::to_string(source.size()) + " bytes)");
  return r;
}

std::string Firmware::start(std::string_view) {
  const int32_t code = compile_and_start();
  if (code == 0) return "";
  return code == kErrCompileFailed ? "the PLC program did not compile"
                                   : "PLCRUN refused (ERR " + std::to_string(code) + ")";
}

int32_t Firmware::plc_state() const {
  if (!source_) return -2;
  if (compile_failed_) return -1;
  return plc_started_ ? 1 : 0;
}

std::optional<int32_t> Firmware::parameter_value(std::string_view name) {
  auto it = values_.find(upper(name));
  if (it != values_.end()) return it->second;
  if (auto n = user_variable_number(name)) return user_vars_[static_cast<size_t>(*n - 1)];
  return std::nullopt;
}

int32_t Firmware::compile_and_start() {
  if (enabled_) return kErrNeedsDisabled;
  stop_plc();
  if (!source_) {
    if (msg_ >= 1) say("No PLC program !");
    return kErrCompileFailed;
  }
  CompileOptions options;
  options.parameter = [this](std::string_view name) { return parameter_value(name); };
  const CompileResult r = compile(SourceFile{source_name(), *source_}, options);
  compile_failed_ = !r.ok();
  report_compile(r);
  program_.reset();  // the old program's globals go with it
  globals_.clear();
  threads_.clear();
  if (compile_failed_) {
    latch(32);
    return kErrCompileFailed;
  }
  std::string error;
  program_ = dialect::LoadedProgram::load(bytecode::encode(r.image), machine_config(), *this,
                                          &error, true, "st");
  if (!program_) {
    compile_failed_ = true;
    runtime_.log("compiled PLC program refused: " + error);
    latch(32);
    return kErrCompileFailed;
  }
  faults_.erase(31);
  faults_.erase(32);
  run_error_ = vm::RunError::None;
  globals_ = program_->image().globals;
  global_bits_ = r.global_bits;
  vm::Machine& m = program_->machine();
  for (size_t i = 0; i < kUserVariables; ++i)
    m.write_global(static_cast<uint32_t>(i), 0, Value::of_int(user_vars_[i]));
  schedule_.clear();
  threads_.clear();
  uint32_t thread = 0;
  for (const bytecode::Task& t : program_->image().tasks) {
    const auto kind = static_cast<ProgramKind>(t.number);
    if (kind == ProgramKind::Init)
      schedule_.set_init(thread, t.routine);
    else if (kind == ProgramKind::Main)
      schedule_.set_background(thread, t.routine, passes_local_of(m.image(), t.routine));
    else
      schedule_.add_task(thread, t.routine, t.period_ns);
    threads_.push_back({thread, std::string(program_name(kind))});
    ++thread;
  }
  if (!schedule_.start(m, runtime_.now_ns())) {
    compile_failed_ = true;
    latch(32);
    return kErrCompileFailed;
  }
  plc_started_ = true;
  runtime_.log("PLC started");
  return 0;
}

// MSG=2: "PLC compile", the sizes (or the errors), the load factor, "PLC start"; MSG=1: only
// errors and the last line.
void Firmware::report_compile(const CompileResult& r) {
  const bool all = msg_ >= 2;
  if (all) say("PLC compile");
  bool load_error = false;
  bool other_errors = false;
  for (const Diagnostic& d : r.diagnostics) {
    if (d.code == static_cast<int>(Error::LoadTooHigh))
      load_error = true;
    else
      other_errors = true;
  }
  if (all && !other_errors) {
    for (const ProgramSize& s : r.sizes.sizes) say(fmt::format("{} (size={})", s.name, s.size));
    if (!load_error) say(fmt::format("load factor {}", r.sizes.load));
  }
  if (msg_ >= 1) {
    for (const Diagnostic& d : r.diagnostics) {
      if (d.code == static_cast<int>(Error::LoadTooHigh))
        say(fmt::format("too high: load factor {} > {} [st 32]", r.sizes.load, kMaxLoad));
      else
        say(fmt::format("line {}: {} [st {}]", d.where.line, d.message, d.code));
    }
    say(r.ok() ? "PLC start" : "PLC not started");
  }
}

void Firmware::stop_plc(uint32_t failed) {
  if (program_) {
    sync_user_variables_out();
    schedule_.stop(program_->machine(), failed);
  }
  plc_started_ = false;
}

void Firmware::sync_user_variables_out() {
  if (!program_) return;
  for (size_t i = 0; i < kUserVariables; ++i) {
    Value v;
    if (program_->machine().read_global(static_cast<uint32_t>(i), 0, v)) user_vars_[i] = v.i;
  }
}

void Firmware::latch(int fault) {
  faults_.insert(fault);
  if (axis_ != nullptr && axis_->motor_on()) {
    axis_->stop();
    axis_->set_motor_on(false);
  }
  enabled_ = false;
}

void Firmware::cycle(const std::vector<uint32_t>&) {
  if (axis_->motor_fault() != 0) {
    record_axis_faults();
    enabled_ = false;  // the fault switched the stage off
  }
  step_motion();
  if (!plc_started_ || !program_) return;
  on_report(schedule_.run(program_->machine(), runtime_.now_ns()));
}

void Firmware::on_report(const scheduling::Report& report) {
  if (report.threads_with_events() == 0) return;
  for (const auto& [thread, name] : threads_) {
    if (report.has(thread, scheduling::ThreadEvent::Overrun)) {
      runtime_.log(name + " overran its time: F32");
      stop_plc();
      latch(32);
      return;
    }
    if (report.has(thread, scheduling::ThreadEvent::Error)) {
      run_error_ = program_->machine().last_error(thread);
      runtime_.log(fmt::format("{}: run-time error {} ({}) at {}: F31", name,
                               static_cast<int>(run_error_), vm::run_error_text(run_error_),
                               program_->where(program_->machine().pc(thread))));
      stop_plc(thread);
      latch(31);
      return;
    }
  }
}

std::string Firmware::program_error_text() const {
  return run_error_ == vm::RunError::None ? std::string() : vm::run_error_text(run_error_);
}

std::string Firmware::state_summary() const {
  return fmt::format("PLC={} PFB={} ACTIVE={} faults={}", plc_state(), user_of(axis_->position()),
                     axis_->motor_on() ? 1 : 0, faults_.size());
}

std::vector<dialect::ThreadInfo> Firmware::threads() const {
  std::vector<dialect::ThreadInfo> out;
  if (!program_) return out;
  const vm::Machine& m = program_->machine();
  for (const auto& [thread, name] : threads_) {
    dialect::ThreadInfo t;
    t.thread = thread;
    t.name = name;
    t.status = m.status(thread);
    if (t.status != vm::ThreadStatus::Idle) t.where = program_->where(m.pc(thread));
    t.error = static_cast<int32_t>(m.last_error(thread));
    out.push_back(std::move(t));
  }
  return out;
}

// --- Host: XREAD, XWRITE, COMMAND and PRINTF go through the command line; a refusal does not
// stop the program (MSG >= 1 prints it with the program and line). Each costs 625 lines and ends
// the machine's slice, so that the schedule looks at its budget again once the line has ended.

namespace {

std::string running_place(const dialect::LoadedProgram& program, uint32_t thread,
                          const std::vector<std::pair<uint32_t, std::string>>& names) {
  std::string name = "PLC";
  for (const auto& [t, n] : names)
    if (t == thread) name = n;
  const bytecode::LineEntry* line = program.image().line_at(program.machine().pc(thread));
  return fmt::format("{} line {}", name, line ? line->line : 0);
}

}  // namespace

// The running program and its line, for the messages a refused call gives.
std::string Firmware::running_here() const {
  return running_place(*program_, scheduling::running_now(schedule_.running(), debugger_runs_),
                       threads_);
}

vm::CommandStatus Firmware::read(uint32_t command, int32_t, Value& out) {
  schedule_.charge(kCostlyCallLines);
  const AsciiEntry* e = ascii_by_id(command);
  out = Value::of_int(0);
  if (e == nullptr) return vm::kCommandEndSlice;
  in_program_ = true;
  const std::vector<dialect::Answer> a = command_line(e->name);
  in_program_ = false;
  if (!a.empty() && !a[0].is_error()) {
    const double v = std::strtod(a[0].text.c_str(), nullptr);
    out = Value::of_int(v >= 2147483647.0    ? INT32_MAX
                        : v <= -2147483648.0 ? INT32_MIN
                                             : static_cast<int32_t>(v));
  } else if (!a.empty() && msg_ >= 1) {
    say(running_here() + ": " + answer_text(a[0]).substr(1));
  }
  return vm::kCommandEndSlice;
}

vm::CommandStatus Firmware::write(uint32_t command, int32_t, Value value) {
  schedule_.charge(kCostlyCallLines);
  const AsciiEntry* e = ascii_by_id(command);
  if (e == nullptr) return vm::kCommandEndSlice;
  in_program_ = true;
  const std::vector<dialect::Answer> a =
      command_line(std::string(e->name) + " " + std::to_string(value.i));
  in_program_ = false;
  if (!a.empty() && a[0].is_error() && msg_ >= 1)
    say(running_here() + ": " + answer_text(a[0]).substr(1));
  return vm::kCommandEndSlice;
}

vm::CommandStatus Firmware::execute(uint32_t command, int32_t, const Value* args, uint32_t count) {
  schedule_.charge(kCostlyCallLines);
  if (command != kCommandAction || count != 1 || !program_) return vm::kCommandEndSlice;
  const std::string_view text = program_->machine().image().text(static_cast<uint32_t>(args[0].i));
  in_program_ = true;
  const std::vector<dialect::Answer> answers = command_line(text);
  in_program_ = false;
  for (const dialect::Answer& a : answers) {
    if (a.is_error() && msg_ >= 1) say(running_here() + ": " + answer_text(a).substr(1));
  }
  return vm::kCommandEndSlice;
}

vm::CommandStatus Firmware::message(uint32_t, uint32_t text, const Value* args, uint32_t count) {
  schedule_.charge(kCostlyCallLines);
  if (!program_) return vm::kCommandEndSlice;
  runtime_.output(format_message(program_->machine().image().text(text), args, count));
  return vm::kCommandEndSlice;
}

}  // namespace uprog::st
