// The interpreter's error enums (gold::DriveError, gold::InterpreterError) carry exactly the
// numbers of src/dialects/gold/interpreter_errors.def, and its run-time codes follow
// src/vm/run_errors.def; a divergence on either side fails here.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dialects/gold/dialect.h"
#include "dialects/gold/drive_commands.h"
#include "dialects/gold/interpreter_errors.h"
#include "dialects/gold/recorder_commands.h"
#include "gold_firmware/gold_drive.h"
#include "vm/run_error.h"

namespace uprog::gold {
namespace {

const dialect::ErrorInfo* listed(std::string_view name) {
  for (const dialect::ErrorInfo& e : dialect().interpreter_errors())
    if (e.name == name) return &e;
  return nullptr;
}

struct EnumValue {
  int32_t value;
  const char* name;  // the constant's name without kError, as the list names it
};

// Every constant of the two enums that is a code a host sees. The name is made from the
// constant itself, so a constant renamed or removed fails to compile.
#define ENUM_VALUE(name) \
  EnumValue { kError##name, #name }
const EnumValue kEnumValues[] = {
    ENUM_VALUE(BadCommand),      ENUM_VALUE(BadIndex),         ENUM_VALUE(NoValue),
    ENUM_VALUE(OutOfRange),      ENUM_VALUE(NotAssignable),    ENUM_VALUE(ModeNotSupported),
    ENUM_VALUE(ReadOnly),        ENUM_VALUE(MotorMustBeOn),    ENUM_VALUE(MotorMustBeOff),
    ENUM_VALUE(FaultPresent),    ENUM_VALUE(InhibitActive),    ENUM_VALUE(Syntax),
    ENUM_VALUE(NoProgram),       ENUM_VALUE(NoSuchEntry),      ENUM_VALUE(ProgramRunning),
    ENUM_VALUE(NotHalted),       ENUM_VALUE(BadArguments),     ENUM_VALUE(Storage),
    ENUM_VALUE(NoStoredProgram), ENUM_VALUE(LineDidNotFinish), ENUM_VALUE(NoSuchVariable),
    ENUM_VALUE(NoDownload),      ENUM_VALUE(DownloadSize),     ENUM_VALUE(DownloadChunk),
    ENUM_VALUE(DownloadRefused), ENUM_VALUE(RecorderBusy),     ENUM_VALUE(RecorderNoSignals),
    ENUM_VALUE(RecorderNoData),  ENUM_VALUE(BadStartData),
};
#undef ENUM_VALUE

TEST(InterpreterErrors, EachEnumValueIsItsListEntry) {
  for (const EnumValue& e : kEnumValues) {
    const dialect::ErrorInfo* entry = listed(e.name);
    ASSERT_NE(entry, nullptr) << "interpreter_errors.def has no " << e.name;
    EXPECT_EQ(entry->code, e.value) << e.name;
  }
}

// The two constants that are no code a host sees: success, and the drive's "the controller's
// command" sentinel, which must never collide with a listed code.
TEST(InterpreterErrors, TheSentinelsAreNotCodes) {
  EXPECT_EQ(kDriveOk, 0);
  for (const dialect::ErrorInfo& e : dialect().interpreter_errors()) {
    EXPECT_NE(e.code, 0) << e.name;
    EXPECT_NE(e.code, kErrorNotHandledHere) << e.name;
  }
}

// 100 + n for run-time error n of a line: one entry per run_errors.def error, with its text.
TEST(InterpreterErrors, RunTimeCodesFollowRunErrors) {
  EXPECT_EQ(kErrorRunTimeBase, 100);
  struct RunError {
    uint32_t code;
    const char* name;
    const char* text;
  };
  const RunError run_errors[] = {
#define RUN_ERROR(name, code, text) {code, #name, text},
#include "vm/run_errors.def"
#undef RUN_ERROR
  };
  for (const RunError& r : run_errors) {
    if (r.code == 0) continue;  // no error: a line that ran answers no error
    const dialect::ErrorInfo* entry = listed(std::string("Run") + r.name);
    ASSERT_NE(entry, nullptr) << "interpreter_errors.def has no Run" << r.name;
    EXPECT_EQ(entry->code, kErrorRunTimeBase + static_cast<int32_t>(r.code)) << r.name;
    EXPECT_EQ(entry->text, r.text) << r.name;
  }
}

// No entry the enums do not explain: each is an enum constant or a run-time code, listed once.
TEST(InterpreterErrors, EveryEntryIsAnEnumValueOrARunTimeCode) {
  std::set<std::string> enum_names;
  for (const EnumValue& e : kEnumValues) enum_names.insert(e.name);
  std::set<int32_t> codes;
  for (const dialect::ErrorInfo& entry : dialect().interpreter_errors()) {
    const std::string name(entry.name);
    SCOPED_TRACE(name);
    EXPECT_TRUE(codes.insert(entry.code).second) << "code " << entry.code << " is listed twice";
    EXPECT_FALSE(entry.text.empty());
    if (enum_names.count(name)) continue;
    vm::RunError r;
    ASSERT_EQ(name.rfind("Run", 0), 0u) << "neither an enum constant nor a run-time code";
    ASSERT_TRUE(vm::run_error_from_code(static_cast<uint32_t>(entry.code - kErrorRunTimeBase), r));
    EXPECT_EQ(name.substr(3), vm::run_error_name(r));
  }
}

// 64 needs a fault whose cause persists, which no transcript can latch (its `fault` directive
// latches a passing one); the Controller's API can. MO=1 is refused while the cause is there.
TEST(InterpreterErrors, FaultPresentRefusesTheMotor) {
  controller::Controller drive(controller::gold_options());
  ASSERT_TRUE(drive.inject_fault("feedback", true));
  const auto answers = drive.send("MO=1");
  ASSERT_EQ(answers.size(), 1u);
  EXPECT_EQ(answers[0].error, listed("FaultPresent")->code);
  const auto mo = drive.send("MO");
  ASSERT_EQ(mo.size(), 1u);
  EXPECT_EQ(mo[0].text, "0");
}

}  // namespace
}  // namespace uprog::gold
