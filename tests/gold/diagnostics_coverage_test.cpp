// Every code of the Gold compiler's list (src/dialects/gold/gold_errors.def) has a case in
// tests/diagnostics/gold that produces it (diagnostics_test.cpp checks that each case does),
// unless it is exempt below with the reason no source text can produce it.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "dialects/gold/errors.h"
#include "testlib/test_files.h"

namespace {

// A code leaves this table when a case produces it: the test fails while both hold.
const std::map<int, const char*> kNoCase = {
    {0, "not an error"},
    {54, "needs a file that cannot be opened: diagnostics_test.cpp MissingFileIsOpenFileFailure"},
    {63, "a failure of the code generator itself; no source may produce it"},
    {65, "needs more than 2^24 words of code, too large for a test case"},
    // The manual's table keeps these numbers; nothing in src/dialects/gold reports them.
    {16, "the compiler's tables grow as needed; a program too large is 65, too many globals 9"},
    {18, "mismatched parentheses and unclosed blocks get their own codes (6, 43)"},
    {19, "the compiler writes no file (`uprog build` reports its own write errors)"},
    {20, "a source that cannot be read is 54"},
    {21, "the compiler keeps no database"},
    {23, "the number of functions has no limit of its own"},
    {31, "unused, as the manual says: arrays have one dimension"},
    {40, "a command line that does not compile gets the code of what is wrong in it"},
    {53, "a statement ends with its line (continued with ...: 52 when too long)"},
    {55, "file paths have no length limit"},
    {62, "every opcode the compiler emits runs on the simulated Gold drive"},
    {66, "no drive setup files are read"},
    {68, "no drive setup files are read"},
    {80, "the code's limit is 65"},
    {81, "tdif is built in (builtins.cpp), so wait always has it"},
    {83, "no keyword is reserved for future use"},
};

TEST(gold_diagnostics, EveryCodeHasACaseOrAReason) {
  std::set<int> covered;
  for (const auto& f : uprog::test::source_files("tests/diagnostics/gold", ".gold"))
    covered.insert(std::stoi(f.filename().string().substr(0, 2)));
  size_t count = 0;
  const uprog::gold::ErrorInfo* errors = uprog::gold::all_errors(count);
  for (size_t i = 0; i < count; ++i) {
    const int code = errors[i].code;
    if (kNoCase.count(code)) {
      EXPECT_FALSE(covered.count(code)) << "gold " << code << " has a case now: drop its exemption";
    } else {
      EXPECT_TRUE(covered.count(code))
          << "no case in tests/diagnostics/gold for gold " << code << " (" << errors[i].name << ")";
    }
  }
  for (const auto& [code, why] : kNoCase) EXPECT_LT(code, static_cast<int>(count)) << why;
}

}  // namespace
