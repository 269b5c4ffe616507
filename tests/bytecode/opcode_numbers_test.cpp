// The opcode numbers of the stored format (format.h): an image in a drive's flash names its
// instructions by these numbers, so a number never moves. Format 6 is the first released format
// and its base set is durable: opcodes are only ever added after the last one here (a new line
// in format.h's history and a table of their own below), never moved or removed. BREAK, the
// debugger's trap, follows the base set and is never in an image; the VM's fused instructions
// come after it (vm/fused.def) and are never in an image either.
#include <gtest/gtest.h>

#include <string_view>

#include "bytecode/format.h"
#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

struct Pinned {
  uint32_t number;
  const char* name;
};

// Format 6: the base set, by number.
constexpr Pinned kFormat6[] = {
    {0, "NOP"}, {1, "PUSHI"}, {2, "PUSHK"}, {3, "POP"}, {4, "DUP"}, {5, "SWAP"}, {6, "LDL"},
    {7, "STL"}, {8, "LDG"}, {9, "STG"}, {10, "LDGX"}, {11, "STGX"}, {12, "INCL"}, {13, "LDM"},
    {14, "STM"}, {15, "LDGE"}, {16, "STGE"}, {17, "LDGW"}, {18, "STGW"}, {19, "ADDI"}, {20, "SUBI"},
    {21, "MULI"}, {22, "DIVI"}, {23, "REMI"}, {24, "NEGI"}, {25, "ANDI"}, {26, "ORI"}, {27, "XORI"},
    {28, "NOTI"}, {29, "SHLI"}, {30, "SHRI"}, {31, "ABSI"}, {32, "SIGNI"}, {33, "SEXT"},
    {34, "ZEXT"}, {35, "SHRU"}, {36, "CMPU"}, {37, "I2W"}, {38, "ADDW"}, {39, "SUBW"},
    {40, "MULDIV"}, {41, "ADDF"}, {42, "SUBF"}, {43, "MULF"}, {44, "DIVF"}, {45, "NEGF"},
    {46, "ABSF"}, {47, "SIGNF"}, {48, "SINF"}, {49, "COSF"}, {50, "SQRTF"}, {51, "EQI"},
    {52, "NEI"}, {53, "LTI"}, {54, "LEI"}, {55, "GTI"}, {56, "GEI"}, {57, "EQF"}, {58, "NEF"},
    {59, "LTF"}, {60, "LEF"}, {61, "GTF"}, {62, "GEF"}, {63, "LNOT"}, {64, "TRUTHF"}, {65, "I2F"},
    {66, "I2F2"}, {67, "F2IR"}, {68, "F2IT"}, {69, "MULID"}, {70, "I2D"}, {71, "F2D"}, {72, "D2F"},
    {73, "D2IR"}, {74, "D2IT"}, {75, "ADDD"}, {76, "SUBD"}, {77, "MULD"}, {78, "DIVD"},
    {79, "NEGD"}, {80, "ABSD"}, {81, "CMPD"}, {82, "JMP"}, {83, "JZ"}, {84, "JNZ"}, {85, "JEQI"},
    {86, "JNEI"}, {87, "JLTI"}, {88, "JLEI"}, {89, "JGTI"}, {90, "JGEI"}, {91, "JNEQF"},
    {92, "JNNEF"}, {93, "JNLTF"}, {94, "JNLEF"}, {95, "JNGTF"}, {96, "JNGEF"}, {97, "CALL"},
    {98, "CALLFEOL"}, {99, "RET"}, {100, "RETEOL"}, {101, "NARGOUT"}, {102, "EXIT"}, {103, "RESET"},
    {104, "EOL"}, {105, "RAISE"}, {106, "YIELD"}, {107, "WAIT"}, {108, "TRY"}, {109, "TRYALL"},
    {110, "ENDTRY"}, {111, "ERRCODE"}, {112, "CLOCK"}, {113, "JLINES"}, {114, "JMPLN"},
    {115, "CMDGET"}, {116, "CMDGETX"}, {117, "CMDSET"}, {118, "CMDSETX"}, {119, "CMDRUN"},
    {120, "CMDRUNX"}, {121, "MSG"},
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

TEST(OpcodeNumbers, BreakFollowsTheBaseSet) {
  EXPECT_EQ(static_cast<uint32_t>(Op::BREAK), kBaseOpCount);
  EXPECT_EQ(kOpCount, kBaseOpCount + 1);
}

}  // namespace
}  // namespace uprog::bytecode
