// Gold programs compiled and run on the VM: the number rules of manual 1.3-1.6 and 1.10, the
// flow control of 2.11-2.13, functions with several outputs, nargout, recursion, try/catch.
#include <gtest/gtest.h>

#include "bytecode/assembly.h"
#include "gold_runner.h"

namespace uprog::gold_test {
namespace {

TEST(gold_run, IntegerAndFloatArithmetic) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int a, b, c, d, e, g, h, w
float x, y, z, q
function main()
a = 2/3                  // 0 (1.3.2)
x = 2.0/3                // 0.666667
b = 1+0x10               // 17 (1.5)
c = 2147483647+10        // wraps: -2147483639
y = 100000*100000        // 1.0e10, a float (1.5)
d = 3/2/2                // 0 (1.4)
e = 3/(2/2)              // 3
g = -0x80000000          // saturates: 2147483647
h = 7.9 & 3.4            // 7 & 3 = 3
z = 1.03+0x20            // 33.03
q = 5/real(2)            // 2.5 (1.7)
w = 20%4 + 5%2 + (8<<2) + (8>>2) + ~3   // 0 + 1 + 32 + 2 - 4 = 31
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("a"), 0);
  EXPECT_FLOAT_EQ(p.f("x"), 2.0f / 3.0f);
  EXPECT_EQ(p.i("b"), 17);
  EXPECT_EQ(p.i("c"), -2147483639);
  EXPECT_FLOAT_EQ(p.f("y"), 1.0e10f);
  EXPECT_EQ(p.i("d"), 0);
  EXPECT_EQ(p.i("e"), 3);
  EXPECT_EQ(p.i("g"), 2147483647);
  EXPECT_EQ(p.i("h"), 3);
  EXPECT_FLOAT_EQ(p.f("z"), 33.03f);
  EXPECT_FLOAT_EQ(p.f("q"), 2.5f);
  EXPECT_EQ(p.i("w"), 31);
}

// A negative literal is one constant: `-1.5` and `-7` compile to no NEGF or NEGI (the values
// as the operators give them, -0x80000000 saturating as NEGI does).
TEST(gold_run, NegativeLiteralsAreConstants) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int a, b
float x
function main()
x = -1.5
a = -7
b = -0x80000000
return
)"));
  const std::string code = bytecode::disassemble(p.image);
  EXPECT_EQ(code.find("NEGF"), std::string::npos) << code;
  EXPECT_EQ(code.find("NEGI"), std::string::npos) << code;
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_FLOAT_EQ(p.f("x"), -1.5f);
  EXPECT_EQ(p.i("a"), -7);
  EXPECT_EQ(p.i("b"), 2147483647);
}

TEST(gold_run, AssignmentConversions) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int a, b, c, big
float t
function main()
a = 12345.6789      // rounds: 12346 (1.10)
b = 215.789e8       // saturates: 2147483647
c = -3.5            // halves away from zero: -4
t = 12345678        // 1.234568e7 as a float
big = 100000*100000 // a float product into an int saturates
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("a"), 12346);
  EXPECT_EQ(p.i("b"), 2147483647);
  EXPECT_EQ(p.i("c"), -4);
  EXPECT_FLOAT_EQ(p.f("t"), 12345678.0f);
  EXPECT_EQ(p.i("big"), 2147483647);
}

TEST(gold_run, LogicAndComparisons) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int r[8]
function main()
r[0] = 1 && 5       // 1
r[1] = 0.21 && 2    // 1 (1.6)
r[2] = !0.0004      // 1: the argument is truncated to 0 (1.6)
r[3] = !4           // 0
r[4] = (25000.0 == 25000)   // 1
r[5] = 3 < 2 || 2 >= 2      // 1
r[6] = 100000*100000 > 2147483647   // a float product compares as a float: 1
r[7] = 0 || 0               // 0
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  const int32_t want[8] = {1, 1, 1, 0, 1, 1, 1, 0};
  for (uint32_t k = 0; k < 8; ++k) EXPECT_EQ(p.i("r", k), want[k]) << "r[" << k << "]";
}

