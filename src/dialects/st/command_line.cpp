// The S300's ASCII command line (firmware.h; shared/spec/s300-drive.md's table): `NAME` reads,
// `NAME value …` writes or runs, case-insensitive; every global of the loaded program by name.
#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "dialects/st/firmware.h"
#include "dialects/st/names.h"
#include "drive/axis.h"
#include "drive/faults.h"

namespace uprog::st {
namespace {

using dialect::Answer;

std::vector<std::string> words_of(std::string_view line) {
  std::vector<std::string> out;
  std::istringstream in{std::string(line)};
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// A number: `out` whole (a float truncated, VLIM 3000.5), `real` as written (T 0.5).
bool to_number(const std::string& s, int64_t& out, double& real) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b != e && *b == '+') ++b;
  const auto [p, ec] = std::from_chars(b, e, out);
  if (ec == std::errc() && p == e) return real = static_cast<double>(out), true;
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || s.empty() || !std::isfinite(d) || std::fabs(d) > 9.2e18)
    return false;
  out = static_cast<int64_t>(d);
  real = d;
  return true;
}

Answer err(int32_t code, std::string text) { return Answer{std::move(text), code}; }
Answer value(int64_t v) { return Answer{std::to_string(v), 0}; }

struct FaultName {
  int number;
  const char* text;
  uint32_t bits;
};
// ERRCODE's texts are the reference's (Kollmorgen's S300/S700 PROFIBUS manual, PNU 1001, the
// manufacturer's error register: "Error F08: Overspeed", ...; docs/dialects/st.md, "Faults").
constexpr FaultName kAxisFaults[] = {
    {1, "Heatsink temperature", drive::kFaultTemperature},
    {2, "Overvoltage", drive::kFaultOvervoltage},
    {3, "Following error", drive::kFaultFollowingError},
    {4, "Feedback", drive::kFaultFeedback},
    {5, "Undervoltage", drive::kFaultUndervoltage},
    {8, "Overspeed", drive::kFaultSpeedLimit | drive::kFaultVelocityError},
    {14, "Output stage", drive::kFaultOvercurrent | drive::kFaultShort},
};

// The values a plain parameter takes: the SERVOSTAR-family reference's ranges where uprog
// simulates the parameter's whole meaning (VUNIT: rpm only, NREF: every type is stored).
std::pair<int64_t, int64_t> range_of(const std::string& name) {
  if (name == "PGEARI" || name == "PGEARO") return {1, INT32_MAX};
  if (name == "SRND" || name == "ERND" || name == "ROFFS") return {INT32_MIN, INT32_MAX};
  if (name == "ACC" || name == "DEC" || name == "DECSTOP") return {1, 32767};  // ms
  if (name == "ANCNFG") return {0, 14};
  if (name == "NREF") return {0, 20};
  if (name == "DREF") return {0, 2};
  if (name == "VUNIT") return {0, 1};
  if (name.starts_with("IN") && name.ends_with("MODE")) return {0, 50};
  if (name == "ANOFF1" || name == "ANOFF2") return {-10000, 10000};
  if (name == "VSCALE1" || name == "VSCALE2") return {-15000, 15000};
  return {0, INT32_MAX};
}

bool has_bits(uint32_t mf, uint32_t bits) {
  // Power-stage faults are codes in bits 13..15 (with bit 12), the rest single bits.
  if ((bits & drive::kFaultPowerStage) != 0) {
    const uint32_t code_bits =
        bits & ~(drive::kFaultVelocityError | drive::kFaultSpeedLimit | drive::kFaultOvercurrent);
    if ((mf & 0xF000u) == (code_bits & 0xF000u) && (code_bits & 0xF000u) != 0) return true;
    return (mf & bits & ~0xF000u) != 0;
  }
  return (mf & bits) != 0;
}

}  // namespace

