// What `uprog dap` and `uprog lsp` share: writing a whole message to a file descriptor, and
// serving one client over TCP (--listen HOST:PORT) with the same loop that serves stdin/stdout.
#pragma once
#include <functional>
#include <string>

namespace uprog::cli {

// False when the peer is gone (EINTR is retried).
bool write_all(int fd, const std::string& bytes);
// Listens on `where` ("HOST:PORT", port 0 picks one), says where on stderr as
// "<tool>: listening on tcp HOST:PORT", takes one client and runs serve(fd, fd) on it.
int serve_one_tcp_client(const char* tool, const std::string& where,
                         const std::function<int(int in, int out)>& serve);

}  // namespace uprog::cli
