// The debugger in transcripts: `debug ...` directives (attach, break with a condition, hit count
// or log message, exceptions, clear, continue, pause, step, single, thread, frame, set, and the
// checks stopped, running, stack, eval and log), and `wait` through the debugger, so that a
// transcript shows what a user at a breakpoint sees: time standing still.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "debug/debugger.h"
#include "transcript/transcript.h"

namespace uprog::debug {

class TranscriptDebugger final : public transcript::Extension {
 public:
  bool directive(controller::Controller& drive, const std::string& name, const std::string& arg,
                 std::string& failure) override;
  void wait(controller::Controller& drive, uint64_t us) override;
  bool holds_time() const override { return debugger_ != nullptr; }

 private:
  std::string command(controller::Controller& drive, const std::string& verb,
                      const std::string& rest);
  std::string check_stopped(const std::string& rest);
  std::string check_stack(const std::string& rest);
  uint32_t thread() const;  // `debug thread`'s, else the stopped one

  std::unique_ptr<Debugger> debugger_;
  std::map<std::string, std::vector<BreakpointSpec>> breakpoints_;  // by file, as set
  std::vector<std::string> logged_;
  uint32_t thread_ = 0;  // 0: the thread that stopped
  uint32_t depth_ = 0;
  bool single_thread_ = false;
};

}  // namespace uprog::debug