// A condition's && and || jump on each side when the right side shows nothing (variables,
// literals, comparisons): no truth is computed, no AND or OR. A right side that calls a
// function is still evaluated, whatever the left (decision 4: both sides always are).
TEST(gold_run, ConditionsJumpOnEachSideThatShowsNothing) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int a, b, r[5]
function main()
global int a, b, r[5]
a = 5
b = 2
if (a > 0 && b < 3)
  r[0] = 1
end
if (a < 0 || b == 2)
  r[1] = 1
end
if (a < 0 && b == 2)
  r[2] = 1
end
while (a > 0 && b < 3.5)
  a = a - 1
  r[3] = r[3] + 1
end
if (!(a > 0 || b > 2))    // a = 0, b = 2
  r[4] = 1
end
return
)"));
  const std::string code = bytecode::disassemble(p.image);
  for (const char* op : {"ANDI", "ORI", "CMPI", "CMPF", "LNOT"})
    EXPECT_EQ(code.find(op), std::string::npos) << op << " in\n" << code;
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  const int32_t want[5] = {1, 1, 0, 5, 1};
  for (uint32_t k = 0; k < 5; ++k) EXPECT_EQ(p.i("r", k), want[k]) << "r[" << k << "]";
  GoldRun calls;
  ASSERT_TRUE(calls.compile(R"(
int calls, r[3]
function [int v] = bump(int x)
global int calls
calls = calls + 1
v = x
return
function main()
global int calls, r[3]
if (0 && bump(1))     // bump runs: calls 1
  r[0] = 1
end
if (1 || bump(0))     // bump runs: calls 2
  r[1] = 1
end
if (!0.0004)          // true: a float's ! truncates first (1.6)
  r[2] = 1
end
return
)"));
  EXPECT_EQ(calls.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(calls.i("r", 0), 0);
  EXPECT_EQ(calls.i("r", 1), 1);
  EXPECT_EQ(calls.i("r", 2), 1);
  EXPECT_EQ(calls.i("calls"), 2);
}

TEST(gold_run, BuiltinFunctions) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int f1, f2, r1, r2, r3, s1, s2, s3, ai
float sine, cs, sq, sq2, af
function main()
f1 = fix(3.8)
f2 = fix(-3.8)
r1 = rnd(3.8)
r2 = rnd(-3.8)
r3 = rnd(3.4)
s1 = sign(-3.8)
s2 = sign(3.8)
s3 = sign(0)
ai = abs(0x80000000)
af = abs(-123.54)
sine = sin(0.523598775598)
cs = cos(1.047197551196)
sq = sqrt(16)
sq2 = sqrt(-625)
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("f1"), 3);
  EXPECT_EQ(p.i("f2"), -3);
  EXPECT_EQ(p.i("r1"), 4);
  EXPECT_EQ(p.i("r2"), -4);
  EXPECT_EQ(p.i("r3"), 3);
  EXPECT_EQ(p.i("s1"), -1);
  EXPECT_EQ(p.i("s2"), 1);
  EXPECT_EQ(p.i("s3"), 0);
  EXPECT_EQ(p.i("ai"), 2147483647);
  EXPECT_FLOAT_EQ(p.f("af"), 123.54f);
  EXPECT_NEAR(p.f("sine"), 0.5f, 1e-5);
  EXPECT_NEAR(p.f("cs"), 0.5f, 1e-5);
  EXPECT_FLOAT_EQ(p.f("sq"), 4.0f);
  EXPECT_FLOAT_EQ(p.f("sq2"), 0.0f);
}

TEST(gold_run, ForLoopsEvaluateBoundsOnce) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int sum, cnt, down, n, k
float fsum
function main()
float x
n = 5
for k = 1:n
  n = 100           // the bound was evaluated once (2.12.2)
  sum = sum + k
end
for k = 1:2:100
  cnt++
end
for k = 10:-3:1
  down = down * 10 + k
