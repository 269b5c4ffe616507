// Runs `uprog sim` as a child process for end-to-end tests: reads the addresses it prints, stops
// it with SIGTERM and reports how it exited.
#pragma once
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace uprog::transport::testing {

class SimProcess {
 public:
  // Starts `uprog sim ARGS...` and waits (up to 10 s) for its "listening on" lines.
  explicit SimProcess(std::vector<std::string> args, int expected_listen_lines = 1) {
    int out[2];
    if (::pipe(out) != 0) throw std::runtime_error("pipe");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    // The readable wire form unless a test asks for another (its CR LF marks end each line).
    if (std::find(args.begin(), args.end(), "--wire") == args.end())
      args.insert(args.end(), {"--wire", "readable"});
    args.insert(args.begin(), {UPROG_BINARY, "sim"});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, UPROG_BINARY, &actions, nullptr, argv.data(), environ) != 0) {
      throw std::runtime_error("cannot start " UPROG_BINARY);
    }
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    stdout_fd_ = out[0];
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    int seen = 0;
    while (seen < expected_listen_lines && std::chrono::steady_clock::now() < deadline) {
      const std::string line = read_line(deadline);
      if (line.empty()) break;
      if (line.starts_with("listening on tcp 127.0.0.1:")) {
        port = static_cast<std::uint16_t>(std::stoi(line.substr(27)));
        ++seen;
      } else if (line.starts_with("listening on pty ")) {
        pty_path = line.substr(17);
        ++seen;
      }
    }
    if (seen < expected_listen_lines) throw std::runtime_error("uprog sim did not start");
  }
  ~SimProcess() { stop(); }
  SimProcess(const SimProcess&) = delete;
  SimProcess& operator=(const SimProcess&) = delete;

  // Sends SIGTERM and returns the exit status (0 for a clean stop), or -1 if killed.
  int stop() {
    if (pid_ <= 0) return status_;
    ::kill(pid_, SIGTERM);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (::waitpid(pid_, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > deadline) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
        break;
      }
      ::usleep(10'000);
    }
    pid_ = 0;
    ::close(stdout_fd_);
    status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return status_;
  }

  // For tests that kill the process themselves: its id, and reaping it once it is gone
  // (blocks; returns the signal that ended it, 0 if it exited).
  pid_t pid() const { return pid_; }
  int reap() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = 0;
    ::close(stdout_fd_);
    status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }

  std::uint16_t port = 0;
  std::string pty_path;

 private:
  std::string read_line(std::chrono::steady_clock::time_point deadline) {
    std::string line;
    char c = 0;
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd p{stdout_fd_, POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      if (::read(stdout_fd_, &c, 1) != 1) return line;
      if (c == '\n') return line;
      line.push_back(c);
    }
    return line;
  }

  pid_t pid_ = 0;
  int stdout_fd_ = -1;
  int status_ = -1;
};

}  // namespace uprog::transport::testing
