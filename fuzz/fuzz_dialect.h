// What the generated fuzz targets of a dialect share (fuzz/dialect_fuzzers.cmake): the dialect
// the target was built for (UPROG_FUZZ_DIALECT, a name in its registry) and a drive of it with the
// dialect's sample program (dialect::SampleProgram) downloaded and loaded as a host does it.
#pragma once
#include <cstdlib>
#include <memory>
#include <string>

#include "controller/controller.h"
#include "dialects/registry.h"

#ifndef UPROG_FUZZ_DIALECT
#error "a dialect fuzz target is built for one dialect: -DUPROG_FUZZ_DIALECT=\"name\""
#endif

namespace uprog::fuzz {

inline const dialect::Dialect& fuzzed_dialect() {
  static const dialect::Dialect* const d = dialects::find(UPROG_FUZZ_DIALECT);
  if (d == nullptr) std::abort();  // the build named a dialect its registry lacks
  return *d;
}

// The sample's stored form, compiled once; a sample that does not compile is a broken dialect.
inline const std::vector<uint8_t>& sample_stored_form() {
  static const std::vector<uint8_t> form = [] {
    const dialect::SampleProgram& s = fuzzed_dialect().sample_program();
    const dialect::CompileOutput out = fuzzed_dialect().compile_source(
        SourceFile{std::string(s.file_name), std::string(s.source)}, {});
    if (!out.ok()) std::abort();
    return out.stored_form;
  }();
  return form;
}

inline std::unique_ptr<controller::Controller> fresh_drive() {
  controller::ControllerOptions options;
  options.dialect = &fuzzed_dialect();
  return std::make_unique<controller::Controller>(options);
}

// A drive with the sample stored and loaded through the host's download lines, then started.
inline std::unique_ptr<controller::Controller> drive_with_sample() {
  auto drive = fresh_drive();
  auto host = drive->open_session();
  for (const std::string& line : fuzzed_dialect().download_lines(sample_stored_form()))
    (void)host->send(line);
  if (!fuzzed_dialect().load_line().empty()) (void)host->send(fuzzed_dialect().load_line());
  (void)drive->start_program(fuzzed_dialect().sample_program().entry);
  return drive;
}

}  // namespace uprog::fuzz
