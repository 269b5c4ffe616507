// One host's Gold command line: its own download in progress (the DL lines, docs/protocol.md);
// everything else goes to the drive's shared command line.
#include "dialects/gold/firmware.h"

namespace uprog::gold {
namespace {

class Session final : public dialect::Session {
 public:
  explicit Session(Firmware& firmware) : firmware_(firmware) {}
  std::vector<dialect::Answer> send(std::string_view line) override {
    return firmware_.send_line(line, true, &download_);
  }

 private:
  Firmware& firmware_;
  dialect::DlReceiver download_;
};

}  // namespace

std::unique_ptr<dialect::Session> Firmware::open_session() {
  return std::make_unique<Session>(*this);
}

}  // namespace uprog::gold
