// SIGKILL at random moments during a download or an SV, 50 times, on a real `uprog sim --state`:
// after each restart the stored program is exactly A or exactly B, the saved parameters exactly
// set A or set B — never a mix, never corrupt — and what the drive acknowledged is what it kept.
// For every registered dialect, kills during downloads of its sample program: the stored form is
// absent (before the first whole download) or whole, and no temporary of a write is left.
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <thread>

#include "bytecode/image.h"
#include "dialect/dl_lines.h"
#include "dialects/gold/compile.h"
#include "dialects/registry.h"
#include "sim_process.h"
#include "support/files.h"
#include "test_client.h"

namespace uprog::transport {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using testing::SimProcess;
using testing::TestClient;

constexpr int kKills = 50;
constexpr int kUserVariables = 24;

// Two programs of 1000 lines each, within the 64 KB program limit (manual 2.17), so that a kill
// often lands mid-transfer.
std::vector<uint8_t> program_image(int which) {
  const std::string g = which == 0 ? "ga" : "gb";
  SourceFile source;
  source.name = which == 0 ? "a.ehl" : "b.ehl";
  source.text = "int " + g + ";\nfunction main()\n";
  for (int k = 0; k < 1000; ++k) {
    source.text +=
        "  " + g + " = " + g + " + " + std::to_string(k * (which == 0 ? 7 : 11) + 3) + "\n";
  }
  source.text += "return\n";
  const gold::CompileResult r = gold::compile(source);
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
  return bytecode::encode(r.image);
}

int32_t parameter_value(int set, int i) { return set == 0 ? 1000 + 7 * i : -(20000 + 13 * i); }

// "UI[1]=1007;UI[2]=1014;..." for a parameter set.
std::string assignments(int set) {
  std::string line;
  for (int i = 1; i <= kUserVariables; ++i) {
    line += "UI[" + std::to_string(i) + "]=" + std::to_string(parameter_value(set, i)) + ";";
  }
  return line + "\n";
}

std::string temp_state_dir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "uprog_kill_XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
  return pattern;
}

std::vector<std::string> sim_args(const std::string& dir) {
  return {"--listen", "127.0.0.1:0", "--safe-boot", "--state", dir};
}

// Sends `lines` one at a time, each waiting for its one answer; the number answered without
// error before the drive went away (or all of them).
std::size_t send_lines(TestClient& client, const std::vector<std::string>& lines,
                       std::string& error) {
  std::size_t answered = 0;
  for (const std::string& line : lines) {
    if (!client.send(line + "\n")) return answered;
    // Its answer, up to the CR LF (fewer when the drive went away).
    const auto replies = client.line_answers(20s);
    if (replies.empty()) return answered;
    if (replies[0].error != 0) {
      error = line.substr(0, 20) + " answered ?" + std::to_string(replies[0].error) + " " +
              replies[0].text;
      return answered;
    }
    ++answered;
  }
  return answered;
}

// What a freshly booted drive holds: -1 for "neither" (a failure is then recorded).
struct Held {
  int program = -1;
  int parameters = -1;
};

// The state directory holds no temporary of an interrupted write (a `NAME.tmp.PID`): a kill
// leaves none, and a drive's start-up removes any (support/files.h).
void expect_no_temporary(const std::string& dir) {
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos)
        << "left behind: " << entry.path();
  }
}