end
for x = 0.5:0.5:2
  fsum = fsum + x
end
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("sum"), 15);
  EXPECT_EQ(p.i("cnt"), 50);
  EXPECT_EQ(p.i("down"), 10741);  // 10, 7, 4, 1
  EXPECT_FLOAT_EQ(p.f("fsum"), 5.0f);
}

TEST(gold_run, ZeroStepIsARunTimeError) {
  GoldRun p;
  ASSERT_TRUE(p.compile("int k, s\nfunction main()\ns = 0\nfor k = 1:s:10\nend\nreturn\n"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Error);
}

TEST(gold_run, WhileBreakContinueAndSwitch) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int arr[10], i, evens, sw[4], a, b, c
function main()
i = 0
while (i < 10)
  i++
  if (i % 2)
    continue
  end
  evens = evens + 1
  if i == 8
    break
  end
end
a=2
b=2
switch(a+b-2)    // 2.11.3, example 1: case 2 runs, only case 2
  case 1
    b=a+1
  case 2
    c=a+b
  case 2
    c=-1
  otherwise
    a=1
    b=2
end
for i = 0:3
  switch i
    case 0, sw[i] = 10
    case 1
      sw[i] = 11
      break
      sw[i] = -1
    otherwise
      sw[i] = 99
  end
end
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("evens"), 4);
  EXPECT_EQ(p.i("i"), 4);  // the for loop left it past 3
  EXPECT_EQ(p.i("a"), 2);
  EXPECT_EQ(p.i("b"), 2);
  EXPECT_EQ(p.i("c"), 4);
  EXPECT_EQ(p.i("sw", 0), 10);
  EXPECT_EQ(p.i("sw", 1), 11);
  EXPECT_EQ(p.i("sw", 2), 99);
  EXPECT_EQ(p.i("sw", 3), 99);
}

TEST(gold_run, FunctionsWithSeveralOutputsNargoutRecursion) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int q, r, n1, n2, fact, location[4], err
float half
function [int quo, int rem] = divmod(int a, int b)
function [int quo, int rem] = divmod(int a, int b)
quo = a / b
rem = a % b
return

function [int n] = nouts()
int k
n = nargout
return

function int f = factorial(int n)
if n <= 1
  f = 1
  return
end
f = n * factorial(n - 1)
return

function float h = halve(float x)
h = x / 2
return

function int Err=Move(int index)
global int location[4]
location[index] = index * 10
Err = 0
return

function main()
[q, r] = divmod(17, 5)
n1 = nouts()
[n2] = nouts()
fact = factorial(10)
half = halve(5)
err = Move(3)
Move(1)
return
)"));
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("q"), 3);
  EXPECT_EQ(p.i("r"), 2);
  EXPECT_EQ(p.i("n1"), 1);
  EXPECT_EQ(p.i("n2"), 1);
  EXPECT_EQ(p.i("fact"), 3628800);
  EXPECT_FLOAT_EQ(p.f("half"), 2.5f);
  EXPECT_EQ(p.i("location", 3), 30);
  EXPECT_EQ(p.i("location", 1), 10);
  EXPECT_EQ(p.i("err"), 0);
}

TEST(gold_run, TryCatchCatchesARefusedCommand) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int stage
function main()
try
  stage = 1
  UM=2  // ACTION THAT WILL FAIL
  stage = 2
catch
  stage = stage + 10
end
return
)"));
  p.host.refuse_write = gold::find_command("UM")->id;
  EXPECT_EQ(p.run("main"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("stage"), 11);
}

TEST(gold_run, DriveCommandsCaseInsensitive) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
##START
il[3]=6
UI[2]=abs(-7*2)
PA=5
pa=PA+1
UI[UI[2]-13]=4
UI[1]++
BG;
)"));
  EXPECT_EQ(p.run("START"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.command("IL", 3).i, 6);
  EXPECT_EQ(p.command("UI", 2).i, 14);
  EXPECT_EQ(p.command("PA").i, 6);
  EXPECT_EQ(p.command("UI", 1).i, 5);
  ASSERT_EQ(p.host.executed.size(), 1u);
  EXPECT_EQ(p.host.executed[0], gold::find_command("BG")->id);
}

