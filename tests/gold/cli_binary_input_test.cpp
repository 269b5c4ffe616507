// `uprog check` and `uprog exec` given a binary file (this test's own executable), as a new user
// might: a bounded number of errors, then a count of the rest, and nothing a terminal would act on.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <string>

#include "testlib/terminal_text.h"

namespace {

struct Finished {
  std::string output;  // stdout and stderr
  int status = -1;
};

Finished run(const std::string& command) {
  Finished r;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf;
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), p)) > 0;) r.output.append(buf.data(), n);
  const int status = pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string self() {
  std::array<char, 4096> path{};
  const ssize_t n = readlink("/proc/self/exe", path.data(), path.size() - 1);
  return n > 0 ? std::string(path.data(), static_cast<size_t>(n)) : std::string();
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(cli_binary_input, CheckShowsThirtyErrorsThenTooManyErrors) {
  const Finished r = run(std::string(UPROG_BINARY) + " check " + self());
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(uprog::test::safe_for_terminal(r.output));
  EXPECT_EQ(count(r.output, ": error: "), 31u) << r.output.substr(0, 2000);
  EXPECT_NE(r.output.find("error: Too many errors [gold 46]\n"), std::string::npos);
}

TEST(cli_binary_input, ExecShowsThirtyErrorsThenHowManyMore) {
  const Finished r = run(std::string(UPROG_BINARY) + " exec " + self());
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(uprog::test::safe_for_terminal(r.output));
  EXPECT_EQ(count(r.output, ": error: "), 30u) << r.output.substr(0, 2000);
  const size_t note = r.output.rfind(": note: ");
  ASSERT_NE(note, std::string::npos);
  EXPECT_NE(r.output.find(" more errors not shown\n", note), std::string::npos)
      << r.output.substr(note);
}
