// The opcode numbers of the stored format (format.h): an image in a drive's flash names its
// instructions by these numbers, so a number never moves within a format version. The first
// table is format 4 as released (opcodes.def at commit c94fedf, the last change of its
// numbering), the second what format 5 added; a change to either is a new format version with
// its own line in format.h's history.
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

// Format 4: every opcode, by number.
constexpr Pinned kFormat4[] = {
    {0, "NOP"},          {1, "PUSHI"},        {2, "PUSHK"},        {3, "POP"},
    {4, "DUP"},          {5, "SWAP"},         {6, "LDL"},          {7, "STL"},
    {8, "LDG"},          {9, "STG"},          {10, "LDGX"},        {11, "STGX"},
    {12, "INCL"},        {13, "LDM"},         {14, "STM"},         {15, "ADDI"},
    {16, "SUBI"},        {17, "MULI"},        {18, "DIVI"},        {19, "REMI"},
    {20, "NEGI"},        {21, "ANDI"},        {22, "ORI"},         {23, "XORI"},
    {24, "NOTI"},        {25, "SHLI"},        {26, "SHRI"},        {27, "ABSI"},
    {28, "SIGNI"},       {29, "SEXT"},        {30, "ZEXT"},        {31, "JCMPMKEOL"},
    {32, "ADDMLK"},      {33, "SHRU"},        {34, "CMPU"},        {35, "I2W"},
    {36, "ADDW"},        {37, "SUBW"},        {38, "MULDIV"},      {39, "ADDF"},
    {40, "SUBF"},        {41, "MULF"},        {42, "DIVF"},        {43, "NEGF"},
    {44, "ABSF"},        {45, "SIGNF"},       {46, "SINF"},        {47, "COSF"},
    {48, "SQRTF"},       {49, "EQI"},         {50, "NEI"},         {51, "LTI"},
    {52, "LEI"},         {53, "GTI"},         {54, "GEI"},         {55, "EQF"},
    {56, "NEF"},         {57, "LTF"},         {58, "LEF"},         {59, "GTF"},
    {60, "GEF"},         {61, "LNOT"},        {62, "TRUTHF"},      {63, "I2F"},
    {64, "I2F2"},        {65, "F2IR"},        {66, "F2IT"},        {67, "MULID"},
    {68, "I2D"},         {69, "F2D"},         {70, "D2F"},         {71, "D2IR"},
    {72, "D2IT"},        {73, "ADDD"},        {74, "SUBD"},        {75, "MULD"},
    {76, "DIVD"},        {77, "NEGD"},        {78, "ABSD"},        {79, "CMPD"},
    {80, "JMP"},         {81, "JZ"},          {82, "JNZ"},         {83, "CALL"},
    {84, "RET"},         {85, "NARGOUT"},     {86, "EXIT"},        {87, "RESET"},
    {88, "EOL"},         {89, "RAISE"},       {90, "YIELD"},       {91, "WAIT"},
    {92, "TRY"},         {93, "TRYALL"},      {94, "ENDTRY"},      {95, "ERRCODE"},
    {96, "CLOCK"},       {97, "ADDLK"},       {98, "REMLK"},       {99, "JEQLL"},
    {100, "JNELL"},      {101, "JLTLL"},      {102, "JLELL"},      {103, "JGTLL"},
    {104, "JGELL"},      {105, "JEQLK"},      {106, "JNELK"},      {107, "JLTLK"},
    {108, "JLELK"},      {109, "JGTLK"},      {110, "JGELK"},      {111, "JEQI"},
    {112, "JNEI"},       {113, "JLTI"},       {114, "JLEI"},       {115, "JGTI"},
    {116, "JGEI"},       {117, "JNEQF"},      {118, "JNNEF"},      {119, "JNLTF"},
    {120, "JNLEF"},      {121, "JNGTF"},      {122, "JNGEF"},      {123, "JNEQFLL"},
    {124, "JNNEFLL"},    {125, "JNLTFLL"},    {126, "JNLEFLL"},    {127, "JNGTFLL"},
    {128, "JNGEFLL"},    {129, "JNEQFLK"},    {130, "JNNEFLK"},    {131, "JNLTFLK"},
    {132, "JNLEFLK"},    {133, "JNGTFLK"},    {134, "JNGEFLK"},    {135, "JMPEOL"},
    {136, "RETEOL"},     {137, "INCLJEOL"},   {138, "STLJEOL"},    {139, "LDL2"},
    {140, "MOVL"},       {141, "LDLK"},       {142, "LDKL"},       {143, "STLK"},
    {144, "ADDILL"},     {145, "SUBILL"},     {146, "ADDFLL"},     {147, "SUBFLL"},
    {148, "MULFLL"},     {149, "ADDILLS"},    {150, "SUBILLS"},    {151, "ADDFLLS"},
    {152, "SUBFLLS"},    {153, "MULFLLS"},    {154, "CMDGET"},     {155, "CMDGETX"},
    {156, "CMDSET"},     {157, "CMDSETX"},    {158, "CMDRUN"},     {159, "CMDRUNX"},
    {160, "MSG"},        {161, "BREAK"},      {162, "STGEOL"},     {163, "STGJEOL"},
    {164, "STGK"},       {165, "LDG2"},       {166, "ADDGK"},      {167, "REMGK"},
    {168, "INCG"},       {169, "JZG"},        {170, "JNZG"},       {171, "JEQGK"},
    {172, "JNEGK"},      {173, "JLTGK"},      {174, "JLEGK"},      {175, "JGTGK"},
    {176, "JGEGK"},      {177, "JNEQFGK"},    {178, "JNNEFGK"},    {179, "JNLTFGK"},
    {180, "JNLEFGK"},    {181, "JNGTFGK"},    {182, "JNGEFGK"},    {183, "ADDIGG"},
    {184, "SUBIGG"},     {185, "ADDFGG"},     {186, "SUBFGG"},     {187, "MULFGG"},
    {188, "INCGEOL"},    {189, "STGKEOL"},    {190, "JEQGKEOL"},   {191, "JNEGKEOL"},
    {192, "JLTGKEOL"},   {193, "JLEGKEOL"},   {194, "JGTGKEOL"},   {195, "JGEGKEOL"},
    {196, "JNEQFGKEOL"}, {197, "JNNEFGKEOL"}, {198, "JNLTFGKEOL"}, {199, "JNLEFGKEOL"},
    {200, "JNGTFGKEOL"}, {201, "JNGEFGKEOL"}, {202, "JNCMPFEOL"},  {203, "JZGEOL"},
    {204, "JNZGEOL"},    {205, "UNTILCK"},    {206, "ADDIGGEOL"},  {207, "SUBIGGEOL"},
    {208, "ADDFGGEOL"},  {209, "SUBFGGEOL"},  {210, "MULFGGEOL"},  {211, "REMGKEOL"},
    {212, "ADDIGEOL"},   {213, "ADDFGEOL"},   {214, "SUBFGEOL"},   {215, "ADDFGK"},
    {216, "SUBFGK"},     {217, "MULFGK"},     {218, "MULFKG"},     {219, "JNEQFGG"},
    {220, "JNNEFGG"},    {221, "JNLTFGG"},    {222, "JNLEFGG"},    {223, "JNGTFGG"},
    {224, "JNGEFGG"},    {225, "JNEQFGGEOL"}, {226, "JNNEFGGEOL"}, {227, "JNLTFGGEOL"},
    {228, "JNLEFGGEOL"}, {229, "JNGTFGGEOL"}, {230, "JNGEFGGEOL"}, {231, "LDMLK"},
    {232, "STMLK"},      {233, "JULTK"},      {234, "LDPMLK"},     {235, "JULTLK"},
    {236, "LDGE"},       {237, "STGE"},       {238, "JLINES"},     {239, "JMPLN"},
    {240, "MOVG"},       {241, "LDGW"},       {242, "STGW"},       {243, "MULIK"},
    {244, "REMIK"},      {245, "ADDIG"},      {246, "JCMPGG"},     {247, "JCMPGGEOL"},
    {248, "INCGJMPLN"},  {249, "LDGWG"},      {250, "STGWG"},      {251, "CALLFEOL"},
};

// Format 5: format 4's, and these after them.
constexpr Pinned kAddedInFormat5[] = {{252, "INCMLKEOL"}};

TEST(OpcodeNumbers, EveryOpcodeOfTheStoredFormatKeepsItsNumber) {
  static_assert(kMinFormatVersion <= 4 && kMaxFormatVersion == 5,
                "a new format version pins its own numbers here");
  ASSERT_EQ(kOpCount, std::size(kFormat4) + std::size(kAddedInFormat5))
      << "an opcode added or removed within format 5";
  for (const Pinned& p : kFormat4) {
    EXPECT_EQ(std::string_view(op_name(static_cast<Op>(p.number))), p.name)
        << "opcode " << p.number << " moved";
  }
  for (const Pinned& p : kAddedInFormat5) {
    EXPECT_EQ(std::string_view(op_name(static_cast<Op>(p.number))), p.name)
        << "opcode " << p.number << " moved";
  }
}

}  // namespace
}  // namespace uprog::bytecode
