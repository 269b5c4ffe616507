// The toy dialect's compiler, firmware and sessions (toy_dialect.h).
#include "toy_dialect.h"

#include <charconv>
#include <string>

#include "dialect/semicolon_wire.h"
#include "support/files.h"

namespace uprog::toy {
namespace {

constexpr std::string_view kRecord = "program.toy";
constexpr uint64_t kCycleNs = 62'500;    // the S300's tick: not a whole number of microseconds
constexpr std::size_t kMaxProgram = 64;  // the largest program its flash takes
constexpr std::string_view kDownload = "program ";  // the host's download line: `program TEXT`

// "every N" → N; 0 for anything else.
uint32_t every_of(const std::vector<uint8_t>& form) {
  const std::string text(form.begin(), form.end());
  uint32_t n = 0;
  if (!text.starts_with("every ")) return 0;
  const auto [p, e] = std::from_chars(text.data() + 6, text.data() + text.size(), n);
  return e == std::errc() && (p == text.data() + text.size() || *p == '\n') ? n : 0;
}

class ToyFirmware final : public dialect::Firmware {
 public:
  explicit ToyFirmware(dialect::Runtime& runtime)
      : runtime_(runtime), wire_(dialect::FramerOptions{}) {}

  const dialect::WireForm& wire() const override { return wire_; }
  void boot(std::vector<std::string>& messages) override {
    counter_ = cycles_ = 0;
    std::string error;
    if (auto form = runtime_.flash().read(kRecord, &error)) {
      every_ = every_of(*form);
      if (every_ == 0) messages.emplace_back("toy: stored program refused");
    }
  }
  uint64_t cycle_ns() const override { return kCycleNs; }
  void cycle(const std::vector<uint32_t>& events) override {
    for (uint32_t e : events) events_seen_ |= e;
    ++cycles_;
    if (every_ != 0 && cycles_ % every_ == 0) ++counter_;
  }
  std::unique_ptr<dialect::Session> open_session() override;
  std::vector<dialect::Answer> query(std::string_view line) override { return answer(line, 0); }
  dialect::DownloadResult download(const std::vector<uint8_t>& form) override {
    dialect::DownloadResult r;
    if (every_of(form) == 0 || form.size() > kMaxProgram) {
      r.error = "a toy program is `every N`";
      return r;
    }
    r.ok = runtime_.flash().write(kRecord, form, &r.error);
    r.storage_failed = !r.ok;
    return r;
  }
  std::string start(std::string_view) override {
    std::vector<std::string> messages;
    boot(messages);
    return every_ != 0 ? "" : "no program";
  }
  bool running() const override { return every_ != 0; }
  int32_t program_error() const override { return 0; }
  std::string program_error_text() const override { return ""; }
  std::string state_summary() const override { return "count=" + std::to_string(counter_); }
  std::vector<dialect::ThreadInfo> threads() const override { return {}; }

  int next_session() { return ++sessions_; }

  std::vector<dialect::Answer> answer(std::string_view line, int session) {
    if (line == "count") return {{std::to_string(counter_), 0}};
    if (line == "cycles") return {{std::to_string(cycles_), 0}};
    if (line == "events") return {{std::to_string(events_seen_), 0}};
    if (line == "ticks") return {{std::to_string(runtime_.now_ns()), 0}};
    if (line == "hello") return {{"session " + std::to_string(session), 0}};
    if (line.starts_with(kDownload)) {
      line.remove_prefix(kDownload.size());
      const dialect::DownloadResult r = download(std::vector<uint8_t>(line.begin(), line.end()));
      return {{r.ok ? "" : r.error, r.ok ? 0 : 2}};
    }
    if (line.starts_with("say ")) {
      runtime_.output(std::string(line.substr(4)) + "\n");
      return {};
    }
    return {{"unknown", 1}};
  }

 private:
  dialect::Runtime& runtime_;
  dialect::SemicolonWire wire_;
  uint32_t every_ = 0;
  uint64_t counter_ = 0, cycles_ = 0;
  uint32_t events_seen_ = 0;
  int sessions_ = 0;
};

class ToySession final : public dialect::Session {
 public:
  explicit ToySession(ToyFirmware& f) : firmware_(f), number_(f.next_session()) {}
  std::vector<dialect::Answer> send(std::string_view line) override {
    return firmware_.answer(line, number_);
  }

 private:
  ToyFirmware& firmware_;
  int number_;
};

std::unique_ptr<dialect::Session> ToyFirmware::open_session() {
  return std::make_unique<ToySession>(*this);
}

class ToyDialect final : public dialect::Dialect {
 public:
  std::string_view name() const override { return "toy"; }
  std::string_view description() const override { return "a test dialect"; }
  std::span<const std::string_view> source_extensions() const override { return kExtensions; }
  std::string_view stored_extension() const override { return ".toy"; }
  dialect::CompileOutput compile_source(const SourceFile& source,
                                        const dialect::CompileSettings&) const override {
    dialect::CompileOutput out;
    out.stored_form.assign(source.text.begin(), source.text.end());
    if (every_of(out.stored_form) == 0) {
      out.stored_form.clear();
      out.diagnostics.push_back(
          Diagnostic{Severity::Error, "toy", 2, "not `every N`", {source.name, 1, 1}, {}});
    }
    return out;
  }
  Diagnostic unreadable_source(const std::string& path, const std::string& why) const override {
    return Diagnostic{Severity::Error, "toy", 1, why, {path, 0, 0}, {}};
  }
  std::span<const dialect::ErrorInfo> diagnostic_codes() const override { return kErrors; }
  std::span<const dialect::ErrorInfo> interpreter_errors() const override { return kErrors; }
  std::unique_ptr<dialect::Firmware> make_firmware(dialect::Runtime& runtime,
                                                   const dialect::FirmwareOptions&) const override {
    return std::make_unique<ToyFirmware>(runtime);
  }
  std::vector<std::string> download_lines(const std::vector<uint8_t>& form) const override {
    return {std::string(kDownload) + std::string(form.begin(), form.end())};
  }
  std::string load_line() const override { return ""; }
  std::size_t max_download_bytes() const override { return kMaxProgram; }
  const dialect::SampleProgram& sample_program() const override { return kSample; }

 private:
  static constexpr std::string_view kExtensions[] = {".toysrc"};
  static constexpr dialect::ErrorInfo kErrors[] = {{1, "Unknown", "unknown"},
                                                   {2, "Refused", "download refused"}};
  // Counting every 4th cycle, the counter is 1 after 4 cycles.
  static constexpr dialect::SampleProgram kSample{
      "sample.toysrc", "every 4", "", "count", "1", 4, "every x", 1, "bogus"};
};

}  // namespace

const dialect::Dialect& dialect() {
  static const ToyDialect toy;
  return toy;
}

}  // namespace uprog::toy
