// The commands from the Elmo reference over the axis: homing through HM, CA[18], TR, LL/HL, the
// identity, SR's program bits, EO, PT/QP/MP, and the refusals of each.
#include <gtest/gtest.h>

#include "dialects/gold/drive_commands.h"
#include "drive/events.h"

namespace uprog::gold {
namespace {

struct Fixture {
  drive::Axis axis;
  DriveCommands commands{axis};

  uint16_t id(const char* name) {
    const CommandInfo* c = find_command(name);
    EXPECT_NE(c, nullptr) << name;
    return c ? c->id : 0;
  }
  int32_t write(const char* name, int32_t index, int32_t v) {
    return commands.write(id(name), index, Value::of_int(v));
  }
  int32_t read(const char* name, int32_t index = 0) {
    Value v{};
    EXPECT_EQ(commands.read(id(name), index, v), kDriveOk) << name << "[" << index << "]";
    return v.i;
  }
  void run_us(uint64_t us) {
    for (uint64_t t = 0; t < us; t += axis.period_us()) axis.step();
  }
  void enable() {
    ASSERT_EQ(write("MO", 0, 1), kDriveOk);
    run_us(drive::kEnableDelay_us + 1000);
  }
};

TEST(gold_reference_commands, HomingThroughHm) {
  Fixture f;
  EXPECT_EQ(f.read("HM", 1), 0);
  ASSERT_EQ(f.write("HM", 2, 1000), kDriveOk);  // the value PX takes
  ASSERT_EQ(f.write("HM", 3, 0), kDriveOk);     // the event: at once
  ASSERT_EQ(f.write("HM", 4, 2), kDriveOk);     // continue
  ASSERT_EQ(f.write("HM", 5, 0), kDriveOk);     // PX = HM[2]
  ASSERT_EQ(f.write("HM", 1, 1), kDriveOk);     // arm
  EXPECT_EQ(f.read("HM", 1), 1);
  EXPECT_EQ(f.read("SR") & (1 << 11), 1 << 11);  // "homing being processed"
  EXPECT_EQ(f.axis.step() & drive::kEventHome, static_cast<uint32_t>(drive::kEventHome));
  EXPECT_EQ(f.read("HM", 1), 0);
  EXPECT_EQ(f.read("SR") & (1 << 11), 0);
  EXPECT_EQ(f.read("PX"), 1000);
  EXPECT_EQ(f.read("HM", 7), 0);  // PX where the event came
  EXPECT_EQ(f.read("HM", 2), 1000);
  EXPECT_EQ(f.read("HM", 3), 0);
  EXPECT_EQ(f.read("HM", 4), 2);
  EXPECT_EQ(f.read("HM", 5), 0);
}

TEST(gold_reference_commands, HmRangesPerIndex) {
  Fixture f;
  EXPECT_EQ(f.write("HM", 1, 2), kErrorOutOfRange);
  EXPECT_EQ(f.write("HM", 3, 10), kErrorOutOfRange);  // 10..12 are no event (homing_events.cpp)
  EXPECT_EQ(f.write("HM", 3, 25), kErrorOutOfRange);
  EXPECT_EQ(f.write("HM", 4, 3), kErrorOutOfRange);
  EXPECT_EQ(f.write("HM", 5, -1), kErrorOutOfRange);
  EXPECT_EQ(f.write("HM", 6, 5), kErrorOutOfRange);  // outputs 1..4 (0: none)
  EXPECT_EQ(f.write("HM", 7, 0), kErrorReadOnly);
  EXPECT_EQ(f.write("HM", 8, 0), kErrorBadIndex);
  EXPECT_EQ(f.write("HM", 2, -2147483647 - 1), kDriveOk);
}

TEST(gold_reference_commands, CountsPerRevolutionSpacesTheIndex) {
  Fixture f;
  EXPECT_EQ(f.read("CA", 18), 65536);
  EXPECT_EQ(f.write("CA", 18, 5), kErrorOutOfRange);  // the reference's 6..530,000,000
  EXPECT_EQ(f.write("CA", 18, 530000001), kErrorOutOfRange);
  ASSERT_EQ(f.write("CA", 18, 4000), kDriveOk);
  EXPECT_EQ(f.axis.parameters().counts_per_revolution(), 4000);
  f.enable();
  EXPECT_EQ(f.write("CA", 18, 8000), kErrorMotorMustBeOff);
  EXPECT_EQ(f.write("CA", 19, 4), kErrorMotorMustBeOff);
  // WS[21] = mod(encoder, CA[18]) (reference, CA[N]).
  ASSERT_EQ(f.write("PX", 0, 10123), kDriveOk);
  EXPECT_EQ(f.read("WS", 21), 10123 % 4000);
  ASSERT_EQ(f.write("PX", 0, -1), kDriveOk);
  EXPECT_EQ(f.read("WS", 21), 3999);
  EXPECT_EQ(f.read("WS", 1), 0);
  // A parameter file (LD) is not range-checked: a CA[18] of 0 must not divide by zero.
  f.axis.parameters().commutation[17] = 0;
  EXPECT_EQ(f.read("WS", 21), 0);
}

TEST(gold_reference_commands, TargetWindowAndFeedbackLimits) {
  Fixture f;
  EXPECT_EQ(f.read("TR", 1), 100);  // reference defaults TR[1]=100, TR[2]=20
  EXPECT_EQ(f.read("TR", 2), 20);
  EXPECT_EQ(f.write("TR", 1, 32001), kErrorOutOfRange);
  EXPECT_EQ(f.write("TR", 2, 101), kErrorOutOfRange);
  EXPECT_EQ(f.write("TR", 1, -1), kErrorOutOfRange);
  ASSERT_EQ(f.write("TR", 2, 100), kDriveOk);
  EXPECT_EQ(f.axis.parameters().target_time_ms, 100);
  ASSERT_EQ(f.write("HL", 2, 123456), kDriveOk);
  ASSERT_EQ(f.write("LL", 3, -99), kDriveOk);
  EXPECT_EQ(f.axis.parameters().speed_fault_high_counts_per_s, 123456);
  EXPECT_EQ(f.axis.parameters().position_fault_low_counts, -99);
  EXPECT_EQ(f.write("LL", 1, 0), kErrorBadIndex);
}

TEST(gold_reference_commands, IdentityTemperatureAndFeedback) {
  Fixture f;
  EXPECT_EQ(f.read("SN", 1), 154);  // Elmo's CANopen vendor id, 0x9A
  EXPECT_EQ(f.read("SN", 4), kIdentity[3]);
  EXPECT_EQ(f.read("TI", 1), kTemperature_c);
  EXPECT_EQ(f.commands.text(f.id("VR")), std::string(kVersionText));
  EXPECT_FALSE(f.commands.text(f.id("PX")).has_value());
  ASSERT_EQ(f.write("PY", 0, 77), kDriveOk);
  EXPECT_EQ(f.read("FP", 2), 77);
  ASSERT_EQ(f.write("PX", 0, 55), kDriveOk);
  EXPECT_EQ(f.read("FP", 1), 55);
  EXPECT_EQ(f.read("FV", 2), 0);
  EXPECT_EQ(f.write("SN", 1, 1), kErrorReadOnly);
}

TEST(gold_reference_commands, SrCarriesTheProgramsBits) {
  Fixture f;
  ProgramState state;
  f.commands.set_program_state_source([&] { return state; });
  EXPECT_EQ(f.read("SR") & ((1 << 12) | (1 << 29)), 0);
  state.running = true;
  EXPECT_EQ(f.read("SR") & (1 << 12), 1 << 12);
  state = {false, true};
  EXPECT_EQ(f.read("SR") & ((1 << 12) | (1 << 29)), 1 << 29);
}

TEST(gold_reference_commands, EchoAndHexAreValuesForTheWire) {
  Fixture f;
  EXPECT_EQ(f.read("EO"), 1);  // a drive echoes until the host turns it off
  EXPECT_TRUE(f.commands.echo());
  ASSERT_EQ(f.write("EO", 0, 0), kDriveOk);
  EXPECT_FALSE(f.commands.echo());
  EXPECT_EQ(f.write("EO", 0, 2), kErrorOutOfRange);
  EXPECT_EQ(f.read("HX"), 0);
  ASSERT_EQ(f.write("HX", 0, 1), kDriveOk);
  EXPECT_TRUE(f.commands.hexadecimal());
}

TEST(gold_reference_commands, PtMotionThroughQpMpPt) {
  Fixture f;
  f.enable();
  for (int32_t k = 1; k <= 3; ++k) ASSERT_EQ(f.write("QP", k, (k - 1) * 500), kDriveOk);
  ASSERT_EQ(f.write("MP", 1, 1), kDriveOk);
  ASSERT_EQ(f.write("MP", 2, 3), kDriveOk);
  ASSERT_EQ(f.write("MP", 4, 1000), kDriveOk);  // 50 ms per point
  ASSERT_EQ(f.write("PT", 0, 4), kDriveOk);
  EXPECT_EQ(f.commands.execute(f.id("BG"), 0), kErrorBadStartData);  // 4 is beyond MP[2]
  ASSERT_EQ(f.write("PT", 0, 1), kDriveOk);
  ASSERT_EQ(f.commands.execute(f.id("BG"), 0), kDriveOk);
  f.run_us(75000);
  EXPECT_EQ(f.read("PT"), 2);  // the executing point
  EXPECT_EQ(f.read("DV", 3), 750);
  f.run_us(100000);
  // At QP[3] the motion ends and stops with SD from 10000 counts/s: 10000^2 / (2 * 1e6) past it.
  EXPECT_EQ(f.read("DV", 3), 1050);
  EXPECT_EQ(f.write("MP", 3, 2), kErrorOutOfRange);
  EXPECT_EQ(f.write("MP", 1, 1025), kErrorOutOfRange);
  EXPECT_EQ(f.write("MP", 4, 0), kErrorOutOfRange);
  EXPECT_EQ(f.write("QP", 1025, 0), kErrorBadIndex);
}

TEST(gold_reference_commands, ProfilerModeAndActiveCurrent) {
  Fixture f;
  EXPECT_EQ(f.read("PM"), 1);
  ASSERT_EQ(f.write("PM", 0, 0), kDriveOk);
  EXPECT_EQ(f.axis.parameters().profiler_mode, 0);
  Value v{};
  ASSERT_EQ(f.commands.read(f.id("IQ"), 0, v), kDriveOk);
  EXPECT_EQ(v.f, 0.0f);  // the motor is off: no current
}

}  // namespace
}  // namespace uprog::gold
