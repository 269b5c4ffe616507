// The debugger in transcripts: `debug ...` directives (attach, break, clear, continue, pause,
// step, and the checks stopped and running), and `wait` through the debugger, so that a
// transcript shows what a user at a breakpoint sees: time standing still.
#pragma once
#include <memory>

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

  std::unique_ptr<Debugger> debugger_;
};

}  // namespace uprog::debug
