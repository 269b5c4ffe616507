// The DAP server's inspection requests (dap_server.h): stackTrace, scopes, variables,
// setVariable, evaluate. A frameId is thread * 1024 + depth + 1; a variablesReference indexes
// the references made since the program last stopped.
#include <filesystem>

#include "debug/dap_server.h"
#include "jsonrpc/fields.h"

namespace uprog::debug {
namespace {

constexpr int64_t kFramesPerThread = 1024;

std::string absolute(const std::string& file) {
  std::error_code ec;
  const auto p = std::filesystem::absolute(file, ec);
  return ec ? file : p.lexically_normal().string();
}

}  // namespace

uint32_t DapServer::reference(Reference r) {
  references_.push_back(r);
  return static_cast<uint32_t>(references_.size());
}

std::pair<uint32_t, uint32_t> DapServer::frame_of(const json* frame_id) const {
  const int64_t id = frame_id == nullptr ? 0 : jsonrpc::as_integer(*frame_id, "frameId");
  if (id > 0) {
    return {static_cast<uint32_t>((id - 1) / kFramesPerThread),
            static_cast<uint32_t>((id - 1) % kFramesPerThread)};
  }
  return {debugger_->last_stop().thread, 0};
}

void DapServer::stack_trace(const json& r) {
  using namespace jsonrpc;
  const json& args = r["arguments"];
  const int64_t id = required_integer(args, "threadId", INT64_MIN, int64_t{UINT32_MAX} + 1);
  if (id < 1) return fail(r, "no thread " + std::to_string(id));
  const uint32_t thread = static_cast<uint32_t>(id - 1);
  const std::vector<StackFrame> frames = debugger_->stack(thread);
  const auto start = static_cast<size_t>(integer_or(args, "startFrame", 0, 0));
  const auto levels = static_cast<size_t>(integer_or(args, "levels", 0, 0));
  json out = json::array();
  for (size_t i = start; i < frames.size() && (levels == 0 || i < start + levels); ++i) {
    const StackFrame& f = frames[i];
    json j = {{"id", int64_t{thread} * kFramesPerThread + f.depth + 1},
              {"name", f.is_event ? f.routine + " (event)" : f.routine},
              {"line", f.line},
              {"column", 1}};
    if (!f.file.empty()) {
      j["source"] = {{"name", std::filesystem::path(f.file).filename().string()},
                     {"path", absolute(f.file)}};
    }
    out.push_back(std::move(j));
  }
  respond(r, {{"stackFrames", out}, {"totalFrames", frames.size()}});
}

void DapServer::scopes(const json& r) {
  const auto [thread, depth] = frame_of(jsonrpc::find(r["arguments"], "frameId"));
  json out = json::array();
  out.push_back({{"name", "Locals"},
                 {"presentationHint", "locals"},
                 {"expensive", false},
                 {"variablesReference", reference({Reference::Kind::Locals, thread, depth, 0})}});
  out.push_back({{"name", "Globals"},
                 {"expensive", false},
                 {"variablesReference", reference({Reference::Kind::Globals, thread, depth, 0})}});
  out.push_back({{"name", "Drive"},
                 {"presentationHint", "registers"},
                 {"expensive", false},
                 {"variablesReference", reference({Reference::Kind::Signals, thread, depth, 0})}});
  respond(r, {{"scopes", out}});
}

void DapServer::variables(const json& r) {
  const int64_t ref = jsonrpc::required_integer(r["arguments"], "variablesReference");
  if (ref < 1 || static_cast<size_t>(ref) > references_.size())
    return fail(r, "no such variablesReference");
  const Reference at = references_[static_cast<size_t>(ref - 1)];
  std::vector<Variable> vars;
  switch (at.kind) {
    case Reference::Kind::Locals:
      vars = debugger_->locals(at.thread, at.depth);
      break;
    case Reference::Kind::Globals:
      vars = debugger_->globals();
      break;
    case Reference::Kind::Signals:
      vars = debugger_->signals();
      break;
    case Reference::Kind::Elements:
      vars = debugger_->elements(at.global);
      break;
  }
  json out = json::array();
  for (const Variable& v : vars) {
    uint32_t children = 0;
    if (v.elements > 0) {
      const int g = debugger_->find_global(v.name);
      if (g >= 0)
        children =
            reference({Reference::Kind::Elements, at.thread, at.depth, static_cast<uint32_t>(g)});
    }
    json j = {
        {"name", v.name}, {"value", v.value}, {"type", v.type}, {"variablesReference", children}};
    if (children != 0) j["indexedVariables"] = v.elements;
    if (at.kind == Reference::Kind::Signals)
      j["presentationHint"] = {{"attributes", json::array({"readOnly"})}};
    out.push_back(std::move(j));
  }
  respond(r, {{"variables", out}});
}

void DapServer::set_variable(const json& r) {
  const json& args = r["arguments"];
  const int64_t ref = jsonrpc::required_integer(args, "variablesReference");
  if (ref < 1 || static_cast<size_t>(ref) > references_.size())
    return fail(r, "no such variablesReference");
  const Reference at = references_[static_cast<size_t>(ref - 1)];
  const std::string name = jsonrpc::required_string(args, "name");
  const std::string value = jsonrpc::required_string(args, "value");
  SetResult result;
  switch (at.kind) {
    case Reference::Kind::Locals:
      result = debugger_->set_local(at.thread, at.depth, name, value);
      break;
    case Reference::Kind::Globals: {
      const int g = debugger_->find_global(name);
      result = g < 0 ? SetResult{false, {}, "no global named '" + name + "'"}
                     : debugger_->set_global(static_cast<uint32_t>(g), 0, value);
      break;
    }
    case Reference::Kind::Elements: {
      // "[3]"
      uint32_t element = 0;
      try {
        element = static_cast<uint32_t>(std::stoul(name.substr(1)));
      } catch (...) {
        return fail(r, "no element " + name);
      }
      result = debugger_->set_global(at.global, element, value);
      break;
    }
    case Reference::Kind::Signals:
      return fail(r, "the drive's signals are read-only");
  }
  if (!result.ok) return fail(r, result.error);
  respond(r, {{"value", result.value}});
}

void DapServer::evaluate(const json& r) {
  const json& args = r["arguments"];
  const std::string expression = jsonrpc::required_string(args, "expression");
  const std::string context = jsonrpc::string_or(args, "context", "");
  if (context == "repl") {
    // The drive's command line, as a terminal would send the line. Stopped, it takes no time.
    const bool stopped = debugger_->state() == RunState::Stopped;
    const std::vector<controller::Answer> answers =
        stopped ? drive_->query(expression) : drive_->send(expression);
    debugger_->program_changed();
    const bool resumed = stopped && debugger_->resumed_elsewhere();
    std::string result;
    for (const controller::Answer& a : answers) {
      if (!result.empty()) result += "\n";
      result +=
          a.is_error() ? "Error: " + a.text + " (EC " + std::to_string(a.error) + ")" : a.text;
    }
    respond(r, {{"result", result}, {"variablesReference", 0}});
    if (resumed) {
      // The program goes on without a continue request: the client is told (DAP's continued).
      references_.clear();
      stop_reported_ = false;
      event("continued", {{"threadId", 1}, {"allThreadsContinued", true}});
    }
    return;
  }
  const auto [thread, depth] = frame_of(jsonrpc::find(args, "frameId"));
  const dialect::Evaluation e = debugger_->evaluate(thread, depth, expression);
  if (!e.ok) return fail(r, e.error);
  respond(r, {{"result", e.value}, {"variablesReference", 0}});
}

}  // namespace uprog::debug
