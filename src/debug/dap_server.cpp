// The DAP server's lifecycle and execution requests (dap_server.h): initialize, launch,
// breakpoints, configurationDone, continue, next, stepIn, stepOut, pause, disconnect, terminate,
// and the events that follow. Inspection requests are in dap_inspect.cpp.
#include "debug/dap_server.h"

#include <fmt/core.h>

#include "drive/axis.h"
#include "jsonrpc/dap_envelope.h"
#include "jsonrpc/framing.h"

namespace uprog::debug {
namespace {

// DAP thread ids start at 1; the VM's threads at 0.
int64_t thread_id(uint32_t thread) { return int64_t{thread} + 1; }

}  // namespace

DapServer::DapServer(DapOptions options, std::function<void(const std::string&)> send)
    : options_(std::move(options)), send_(std::move(send)) {}
DapServer::~DapServer() {
  if (attached_) detach();  // a client gone without disconnect leaves the program running on
}

void DapServer::handle(const std::string& message) {
  if (done_) return;  // after disconnect's response nothing more is said
  jsonrpc::DapEnvelope envelope = jsonrpc::check_dap_message(message);
  switch (envelope.kind) {
    case jsonrpc::DapEnvelope::Kind::NotRequest:
      // No one to answer: the client's console is told, the session goes on.
      event("output", {{"category", "stderr"}, {"output", envelope.error + "\n"}});
      return;
    case jsonrpc::DapEnvelope::Kind::BadRequest:
      send_(jsonrpc::frame_message(jsonrpc::to_text(
          jsonrpc::dap_error_response(seq_++, envelope.seq, envelope.command, envelope.error))));
      return;
    case jsonrpc::DapEnvelope::Kind::Request:
      break;
  }
  const json& request = envelope.message;
  if (envelope.command == "initialize") initialize_request_ = message;
  try {
    dispatch(request);
  } catch (const jsonrpc::FieldError& e) {
    // A field of the wrong type: the request fails, the session goes on.
    fail(request, std::string("malformed arguments: ") + e.what());
  } catch (const json::exception& e) {
    fail(request, std::string("malformed arguments: ") + e.what());
  }
  report();
}

// `r` passed check_dap_message: its seq, command and arguments have their types.
void DapServer::dispatch(const json& r) {
  const std::string command = r["command"];
  if (command == "initialize") return initialize(r);
  if (command == "launch") return launch(r);
  if (command == "attach") return attach(r);
  if (command == "disconnect") return end(r, false);
  if (command == "terminate") return end(r, true);
  if (!debugger_) {
    if (command == "setBreakpoints" || command == "setFunctionBreakpoints" ||
        command == "setExceptionBreakpoints" || command == "configurationDone" ||
        command == "threads") {
      // Before a launch there is nothing to set them in; a client that sends them early is told so.
      return fail(r, "no program: launch first");
    }
    return fail(r, "unknown request '" + command + "' or no program launched");
  }
  if (command == "setBreakpoints") return set_breakpoints(r);
  if (command == "setFunctionBreakpoints") return set_function_breakpoints(r);
  if (command == "setExceptionBreakpoints") return set_exception_breakpoints(r);
  if (command == "configurationDone") return configuration_done(r);
  if (command == "threads") return threads(r);
  if (command == "stackTrace") return stack_trace(r);
  if (command == "scopes") return scopes(r);
  if (command == "variables") return variables(r);
  if (command == "setVariable") return set_variable(r);
  if (command == "evaluate") return evaluate(r);
  if (command == "continue") return step(r, std::nullopt);
  if (command == "next") return step(r, StepKind::Over);
  if (command == "stepIn") return step(r, StepKind::In);
  if (command == "stepOut") return step(r, StepKind::Out);
  if (command == "pause") return pause(r);
  fail(r, "unknown request '" + command + "'");
}

void DapServer::respond(const json& request, json body) {
  json m = {{"seq", seq_++},
            {"type", "response"},
            {"request_seq", request["seq"]},
            {"success", true},
            {"command", request["command"]}};
  if (!body.empty()) m["body"] = std::move(body);
  send_(jsonrpc::frame_message(jsonrpc::to_text(m)));
}

void DapServer::fail(const json& request, const std::string& message) {
  send_(jsonrpc::frame_message(jsonrpc::to_text(jsonrpc::dap_error_response(
      seq_++, request["seq"].get<int64_t>(), request["command"].get<std::string>(), message))));
}

void DapServer::event(const std::string& name, json body) {
  json m = {{"seq", seq_++}, {"type", "event"}, {"event", name}};
  if (!body.empty()) m["body"] = std::move(body);
  send_(jsonrpc::frame_message(jsonrpc::to_text(m)));
}

void DapServer::initialize(const json& r) {
  respond(r,
          {{"supportsConfigurationDoneRequest", true},
           {"supportsFunctionBreakpoints", true},
           {"supportsConditionalBreakpoints", true},
           {"supportsHitConditionalBreakpoints", true},
           {"supportsLogPoints", true},
           {"supportsSetVariable", true},
           {"supportsEvaluateForHovers", true},
           {"supportsTerminateRequest", true},
           {"exceptionBreakpointFilters",
            json::array({{{"filter", "error"},
                          {"label", "Run-time errors"},
                          {"default", false},
                          {"description",
                           "Stop where a run-time error that no try block catches happens"}}})}});
}

void DapServer::launch(const json& r) {
  if (drive_) return fail(r, "a program is already launched");
  if (options_.attach_target != nullptr)
    return fail(r, "this is a drive's own debugger: attach to the program it runs");
  using namespace jsonrpc;
  const json& args = r["arguments"];
  const std::string program = string_or(args, "program", "");
  if (program.empty()) return fail(r, "launch needs \"program\": the path of the source file");
  std::string error;
  const dialect::Dialect* d =
      options_.choose_dialect(string_or(args, "dialect", ""), program, error);
  if (d == nullptr) return fail(r, error);
  std::vector<std::string> input_items = strings_or_empty(args, "inputs");
  auto inputs = parse_input_changes(input_items, &error);
  if (!inputs) return fail(r, error);
  const std::vector<double> entry_args = numbers_or_empty(args, "args");
  const std::string entry = string_or(args, "entry", "");
  const bool stop_on_entry = bool_or(args, "stopOnEntry", false);
  const bool realtime = bool_or(args, "realtime", false);

  controller::ControllerOptions o;
  o.dialect = d;
  auto drive = std::make_unique<controller::Controller>(o);
  std::vector<Diagnostic> diagnostics;
  const bool compiled = drive->download_source_file(program, diagnostics);
  if (!diagnostics.empty())
    event("output", {{"category", "stderr"}, {"output", format_text(diagnostics)}});
  if (!compiled) return fail(r, "the program did not compile: " + program);
  if (const std::string why = drive->firmware().start_with_arguments(entry, entry_args);
      !why.empty()) {
    return fail(r, why);
  }
  owned_drive_ = std::move(drive);
  drive_ = owned_drive_.get();
  debugger_ = std::make_unique<Debugger>(*drive_);
  debugger_->program_changed();
  inputs_ = std::move(*inputs);
  start_us_ = drive_->now_us();
  stop_on_entry_ = stop_on_entry;
  realtime_ = realtime;
  respond(r);
  event("initialized");
  for (const dialect::ThreadInfo& t : debugger_->threads()) {
    event("thread", {{"reason", "started"}, {"threadId", thread_id(t.thread)}});
  }
}

// `uprog sim --dap`: the program this process's drive runs. `uprog dap`: a connection to such a
// sim, which answers this request and all that follow (the tool relays them).
void DapServer::attach(const json& r) {
  if (drive_) return fail(r, "a program is already being debugged");
  if (options_.attach_target == nullptr) {
    const json& args = r["arguments"];
    const std::string host = jsonrpc::string_or(args, "host", "127.0.0.1");
    const int64_t port = jsonrpc::integer_or(args, "port", 0);
    if (!options_.connect_remote) return fail(r, "attach: no drive to attach to here");
    if (port < 1 || port > 65535)
      return fail(r, "attach needs \"port\": the debugger port of a `uprog sim --dap`");
    std::string error;
    if (!options_.connect_remote(host, static_cast<uint16_t>(port), error))
      return fail(r, "attach: " + error);
    relay_start_ = {initialize_request_, jsonrpc::to_text(r)};
    return;
  }
  drive_ = options_.attach_target;
  attached_ = true;
  debugger_ = std::make_unique<Debugger>(*drive_);
  debugger_->program_changed();
  respond(r);
  event("initialized");
  for (const dialect::ThreadInfo& t : debugger_->threads()) {
    event("thread", {{"reason", "started"}, {"threadId", thread_id(t.thread)}});
  }
}

void DapServer::detach() {
  if (!attached_ || !debugger_) return;
  debugger_->clear_breakpoints();
  debugger_->set_break_on_error(false);
  debugger_->resume();
  drive_->set_lines_take_time(true);
  debugger_.reset();
  attached_ = false;
}

std::vector<std::string> DapServer::relay_start() {
  std::vector<std::string> out;
  out.swap(relay_start_);
  relayed_ = relayed_ || !out.empty();
  return out;
}

bool DapServer::keep_time(uint64_t ns) {
  if (!attached_ || !debugger_ || ended_) return false;
  if (debugger_->state() == RunState::Ended) {
    report();  // said once configured; till then, and after, the drive's time runs as usual
    return false;
  }
  if (debugger_->state() == RunState::Running) debugger_->run(ns);
  report();
  if (attached_) drive_->set_lines_take_time(debugger_->state() != RunState::Stopped);
  return true;
}

void DapServer::after_host_line() {
  if (!attached_ || !debugger_ || ended_) return;
  debugger_->program_changed();
  if (debugger_->resumed_elsewhere()) {
    // XC, DB##GO or the like from a terminal: the program goes on without a continue request.
    references_.clear();
    stop_reported_ = false;
    event("continued", {{"threadId", 1}, {"allThreadsContinued", true}});
  }
  report();
  if (attached_) drive_->set_lines_take_time(debugger_->state() != RunState::Stopped);
}

void DapServer::program_output(const std::string& text) {
  if (attached_ && !done_) event("output", {{"category", "stdout"}, {"output", text}});
}

void DapServer::set_breakpoints(const json& r) {
  using namespace jsonrpc;
  const json& args = r["arguments"];
  const json& source = required_object(args, "source");
  const std::string path = string_or(source, "path", string_or(source, "name", ""));
  std::vector<BreakpointSpec> specs;
  if (find(args, "breakpoints") != nullptr) {
    for (const json& b : array_or_empty(args, "breakpoints")) {
      BreakpointSpec s;
      s.line = static_cast<uint32_t>(required_integer(b, "line", 0, UINT32_MAX));
      s.condition = string_or(b, "condition", "");
      s.hit_condition = string_or(b, "hitCondition", "");
      s.log_message = string_or(b, "logMessage", "");
      specs.push_back(std::move(s));
    }
  } else {
    for (const json& l : array_or_empty(args, "lines")) {
      BreakpointSpec s;
      s.line = static_cast<uint32_t>(as_integer(l, "lines", 0, UINT32_MAX));
      specs.push_back(std::move(s));
    }
  }
  json out = json::array();
  for (const BreakpointState& b : debugger_->set_line_breakpoints(path, specs)) {
    json j = {{"id", b.id}, {"verified", b.verified}, {"line", b.line}};
    if (!b.message.empty()) j["message"] = b.message;
    if (b.verified) j["source"] = {{"path", path}};
    out.push_back(std::move(j));
  }
  respond(r, {{"breakpoints", out}});
}

void DapServer::set_function_breakpoints(const json& r) {
  std::vector<BreakpointSpec> specs;
  for (const json& b : jsonrpc::array_or_empty(r["arguments"], "breakpoints")) {
    BreakpointSpec s;
    s.function = jsonrpc::required_string(b, "name");
    s.condition = jsonrpc::string_or(b, "condition", "");
    s.hit_condition = jsonrpc::string_or(b, "hitCondition", "");
    specs.push_back(std::move(s));
  }
  json out = json::array();
  for (const BreakpointState& b : debugger_->set_function_breakpoints(specs)) {
    json j = {{"id", b.id}, {"verified", b.verified}};
    if (b.verified) j["line"] = b.line;
    if (!b.message.empty()) j["message"] = b.message;
    out.push_back(std::move(j));
  }
  respond(r, {{"breakpoints", out}});
}

void DapServer::set_exception_breakpoints(const json& r) {
  bool on = false;
  for (const std::string& f : jsonrpc::strings_or_empty(r["arguments"], "filters")) {
    if (f == "error") on = true;
  }
  debugger_->set_break_on_error(on);
  respond(r, {{"breakpoints", json::array({{{"verified", true}}})}});
}

void DapServer::configuration_done(const json& r) {
  respond(r);
  if (configured_) return;
  configured_ = true;
  if (stop_on_entry_) debugger_->stop_at_entry();
}

void DapServer::threads(const json& r) {
  json out = json::array();
  for (const dialect::ThreadInfo& t : debugger_->threads()) {
    out.push_back({{"id", thread_id(t.thread)}, {"name", t.name}});
  }
  respond(r, {{"threads", out}});
}

void DapServer::step(const json& r, std::optional<StepKind> kind) {
  if (ended_) return fail(r, "the program has ended");
  const json& args = r["arguments"];
  const int64_t id = jsonrpc::integer_or(args, "threadId", 1, 0, int64_t{UINT32_MAX} + 1);
  const bool single_thread = jsonrpc::bool_or(args, "singleThread", false);
  if (debugger_->state() != RunState::Stopped) {
    return fail(r, "the program is running");
  }
  references_.clear();
  stop_reported_ = false;
  if (kind) {
    debugger_->step(static_cast<uint32_t>(std::max<int64_t>(id - 1, 0)), *kind, single_thread);
    respond(r);
  } else {
    debugger_->resume();
    respond(r, {{"allThreadsContinued", true}});
  }
}

void DapServer::pause(const json& r) {
  respond(r);
  if (debugger_->state() == RunState::Running && configured_) debugger_->pause();
}

void DapServer::end(const json& r, bool terminate) {
  respond(r);
  if (attached_) {
    // The drive is not this session's to end: detaching leaves its program running on.
    detach();
    ended_ = true;
    if (terminate) return event("terminated");
    done_ = true;
    return;
  }
  if (terminate && !ended_ && debugger_) {
    ended_ = true;
    event("terminated");
    return;
  }
  done_ = !terminate || !debugger_;
}

bool DapServer::running_program() const {
  return !done_ && debugger_ && configured_ && !ended_ && debugger_->state() == RunState::Running;
}

bool DapServer::running() const { return running_program(); }

bool DapServer::poll(uint64_t budget_ns) {
  if (!running_program()) return false;
  // Inputs change when virtual time reaches them: a run stops short of the next one.
  while (next_input_ < inputs_.size() &&
         inputs_[next_input_].at_us <= drive_->now_us() - start_us_) {
    drive_->set_input_level(inputs_[next_input_].input, inputs_[next_input_].level);
    ++next_input_;
  }
  uint64_t budget = budget_ns;
  if (next_input_ < inputs_.size()) {
    const uint64_t due_ns = (inputs_[next_input_].at_us - (drive_->now_us() - start_us_)) * 1000;
    budget = std::min(budget, std::max<uint64_t>(due_ns, 1));
  }
  debugger_->run(budget);
  report();
  return running_program();
}

void DapServer::flush_output() {
  if (!drive_) return;
  // An attached drive's log and output are its hosts' (the sim passes its output on).
  if (!attached_) {
    for (const controller::LogEntry& e : drive_->take_log()) {
      event("output", {{"category", "console"},
                       {"output", fmt::format("[{:.3f} ms] {}\n",
                                              static_cast<double>(e.time_us) / 1000.0, e.text)}});
    }
    for (const std::string& text : drive_->take_output())
      event("output", {{"category", "stdout"}, {"output", text}});
  }
  if (debugger_) {
    for (const std::string& m : debugger_->take_messages())
      event("output", {{"category", "console"}, {"output", m + "\n"}});
  }
}

void DapServer::report() {
  if (done_) return;
  flush_output();
  if (!debugger_ || ended_ || !configured_) return;
  if (debugger_->state() == RunState::Stopped && !stop_reported_) {
    stop_reported_ = true;
    const Stop& s = debugger_->last_stop();
    json body = {{"reason", stop_reason_name(s.reason)},
                 {"threadId", thread_id(s.thread)},
                 {"allThreadsStopped", true}};
    if (!s.description.empty()) {
      body["description"] = s.description;
      body["text"] = s.description;
    }
    if (!s.breakpoints.empty()) body["hitBreakpointIds"] = s.breakpoints;
    event("stopped", std::move(body));
  } else if (debugger_->state() == RunState::Ended) {
    ended_ = true;
    int exit_code = drive_->program_error() != 0 ? 1 : 0;
    for (const dialect::ThreadInfo& t : debugger_->threads()) {
      if (t.status == vm::ThreadStatus::Error) exit_code = 1;  // stopped by a run-time error
      event("thread", {{"reason", "exited"}, {"threadId", thread_id(t.thread)}});
    }
    event("exited", {{"exitCode", exit_code}});
    event("terminated");
    detach();
  }
}

}  // namespace uprog::debug
