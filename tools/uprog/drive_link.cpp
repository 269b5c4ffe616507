// Connecting to a drive of a known dialect (drive_link.h).
#include "drive_link.h"

#include <algorithm>
#include <chrono>

namespace uprog::cli {

std::unique_ptr<transport::DriveClient> connect_to_drive(const std::string& address,
                                                         const dialect::Dialect& d,
                                                         std::string& error) {
  auto client = transport::DriveClient::connect(address, error);
  if (client) {
    if (const auto framing = d.host_framing()) client->count_answers(*framing);
    const auto prompt = d.host_prompt();
    if (prompt && !client->read_prompts(*prompt, std::chrono::seconds(10))) {
      error = "the drive at " + address + " did not answer with its prompt";
      return nullptr;
    }
  }
  return client;
}

std::string shown_error(const dialect::Dialect& d, const transport::Reply& reply) {
  std::string text = reply.text;
  if (text.empty()) {
    const auto errors = d.interpreter_errors();
    const auto it = std::find_if(errors.begin(), errors.end(),
                                 [&](const auto& e) { return e.code == reply.error; });
    if (it != errors.end()) text = it->text;
  }
  return "?" + std::to_string(reply.error) + (text.empty() ? "" : " " + text);
}

}  // namespace uprog::cli
