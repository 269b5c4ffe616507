// One host's conversation with the drive: its command lines go to the shared Controller, and what
// belongs to that host alone — a program download in progress — lives here and dies with it.
#pragma once
#include <string_view>
#include <vector>

#include "controller/controller.h"
#include "controller/download_receiver.h"

namespace uprog::controller {

class Connection {
 public:
  explicit Connection(Controller& controller) : controller_(controller) {}

  // As Controller::send, plus the download commands (DL##BEGIN=n, DL=hex, DL##END, DL##ABORT).
  std::vector<Answer> send(std::string_view line);
  bool download_in_progress() const { return download_.in_progress(); }

 private:
  void download_expression(std::string_view expression, std::vector<Answer>& answers);

  Controller& controller_;
  DownloadReceiver download_;
};

}  // namespace uprog::controller
