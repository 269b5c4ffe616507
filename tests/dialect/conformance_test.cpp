// The conformance suite: the same checks on every dialect of the registry it is linked with, one
// case per dialect and check (ctest names `Registered/Conformance.Check/NAME`). Each dialect's
// sample program (dialect::SampleProgram, given by its registration) is compiled in memory and
// from a file, downloaded as a host downloads it (the dialect's download lines, then its load
// line), started, stepped cycle by cycle until it has done what it does, and still there after a
// power cycle; a bad source, a bad host line and an oversized stored form are refused, and the
// stored program stays. Built twice: over the registry of the build (conformance_test) and over
// it plus a toy fifth dialect registered in one line (conformance_toy_test, toy_registry.def).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "controller/controller.h"
#include "dialects/registry.h"
#include "support/files.h"

namespace uprog::dialect {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> registered_names() {
  std::vector<std::string> names;
  for (const Dialect* d : dialects::all()) names.emplace_back(d->name());
  return names;
}

class Conformance : public ::testing::TestWithParam<std::string> {
 protected:
  const Dialect& dialect() const { return *dialects::find(GetParam()); }
  const SampleProgram& sample() const { return dialect().sample_program(); }

  CompileOutput compile_sample() const {
    return dialect().compile_source(
        SourceFile{std::string(sample().file_name), std::string(sample().source)}, {});
  }

  // A drive of the dialect with the sample downloaded and loaded by a host's lines.
  std::unique_ptr<controller::Controller> drive_with_sample(const std::string& state_dir = {}) {
    controller::ControllerOptions options;
    options.dialect = &dialect();
    options.state_dir = state_dir;
    auto drive = std::make_unique<controller::Controller>(options);
    const CompileOutput out = compile_sample();
    EXPECT_TRUE(out.ok()) << format_text(out.diagnostics);
    auto host = drive->open_session();
    std::vector<std::string> lines = dialect().download_lines(out.stored_form);
    if (!dialect().load_line().empty()) lines.push_back(dialect().load_line());
    for (const std::string& line : lines) {
      for (const Answer& a : host->send(line)) {
        EXPECT_FALSE(a.is_error())
            << line.substr(0, 40) << " answered " << a.error << " " << a.text;
      }
    }
    return drive;
  }

  std::string ask(controller::Controller& drive) const {
    const std::vector<Answer> answers = drive.query(sample().query);
    if (answers.size() != 1) return "<" + std::to_string(answers.size()) + " answers>";
    return answers[0].is_error() ? "! " + std::to_string(answers[0].error) : answers[0].text;
  }

  // Starts the sample and steps the drive one firmware cycle at a time: the answer is not there
  // before the first cycle and is there within max_cycles; the number of cycles it took.
  uint32_t run_and_step(controller::Controller& drive) const {
    EXPECT_EQ(drive.start_program(sample().entry), "");
    EXPECT_NE(ask(drive), sample().answer) << "answered before the program ran";
    for (uint32_t cycle = 1; cycle <= sample().max_cycles; ++cycle) {
      drive.advance_ns(drive.firmware().cycle_ns());
      if (ask(drive) == sample().answer) return cycle;
    }
    ADD_FAILURE() << "after " << sample().max_cycles << " cycles `" << sample().query
                  << "` answers " << ask(drive) << ", not " << sample().answer;
    return 0;
  }