Held inspect(SimProcess& sim, const std::string& dir, const std::vector<uint8_t> images[2]) {
  Held held;
  expect_no_temporary(dir);
  const auto file = read_binary_file(dir + "/program.upi");
  if (!file) {
    ADD_FAILURE() << "no stored program in " << dir;
    return held;
  }
  for (int p = 0; p < 2; ++p) {
    if (*file == images[p]) held.program = p;
  }
  if (held.program < 0) {
    ADD_FAILURE() << "the stored program is neither A nor B (" << file->size() << " bytes)";
    return held;
  }
  TestClient client(sim.port);
  // The drive accepted it at boot too: CC loads it and LS names its global.
  client.send("CC\nLS\nLD\n");
  const auto cc = client.line_answers(20s);
  const auto ls = client.line_answers(20s);
  const auto ld = client.line_answers(20s);
  EXPECT_EQ(cc, (std::vector<Reply>{{"", 0}})) << "CC of the stored program";
  const std::string global = held.program == 0 ? "int ga" : "int gb";
  EXPECT_TRUE(std::find(ls.begin(), ls.end(), Reply{global, 0}) != ls.end())
      << "LS lacks " << global;
  if (ld != std::vector<Reply>{{"", 0}}) {
    ADD_FAILURE() << "LD failed: the saved parameters were refused ("
                  << (ld.empty() ? std::string("no answer") : ld[0].text) << ")";
    return held;
  }
  std::string read;
  for (int i = 1; i <= kUserVariables; ++i) read += "UI[" + std::to_string(i) + "];";
  client.send(read + "\n");
  const auto values = client.line_answers(20s);
  for (int set = 0; set < 2; ++set) {
    bool all = values.size() == kUserVariables;
    for (int i = 1; all && i <= kUserVariables; ++i) {
      all = values[static_cast<std::size_t>(i - 1)] ==
            Reply{std::to_string(parameter_value(set, i)), 0};
    }
    if (all) held.parameters = set;
  }
  if (held.parameters < 0) {
    std::string got;
    for (const auto& v : values) got += v.text + " ";
    ADD_FAILURE() << "the saved parameters are neither set A nor set B: " << got;
  }
  return held;
}

