// Paces virtual time to the wall clock: every period, advances the LineService by the wall time
// that has passed. The only place in uprog where real time matters; the core never sees it.
#pragma once
#include <chrono>
#include <cstdint>

#include "transport/asio.h"
#include "transport/line_service.h"

namespace uprog::transport {

class Pacer {
 public:
  using Clock = std::chrono::steady_clock;
  // A late tick (a slow host, a stopped process) catches up at most this much at once.
  static constexpr std::uint32_t kMaxStepUs = 100'000;

  Pacer(boost::asio::io_context& io, LineService& service,
        std::chrono::microseconds period = std::chrono::milliseconds(1));

  void start();
  void stop();
  // Virtual microseconds given to the service so far.
  std::uint64_t advanced_us() const { return advanced_us_; }

 private:
  void schedule();
  void tick();

  boost::asio::steady_timer timer_;
  LineService& service_;
  std::chrono::microseconds period_;
  Clock::time_point last_{};
  std::uint64_t advanced_us_ = 0;
  bool running_ = false;
};

}  // namespace uprog::transport
