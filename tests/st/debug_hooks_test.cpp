// What the S300 firmware offers the debugger: its PLC programs as threads by their names, and ST
// expressions evaluated against the running program's globals (a variable alone, a DLONG as
// one number, an expression, an assignment that stays made, an error with the compiler's text);
// and a breakpoint on a PLC1 line through the debugger, whose expression condition is ST.
#include <gtest/gtest.h>

#include "controller/controller.h"
#include "debug/debugger.h"
#include "dialects/st/dialect.h"

namespace uprog {
namespace {

const std::string kProgram = UPROG_SOURCE_DIR "/tests/transcripts/debug/programs/st_tasks.st";

struct Drive {
  controller::Controller drive{[] {
    controller::ControllerOptions o;
    o.dialect = &st::dialect();
    return o;
  }()};
  Drive() {
    std::vector<Diagnostic> diagnostics;
    EXPECT_TRUE(drive.download_source_file(kProgram, diagnostics));
    EXPECT_EQ(drive.start_program(""), "");
  }
  dialect::Evaluation eval(const std::string& e) { return drive.firmware().evaluate(0, 0, e); }
};

TEST(st_debug, TheProgramsAreTheThreads) {
  Drive d;
  ASSERT_NE(d.drive.firmware().debug_program(), nullptr);
  const auto threads = d.drive.firmware().threads();
  ASSERT_EQ(threads.size(), 2u);
  EXPECT_EQ(threads[0].name, "PLC1");
  EXPECT_EQ(threads[1].name, "PLCMAIN");
}

TEST(st_debug, ExpressionsAreStAndTakeNoTime) {
  Drive d;
  d.drive.advance(10'500);  // PLC1 has run 10 or 11 times: read N, whatever it is
  const dialect::Evaluation n = d.eval("N");
  ASSERT_TRUE(n.ok) << n.error;
  const int32_t runs = std::stoi(n.value);
  EXPECT_GT(runs, 0);
  const uint64_t now = d.drive.now_ns();
  // `*` multiplies the low 16 bits; relations give TRUE = -1.
  EXPECT_EQ(d.eval("N * 2 + 1").value, std::to_string(runs * 2 + 1));
  EXPECT_EQ(d.eval("N > 0").value, "-1");
  EXPECT_TRUE(d.eval("N > 0").is_true);
  EXPECT_FALSE(d.eval("N < 0").is_true);
  // An assignment stays made, and the command line sees it.
  EXPECT_EQ(d.eval("K := 7").value, "7");
  EXPECT_EQ(d.drive.query("K").at(0).text, "7");
  EXPECT_EQ(d.drive.now_ns(), now);
  const dialect::Evaluation bad = d.eval("N +");
  EXPECT_FALSE(bad.ok);
  EXPECT_FALSE(bad.error.empty());
  EXPECT_FALSE(d.eval("NOSUCH + 1").ok);
  EXPECT_FALSE(d.eval("K := 1; K := 2").ok);
}

TEST(st_debug, ABreakpointOnAPlc1LineWithAnStCondition) {
  Drive d;
  debug::Debugger debugger(d.drive);
  debugger.program_changed();
  debug::BreakpointSpec b;
  b.line = 5;
  b.condition = "N = 3";
  // The drive compiles the source under its file's name (the controller gave it with the download).
  const auto states = debugger.set_line_breakpoints(kProgram, {b});
  ASSERT_EQ(states.size(), 1u);
  ASSERT_TRUE(states[0].verified) << states[0].message;
  ASSERT_EQ(debugger.run(1'000'000'000), debug::RunState::Stopped);
  EXPECT_EQ(d.eval("N").value, "3");  // stopped before the fourth run's N := N + 1
  EXPECT_EQ(d.eval("K").value, "6");
  EXPECT_EQ(debugger.stack(0).at(0).line, 5u);
}

}  // namespace
}  // namespace uprog
