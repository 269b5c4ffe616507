// `debug` directives for transcripts (transcript_debugger.h); the syntax is in docs/debugging.md.
#include "debug/transcript_debugger.h"

#include <filesystem>
#include <sstream>

namespace uprog::debug {
namespace {

// "paused.ehl:12" -> file and line; false when it is not FILE:LINE.
bool split_place(const std::string& text, std::string& file, uint32_t& line) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0) return false;
  file = text.substr(0, colon);
  try {
    const unsigned long n = std::stoul(text.substr(colon + 1));
    line = static_cast<uint32_t>(n);
    return n > 0 && std::to_string(n) == text.substr(colon + 1);
  } catch (...) {
    return false;
  }
}

}  // namespace

bool TranscriptDebugger::directive(controller::Controller& drive, const std::string& name,
                                   const std::string& arg, std::string& failure) {
  if (name != "debug") return false;
  std::istringstream in(arg);
  std::string verb, rest;
  in >> verb;
  std::getline(in >> std::ws, rest);
  failure = command(drive, verb, rest);
  return true;
}

std::string TranscriptDebugger::command(controller::Controller& drive, const std::string& verb,
                                        const std::string& rest) {
  if (verb == "attach") {
    debugger_ = std::make_unique<Debugger>(drive);
    return "";
  }
  if (!debugger_) return "debug " + verb + ": no debugger attached (debug attach first)";
  if (verb == "break") {
    std::string file;
    BreakpointSpec b;
    if (!split_place(rest, file, b.line)) return "debug break needs FILE:LINE";
    const auto states = debugger_->set_line_breakpoints(file, {b});
    return states.at(0).verified ? "" : "debug break " + rest + ": " + states.at(0).message;
  }
  if (verb == "clear") {
    debugger_->clear_breakpoints();
    return "";
  }
  if (verb == "continue") {
    debugger_->resume();
    return "";
  }
  if (verb == "pause") {
    debugger_->pause();
    return debugger_->state() == RunState::Stopped ? "" : "debug pause: the program did not stop";
  }
  if (verb == "step") {
    const StepKind kind = rest == "in"    ? StepKind::In
                          : rest == "out" ? StepKind::Out
                                          : StepKind::Over;
    if (rest != "in" && rest != "out" && rest != "over") return "debug step needs in, over or out";
    debugger_->step(debugger_->last_stop().thread, kind);
    debugger_->run(uint64_t{1'000'000'000});  // a step ends within a second of virtual time here
    return "";
  }
  if (verb == "stopped") return check_stopped(rest);
  if (verb == "running") {
    return debugger_->state() == RunState::Running ? "" : "expected the program running, it is not";
  }
  return "debug: unknown command '" + verb + "'";
}

// "breakpoint paused.ehl:12": the reason and the innermost frame's place.
std::string TranscriptDebugger::check_stopped(const std::string& rest) {
  if (debugger_->state() != RunState::Stopped) return "expected the program stopped, it is not";
  const std::string reason = stop_reason_name(debugger_->last_stop().reason);
  const auto frames = debugger_->stack(debugger_->last_stop().thread);
  const std::string where = frames.empty()
                                ? "(no frame)"
                                : std::filesystem::path(frames[0].file).filename().string() + ":" +
                                      std::to_string(frames[0].line);
  const std::string got = reason + " " + where;
  return got == rest ? "" : "expected stopped " + rest + ", got " + got;
}

void TranscriptDebugger::wait(controller::Controller& drive, uint64_t us) {
  if (!debugger_) return drive.advance(us);
  // The user's time passes; the drive's only while the program runs.
  debugger_->run(us * 1000);
}

}  // namespace uprog::debug
