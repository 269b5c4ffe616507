// The pseudo-terminal: posix_openpt, raw mode, one session on the master (pty_server.h).
#include "transport/pty_server.h"

#include <fcntl.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>

namespace uprog::transport {

namespace {

[[noreturn]] void throw_errno(const char* what) {
  throw boost::system::system_error(errno, boost::system::system_category(), what);
}

}  // namespace

PtyServer::PtyServer(boost::asio::io_context& io, LineService& service) : service_(service) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0) throw_errno("posix_openpt");
  if (grantpt(master) != 0 || unlockpt(master) != 0) {
    const int saved = errno;
    ::close(master);
    errno = saved;
    throw_errno("grantpt/unlockpt");
  }
  const char* name = ptsname(master);
  if (name == nullptr) {
    ::close(master);
    throw_errno("ptsname");
  }
  slave_path_ = name;
  slave_fd_ = ::open(name, O_RDWR | O_NOCTTY);
  if (slave_fd_ < 0) {
    ::close(master);
    throw_errno("open pty slave");
  }
  // Raw, like a serial port: no echo, no line editing, no CR/LF translation, 8 bits.
  termios settings{};
  if (tcgetattr(slave_fd_, &settings) == 0) {
    cfmakeraw(&settings);
    cfsetispeed(&settings, B115200);
    cfsetospeed(&settings, B115200);
    tcsetattr(slave_fd_, TCSANOW, &settings);
  }
  session_ = std::make_shared<Session>(boost::asio::posix::stream_descriptor(io, master), service);
  session_->start();
  output_listener_ = service_.add_output_listener([this](std::string_view text) {
    if (session_) session_->deliver_output(text);
  });
}

PtyServer::~PtyServer() {
  service_.remove_output_listener(output_listener_);
  stop();
}

void PtyServer::stop() {
  if (session_) session_->close();
  session_.reset();
  if (slave_fd_ >= 0) ::close(slave_fd_);
  slave_fd_ = -1;
}

}  // namespace uprog::transport