std::vector<Answer> Firmware::command_line(std::string_view line) {
  const std::vector<std::string> w = words_of(line);
  if (w.empty()) return {};
  const std::string name = upper(w[0]);
  const size_t argc = w.size() - 1;
  std::vector<int64_t> args;
  std::vector<double> reals;
  for (size_t i = 1; i < w.size(); ++i) {
    int64_t v = 0;
    double real = 0;
    if (!to_number(w[i], v, real)) {
      if (name == "PLCDL" || is_debug_command(name)) break;
      return {err(kErrSyntax, "syntax error")};
    }
    args.push_back(v);
    reals.push_back(real);
  }
  const auto arg32 = [&](size_t i) { return static_cast<int32_t>(args[i]); };
  const auto fault_bits = [&] { return axis_->motor_fault(); };
  const auto faulted = [&] { return !faults_.empty() || fault_bits() != 0; };

  // The loaded program's globals, by name (DLONG as one 64-bit number).
  if (const AsciiEntry* e = find_ascii(name); program_ && (e == nullptr || !reserves_name(*e))) {
    for (size_t g = kUserVariables; g < globals_.size(); ++g) {
      if (globals_[g].name != name) continue;
      vm::Machine& m = program_->machine();
      const auto id = static_cast<uint32_t>(g);
      if (argc == 0) {
        Value lo, hi;
        m.read_global(id, 0, lo);
        if (globals_[g].length == 1) return {value(lo.i)};
        m.read_global(id, 1, hi);
        return {value(static_cast<int64_t>((uint64_t(uint32_t(hi.i)) << 32) | uint32_t(lo.i)))};
      }
      if (argc != 1) return {err(kErrSyntax, "syntax error")};
      // Cut to the variable's type, as the program's own store is (BB 200 reads -56).
      const uint8_t bits = g < global_bits_.size() ? global_bits_[g] : 32;
      const auto low = static_cast<uint32_t>(args[0]);
      const int32_t stored = bits == 8    ? static_cast<int8_t>(low & 0xFFu)
                             : bits == 16 ? static_cast<int16_t>(low & 0xFFFFu)
                                          : static_cast<int32_t>(low);
      m.write_global(id, 0, Value::of_int(stored));
      if (globals_[g].length == 2)
        m.write_global(id, 1,
                       Value::of_int(static_cast<int32_t>(static_cast<uint64_t>(args[0]) >> 32)));
      return {};
    }
  }

  const AsciiEntry* e = find_ascii(name);
  if (e == nullptr) return {err(kErrUnknown, "unknown command")};
  // A program cannot stop, replace or reboot itself from inside its own run.
  if (in_program_ && (name == "PLCSTOP" || name == "PLCRUN" || name == "PLCSTART" ||
                      name == "COLDSTART" || name == "PLCDL" || is_debug_command(name)))
    return {err(kErrSyntax, "not from a PLC program")};
  if (argc > 0 && e->access == AsciiAccess::Read) return {err(kErrReadOnly, "read only")};
  if (is_debug_command(name)) return debug_command(name, w);

  if (auto n = user_variable_number(name)) {
    const auto i = static_cast<size_t>(*n - 1);
    if (program_) {
      Value v;
      if (argc == 0)
        return program_->machine().read_global(static_cast<uint32_t>(i), 0, v),
               std::vector{value(v.i)};
      program_->machine().write_global(static_cast<uint32_t>(i), 0, Value::of_int(arg32(0)));
    }
    if (argc == 0) return {value(user_vars_[i])};
    if (args[0] < INT32_MIN || args[0] > INT32_MAX) return {err(kErrRange, "out of range")};
    user_vars_[i] = arg32(0);
    return {};
  }

  // --- enable, modes, motion ---
  if (name == "EN") {
    if (faulted()) return {err(kErrFault, "fault")};
    apply_limits();
    if (axis_->set_motor_on(true) != drive::Status::kOk) return {err(kErrFault, "fault")};
    enabled_ = true;
    return {};
  }
  if (name == "DIS") {
    axis_->stop();
    axis_->set_motor_on(false);
    enabled_ = false;
    next_pending_ = false;
    deferred_ = Deferred{};
    end_homing();
    return {};
  }
  if (name == "ACTIVE") return {value(axis_->motor_on() ? 1 : 0)};
  if (name == "OPMODE") {
    if (argc == 0) return {value(opmode_)};
    if (args[0] != 0 && args[0] != 1 && args[0] != 2 && args[0] != 8)
      return {err(kErrRange, "out of range")};
    if (axis_->motor_on()) return {err(kErrNeedsDisabled, "needs disabled")};
    opmode_ = arg32(0);
    axis_->set_unit_mode(opmode_ <= 1 ? 2 : opmode_ == 2 ? 1 : 5);
    return {};
  }
  if (name == "J") {
    if (argc < 1 || argc > 2) return {err(kErrSyntax, "syntax error")};
    const int32_t code = jog(arg32(0), argc == 2 ? arg32(1) : 0);
    return code == 0 ? std::vector<Answer>{}
                     : std::vector{err(code, code == kErrOpmode ? "OPMODE" : "needs enabled")};
  }
  if (name == "T") {
    if (argc != 1) return {err(kErrSyntax, "syntax error")};
    if (!axis_->motor_on()) return {err(kErrNeedsEnabled, "needs enabled")};
    if (opmode_ != 2) return {err(kErrOpmode, "OPMODE")};
    axis_->set_torque_command(static_cast<float>(reals[0]));
    return {};
  }
  if (name == "ORDER") {
    if (argc == 0) return {err(kErrSyntax, "syntax error")};
    const int32_t nr = arg32(0);
    if (!(nr == 0 || (nr >= 1 && nr <= 180) || (nr >= 192 && nr <= 255)))
      return {err(kErrRange, "out of range")};
    if (argc == 1) {
      auto it = tasks_.find(nr);
      const MotionTask t = it == tasks_.end() ? MotionTask{} : it->second;
      return {Answer{fmt::format("{} {} {} {} {} {} {} {} {} {}", nr, t.p, t.v, t.c, t.acc, t.dec,
                                 t.a2, t.d2, t.fn, t.ft),
                     0}};
    }
    if (argc != 10) return {err(kErrSyntax, "syntax error")};
    if (nr >= 1 && nr <= 180 && axis_->motor_on())
      return {err(kErrNeedsDisabled, "needs disabled")};
    MotionTask t{arg32(1), arg32(2), arg32(3), arg32(4), arg32(5),
                 arg32(6), arg32(7), arg32(8), arg32(9), true};
    tasks_[nr] = t;
    return {};
  }
  if (name == "MOVE") {
    if (argc == 0) return {value(last_move_)};
    const int32_t code = start_task(arg32(0));
    return code == 0 ? std::vector<Answer>{}
                     : std::vector{err(code, code == kErrTask     ? "no such task"
                                             : code == kErrOpmode ? "OPMODE"
                                                                  : "needs enabled")};
  }
  if (name == "STOP") {
    stop_motion();
    return {};
  }
  if (name == "MTMUX") {
    if (argc == 0) return {value(mtmux_)};
    if (!(args[0] == 0 || (args[0] >= 192 && args[0] <= 255)))
      return {err(kErrRange, "out of range")};
    mtmux_ = arg32(0);
    return {};
  }
  if (name.starts_with("O_")) {
    MotionTask& t = tasks_[mtmux_];
    t.defined = true;
    int32_t* field = name == "O_P"      ? &t.p
                     : name == "O_V"    ? &t.v
                     : name == "O_C"    ? &t.c
                     : name == "O_ACC1" ? &t.acc
                     : name == "O_DEC1" ? &t.dec
                     : name == "O_FN"   ? &t.fn
                                        : &t.ft;
    if (argc == 0) return {value(*field)};
    *field = arg32(0);
    return {};
  }
  if (name == "MH") {
    const int32_t code = start_homing();
    return code == 0 ? std::vector<Answer>{}
                     : std::vector{err(code, code == kErrRange    ? "homing type or input"
                                             : code == kErrOpmode ? "OPMODE"
                                                                  : "needs enabled")};
  }
  if (name == "SETREF") {
    set_reference();
    return {};
  }
  if (name == "ANIN1" || name == "ANIN2") return {value(analog_input_mv(name[4] - '0'))};
  if (name == "ANZERO1" || name == "ANZERO2") {
    // The reference's ANZERO1: with the input short-circuited, the offset found goes to ANOFF1.
    values_.at(name == "ANZERO1" ? "ANOFF1" : "ANOFF2") = -analog_input_mv(name[6] - '0');
    return {};
  }
  if (name == "PRD") return {value(feedback_within_turn())};
  if (name == "REFPOS") return {value(within_turn(refpos_motor_))};
  if (name == "PFB") return {value(user_of(axis_->position_exact()))};
  if (name == "PE") return {value(user_of(axis_->position_error()))};
  if (name == "PV") return {value(user_of(axis_->velocity()))};
  if (name == "V") {
    const double rpm = axis_->velocity() * 60.0 / axis_->parameters().counts_per_revolution();
    return {Answer{fmt::format("{:.3f}", rpm), 0}};
  }
  if (name == "I") {  // the reference's I: "the actual current value in amperes", positive
    return {Answer{fmt::format("{:.3f}", std::fabs(axis_->motor_state().current_a)), 0}};
  }
  if (name == "INPOS") {
    const int64_t off =
        std::llabs(int64_t{user_of(target_counts_)} - user_of(axis_->position_exact()));
    // A task waiting for the enable delay's end is not there yet.
    const bool waiting = deferred_.kind != Deferred::kNone;
    return {value(off <= values_.at("PEINPOS") && !axis_->profiler_moving() && !waiting ? 1 : 0)};
  }
  if (name.size() == 3 && name.starts_with("IN"))
    return {value(axis_->input_active(name[2] - '0') ? 1 : 0)};
  if (name == "O1" || name == "O2") {
    const int n = name[1] - '0';
    if (argc == 0) return {value(axis_->output(n) ? 1 : 0)};
    if (args[0] != 0 && args[0] != 1) return {err(kErrRange, "out of range")};
    axis_->set_output(n, args[0] == 1);
    return {};
  }

  // --- faults and status ---
  if (name == "ERRCODE") {
    std::vector<Answer> out;
    record_axis_faults();
    for (int f : faults_) {
      const char* text = f == 31 ? "run-time error" : f == 32 ? "System error" : "fault";
      for (const FaultName& n : kAxisFaults)
        if (n.number == f) text = n.text;
      out.push_back(Answer{fmt::format("F{:02} {}", f, text), 0});
    }
    if (out.empty()) out.push_back(Answer{"no error", 0});
    return out;
  }
  if (name == "STATUS") {
    uint32_t w1 = 0, w2 = 0, w5 = 0;
    if (!axis_->motor_on()) w1 |= 1u << 1;
    if (faulted()) w1 |= 1u << 3;
    record_axis_faults();
    for (int f : faults_) w2 |= 1u << (f - 1);
    // Word 5 (the reference's STATUS): bit 0 a task, homing or jog under way, bit 1 the
    // reference point set, bit 2 the reference switch (INxMODE 12) on, bit 3 in position.
    if (axis_->profiler_moving()) w5 |= 1u;
    if (reference_set_) w5 |= 1u << 1;
    for (size_t n = 0; n < input_modes_.size(); ++n)
      if (input_modes_[n] == kModeReference && axis_->input_level(static_cast<int>(n) + 1))
        w5 |= 1u << 2;
    if (command_line("INPOS")[0].text == "1") w5 |= 1u << 3;
    return {Answer{fmt::format("{:08X} {:08X} {:08X} {:08X} {:08X}", w1, w2, 0, 0, w5), 0}};
  }
  if (name == "CLRFAULT") {
    // Every fault whose cause is gone: the PLC's (its programs stay stopped) and the axis' that
    // no persisting cause holds (a scenario's injected temperature, say).
    record_axis_faults();
    axis_->clear_faults();
    std::set<int> kept;
    for (const FaultName& f : kAxisFaults)
      if (has_bits(fault_bits(), f.bits)) kept.insert(f.number);
    faults_ = kept;
    return {};
  }
  if (name == "SAVE") {
    const int32_t code = save();
    return code == 0 ? std::vector<Answer>{} : std::vector{err(code, "storage")};
  }
  if (name == "LOAD") {
    if (axis_->motor_on()) return {err(kErrNeedsDisabled, "needs disabled")};
    const int32_t code = load();
    return code == 0 ? std::vector<Answer>{} : std::vector{err(code, "storage")};
  }
  if (name == "RSTVAR") {
    if (axis_->motor_on()) return {err(kErrNeedsDisabled, "needs disabled")};
    const int32_t msg = msg_, prompt = prompt_;
    defaults();
    msg_ = msg, prompt_ = prompt;  // the interface keeps talking as it did
    return {};
  }
  if (name == "COLDSTART") {
    runtime_.reboot();
    return {};
  }
  if (name == "MSG" || name == "PROMPT") {
    int32_t& target = name == "MSG" ? msg_ : prompt_;
    if (argc == 0) return {value(target)};
    if (args[0] < 0 || args[0] > (name == "MSG" ? 2 : 2)) return {err(kErrRange, "out of range")};
    target = name == "PROMPT" && args[0] == 2 ? 1 : arg32(0);
    return {};
  }
  if (name == "TASK") {
    std::string out;
    for (uint32_t i = 0; i < schedule_.task_count(); ++i) {
      const scheduling::CyclicTaskStats& s = schedule_.stats(i);
      for (const auto& [thread, n] : threads_)
        if (thread == s.thread) out += fmt::format("{} {}% ", n, s.largest_run_percent());
    }
    bool has_main = false;
    for (const auto& [thread, n] : threads_) has_main |= n == "PLCMAIN";
    if (has_main)
      out += fmt::format("PLC {}", plc_started_ ? schedule_.background_loops_last_second() : 0);
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return {Answer{out, 0}};
  }
  if (name == "VER") return {Answer{"uprog S300 sim 1.0", 0}};
  if (name == "PLCSTOP") {
    stop_plc();
    return {};
  }
  if (name == "PLC") return {value(plc_state())};
  if (name == "PLCRUN" || name == "PLCSTART") {
    const int32_t code = compile_and_start();
    if (code == 0) return {};
    return {err(code, code == kErrNeedsDisabled ? "needs disabled" : "compile failed")};
  }
  if (name == "PLIST") {
    std::vector<Answer> out;
    if (!source_) return {err(kErrCompileFailed, "no PLC program")};
    std::istringstream in(*source_);
    for (std::string l; std::getline(in, l);) {
      if (!l.empty() && l.back() == '\r') l.pop_back();
      out.push_back(Answer{l, 0});
    }
    return out;
  }
  if (name == "PLCDL") return {err(kErrUnknown, "PLCDL needs a host session")};

  // --- plain stored parameters ---
  auto it = values_.find(name);
  if (it == values_.end()) return {err(kErrUnknown, "unknown command")};
  if (argc == 0) return {value(it->second)};
  if (argc != 1) return {err(kErrSyntax, "syntax error")};
  if (e->disabled_only && axis_->motor_on()) return {err(kErrNeedsDisabled, "needs disabled")};
  const auto [low, high] = range_of(name);
  if (args[0] < low || args[0] > high) return {err(kErrRange, "out of range")};
  it->second = arg32(0);
  apply_limits();
  return {};
}

// The axis' latched faults as F numbers, kept until CLRFAULT (the axis' MF holds one
// power-stage code at a time; ERRCODE lists every fault latched since).
void Firmware::record_axis_faults() {
  const uint32_t mf = axis_->motor_fault();
  if (mf == 0) return;
  const uint32_t codes = axis_->latched_power_stage_codes();
  for (const FaultName& f : kAxisFaults) {
    const uint32_t code = drive::power_stage_code(f.bits & ~drive::kFaultOvercurrent);
    if (has_bits(mf, f.bits) || (code != 0 && (codes >> code & 1u) != 0)) faults_.insert(f.number);
  }
}

}  // namespace uprog::st