TEST(gold_run, UntilAndWaitTakeTime) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int t0, t1
function main()
t0 = utick(0)
wait(200)
until (UI[1] == 0)
t1 = utock(t0)
return
)"));
  EXPECT_EQ(p.run("main", 1000), vm::SliceEnd::Finished);
  EXPECT_GE(p.i("t1"), 200000);
  EXPECT_LT(p.i("t1"), 210000);
}

TEST(gold_run, GotoLabelsAndReset) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int n, m
##START
n = n + 1
if n < 3
  goto##START
end
goto ##DONE
n = 100
##DONE
m = count()
return

function int c = count()
int k
k = 0
##AGAIN
k++
if k < 5
  goto##AGAIN
end
c = k
return
)"));
  EXPECT_EQ(p.run("START"), vm::SliceEnd::Finished);
  EXPECT_EQ(p.i("n"), 3);
  EXPECT_EQ(p.i("m"), 5);
}

TEST(gold_run, EveryLineEndsWithEol) {
  GoldRun p;
  ASSERT_TRUE(p.compile("int a\n##START\na = 1\na = 2; a = 3\nwhile(1)\nend\n"));
  // The endless loop still gives the machine a line end each turn.
  const int r = p.image.find_routine("START");
  ASSERT_GE(r, 0);
  p.machine.start(0, static_cast<uint32_t>(r));
  const auto s = p.machine.run_slice(0, vm::Budget::of_lines(2));
  EXPECT_EQ(s.end, vm::SliceEnd::LineEnd);
  EXPECT_EQ(p.i("a"), 3);  // both statements of line 4 ran before its one EOL
  EXPECT_EQ(p.machine.run_slice(0, vm::Budget::of_lines(5)).end, vm::SliceEnd::LineEnd);
  ASSERT_FALSE(p.image.lines.empty());
  EXPECT_EQ(p.image.lines.front().line, 3u);
}

TEST(gold_run, ImageNamesGlobalsLocalsRoutinesAndEvents) {
  GoldRun p;
  ASSERT_TRUE(p.compile(R"(
int g, arr[3]
float fl
function [int y] = f(int a, float b)
int loc
float fl2
y = a
return
#@AUTO_I2
g = 1
return
##MAIN
g = f(1, 2.0)
)"));
  const auto& img = p.image;
  ASSERT_EQ(img.globals.size(), 3u);
  EXPECT_EQ(img.globals[1].name, "arr");
  EXPECT_EQ(img.globals[1].length, 3u);
  EXPECT_EQ(img.globals[2].type, ValueType::Float);
  const int f = img.find_routine("f");
  ASSERT_GE(f, 0);
  const auto& r = img.routines[static_cast<size_t>(f)];
  EXPECT_EQ(r.inputs, 2u);
  EXPECT_EQ(r.outputs, 1u);
  ASSERT_GE(r.locals.size(), 5u);
  EXPECT_EQ(r.locals[0].name, "a");
  EXPECT_EQ(r.locals[1].type, ValueType::Float);
  EXPECT_EQ(r.locals[2].name, "y");
  EXPECT_EQ(r.locals[3].name, "loc");
  EXPECT_EQ(r.locals[4].name, "fl2");
  const int a = img.find_routine("AUTO_I2");
  ASSERT_GE(a, 0);
  EXPECT_EQ(img.routines[static_cast<size_t>(a)].kind, bytecode::RoutineKind::AutoRoutine);
  ASSERT_EQ(img.events.size(), 1u);
  EXPECT_EQ(img.events[0].event, 8u);  // AUTO_I2 is masked by MI bit 8 (256)
  EXPECT_EQ(img.routines[static_cast<size_t>(img.find_routine("MAIN"))].kind,
            bytecode::RoutineKind::Label);
}

}  // namespace
}  // namespace uprog::gold_test
