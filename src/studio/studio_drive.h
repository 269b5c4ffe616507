// The studio's drive, free of I/O: one simulated drive paced to the wall clock (paused, x0.1..x10
// or as fast as it goes), the page's drive messages (a terminal line, build and download, run
// controls, inputs, switches, faults, the scope's channels) answered as JSON texts, and what the
// drive does on its own (status, output, scope samples) sent to every page. docs/studio.md.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "studio/scope_stream.h"
#include "transport/controller_service.h"

namespace uprog::studio {

struct StudioDriveOptions {
  const dialect::Dialect* dialect = nullptr;  // required
  std::string file;                           // the program the page opens ("" for none)
  std::string source;                         // its text
  uint32_t servo_period_us = 0;               // 0: the drive's own
};

// What the studio sends one page: a JSON text, or scope samples as a binary message.
struct PageSink {
  std::function<void(const std::string& text)> text;
  std::function<void(const std::string& bytes)> binary;
};

class StudioDrive {
 public:
  // Virtual time per tick when running as fast as it goes.
  static constexpr uint64_t kMaxSpeedStepNs = 50'000'000;
  // A late tick (a busy machine) catches up at most this much virtual time at once.
  static constexpr uint64_t kMaxStepNs = 200'000'000;

  explicit StudioDrive(StudioDriveOptions options);
  ~StudioDrive();

  controller::Controller& controller() { return *controller_; }
  transport::ControllerService& service() { return *service_; }

  // A page connects: it gets the hello (dialect, file, source, channels, inputs, faults) at once.
  uint64_t connect(PageSink sink);
  void disconnect(uint64_t page);
  // One message of a page. Anything that is not a known request gets {"type":"error"} back.
  void handle(uint64_t page, const std::string& text);

  // `wall_ns` of wall time has passed: virtual time passes at the chosen speed, the scope's
  // samples and the drive's output go to every page. `pages_behind`: a page has not read what
  // it was sent, so "as fast as possible" keeps to the wall clock until it has.
  void tick(uint64_t wall_ns, bool pages_behind = false);
  // Status (time, program, threads, inputs, faults) to every page.
  void broadcast_status();
  // 0 paused; 1 the wall clock; up to 10; kMaxSpeed as fast as it goes.
  static constexpr double kMaxSpeed = -1.0;
  double speed() const { return speed_; }
  // A debugger that holds the program takes the time (DapServer::keep_time); null: none.
  void set_time_keeper(std::function<bool(uint64_t ns)> keeper, std::function<void()> after_line);
  // Told after anything that changed the program (a build, a start, a reset): the debugger.
  void set_program_changed(std::function<void()> changed) { program_changed_ = std::move(changed); }

 private:
  using json = nlohmann::json;
  struct Page {
    PageSink sink;
    std::unique_ptr<transport::LineChannel> channel;  // its terminal's own session
  };

  json hello() const;
  json status() const;
  void send(uint64_t page, const json& message);
  void send_all(const json& message);
  void dispatch(uint64_t page, const json& request);
  void terminal_line(uint64_t page, const std::string& line);
  void build(uint64_t page, const json& request);
  void start(uint64_t page);
  void stop(uint64_t page);
  void reset(uint64_t page);
  void set_speed(uint64_t page, const json& request);
  void set_input(uint64_t page, const json& request);
  void place_switch(uint64_t page, const json& request);
  void inject_fault(uint64_t page, const json& request);
  void set_scope(uint64_t page, const json& request);
  void flush_output();
  void send_samples();

  StudioDriveOptions options_;
  std::unique_ptr<controller::Controller> controller_;
  std::unique_ptr<transport::ControllerService> service_;
  std::unique_ptr<ScopeStream> scope_;
  std::function<void()> program_changed_;
  std::map<uint64_t, Page> pages_;
  uint64_t next_page_ = 1;
  std::vector<std::string> output_;  // what the drive sent on its own since the last tick
  uint64_t output_listener_ = 0;
  double speed_ = 1.0;
  uint64_t pending_ns_ = 0;  // virtual time owed below a microsecond
};

}  // namespace uprog::studio
