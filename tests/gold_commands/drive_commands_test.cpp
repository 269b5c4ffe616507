// The mapping of Gold commands onto the axis: every command read or written, every refusal.
#include "dialects/gold/drive_commands.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "drive/faults.h"

namespace uprog::gold {
namespace {

uint16_t id(const char* name) {
  const CommandInfo* c = find_command(name);
  EXPECT_NE(c, nullptr) << name;
  return c ? c->id : 0;
}

struct Fixture {
  drive::Axis axis;
  DriveCommands commands{axis};

  int32_t write_int(const char* name, int32_t v, int32_t index = 0) {
    return commands.write(id(name), index, Value::of_int(v));
  }
  int32_t write_float(const char* name, float v, int32_t index = 0) {
    return commands.write(id(name), index, Value::of_float(v));
  }
  int32_t read_int(const char* name, int32_t index = 0) {
    Value v{};
    EXPECT_EQ(commands.read(id(name), index, v), kDriveOk) << name;
    return v.i;
  }
  float read_float(const char* name, int32_t index = 0) {
    Value v{};
    EXPECT_EQ(commands.read(id(name), index, v), kDriveOk) << name;
    return v.f;
  }
  void run_us(uint64_t us) {
    for (uint64_t t = 0; t < us; t += axis.period_us()) axis.step();
  }
  void enable() {
    ASSERT_EQ(write_int("MO", 1), kDriveOk);
    run_us(drive::kEnableDelay_us + 1000);
    ASSERT_EQ(read_int("SO"), 1);
  }
};

// A value inside each writable drive command's range, and the value read back after it.
struct Sample {
  int32_t index;
  bool is_float;
  double write;
  double read_back;
};
const std::map<std::string, Sample> kWritable{
    {"MO", {0, false, 0, 0}},         {"UM", {0, false, 2, 2}},
    {"PA", {0, false, 777, 777}},     {"PR", {0, false, -5, -5}},
    {"SP", {0, false, 1234, 1234}},   {"AC", {0, false, 5000, 5000}},
    {"DC", {0, false, 6000, 6000}},   {"SD", {0, false, 7000, 7000}},
    {"SF", {0, false, 12, 12}},       {"JV", {0, false, -300, -300}},
    {"TC", {0, true, 0.25, 0.25}},    {"PX", {0, false, 4242, 4242}},
    {"ER", {3, false, 999, 999}},     {"VH", {2, false, 30000, 30000}},
    {"VL", {3, false, -4000, -4000}}, {"XM", {2, false, 360, 360}},
    {"KP", {3, true, 150.5, 150.5}},  {"KI", {2, true, 33.0, 33.0}},
    {"KV", {1, true, 0.5, 0.5}},      {"CL", {1, true, 2.5, 2.5}},
    {"PL", {1, true, 5.5, 5.5}},      {"IL", {4, false, 9, 9}},
    {"OP", {0, false, 5, 5}},         {"OB", {4, false, 1, 1}},
    {"TM", {0, false, 100, 100}},     {"TS", {0, false, 100, 100}},
    {"UI", {24, false, -17, -17}},    {"UF", {1, true, 1.5, 1.5}},
    {"RV", {8, false, 3, 3}},         {"RL", {0, false, 500, 500}},
    {"RG", {0, false, 4, 4}},         {"RR", {0, false, 0, -1}},  // RR=0 kills; no valid data
    {"RC", {0, false, 5, 5}},         {"RP", {2, false, 20, 20}},
    {"HM", {2, false, 1234, 1234}},   {"CA", {19, false, 4, 4}},
    {"QP", {10, false, -5, -5}},      {"TR", {1, false, 50, 50}},
    {"EO", {0, false, 0, 0}},         {"LL", {2, false, -3000000, -3000000}},
    {"HL", {3, false, 900, 900}},     {"MP", {2, false, 10, 10}},
    {"PT", {0, false, 5, 5}},         {"PY", {0, false, 77, 77}},
    {"PM", {0, false, 0, 0}},         {"HX", {0, false, 1, 1}},
    {"RM", {0, false, 1, 1}},         {"FC", {5, false, 2, 2}},
    {"BP", {2, false, 100, 100}},     {"SC", {13, false, 3, 3}},
    {"FS", {0, false, 0, 0}},
};

TEST(gold_commands_mapping, EveryCommandIsReadWrittenOrExecuted) {
  Fixture f;
  int served = 0;
  for (const CommandInfo& c : all_commands()) {
    const int32_t index = (c.flags & kIndexed) ? c.min_index : 0;
    Value v{};
    if (!handled_by_drive(c.id)) {
      EXPECT_EQ(f.commands.read(c.id, index, v), kErrorNotHandledHere) << c.name;
      EXPECT_EQ(f.commands.write(c.id, index, Value::of_int(0)), kErrorNotHandledHere) << c.name;
      EXPECT_EQ(f.commands.execute(c.id, index), kErrorNotHandledHere) << c.name;
      continue;
    }
    ++served;
    if (c.flags & kAction) {
      EXPECT_EQ(f.commands.read(c.id, index, v), kErrorNoValue) << c.name;
      continue;
    }
    if (c.flags & kText) {
      EXPECT_EQ(f.commands.read(c.id, index, v), kErrorNoValue) << c.name;
      EXPECT_TRUE(f.commands.text(c.id).has_value()) << c.name;
      continue;
    }
    EXPECT_EQ(f.commands.read(c.id, index, v), kDriveOk) << c.name;
    if (c.flags & kReadOnly) continue;
    const auto it = kWritable.find(std::string(c.name));
    ASSERT_NE(it, kWritable.end()) << "no sample value for writable " << c.name;
    const Sample& s = it->second;
    const Value w = s.is_float ? Value::of_float(static_cast<float>(s.write))
                               : Value::of_int(static_cast<int32_t>(s.write));
    ASSERT_EQ(f.commands.write(c.id, s.index, w), kDriveOk) << c.name;
    ASSERT_EQ(f.commands.read(c.id, s.index, v), kDriveOk) << c.name;
    if (s.is_float) {
      EXPECT_EQ(v.f, static_cast<float>(s.read_back)) << c.name;
    } else {
      EXPECT_EQ(v.i, static_cast<int32_t>(s.read_back)) << c.name;
    }
  }
  EXPECT_EQ(served, 74);  // with the recorder's RC, RP, WI, BH (17) and the preflight's 8 (38)
  // The actions the drive serves.
  EXPECT_EQ(f.commands.execute(id("ST"), 0), kDriveOk);
  f.write_int("UM", 5);
  f.enable();
  EXPECT_EQ(f.commands.execute(id("BG"), 0), kDriveOk);
}

TEST(gold_commands_mapping, MoveThroughCommands) {
  Fixture f;
  f.enable();
  ASSERT_EQ(f.write_int("SP", 50000), kDriveOk);
  ASSERT_EQ(f.write_int("AC", 1000000), kDriveOk);
  ASSERT_EQ(f.write_int("DC", 1000000), kDriveOk);
  ASSERT_EQ(f.write_int("PA", 10000), kDriveOk);
  ASSERT_EQ(f.commands.execute(id("BG"), 0), kDriveOk);
  EXPECT_EQ(f.read_int("MS"), 2);
  EXPECT_EQ((f.read_int("SR") >> 14) & 3, 3);  // Gold: SR bits 14..15 are the STO inputs
  // Trapezoid: 0.05 s ramps of 1250 counts, 7500 counts of cruise (0.15 s): ends at 0.25 s.
  f.run_us(300000);
  EXPECT_NEAR(f.read_int("PX"), 10000, 1);
  EXPECT_NEAR(f.read_int("DV", 3), 10000, 0);
  EXPECT_EQ(f.read_int("DV", 2), 0);
  EXPECT_NEAR(f.read_int("PE"), 0, 1);
  EXPECT_NEAR(f.read_int("VX"), 0, 50);
  EXPECT_EQ(f.read_int("MS"), 0);  // 50 ms within TR[1] after the profile: more than TR[2]
  // MO in bit 4, UM in bits 8..10, the STO inputs in 14 and 15 (docs/dialects/gold.md, "SR")
  EXPECT_EQ(f.read_int("SR"), 0x10 | (5 << 8) | (3 << 14));
}

TEST(gold_commands_mapping, UserVariablesAndIo) {
  Fixture f;
  ASSERT_EQ(f.write_int("UI", 7, 3), kDriveOk);
  EXPECT_EQ(f.axis.parameters().user_ints[2], 7);
  ASSERT_EQ(f.write_float("UF", -2.5f, 24), kDriveOk);
  EXPECT_EQ(f.axis.parameters().user_floats[23], -2.5f);
  f.axis.set_input_level(2, true);
  EXPECT_EQ(f.read_int("IB", 1), 1);   // general-purpose input 2 active: bit 1
  EXPECT_EQ(f.read_int("IB", 17), 1);  // its level: bit 16 + 1
  EXPECT_EQ(f.read_int("IP"), 0b10 | (1 << 17));
  ASSERT_EQ(f.write_int("IL", 6, 2), kDriveOk);  // now active low: high = inactive
  EXPECT_EQ(f.read_int("IB", 1), 0);
  EXPECT_EQ(f.read_int("IB", 17), 1);
  ASSERT_EQ(f.write_int("OB", 1, 2), kDriveOk);
  EXPECT_EQ(f.read_int("OP"), 0b10);
  f.axis.inject_fault("overcurrent");
  EXPECT_EQ(f.read_int("MF"), static_cast<int32_t>(drive::kFaultOvercurrent));
}

TEST(gold_commands_mapping, TimeWrapsAndCanBeSet) {
  Fixture f;
  ASSERT_EQ(f.write_int("TM", -100), kDriveOk);  // 0xFFFFFF9C
  f.run_us(150);
  EXPECT_EQ(f.read_int("TM"), 50);
}

TEST(gold_commands_mapping, RefusedUnknownCommandAndBadIndex) {
  Fixture f;
  Value v{};
  EXPECT_EQ(f.commands.read(999, 0, v), kErrorBadCommand);
  EXPECT_EQ(f.commands.write(999, 0, Value::of_int(1)), kErrorBadCommand);
  EXPECT_EQ(f.commands.execute(999, 0), kErrorBadCommand);
  EXPECT_EQ(f.commands.read(id("UI"), 25, v), kErrorBadIndex);
  EXPECT_EQ(f.commands.read(id("UI"), 0, v), kErrorBadIndex);
  EXPECT_EQ(f.write_int("OB", 1, 5), kErrorBadIndex);
  EXPECT_EQ(f.commands.read(id("DV"), 1, v), kErrorBadIndex);
  EXPECT_EQ(f.commands.read(id("PX"), 1, v), kErrorBadIndex);  // PX takes no index
}

TEST(gold_commands_mapping, RefusedOutOfRange) {
  Fixture f;
  EXPECT_EQ(f.write_int("SP", 0), kErrorOutOfRange);
  EXPECT_EQ(f.write_int("MO", 2), kErrorOutOfRange);
  EXPECT_EQ(f.write_int("UM", 3), kErrorOutOfRange);      // inside 1..5 but not a mode
  EXPECT_EQ(f.write_int("IL", 24, 1), kErrorOutOfRange);  // beyond the last input function
  EXPECT_EQ(f.write_int("TS", 10), kErrorOutOfRange);
  EXPECT_EQ(f.write_float("UF", std::numeric_limits<float>::quiet_NaN(), 1), kErrorOutOfRange);
  EXPECT_EQ(f.write_float("UF", 2e37f, 1), kErrorOutOfRange);
  EXPECT_EQ(f.read_int("SP"), f.axis.parameters().speed_counts_per_s);
  EXPECT_EQ(f.axis.parameters().unit_mode, 5);
}

TEST(gold_commands_mapping, RefusedNotAssignableAndReadOnly) {
  Fixture f;
  EXPECT_EQ(f.write_int("BG", 1), kErrorNotAssignable);
  EXPECT_EQ(f.write_int("ST", 1), kErrorNotAssignable);
  EXPECT_EQ(f.write_int("VX", 0), kErrorReadOnly);
  EXPECT_EQ(f.write_int("MF", 0), kErrorReadOnly);
  EXPECT_EQ(f.write_int("IB", 1, 1), kErrorReadOnly);
  Value v{};
  EXPECT_EQ(f.commands.read(id("BG"), 0, v), kErrorNoValue);
  EXPECT_EQ(f.commands.execute(id("PX"), 0), kErrorNoValue);
}

TEST(gold_commands_mapping, RefusedWhileMotorOn) {
  Fixture f;
  f.enable();
  EXPECT_EQ(f.write_int("UM", 2), kErrorMotorMustBeOff);
  EXPECT_EQ(f.read_int("UM"), 5);
  ASSERT_EQ(f.write_int("MO", 0), kDriveOk);
  EXPECT_EQ(f.write_int("UM", 2), kDriveOk);
}

TEST(gold_commands_mapping, RefusedNotAllowed) {
  Fixture f;
  EXPECT_EQ(f.commands.execute(id("BG"), 0), kErrorMotorMustBeOn);

  ASSERT_TRUE(f.axis.inject_fault("overvoltage", true));
  EXPECT_EQ(f.write_int("MO", 1), kErrorFaultPresent);
  EXPECT_EQ(f.read_int("MO"), 0);
  f.axis.clear_fault_cause("overvoltage");
  EXPECT_EQ(f.write_int("MO", 1), kDriveOk);
  EXPECT_EQ(f.read_int("MF"), 0);
  f.write_int("MO", 0);

  ASSERT_EQ(f.write_int("IL", 1, 3), kDriveOk);  // inhibit, active high
  f.axis.set_input_level(3, true);
  EXPECT_EQ(f.write_int("MO", 1), kErrorInhibitActive);
  f.axis.set_input_level(3, false);
  ASSERT_EQ(f.write_int("MO", 1), kDriveOk);
  f.write_int("MO", 0);

  ASSERT_EQ(f.write_int("UM", 1), kDriveOk);
  f.enable();
  EXPECT_EQ(f.commands.execute(id("BG"), 0), kErrorModeNotSupported);
}

TEST(gold_commands_mapping, ControllerCommandsAreLeftToTheCaller) {
  for (const char* name :
       {"XQ", "HP", "XC", "KL", "PS", "CC", "LS", "MI", "DB", "RS", "SV", "LD", "EC"})
    EXPECT_FALSE(handled_by_drive(id(name))) << name;
  for (const char* name : {"BG", "PX", "UI", "RV", "TM"})
    EXPECT_TRUE(handled_by_drive(id(name))) << name;
}

}  // namespace
}  // namespace uprog::gold
