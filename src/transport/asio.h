// The parts of Boost.Asio the transports use. (Boost 1.74's <boost/asio.hpp> pulls in
// awaitable.hpp, which misses <utility> under g++ 12; naming the parts avoids that.)
#pragma once
#include <boost/asio/buffer.hpp>
#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <utility>
