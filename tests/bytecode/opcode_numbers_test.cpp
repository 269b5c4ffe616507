// The opcode numbers of the stored format (format.h): an image in a drive's flash names its
// instructions by these numbers, so a number never moves. Format 6 is the first released format
// and its base set is durable: opcodes are only ever added after the last one here (a new line
// in format.h's history and a table of their own below), never moved or removed. BREAK, the
// debugger's trap, follows the base set and is never in an image; the VM's fused instructions
// come after it (vm/fused.def) and are never in an image either.
#include <gtest/gtest.h>

#include <string_view>

#include "bytecode/format.h"
#include "bytecode/intrinsics.h"
#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

struct Pinned {
  uint32_t number;
  const char* name;
};

// Format 6: the base set, by number.
constexpr Pinned kFormat6[] = {
    {0, "NOP"},       {1, "PUSHI"},     {2, "PUSHK"},    {3, "POP"},       {4, "DUP"},
    {5, "SWAP"},      {6, "LDL"},       {7, "STL"},      {8, "LDG"},       {9, "STG"},
    {10, "LDGX"},     {11, "STGX"},     {12, "INCL"},    {13, "LDM"},      {14, "STM"},
    {15, "LDGE"},     {16, "STGE"},     {17, "LDGW"},    {18, "STGW"},     {19, "ADDI"},
    {20, "SUBI"},     {21, "MULI"},     {22, "DIVI"},    {23, "REMI"},     {24, "NEGI"},
    {25, "ANDI"},     {26, "ORI"},      {27, "XORI"},    {28, "NOTI"},     {29, "SHLI"},
    {30, "SHRI"},     {31, "ABSI"},     {32, "SIGNI"},   {33, "SEXT"},     {34, "ZEXT"},
    {35, "SHRU"},     {36, "CMPU"},     {37, "I2W"},     {38, "ADDW"},     {39, "SUBW"},
    {40, "MULDIV"},   {41, "ADDF"},     {42, "SUBF"},    {43, "MULF"},     {44, "DIVF"},
    {45, "NEGF"},     {46, "ABSF"},     {47, "SIGNF"},   {48, "SINF"},     {49, "COSF"},
    {50, "SQRTF"},    {51, "CMPI"},     {52, "CMPF"},    {53, "LNOT"},     {54, "TRUTHF"},
    {55, "I2F"},      {56, "I2F2"},     {57, "F2IR"},    {58, "F2IT"},     {59, "MULID"},
    {60, "I2D"},      {61, "F2D"},      {62, "D2F"},     {63, "D2IR"},     {64, "D2IT"},
    {65, "ADDD"},     {66, "SUBD"},     {67, "MULD"},    {68, "DIVD"},     {69, "NEGD"},
    {70, "ABSD"},     {71, "CMPD"},     {72, "JMP"},     {73, "JZ"},       {74, "JNZ"},
    {75, "JEQI"},     {76, "JNEI"},     {77, "JLTI"},    {78, "JLEI"},     {79, "JGTI"},
    {80, "JGEI"},     {81, "JNEQF"},    {82, "JNNEF"},   {83, "JNLTF"},    {84, "JNLEF"},
    {85, "JNGTF"},    {86, "JNGEF"},    {87, "CALL"},    {88, "CALLFEOL"}, {89, "RET"},
    {90, "RETEOL"},   {91, "NARGOUT"},  {92, "EXIT"},    {93, "RESET"},    {94, "EOL"},
    {95, "RAISE"},    {96, "YIELD"},    {97, "WAIT"},    {98, "TRY"},      {99, "TRYALL"},
    {100, "ENDTRY"},  {101, "ERRCODE"}, {102, "CLOCK"},  {103, "JLINES"},  {104, "JMPLN"},
    {105, "CMDGET"},  {106, "CMDGETX"}, {107, "CMDSET"}, {108, "CMDSETX"}, {109, "CMDRUN"},
    {110, "CMDRUNX"}, {111, "INTRIN"},  {112, "MSG"},
};

TEST(OpcodeNumbers, EveryBaseOpcodeKeepsItsNumber) {
  static_assert(kMinFormatVersion == 6 && kMaxFormatVersion == 6,
                "a new format version adds its own opcodes here, after format 6's");
  ASSERT_EQ(kBaseOpCount, std::size(kFormat6)) << "a base opcode added or removed within format 6";
  for (const Pinned& p : kFormat6) {
    EXPECT_EQ(std::string_view(op_name(static_cast<Op>(p.number))), p.name)
        << "opcode " << p.number << " moved";
  }
}

// Format 6: INTRIN's functions (intrinsics.def), by number; they are part of the format as the
// opcodes are.
constexpr Pinned kFormat6Intrinsics[] = {
    {0, "DIVU"},    {1, "REMU"}, {2, "ISQRT"},   {3, "IPOW"},  {4, "SINM"},
    {5, "COSM"},    {6, "TANM"}, {7, "ASINM"},   {8, "ACOSM"}, {9, "ATANM"},
    {10, "ATAN2M"}, {11, "LNM"}, {12, "LOG10M"}, {13, "EXPM"},
};

TEST(OpcodeNumbers, EveryIntrinsicKeepsItsNumber) {
  ASSERT_EQ(kIntrinsicCount, std::size(kFormat6Intrinsics))
      << "an intrinsic function added or removed within format 6";
  for (const Pinned& p : kFormat6Intrinsics)
    EXPECT_EQ(std::string_view(kIntrinsicNames[p.number]), p.name)
        << "intrinsic " << p.number << " moved";
}

TEST(OpcodeNumbers, BreakFollowsTheBaseSet) {
  EXPECT_EQ(static_cast<uint32_t>(Op::BREAK), kBaseOpCount);
  EXPECT_EQ(kOpCount, kBaseOpCount + 1);
}

}  // namespace
}  // namespace uprog::bytecode
