// The program store (dialect/program_store.h) and the atomic file replacement under it
// (support/files.h): a writer killed while it writes leaves the old file whole and no temporary;
// a drive's flash removes the temporaries of dead writers at start-up and keeps a living one's;
// a refused or unstorable download leaves the stored form as it was.
#include "dialect/program_store.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <thread>

#include "controller/flash.h"
#include "support/files.h"

namespace uprog::dialect {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  std::string path;
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "uprog_store_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp");
    path = pattern;
  }
  ~TempDir() { fs::remove_all(path); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(path)) out.push_back(e.path().filename());
    std::sort(out.begin(), out.end());
    return out;
  }
};

// A file of `size` bytes all equal to `fill`.
std::vector<uint8_t> filled(size_t size, uint8_t fill) { return std::vector<uint8_t>(size, fill); }

pid_t dead_process() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(program_store, AWriterKilledWhileWritingLeavesTheOldFileWholeAndNoTemporary) {
  TempDir dir;
  const std::string path = dir.path + "/program.pdi";
  constexpr size_t kSize = 8u << 20;  // 8 MiB: the write and its fsync take a while
  ASSERT_TRUE(write_file_atomically(path, filled(kSize, 'A').data(), kSize));
  for (int round = 0; round < 6; ++round) {
    const pid_t writer = ::fork();
    ASSERT_GE(writer, 0);
    if (writer == 0) {
      const auto b = filled(kSize, 'B');
      for (;;) write_file_atomically(path, b.data(), b.size());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5 + 7 * round));
    ::kill(writer, SIGKILL);
    int status = 0;
    ::waitpid(writer, &status, 0);
    EXPECT_EQ(dir.names(), std::vector<std::string>{"program.pdi"}) << "round " << round;
    const auto now = read_binary_file(path);
    ASSERT_TRUE(now.has_value());
    EXPECT_TRUE(*now == filled(kSize, 'A') || *now == filled(kSize, 'B')) << "round " << round;
  }
}

TEST(program_store, TheFlashRemovesTheTemporariesOfDeadWritersAtStartUp) {
  TempDir dir;
  const std::string dead = "program.st.tmp." + std::to_string(dead_process());
  const std::string living = "program.upi.tmp.1";  // init never dies: it may be mid-rename
  for (const std::string& name : {dead, living, std::string("program.cup")}) {
    ASSERT_TRUE(write_file_atomically(dir.path + "/" + name, "x", 1));
  }
  controller::StateFlash flash(dir.path);
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"program.cup", living}));
}

// A flash in memory whose writes can be made to fail.
class MemoryFlash final : public Flash {
 public:
  bool failing = false;
  std::map<std::string, std::vector<uint8_t>, std::less<>> records;
  std::optional<std::vector<uint8_t>> read(std::string_view name, std::string* error) override {
    if (error) error->clear();
    const auto it = records.find(name);
    if (it == records.end()) return std::nullopt;
    return it->second;
  }
  bool write(std::string_view name, std::span<const uint8_t> bytes, std::string* error) override {
    if (failing) {
      *error = "the flash is full";
      return false;
    }
    records[std::string(name)].assign(bytes.begin(), bytes.end());
    return true;
  }
  std::string where(std::string_view name) const override { return std::string(name); }
};

std::string starts_with_p(const std::vector<uint8_t>& bytes) {
  return !bytes.empty() && bytes[0] == 'p' ? "" : "not a p program";
}

TEST(program_store, ARefusedOrUnstorableDownloadLeavesTheStoredFormAsItWas) {
  MemoryFlash flash;
  const ProgramStore store("program.x", "program");
  const std::vector<uint8_t> good{'p', '1'}, bad{'q'}, other{'p', '2'};
  ASSERT_TRUE(store.store(flash, good, starts_with_p).ok);

  const DownloadResult refused = store.store(flash, bad, starts_with_p);
  EXPECT_FALSE(refused.ok);
  EXPECT_FALSE(refused.storage_failed);
  EXPECT_EQ(refused.error, "not a p program");

  flash.failing = true;
  const DownloadResult unstored = store.store(flash, other, starts_with_p);
  EXPECT_FALSE(unstored.ok);
  EXPECT_TRUE(unstored.storage_failed);
  EXPECT_EQ(unstored.error, "could not store the program: the flash is full");
  EXPECT_EQ(flash.records["program.x"], good);
}

TEST(program_store, APowerUpReadRefusesAStoredFormItsCheckRefusesAndSaysWhy) {
  MemoryFlash flash;
  const ProgramStore store("program.x", "program");
  std::vector<std::string> messages;
  EXPECT_FALSE(store.read(flash, starts_with_p, messages).has_value());
  EXPECT_TRUE(messages.empty()) << "no program stored is no message";

  flash.records["program.x"] = {'q'};
  EXPECT_FALSE(store.read(flash, starts_with_p, messages, "; starting without").has_value());
  EXPECT_EQ(messages, std::vector<std::string>{"stored program program.x refused: not a p program; "
                                               "starting without"});

  flash.records["program.x"] = {'p'};
  messages.clear();
  EXPECT_EQ(store.read(flash, starts_with_p, messages), (std::vector<uint8_t>{'p'}));
  EXPECT_TRUE(messages.empty());
}

}  // namespace
}  // namespace uprog::dialect
