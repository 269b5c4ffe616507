// The studio's drive and its page messages (studio_drive.h; the messages in docs/studio.md).
#include "studio/studio_drive.h"

#include <algorithm>
#include <cmath>

#include "drive/axis.h"
#include "drive/faults.h"
#include "drive/parameters.h"
#include "jsonrpc/fields.h"
#include "studio/stop_lines.h"
#include "vm/machine.h"

namespace uprog::studio {
namespace {

using nlohmann::json;

json diagnostic_json(const Diagnostic& d) {
  const char* severity = d.severity == Severity::Error     ? "error"
                         : d.severity == Severity::Warning ? "warning"
                                                           : "note";
  return {{"file", d.where.file}, {"line", d.where.line}, {"column", d.where.column},
          {"severity", severity}, {"code", d.code},       {"message", d.message}};
}

json answers_json(const std::vector<dialect::Answer>& answers) {
  json out = json::array();
  for (const dialect::Answer& a : answers) out.push_back({{"text", a.text}, {"error", a.error}});
  return out;
}

}  // namespace

StudioDrive::StudioDrive(StudioDriveOptions options) : options_(std::move(options)) {
  controller::ControllerOptions c;
  c.dialect = options_.dialect;
  c.servo_period_us = options_.servo_period_us;
  c.wire_style = dialect::WireStyle::kReadable;
  controller_ = std::make_unique<controller::Controller>(c);
  service_ = std::make_unique<transport::ControllerService>(*controller_);
  output_listener_ =
      service_->add_output_listener([this](std::string_view text) { output_.emplace_back(text); });
  scope_ = std::make_unique<ScopeStream>(*controller_);
}

StudioDrive::~StudioDrive() { service_->remove_output_listener(output_listener_); }

void StudioDrive::set_time_keeper(std::function<bool(uint64_t ns)> keeper,
                                  std::function<void()> after_line) {
  service_->set_time_keeper(std::move(keeper), std::move(after_line));
}

uint64_t StudioDrive::connect(PageSink sink) {
  const uint64_t id = next_page_++;
  pages_[id] = Page{std::move(sink), service_->open_channel()};
  send(id, hello());
  send(id, status());
  return id;
}

void StudioDrive::disconnect(uint64_t page) {
  // The page's channel goes with it, and with the channel a download it had begun: the stored
  // program stays as it was (transport::HostSession::disconnect does the same for TCP hosts).
  pages_.erase(page);
}

json StudioDrive::hello() const {
  json signals = json::array();
  for (const drive::SignalInfo& s : drive::all_signals()) signals.push_back(s.name);
  json faults = json::array();
  for (const drive::FaultName& f : drive::fault_names()) faults.push_back(f.name);
  return {{"type", "hello"},       {"dialect", std::string(options_.dialect->name())},
          {"file", options_.file}, {"source", options_.source},
          {"signals", signals},    {"inputs", drive::kInputCount},
          {"faults", faults},      {"speed", speed_}};
}

json StudioDrive::status() const {
  json threads = json::array();
  for (const dialect::ThreadInfo& t : controller_->firmware().threads()) {
    threads.push_back({{"thread", t.thread},
                       {"name", t.name},
                       {"status", vm::thread_status_name(t.status)},
                       {"where", t.where},
                       {"error", t.error}});
  }
  const drive::Axis& axis = controller_->axis();
  json inputs = json::array();
  for (int n = 1; n <= drive::kInputCount; ++n) inputs.push_back(axis.input_level(n));
  return {{"type", "status"},
          {"time_us", controller_->now_us()},
          {"running", controller_->program_running()},
          {"error", controller_->program_error_text()},
          {"threads", threads},
          {"inputs", inputs},
          {"motor_fault", axis.motor_fault()},
          {"speed", speed_}};
}

void StudioDrive::send(uint64_t page, const json& message) {
  const auto it = pages_.find(page);
  if (it != pages_.end() && it->second.sink.text) it->second.sink.text(jsonrpc::to_text(message));
}

void StudioDrive::send_all(const json& message) {
  const std::string text = jsonrpc::to_text(message);
  for (auto& [id, page] : pages_) {
    if (page.sink.text) page.sink.text(text);
  }
}

void StudioDrive::handle(uint64_t page, const std::string& text) {
  if (pages_.count(page) == 0) return;
  const json request = json::parse(text, nullptr, false);
  if (request.is_discarded() || !request.is_object()) {
    return send(page, {{"type", "error"}, {"message", "not a JSON object"}});
  }
  try {
    dispatch(page, request);
  } catch (const jsonrpc::FieldError& e) {
    send(page, {{"type", "error"}, {"message", e.what()}});
  }
  flush_output();
}

void StudioDrive::dispatch(uint64_t page, const json& request) {
  const std::string op = jsonrpc::required_string(request, "op");
  if (op == "line") return terminal_line(page, jsonrpc::required_string(request, "text"));
  if (op == "build") return build(page, request);
  if (op == "start") return start(page);
  if (op == "stop") return stop(page);
  if (op == "reset") return reset(page);
  if (op == "speed") return set_speed(page, request);
  if (op == "input") return set_input(page, request);
  if (op == "switch") return place_switch(page, request);
  if (op == "fault") return inject_fault(page, request);
  if (op == "scope") return set_scope(page, request);
  if (op == "status") return send(page, status());
  send(page, {{"type", "error"}, {"message", "unknown op '" + op + "'"}});
}

void StudioDrive::terminal_line(uint64_t page, const std::string& line) {
  Page& p = pages_.at(page);
  const auto answers =
      p.channel ? p.channel->handle_line(line) : service_->handle_line(std::string_view(line));
  send(page, {{"type", "answers"}, {"line", line}, {"answers", answers_json(answers)}});
}

void StudioDrive::build(uint64_t page, const json& request) {
  const std::string source = jsonrpc::required_string(request, "source");
  const bool run = jsonrpc::bool_or(request, "run", false);
  dialect::CompileOutput out = options_.dialect->compile_source(
      SourceFile{options_.file.empty() ? "program" : options_.file, source}, {});
  json diagnostics = json::array();
  for (const Diagnostic& d : out.diagnostics) diagnostics.push_back(diagnostic_json(d));
  std::string error;
  if (out.ok()) {
    const dialect::DownloadResult r = controller_->download(out.stored_form);
    if (r.ok && !out.debug_map.empty()) controller_->firmware().set_debug_map(out.debug_map);
    if (!r.ok) error = r.error;
    if (r.ok) options_.source = source;
    // Stored only: a dialect's load line (PDL's reset, the S300's PLCRUN) would start it too;
    // Run (start_program) loads and starts it, with the debugger ready (docs/studio.md).
  }
  const bool ok = out.ok() && error.empty();
  send(page, {{"type", "build"}, {"ok", ok}, {"error", error}, {"diagnostics", diagnostics}});
  if (program_changed_) program_changed_();
  if (ok && run) start(page);
}

void StudioDrive::start(uint64_t page) {
  const std::string why = controller_->start_program();
  if (program_changed_) program_changed_();
  send(page, {{"type", "started"}, {"ok", why.empty()}, {"error", why}});
  broadcast_status();
}

void StudioDrive::stop(uint64_t page) {
  json answers = json::array();
  for (const std::string& line :
       stop_lines(options_.dialect->name(), controller_->firmware().threads())) {
    for (const json& a : answers_json(service_->handle_line(line))) answers.push_back(a);
  }
  send(page, {{"type", "stopped"}, {"answers", answers}});
  broadcast_status();
}

void StudioDrive::reset(uint64_t page) {
  controller_->reboot();
  if (program_changed_) program_changed_();
  json messages = controller_->boot_messages();
  send(page, {{"type", "reset"}, {"messages", messages}});
  broadcast_status();
}

void StudioDrive::set_speed(uint64_t page, const json& request) {
  const json* factor = jsonrpc::find(request, "factor");
  if (factor != nullptr && factor->is_string() && *factor == "max") {
    speed_ = kMaxSpeed;
  } else {
    const double f = jsonrpc::number_or(request, "factor", 1.0);
    // 0 pauses; otherwise x0.1 .. x10 of the wall clock.
    if (!(f == 0.0 || (f >= 0.1 && f <= 10.0))) {
      return send(page, {{"type", "error"}, {"message", "speed: 0 (pause), 0.1..10 or \"max\""}});
    }
    speed_ = f;
  }
  broadcast_status();
}

void StudioDrive::set_input(uint64_t page, const json& request) {
  const int n = static_cast<int>(jsonrpc::required_integer(request, "n", 1, drive::kInputCount));
  controller_->set_input_level(n, jsonrpc::bool_or(request, "high", false));
  send(page, {{"type", "input"}, {"n", n}, {"high", controller_->axis().input_level(n)}});
}

void StudioDrive::place_switch(uint64_t page, const json& request) {
  const int n = static_cast<int>(jsonrpc::required_integer(request, "n", 1, drive::kInputCount));
  if (jsonrpc::find(request, "from") == nullptr) {
    controller_->axis().remove_position_switch(n);
  } else {
    const double from = jsonrpc::number_or(request, "from", 0.0);
    const double to = jsonrpc::number_or(request, "to", from);
    if (!std::isfinite(from) || !std::isfinite(to) || to < from) {
      return send(page, {{"type", "error"}, {"message", "switch: from <= to, both finite"}});
    }
    controller_->axis().place_position_switch(n, from, to);
  }
  send(page, {{"type", "switch"}, {"n", n}});
}

void StudioDrive::inject_fault(uint64_t page, const json& request) {
  const std::string name = jsonrpc::required_string(request, "name");
  if (!controller_->inject_fault(name, jsonrpc::bool_or(request, "persistent", false))) {
    return send(page, {{"type", "error"}, {"message", "no fault named '" + name + "'"}});
  }
  send(page, {{"type", "fault"}, {"name", name}});
  broadcast_status();
}

void StudioDrive::set_scope(uint64_t page, const json& request) {
  const std::string why = scope_->choose(jsonrpc::strings_or_empty(request, "channels"));
  if (!why.empty()) return send(page, {{"type", "error"}, {"message", "scope: " + why}});
  json channels = json::array();
  for (const drive::Channel& c : scope_->channels())
    channels.push_back({{"name", c.name}, {"unit", c.unit}});
  send_all(
      {{"type", "scope"}, {"channels", channels}, {"period_us", controller_->axis().period_us()}});
}

void StudioDrive::tick(uint64_t wall_ns, bool pages_behind) {
  if (speed_ != 0.0) {
    const double factor = speed_ == kMaxSpeed ? 1.0 : speed_;
    const double virtual_ns =
        speed_ == kMaxSpeed && !pages_behind ? double(kMaxSpeedStepNs) : double(wall_ns) * factor;
    pending_ns_ += std::min(kMaxStepNs, static_cast<uint64_t>(virtual_ns));
    const uint64_t us = pending_ns_ / 1000;
    pending_ns_ %= 1000;
    if (us > 0) {
      if (const std::string why = scope_->prepare(us * 1000); !why.empty()) {
        scope_->choose({});
        send_all({{"type", "error"}, {"message", "scope: " + why}});
      }
      service_->advance(static_cast<uint32_t>(us));
      send_samples();
    }
  }
  flush_output();
}

void StudioDrive::send_samples() {
  const auto block = scope_->collect();
  if (!block) return;
  const std::string bytes = encode_block(*block);
  for (auto& [id, page] : pages_) {
    if (page.sink.binary) page.sink.binary(bytes);
  }
}

void StudioDrive::broadcast_status() { send_all(status()); }

void StudioDrive::flush_output() {
  service_->settle();
  if (output_.empty()) return;
  json lines = json::array();
  for (std::string& text : output_) lines.push_back(std::move(text));
  output_.clear();
  send_all({{"type", "output"}, {"lines", lines}});
}

}  // namespace uprog::studio
