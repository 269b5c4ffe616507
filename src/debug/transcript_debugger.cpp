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
  if (verb == "break" || verb == "exceptions") {
    if (verb == "exceptions") {
      debugger_->set_break_on_error(rest == "on");
      return rest == "on" || rest == "off" ? "" : "debug exceptions needs on or off";
    }
    // "FILE:LINE", then at most one of "if CONDITION", "hits HIT-CONDITION", "log MESSAGE"; it is
    // added to the file's breakpoints.
    std::string file, place = rest, modifier;
    if (const size_t space = rest.find(' '); space != std::string::npos) {
      place = rest.substr(0, space);
      modifier = rest.substr(space + 1);
    }
    BreakpointSpec b;
    if (!split_place(place, file, b.line)) return "debug break needs FILE:LINE";
    const auto take = [&](const char* word, std::string& into) {
      const std::string w = std::string(word) + " ";
      if (modifier.rfind(w, 0) != 0) return false;
      into = modifier.substr(w.size());
      return true;
    };
    if (!modifier.empty() && !take("if", b.condition) && !take("hits", b.hit_condition) &&
        !take("log", b.log_message))
      return "debug break: '" + modifier + "' is not if, hits or log";
    std::vector<BreakpointSpec>& specs = breakpoints_[file];
    specs.push_back(b);
    const auto states = debugger_->set_line_breakpoints(file, specs);
    return states.back().verified ? "" : "debug break " + rest + ": " + states.back().message;
  }
  if (verb == "log") {
    // The next log message of a breakpoint that logs, in order.
    for (std::string& m : debugger_->take_messages()) logged_.push_back(std::move(m));
    if (logged_.empty()) return "debug log: no message, expected " + rest;
    const std::string got = logged_.front();
    logged_.erase(logged_.begin());
    return got == rest ? "" : "debug log: expected " + rest + ", got " + got;
  }
  if (verb == "clear") {
    breakpoints_.clear();
    debugger_->clear_breakpoints();
    return "";
  }
  if (verb == "single") {
    // "on": the steps that follow run the stepped thread alone (the others stay stopped).
    single_thread_ = rest == "on";
    return rest == "on" || rest == "off" ? "" : "debug single needs on or off";
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
    debugger_->step(thread(), kind, single_thread_);
    debugger_->run(uint64_t{1'000'000'000});  // a step ends within a second of virtual time here
    return "";
  }
  if (verb == "stopped") return check_stopped(rest);
  if (verb == "eval") {
    // "EXPR -> VALUE": in the innermost frame of the stopped thread (or of `debug frame`).
    const size_t arrow = rest.rfind(" -> ");
    if (arrow == std::string::npos) return "debug eval needs EXPR -> VALUE";
    const dialect::Evaluation e = debugger_->evaluate(thread(), depth_, rest.substr(0, arrow));
    const std::string got = e.ok ? e.value : "error: " + e.error;
    return got == rest.substr(arrow + 4) ? ""
                                         : "debug eval " + rest.substr(0, arrow) + ": got " + got;
  }
  if (verb == "stack") return check_stack(rest);
  if (verb == "thread" || verb == "frame") {
    try {
      (verb == "thread" ? thread_ : depth_) = static_cast<uint32_t>(std::stoul(rest));
    } catch (...) {
      return "debug " + verb + " needs a number";
    }
    if (verb == "thread") depth_ = 0;
    return "";
  }
  if (verb == "set") {
    // "NAME = VALUE": a local of the frame, else a global (an element as NAME[i]).
    const size_t eq = rest.find(" = ");
    if (eq == std::string::npos) return "debug set needs NAME = VALUE";
    std::string name = rest.substr(0, eq);
    uint32_t element = 0;
    if (const size_t open = name.find('['); open != std::string::npos && name.back() == ']') {
      element = static_cast<uint32_t>(std::stoul(name.substr(open + 1)));
      name.erase(open);
    }
    SetResult r;
    for (const Variable& v : debugger_->locals(thread(), depth_))
      if (v.name == name) r = debugger_->set_local(thread(), depth_, name, rest.substr(eq + 3));
    if (!r.ok && r.error.empty()) {
      const int g = debugger_->find_global(name);
      if (g < 0) return "debug set: no variable " + name;
      r = debugger_->set_global(static_cast<uint32_t>(g), element, rest.substr(eq + 3));
    }
    return r.ok ? "" : "debug set " + name + ": " + r.error;
  }
  if (verb == "running") {
    return debugger_->state() == RunState::Running ? "" : "expected the program running, it is not";
  }
  return "debug: unknown command '" + verb + "'";
}

// "breakpoint paused.ehl:12": the reason and the innermost frame's place.
std::string TranscriptDebugger::check_stopped(const std::string& rest) {
  if (debugger_->state() != RunState::Stopped) return "expected the program stopped, it is not";
  thread_ = 0;  // `debug thread` holds until the next stop is checked
  depth_ = 0;
  const std::string reason = stop_reason_name(debugger_->last_stop().reason);
  const auto frames = debugger_->stack(debugger_->last_stop().thread);
  const std::string where = frames.empty()
                                ? "(no frame)"
                                : std::filesystem::path(frames[0].file).filename().string() + ":" +
                                      std::to_string(frames[0].line);
  const std::string got = reason + " " + where;
  return got == rest ? "" : "expected stopped " + rest + ", got " + got;
}

uint32_t TranscriptDebugger::thread() const {
  return thread_ != 0 ? thread_ : debugger_->last_stop().thread;
}

// "twice@scale.h:5 scale@scale.h:12 _t1@pdl_debug.pdl:11": the stopped thread's frames, innermost
// first, each routine@file:line.
std::string TranscriptDebugger::check_stack(const std::string& rest) {
  if (debugger_->state() != RunState::Stopped) return "expected the program stopped, it is not";
  std::string got;
  for (const StackFrame& f : debugger_->stack(thread())) {
    got += (got.empty() ? "" : " ") + f.routine + "@" +
           std::filesystem::path(f.file).filename().string() + ":" + std::to_string(f.line);
  }
  return got == rest ? "" : "expected stack " + rest + ", got " + got;
}

void TranscriptDebugger::wait(controller::Controller& drive, uint64_t us) {
  if (!debugger_) return drive.advance(us);
  // The user's time passes; the drive's only while the program runs.
  debugger_->run(us * 1000);
}

}  // namespace uprog::debug
