// Every dialect's reference (dialect/reference.h): each entry has its text and its source, no
// name twice, and every name the dialect's own tables know — Gold's commands, keywords and
// built-ins, PDL's system variables and states, the AG300's keywords, the S300's ASCII
// commands — has an entry, so hover cannot miss a command the compiler knows.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dialects/gold/builtins.h"
#include "dialects/gold/commands.h"
#include "dialects/gold/keywords.h"
#include "dialects/pup/keywords.h"
#include "dialects/registry.h"
#include "dialects/st/ascii_table.h"

namespace uprog::lsp {
namespace {

std::set<std::string> names_of(const std::string& dialect) {
  std::set<std::string> names;
  for (const dialect::ReferenceEntry& e : dialects::find(dialect)->reference())
    names.insert(e.name);
  return names;
}

TEST(Reference, EveryEntryHasTextAndASourceAndNoNameComesTwice) {
  for (const dialect::Dialect* d : dialects::all()) {
    const std::vector<dialect::ReferenceEntry> entries = d->reference();
    EXPECT_FALSE(entries.empty()) << d->name();
    std::set<std::string> seen;
    for (const dialect::ReferenceEntry& e : entries) {
      EXPECT_FALSE(e.summary.empty()) << d->name() << ": " << e.name << " has no text";
      EXPECT_FALSE(e.source.empty()) << d->name() << ": " << e.name << " has no source";
      EXPECT_TRUE(seen.insert(e.name).second) << d->name() << ": " << e.name << " twice";
    }
  }
}

TEST(Reference, GoldHasEveryCommandKeywordAndBuiltin) {
  const std::set<std::string> names = names_of("gold");
  for (const gold::CommandInfo& c : gold::all_commands())
    EXPECT_TRUE(names.count(std::string(c.name))) << c.name;
  // Manual 2.3's keyword table, plus nargout (keywords.h).
  for (const char* k :
       {"break",     "case",  "catch",    "continue", "else", "elseif", "end",  "exit",
        "float",     "for",   "function", "global",   "goto", "if",     "int",  "nargout",
        "otherwise", "reset", "return",   "switch",   "try",  "until",  "wait", "while"}) {
    EXPECT_NE(gold::keyword_of(k), gold::Keyword::None) << k;
    EXPECT_TRUE(names.count(k)) << k;
  }
  size_t keywords = 0;
  for (const std::string& n : names) {
    if (gold::keyword_of(n) != gold::Keyword::None) ++keywords;
  }
  EXPECT_EQ(keywords, 24u);
  for (const char* f : {"sin", "cos", "abs", "sqrt", "fix", "rnd", "sign", "real", "tdif", "prgerr",
                        "tick", "tock", "utick", "utock"}) {
    EXPECT_NE(gold::find_builtin(f), nullptr) << f;
    EXPECT_TRUE(names.count(f)) << f;
  }
}

TEST(Reference, PdlHasEverySystemVariableAndState) {
  const std::set<std::string> names = names_of("pdl");
#define SYSVAR(name, id, access, slave, length)         \
  EXPECT_TRUE(names.count(#name)) << #name;             \
  if (slave) {                                          \
    EXPECT_TRUE(names.count("X_" #name)) << "X_" #name; \
  }
#include "dialects/pdl/system_names.def"
#undef SYSVAR
#define STATE(name, number, writable) EXPECT_TRUE(names.count(#name)) << #name;
#include "dialects/pdl/states.def"
#undef STATE
}

TEST(Reference, PupHasEveryControllerKeyword) {
  const std::set<std::string> names = names_of("pup");
  for (size_t i = 0; i < static_cast<size_t>(pup::KeywordId::kCount); ++i) {
    const pup::Keyword& k = pup::keyword(static_cast<pup::KeywordId>(i));
    EXPECT_TRUE(names.count(std::string(k.name))) << k.name;
  }
}

TEST(Reference, StHasEveryAsciiCommand) {
  const std::set<std::string> names = names_of("st");
  for (const st::AsciiEntry& e : st::ascii_table())
    EXPECT_TRUE(names.count(std::string(e.name))) << e.name;
  for (int n = 1; n <= st::kUserVariables; ++n)
    EXPECT_TRUE(names.count(st::user_variable_name(n))) << n;
}

// Entries carry the table's own values: Gold's PX is its row's text, range and access.
TEST(Reference, EntriesCarryTheirTablesValues) {
  for (const dialect::ReferenceEntry& e : dialects::find("gold")->reference()) {
    if (e.name != "AC") continue;
    const gold::CommandInfo* ac = gold::find_command("AC");
    EXPECT_EQ(e.summary, std::string(ac->meaning));
    EXPECT_EQ(e.unit, "counts/s^2");        // the row's text ends ", counts/s^2"
    EXPECT_EQ(e.range, "1 to 2147483647");  // the row's min and max (AC must be positive)
    EXPECT_EQ(e.access, "read/write");
  }
}

}  // namespace
}  // namespace uprog::lsp
