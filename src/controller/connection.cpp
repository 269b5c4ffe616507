// A host's command line with its own download state (connection.h).
#include "controller/connection.h"

#include "controller/controller_impl.h"
#include "controller/download_protocol.h"
#include "controller/line_splitter.h"

namespace uprog::controller {

std::vector<Answer> Connection::send(std::string_view line) {
  std::vector<Answer> answers;
  for (const std::string& e : split_expressions(line)) {
    if (e.size() <= kMaxExpressionChars && DownloadReceiver::is_download_command(e)) {
      download_expression(e, answers);
      // Like every expression, a download line takes one servo cycle of the background loop.
      controller_.advance(controller_.axis().period_us());
    } else {
      for (Answer& a : controller_.send(e)) answers.push_back(std::move(a));
    }
  }
  return answers;
}

void Connection::download_expression(std::string_view expression, std::vector<Answer>& answers) {
  std::vector<uint8_t> image;
  if (auto error = download_.handle(expression, image)) {
    answers.push_back(std::move(*error));
    return;
  }
  if (image.empty()) return;  // BEGIN, a chunk or ABORT: nothing more to do
  // The controller checks the CRC and runs the verifier before it stores anything.
  const DownloadResult r = controller_.download(image);
  if (r.ok) return;
  answers.push_back(Answer{"Error: " + r.error, r.storage_failed ? int32_t{kErrorStorage} : int32_t{kErrorDownloadRefused}});
}

}  // namespace uprog::controller