  bool registered_interpreter_error(int32_t code) const {
    const auto list = dialect().interpreter_errors();
    return std::any_of(list.begin(), list.end(),
                       [&](const ErrorInfo& e) { return e.code == code; });
  }
};

TEST_P(Conformance, TheSampleCompilesInMemoryAndFromAFileToTheSameStoredForm) {
  const fs::path dir = fs::temp_directory_path() / ("uprog_conformance_" + GetParam());
  fs::create_directories(dir);
  const std::string path = (dir / std::string(sample().file_name)).string();
  // The same name both ways: a stored form may carry it (a line table's file).
  const CompileOutput memory =
      dialect().compile_source(SourceFile{path, std::string(sample().source)}, {});
  ASSERT_TRUE(memory.ok()) << format_text(memory.diagnostics);
  EXPECT_FALSE(memory.stored_form.empty());
  EXPECT_LE(memory.stored_form.size(), dialect().max_download_bytes());
  ASSERT_TRUE(write_file_atomically(path, sample().source.data(), sample().source.size()));
  const CompileOutput file = dialect().compile_file(path, {});
  EXPECT_TRUE(file.ok()) << format_text(file.diagnostics);
  EXPECT_EQ(file.stored_form, memory.stored_form);
  EXPECT_EQ(dialects::for_file(path), &dialect()) << "the sample's extension names its dialect";
  const CompileOutput missing =
      dialect().compile_file((dir / "missing" / std::string(sample().file_name)).string(), {});
  EXPECT_FALSE(missing.ok()) << "an unreadable file is an error";
  fs::remove_all(dir);
}

TEST_P(Conformance, ABadSourceIsRefusedAtItsLine) {
  const CompileOutput out = dialect().compile_source(
      SourceFile{std::string(sample().file_name), std::string(sample().bad_source)}, {});
  ASSERT_FALSE(out.ok());
  EXPECT_TRUE(out.stored_form.empty());
  const auto first =
      std::find_if(out.diagnostics.begin(), out.diagnostics.end(),
                   [](const Diagnostic& d) { return d.severity == Severity::Error; });
  ASSERT_NE(first, out.diagnostics.end());
  EXPECT_EQ(first->where.line, static_cast<int>(sample().bad_source_line)) << first->message;
  EXPECT_EQ(first->where.file, sample().file_name);
}

TEST_P(Conformance, TheDownloadedSampleRunsAndStepsCycleByCycle) {
  auto drive = drive_with_sample();
  EXPECT_GT(run_and_step(*drive), 0u);
  EXPECT_EQ(drive->program_error(), 0) << drive->program_error_text();
}

TEST_P(Conformance, TheStoredSampleOutlivesAPowerCycleAndARefusedDownload) {
  const fs::path dir = fs::temp_directory_path() / ("uprog_conformance_state_" + GetParam());
  fs::remove_all(dir);
  {
    auto drive = drive_with_sample(dir.string());
    // One byte over what the drive takes: refused, and nothing stored.
    const std::vector<uint8_t> oversized(dialect().max_download_bytes() + 1, ' ');
    const controller::DownloadResult r = drive->download(oversized);
    EXPECT_FALSE(r.ok);
    EXPECT_FALSE(r.error.empty());
  }
  {
    controller::ControllerOptions options;
    options.dialect = &dialect();
    options.state_dir = dir.string();
    controller::Controller drive(options);
    EXPECT_TRUE(drive.boot_messages().empty()) << drive.boot_messages().front();
    EXPECT_GT(run_and_step(drive), 0u);
  }
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();
  fs::remove_all(dir);
}

TEST_P(Conformance, ABadHostLineIsARegisteredErrorAndTheProgramRunsOn) {
  auto drive = drive_with_sample();
  auto host = drive->open_session();
  const std::vector<Answer> answers = host->send(sample().bad_host_line);
  ASSERT_FALSE(answers.empty());
  EXPECT_TRUE(answers.back().is_error());
  EXPECT_TRUE(registered_interpreter_error(answers.back().error))
      << answers.back().error << " is not in the dialect's interpreter error list";
  EXPECT_GT(run_and_step(*drive), 0u);
}

TEST_P(Conformance, ItsListsAreRegistered) {
  EXPECT_FALSE(dialect().interpreter_errors().empty());
  EXPECT_FALSE(dialect().diagnostic_codes().empty());
  EXPECT_FALSE(dialect().source_extensions().empty());
  EXPECT_FALSE(dialect().description().empty());
}

INSTANTIATE_TEST_SUITE_P(Registered, Conformance, ::testing::ValuesIn(registered_names()),
                         [](const auto& param_info) { return param_info.param; });

#ifdef UPROG_EXPECTED_DIALECT
// The suite above ran on the dialect this build's registry was made to add.
TEST(ConformanceRegistry, HoldsTheDialectItWasBuiltWith) {
  EXPECT_NE(dialects::find(UPROG_EXPECTED_DIALECT), nullptr);
}
#endif

}  // namespace
}  // namespace uprog::dialect