TEST(transport_sim_kill, SigkillDuringDownloadOrSvNeverLosesOrMixesTheStoredState) {
  const char* seed_text = std::getenv("UPROG_KILL_SEED");
  const std::uint64_t seed =
      seed_text != nullptr ? std::strtoull(seed_text, nullptr, 10) : std::random_device{}();
  std::printf("seed %llu (set UPROG_KILL_SEED to replay)\n", static_cast<unsigned long long>(seed));
  std::fflush(stdout);
  std::mt19937_64 rng(seed);
  const auto started = Clock::now();

  const std::vector<uint8_t> images[2] = {program_image(0), program_image(1)};
  ASSERT_NE(images[0], images[1]);
  const std::vector<std::string> lines[2] = {dialect::download_lines(images[0]),
                                             dialect::download_lines(images[1])};
  const std::string dir = temp_state_dir();
  struct RemoveAtEnd {
    std::string dir;
    ~RemoveAtEnd() { std::filesystem::remove_all(dir); }
  } remove_at_end{dir};

  // Program A and parameter set A, stored cleanly after four rounds of each (B, A, B, A) that
  // time the phases: the median time until DL##END goes out and until it is answered, and of
  // UI[..]= plus SV. Kills are aimed at random moments across those phases.
  long long end_sent_us = 0, download_us = 0, sv_us = 0;
  {
    SimProcess sim(sim_args(dir));
    TestClient client(sim.port);
    std::vector<long long> end_sent, whole, sv;
    std::string error;
    for (int i = 0; i < 4; ++i) {
      const int which = i % 2 == 0 ? 1 : 0;
      const auto t0 = Clock::now();
      ASSERT_EQ(send_lines(client, {lines[which].begin(), lines[which].end() - 1}, error),
                lines[which].size() - 1)
          << error;
      const auto t1 = Clock::now();
      ASSERT_EQ(send_lines(client, {"DL##END"}, error), 1u) << error;
      const auto t2 = Clock::now();
      client.send(assignments(which));
      ASSERT_EQ(client.line_answers(20s).size(), static_cast<std::size_t>(kUserVariables));
      ASSERT_EQ(send_lines(client, {"SV"}, error), 1u) << error;
      const auto t3 = Clock::now();
      end_sent.push_back(std::chrono::duration_cast<std::chrono::microseconds>(t1 - t0).count());
      whole.push_back(std::chrono::duration_cast<std::chrono::microseconds>(t2 - t0).count());
      sv.push_back(std::chrono::duration_cast<std::chrono::microseconds>(t3 - t2).count());
    }
    for (auto* v : {&end_sent, &whole, &sv}) std::sort(v->begin(), v->end());
    end_sent_us = end_sent[1];
    download_us = std::max(whole[1], end_sent_us + 1);
    sv_us = sv[1];
    ASSERT_EQ(sim.stop(), 0);
  }
  std::printf(
      "a download (%zu bytes, %zu lines) takes %lld us, %lld of them until DL##END is "
      "sent; UI[1..24]= and SV %lld us\n",
      images[1].size(), lines[1].size(), download_us, end_sent_us, sv_us);

  // What the last round allows the next boot to find.
  struct Allowed {
    Held old_state, new_state;
    bool may_be_old = true, may_be_new = false;
  } allowed{{0, 0}, {0, 0}};
  int before = 0, mid_download = 0, during_end = 0, during_sv = 0, after = 0;
  for (int round = 0; round <= kKills; ++round) {
    SimProcess sim(sim_args(dir));
    const Held held = inspect(sim, dir, images);
    const bool is_old = held.program == allowed.old_state.program &&
                        held.parameters == allowed.old_state.parameters;
    const bool is_new = held.program == allowed.new_state.program &&
                        held.parameters == allowed.new_state.parameters;
    ASSERT_TRUE((is_old && allowed.may_be_old) || (is_new && allowed.may_be_new))
        << "after kill " << round << " (seed " << seed << "): program " << held.program
        << ", parameters " << held.parameters << "; old " << allowed.old_state.program << "/"
        << allowed.old_state.parameters << (allowed.may_be_old ? " allowed" : " not allowed")
        << ", new " << allowed.new_state.program << "/" << allowed.new_state.parameters
        << (allowed.may_be_new ? " allowed" : " not allowed");
    if (round == kKills) {
      EXPECT_EQ(sim.stop(), 0);
      break;
    }

    // Alternate: a download of the other program, then an SV of the other parameter set.
    const bool download = round % 2 == 0;
    // A download round kills within the transfer two times in three, else anywhere up to a
    // little after the answer to DL##END; an SV round anywhere up to a little after SV's answer.
    long long low = 0, high = download ? download_us * 6 / 5 : sv_us * 6 / 5;
    if (download && std::uniform_int_distribution<int>(0, 2)(rng) != 0) high = end_sent_us;
    const auto delay =
        std::chrono::microseconds(std::uniform_int_distribution<long long>(low, high)(rng));
    TestClient client(sim.port);
    const pid_t pid = sim.pid();
    const auto kill_at = Clock::now() + delay;  // counted from here, not from the thread's start
    std::thread killer([pid, kill_at] {
      std::this_thread::sleep_until(kill_at);
      ::kill(pid, SIGKILL);
    });
    std::string error;
    // Before the host's last line went out, only the old state may survive; once the drive has
    // acknowledged that line, only the new one; in between, either.
    allowed = Allowed{held, held, true, true};
    if (download) {
      allowed.new_state.program = 1 - held.program;
      const auto& send = lines[allowed.new_state.program];
      const std::size_t answered = send_lines(client, send, error);
      if (answered == send.size()) {
        ++after;
        allowed.may_be_old = false;
      } else if (answered == 0) {
        ++before;
        allowed.may_be_new = false;
      } else if (answered + 1 == send.size()) {
        ++during_end;  // DL##END was sent: the kill fell into the check and the store
      } else {
        ++mid_download;
        allowed.may_be_new = false;
      }
    } else {
      allowed.new_state.parameters = 1 - held.parameters;
      client.send(assignments(allowed.new_state.parameters));
      const auto set = client.line_answers(20s);
      if (set.size() < static_cast<std::size_t>(kUserVariables)) {
        ++before;
        allowed.may_be_new = false;
      } else if (send_lines(client, {"SV"}, error) == 1) {
        ++after;
        allowed.may_be_old = false;
      } else {
        ++during_sv;  // SV was sent, its answer never came
      }
    }
    EXPECT_EQ(error, "") << "round " << round;
    killer.join();
    EXPECT_EQ(sim.reap(), SIGKILL) << "round " << round;
  }
  const auto seconds = std::chrono::duration<double>(Clock::now() - started).count();
  std::printf(
      "%d kills: %d mid-download, %d during DL##END, %d during SV, %d before the first "
      "answer, %d after the last; %.1f s\n",
      kKills, mid_download, during_end, during_sv, before, after, seconds);
}

