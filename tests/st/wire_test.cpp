// The S300's ASCII wire end to end through a host's session: PROMPT=0 answers bare lines,
// PROMPT=1 echoes the input with CR LF and ends with the prompt `-->`, an error is BEL `ERR`
// code text; PRINTF's text reaches the host as unsolicited CR LF lines.
#include "dialects/st/wire.h"

#include <gtest/gtest.h>

#include "controller/controller.h"
#include "dialects/st/dialect.h"
#include "drive/axis.h"
#include "transport/controller_service.h"
#include "transport/host_session.h"

namespace uprog {
namespace {

struct Drive {
  Drive() : controller(options()), service(controller), session(service) {}
  static controller::ControllerOptions options() {
    controller::ControllerOptions o;
    o.dialect = &st::dialect();
    return o;
  }
  std::string say(std::string_view bytes) {
    std::string out;
    session.receive(bytes, out);
    return out;
  }
  controller::Controller controller;
  transport::ControllerService service;
  transport::HostSession session;
};

// A fresh drive prompts and echoes: PROMPT's default is 1 (the SERVOSTAR-family ASCII
// reference, PROMPT: "Default 1", "-->" plus echo; docs/dialects/st.md, "Echo").
TEST(st_wire, AFreshDriveEchoesAndPrompts) {
  Drive d;
  EXPECT_EQ(d.say("PFB\r"), "PFB\r\n0\r\n-->");
  EXPECT_EQ(d.say("PROMPT\r"), "PROMPT\r\n1\r\n-->");
}

TEST(st_wire, PromptZeroAnswersWithoutEchoOrPrompt) {
  Drive d;
  EXPECT_EQ(d.say("PROMPT 0\r"), "PROMPT 0\r\n");  // echoed as it arrived, then no prompt
  EXPECT_EQ(d.say("VER\r"), "uprog S300 sim 1.0\r\n");
  EXPECT_EQ(d.say("PGEARI 20000\r"), "");  // a write answers none
  EXPECT_EQ(d.say("pgeari\n"), "20000\r\n");
  EXPECT_EQ(d.say("NOSUCH\r"), "\aERR 1 unknown command\r\n");
}

TEST(st_wire, PromptOneEchoesAndPrompts) {
  Drive d;
  EXPECT_EQ(d.say("PROMPT 0\r"), "PROMPT 0\r\n");
  EXPECT_EQ(d.say("PROMPT 1\r"), "-->");  // the echo is decided as the line arrives
  EXPECT_EQ(d.say("VER\r"), "VER\r\nuprog S300 sim 1.0\r\n-->");
  EXPECT_EQ(d.say("MSG 2\r"), "MSG 2\r\n-->");
  // Each byte comes back as it arrives; the answer when its CR does.
  EXPECT_EQ(d.say("V"), "V");
  EXPECT_EQ(d.say("ER\r\n"), "ER\r\nuprog S300 sim 1.0\r\n-->");
  EXPECT_EQ(d.say("PFB 3\r"), "PFB 3\r\n\aERR 4 read only\r\n-->");
  EXPECT_EQ(d.say("ERRCODE\r"), "ERRCODE\r\nno error\r\n-->");
  EXPECT_EQ(d.say("PROMPT 0\r"), "PROMPT 0\r\n");
}

// A host sends CR alone and waits for the prompt (the reference's PROMPT=1: "the prompt (-->)
// symbol is given for inputting data"; PROMPT=2, which repeats the last command on a CR at the
// start of a line, is the spec's 1): an empty line gives CR LF and `-->` again, whether it ends
// with CR, CR LF or LF; with PROMPT=0 nothing comes back.
TEST(st_wire, AnEmptyLineGivesThePromptAgain) {
  Drive d;
  EXPECT_EQ(d.say("\r"), "\r\n-->");
  EXPECT_EQ(d.say("\r\n"), "\r\n-->");
  EXPECT_EQ(d.say("\n"), "\r\n-->");
  EXPECT_EQ(d.say("  \r"), "  \r\n-->");
  EXPECT_EQ(d.say("PROMPT 0\r"), "PROMPT 0\r\n");
  EXPECT_EQ(d.say("\r\n"), "");
}

// A line ended by LF alone comes back with CR LF as one ended by CR does, so a host that waits
// for its echo line reads the answer on a line of its own (it read "pfb0" before); the LF of a
// CR LF adds nothing, also when the CR came while PROMPT was 0.
TEST(st_wire, ALineEndedByLfAloneEchoesCrLf) {
  Drive d;
  EXPECT_EQ(d.say("pfb\n"), "pfb\r\n0\r\n-->");
  EXPECT_EQ(d.say("PFB\r\n"), "PFB\r\n0\r\n-->");
  EXPECT_EQ(d.say("PROMPT 0\r"), "PROMPT 0\r\n");
  EXPECT_EQ(d.say("PROMPT 1\r"), "-->");
  EXPECT_EQ(d.say("\n"), "");  // the LF of the CR LF that ended `PROMPT 1`
  EXPECT_EQ(d.say("VER\n"), "VER\r\nuprog S300 sim 1.0\r\n-->");
}

// `T a` commands a amperes, fraction and all (spec: "OPMODE 2: a amperes"; issue 39: `T 0.5`
// commanded 0 A): the axis' torque command is 0.5 A, and -1.25 A after `T -1.25`.
TEST(st_wire, TorqueTakesAFraction) {
  Drive d;
  d.say("PROMPT 0\r");
  EXPECT_EQ(d.say("OPMODE 2\r"), "");
  EXPECT_EQ(d.say("EN\r"), "");
  d.controller.advance(50'000);
  EXPECT_EQ(d.say("T 0.5\r"), "");
  EXPECT_FLOAT_EQ(d.controller.axis().torque_command(), 0.5f);
  EXPECT_EQ(d.say("T -1.25\r"), "");
  EXPECT_FLOAT_EQ(d.controller.axis().torque_command(), -1.25f);
}

TEST(st_wire, UnsolicitedTextEndsItsLinesWithCrLf) {
  std::string out;
  const int32_t prompt = 0;
  st::S300Wire wire(prompt, dialect::WireStyle::kDrive);
  wire.write_output("Hello world in the year 2011\n", out);
  EXPECT_EQ(out, "Hello world in the year 2011\r\n");
  EXPECT_EQ(st::answer_text({"unknown command", 1}), "\aERR 1 unknown command");
}

// The readable form (docs/protocol.md) for uprog's own hosts: `;` after each answer, `?CODE
// TEXT;` for an error, `;` for a line without answers, CR LF after the line; no echo, no prompt
// whatever PROMPT says.
TEST(st_wire, TheReadableFormIsTheProtocolsOwn) {
  const int32_t prompt = 1;
  st::S300Wire wire(prompt, dialect::WireStyle::kReadable);
  std::string out;
  EXPECT_FALSE(wire.echoes());
  wire.write_echo("VER\r", out);
  wire.write_answer({"uprog S300 sim 1.0", 0}, out);
  wire.write_line_end(out);
  wire.write_answer({"unknown command", 1}, out);
  wire.write_line_end(out);
  wire.write_silent_line(out);
  wire.write_line_end(out);
  EXPECT_EQ(out, "uprog S300 sim 1.0;\r\n?1 unknown command;\r\n;\r\n");
}

}  // namespace
}  // namespace uprog
