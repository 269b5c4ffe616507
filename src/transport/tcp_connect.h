// Connecting a host tool (uprog term, uprog download) to a drive at "HOST:PORT" or "[V6]:PORT".
#pragma once
#include <string>

#include "transport/asio.h"

namespace uprog::transport {

namespace asio = boost::asio;

// False with `error` set ("expected HOST:PORT", or why the connection failed).
bool connect_tcp(asio::io_context& io, const std::string& address, asio::ip::tcp::socket& socket,
                 std::string& error);

}  // namespace uprog::transport
