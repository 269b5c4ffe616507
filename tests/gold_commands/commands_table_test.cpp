// The Gold command table: every command of shared/spec/gold-drive.md and the Elmo reference's
// that real programs and hosts send, stable ids, flags, ranges.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dialects/gold/commands.h"

namespace uprog::gold {
namespace {

const char* const kSpecCommands[] = {
    "MO", "SO", "UM", "PA", "PR", "SP", "AC", "DC", "SD", "SF", "JV", "BG", "ST", "TC",
    "PX", "VX", "PE", "DV", "MS", "ER", "VH", "VL", "XM", "KP", "KI", "KV", "CL", "PL",
    "IL", "IP", "IB", "OP", "OB", "MF", "SR", "TM", "TS", "UI", "UF", "SV", "LD", "RS",
    "MI", "XQ", "HP", "XC", "KL", "PS", "CC", "LS", "EC", "DB", "RV", "RL", "RG", "RR"};

// Issue 12's list (docs/dialects/gold.md, "Commands from the reference"), with IQ and HX that
// host drivers send.
const char* const kReferenceCommands[] = {
    "HM", "CA", "QP", "TR", "TI", "WS", "EO", "LL", "HL", "FP", "FV", "VR",
    "SN", "MP", "PT", "PY", "PM", "IQ", "HX", "RC", "RP", "WI", "BH",  // issue 17: the recorder's
    "RM", "ID", "FC", "BP", "SC", "FS", "OV", "LC"};                   // 38

const CommandInfo& get(const char* name) {
  const CommandInfo* c = find_command(name);
  EXPECT_NE(c, nullptr) << name;
  static const CommandInfo kNone{};
  return c ? *c : kNone;
}

TEST(gold_commands_table, EveryCommandOfTheSpecIsThere) {
  for (const char* name : kSpecCommands) EXPECT_NE(find_command(name), nullptr) << name;
  for (const char* name : kReferenceCommands) EXPECT_NE(find_command(name), nullptr) << name;
  EXPECT_EQ(all_commands().size(), std::size(kSpecCommands) + std::size(kReferenceCommands));
  EXPECT_EQ(find_command("XY"), nullptr);
  EXPECT_EQ(find_command(""), nullptr);
  EXPECT_EQ(find_command(uint16_t{0}), nullptr);
}

TEST(gold_commands_table, LookupIgnoresCaseAndIdsRoundTrip) {
  EXPECT_EQ(find_command("px"), find_command("PX"));
  EXPECT_EQ(find_command("Ui"), find_command("UI"));
  std::set<uint16_t> ids;
  std::set<std::string> names;
  for (const CommandInfo& c : all_commands()) {
    EXPECT_TRUE(ids.insert(c.id).second) << "duplicate id " << c.id;
    EXPECT_TRUE(names.insert(std::string(c.name)).second) << c.name;
    EXPECT_EQ(find_command(c.id), &c);
    EXPECT_FALSE(c.meaning.empty()) << c.name;
  }
}

TEST(gold_commands_table, IdsAreStable) {
  // Images store these numbers: changing one breaks every compiled program.
  EXPECT_EQ(get("MO").id, 1);
  EXPECT_EQ(get("PA").id, 4);
  EXPECT_EQ(get("BG").id, 12);
  EXPECT_EQ(get("PX").id, 15);
  EXPECT_EQ(get("IL").id, 29);
  EXPECT_EQ(get("TM").id, 36);
  EXPECT_EQ(get("UI").id, 38);
  EXPECT_EQ(get("UF").id, 39);
  EXPECT_EQ(get("XQ").id, 44);
  EXPECT_EQ(get("LS").id, 50);
  EXPECT_EQ(get("RR").id, 56);
  EXPECT_EQ(get("HM").id, 57);
  EXPECT_EQ(get("HX").id, 75);
}

TEST(gold_commands_table, ActionsAreNotAssignable) {
  for (const char* name :
       {"BG", "ST", "SV", "LD", "RS", "HP", "XC", "KL", "CC", "LS", "XQ", "DB"}) {
    EXPECT_TRUE(get(name).flags & kAction) << name;
    EXPECT_TRUE(get(name).flags & kNotAssignable) << name;
  }
  EXPECT_FALSE(get("PA").flags & (kAction | kNotAssignable));
}

TEST(gold_commands_table, HostOnlyCommandsAreNotProgram) {
  for (const char* name : {"LS", "SV", "LD", "RS", "HP", "XC", "KL", "CC", "DB"})
    EXPECT_TRUE(get(name).flags & kNotProgram) << name;
  for (const char* name : {"BG", "ST", "XQ", "MO", "UI", "PS", "MI"})
    EXPECT_FALSE(get(name).flags & kNotProgram) << name;
}

TEST(gold_commands_table, StatusesAreReadOnly) {
  for (const char* name : {"SO", "VX", "PE", "DV", "MS", "IP", "IB", "MF", "SR", "PS", "EC", "TI",
                           "WS", "FP", "FV", "VR", "SN", "IQ"})
    EXPECT_TRUE(get(name).flags & kReadOnly) << name;
  for (const char* name : {"MO", "PX", "TM", "OP", "OB", "UI", "IL"})
    EXPECT_FALSE(get(name).flags & kReadOnly) << name;
  EXPECT_TRUE(get("UM").flags & kMotorOffOnly);
  EXPECT_TRUE(get("CA").flags & kMotorOffOnly);
  // VR answers text, which a program cannot hold.
  EXPECT_TRUE(get("VR").flags & kText);
  EXPECT_TRUE(get("VR").flags & kNotProgram);
}

TEST(gold_commands_table, IndexRanges) {
  struct Range {
    const char* name;
    int32_t lo, hi;
  };
  for (const Range& r :
       {Range{"UI", 1, 24}, Range{"UF", 1, 24}, Range{"IL", 1, 6},    Range{"IB", 0, 31},
        Range{"HM", 1, 7},  Range{"CA", 1, 57}, Range{"QP", 1, 1024}, Range{"TR", 1, 2},
        Range{"LL", 2, 3},  Range{"HL", 2, 3},  Range{"SN", 1, 4},    Range{"MP", 1, 6},
        Range{"OB", 1, 4},  Range{"RV", 1, 8},  Range{"DV", 2, 3},    Range{"ER", 2, 3},
        Range{"VH", 2, 3},  Range{"VL", 2, 3},  Range{"XM", 1, 2},    Range{"KP", 1, 3},
        Range{"CL", 1, 1},  Range{"PL", 1, 1}}) {
    const CommandInfo& c = get(r.name);
    EXPECT_TRUE(c.flags & kIndexed) << r.name;
    EXPECT_EQ(c.min_index, r.lo) << r.name;
    EXPECT_EQ(c.max_index, r.hi) << r.name;
  }
  for (const CommandInfo& c : all_commands()) {
    if (!(c.flags & kIndexed)) {
      EXPECT_EQ(c.max_index, 0) << c.name;
    }
  }
}

TEST(gold_commands_table, TypesAndValueRanges) {
  for (const char* name : {"TC", "KP", "KI", "KV", "CL", "PL", "UF"})
    EXPECT_EQ(get(name).type, ValueType::Float) << name;
  for (const char* name : {"PX", "PA", "UI", "MO", "TM", "SR"})
    EXPECT_EQ(get(name).type, ValueType::Int) << name;
  EXPECT_EQ(get("MO").min_value, 0);
  EXPECT_EQ(get("MO").max_value, 1);
  EXPECT_EQ(get("SP").min_value, 1);
  EXPECT_EQ(get("UI").min_value, -2147483648.0);
  EXPECT_EQ(get("UI").max_value, 2147483647.0);
  EXPECT_EQ(get("OP").max_value, 15);
  for (const CommandInfo& c : all_commands()) EXPECT_LE(c.min_value, c.max_value) << c.name;
}

}  // namespace
}  // namespace uprog::gold