// Kills during downloads of each registered dialect's sample program, by its own download lines.
TEST(transport_sim_kill, EveryDialectsKilledDownloadLeavesItsProgramWholeAndNoTemporary) {
  constexpr int kRoundsPerDialect = 6;
  const char* seed_text = std::getenv("UPROG_KILL_SEED");
  const std::uint64_t seed =
      seed_text != nullptr ? std::strtoull(seed_text, nullptr, 10) : std::random_device{}();
  std::printf("seed %llu (set UPROG_KILL_SEED to replay)\n", static_cast<unsigned long long>(seed));
  std::mt19937_64 rng(seed);
  for (const dialect::Dialect* d : dialects::all()) {
    SCOPED_TRACE(std::string(d->name()));
    const dialect::SampleProgram& sample = d->sample_program();
    const dialect::CompileOutput out = d->compile_source(
        SourceFile{std::string(sample.file_name), std::string(sample.source)}, {});
    ASSERT_TRUE(out.ok()) << format_text(out.diagnostics);
    std::string lines;
    for (const std::string& line : d->download_lines(out.stored_form)) lines += line + "\n";
    const std::string dir = temp_state_dir();
    struct RemoveAtEnd {
      std::string dir;
      ~RemoveAtEnd() { std::filesystem::remove_all(dir); }
    } remove_at_end{dir};
    const std::string record = dir + "/program" + std::string(d->stored_extension());
    // A temporary a killed writer left before this drive ever started: removed at start-up.
    ASSERT_TRUE(write_file_atomically(record + ".tmp.999999999", "x", 1));
    const std::vector<std::string> args = {
        "--listen", "127.0.0.1:0", "--safe-boot",         "--state",
        dir,        "--dialect",   std::string(d->name())};
    // One clean download, timed until the record holds the program.
    long long download_us = 0;
    {
      SimProcess sim(args);
      expect_no_temporary(dir);
      TestClient client(sim.port);
      const auto t0 = Clock::now();
      ASSERT_TRUE(client.send(lines));
      while (read_binary_file(record) != out.stored_form && Clock::now() - t0 < 20s)
        std::this_thread::sleep_for(100us);
      download_us =
          std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - t0).count();
      ASSERT_EQ(read_binary_file(record), out.stored_form) << "the download did not store";
      ASSERT_EQ(sim.stop(), 0);
    }
    for (int round = 0; round < kRoundsPerDialect; ++round) {
      SimProcess sim(args);
      expect_no_temporary(dir);
      EXPECT_EQ(read_binary_file(record), out.stored_form) << "round " << round;
      TestClient client(sim.port);
      const pid_t pid = sim.pid();
      const auto kill_at =
          Clock::now() + std::chrono::microseconds(
                             std::uniform_int_distribution<long long>(0, download_us * 6 / 5)(rng));
      std::thread killer([pid, kill_at] {
        std::this_thread::sleep_until(kill_at);
        ::kill(pid, SIGKILL);
      });
      (void)client.send(lines);
      killer.join();
      EXPECT_EQ(sim.reap(), SIGKILL) << "round " << round;
    }
    SimProcess sim(args);
    expect_no_temporary(dir);
    EXPECT_EQ(read_binary_file(record), out.stored_form);
    TestClient client(sim.port);
    // A last whole download, answered, on the drive that booted from what the kills left; then a
    // clean stop, which keeps the new program whole and leaves no temporary either.
    client.send(lines + std::string(sample.query) + "\n");
    pollfd answer{client.fd(), POLLIN, 0};
    EXPECT_EQ(::poll(&answer, 1, 20'000), 1) << "no answer from the drive";
    std::this_thread::sleep_for(std::chrono::microseconds(2 * download_us));
    EXPECT_EQ(sim.stop(), 0);
    EXPECT_EQ(read_binary_file(record), out.stored_form);
    expect_no_temporary(dir);
  }
}

}  // namespace
}  // namespace uprog::transport
