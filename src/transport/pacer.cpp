// The wall-clock pacer (pacer.h).
#include "transport/pacer.h"

#include <algorithm>

namespace uprog::transport {

Pacer::Pacer(boost::asio::io_context& io, LineService& service, std::chrono::microseconds period)
    : timer_(io), service_(service), period_(period) {}

void Pacer::start() {
  running_ = true;
  last_ = Clock::now();
  timer_.expires_at(last_);
  schedule();
}

void Pacer::stop() {
  running_ = false;
  timer_.cancel();
}

void Pacer::schedule() {
  timer_.expires_at(timer_.expiry() + period_);
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec || !running_) return;
    tick();
    schedule();
  });
}

void Pacer::tick() {
  const auto now = Clock::now();
  const auto elapsed = std::chrono::duration_cast<std::chrono::microseconds>(now - last_).count();
  if (elapsed <= 0) return;
  const auto step = static_cast<std::uint32_t>(std::min<std::int64_t>(elapsed, kMaxStepUs));
  // Whole microseconds only; the fraction stays for the next tick, so no time drifts away.
  last_ += std::chrono::microseconds(elapsed);
  advanced_us_ += step;
  service_.advance(step);
  if (timer_.expiry() + period_ < now) timer_.expires_at(now);  // do not fire a burst of ticks
}

}  // namespace uprog::transport
