// `uprog dap`'s protocol: a Debug Adapter Protocol server over the debugger (debugger.h). It takes
// requests as JSON texts and sends responses and events, framed, through a callback, in order;
// `launch` runs the program on a fresh simulated drive in this process. The transport (stdin and
// stdout, a TCP connection) is the tool's.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "debug/debugger.h"
#include "debug/input_schedule.h"

namespace uprog::debug {

struct DapOptions {
  // The dialect of a launch: by `name` when given, else by the program's extension; nullptr with
  // `error` set when there is none (the tools' registry lives above this library).
  std::function<const dialect::Dialect*(const std::string& name, const std::string& path,
                                        std::string& error)>
      choose_dialect;
  // The drive of this very process that `attach` debugs (`uprog sim --dap`); null: there is none.
  controller::Controller* attach_target = nullptr;
  // Without a target, `attach {"host", "port"}` asks the tool to connect to a `uprog sim`'s
  // debugger there: true when connected, and the tool relays the session from then on
  // (relay_start()); false with `error` set.
  std::function<bool(const std::string& host, uint16_t port, std::string& error)> connect_remote =
      nullptr;
};

class DapServer {
 public:
  // `send` gets each outgoing message, framed.
  DapServer(DapOptions options, std::function<void(const std::string&)> send);
  ~DapServer();

  // One incoming message's body, checked by jsonrpc::check_dap_message: a request with a wrong
  // field gets a failed response, a text that is not a request an error event (an output).
  void handle(const std::string& message);
  // Lets a running program run for up to `budget_ns` of virtual time and sends what happened.
  // False when nothing runs: the server only waits for requests.
  bool poll(uint64_t budget_ns);
  bool running() const;
  bool done() const { return done_; }          // disconnected: the tool stops
  bool realtime() const { return realtime_; }  // the launch asked to pace virtual time to the wall

  // --- relaying an attach to a `uprog sim` (connect_remote) ---
  bool relaying() const { return !relay_start_.empty() || relayed_; }
  // The requests the remote debugger is to get first (the client's initialize and attach), once.
  std::vector<std::string> relay_start();
  // The sequence number of the next message this session sends (a relayed one takes it).
  int64_t next_seq() { return seq_++; }

  // --- attached to this process's drive (attach_target) ---
  // The time keeper of a drive that paces itself (transport::ControllerService): `ns` of time
  // passes through the debugger, none while the program is stopped; false when no debugger is
  // attached (or the program has ended): the drive advances as usual.
  bool keep_time(uint64_t ns);
  // After a host's line on the drive's command line: the program may have changed or resumed.
  void after_host_line();
  // The text the drive sent its hosts, for the debug console too.
  void program_output(const std::string& text);

 private:
  using json = nlohmann::json;
  struct Reference {
    enum class Kind : uint8_t { Locals, Globals, Signals, Elements } kind;
    uint32_t thread = 0, depth = 0, global = 0;
  };

  void dispatch(const json& request);
  void respond(const json& request, json body = json::object());
  void fail(const json& request, const std::string& message);
  void event(const std::string& name, json body = json::object());

  void initialize(const json& request);
  void launch(const json& request);
  void attach(const json& request);
  // Ends an attach: the breakpoints cleared, the program running on as if never debugged.
  void detach();
  void set_breakpoints(const json& request);
  void set_function_breakpoints(const json& request);
  void set_exception_breakpoints(const json& request);
  void configuration_done(const json& request);
  void threads(const json& request);
  void stack_trace(const json& request);
  void scopes(const json& request);
  void variables(const json& request);
  void set_variable(const json& request);
  void evaluate(const json& request);
  void step(const json& request, std::optional<StepKind> kind);
  void pause(const json& request);
  void end(const json& request, bool terminate);

  // After anything that may have let the program run: output, a stop, the end.
  void report();
  void flush_output();
  uint32_t reference(Reference r);
  // The thread and frame depth of a frameId (0: the stopped thread's innermost).
  std::pair<uint32_t, uint32_t> frame_of(const json* frame_id) const;
  bool running_program() const;

  DapOptions options_;
  std::function<void(const std::string&)> send_;
  int64_t seq_ = 1;
  std::unique_ptr<controller::Controller> owned_drive_;  // a launch's drive
  controller::Controller* drive_ = nullptr;              // the launched or attached drive
  bool attached_ = false;
  std::string initialize_request_;
  std::vector<std::string> relay_start_;
  bool relayed_ = false;
  std::unique_ptr<Debugger> debugger_;
  bool configured_ = false;  // configurationDone: the program may run
  bool stop_on_entry_ = false;
  bool realtime_ = false;
  bool ended_ = false;
  bool done_ = false;
  bool stop_reported_ = false;
  uint64_t start_us_ = 0;
  std::vector<InputChange> inputs_;
  size_t next_input_ = 0;
  std::vector<Reference>
      references_;  // variablesReference n is references_[n - 1], until the program runs on
};

}  // namespace uprog::debug
