// The code the ST compiler makes of a condition's line (IF, WHILE, UNTIL, FOR): the line ends
// after its branch on both paths, so that the compile-time pass makes comparison, branch and end
// of line one compare-and-jump carrying the line-end mark (which the VM fuses with the loads
// before it at load); and every path still ends each line exactly once, since the drive's line
// budget and TASK's figures count the line ends.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "bytecode/image.h"
#include "bytecode/opcodes.h"
#include "dialect/loaded_program.h"
#include "dialects/st/compile.h"

namespace uprog {
namespace {

bytecode::Image compiled(const std::string& source) {
  const st::CompileResult r = st::compile(SourceFile{"t.st", source});
  EXPECT_TRUE(r.ok()) << format_text(r.diagnostics);
  return r.image;
}

// The instructions of source line `line`, from each place it starts up to the next line's
// start, by name.
std::vector<std::string> ops_on_line(const bytecode::Image& image, uint32_t line) {
  std::vector<std::string> out;
  for (size_t k = 0; k < image.lines.size(); ++k) {
    if (image.lines[k].line != line) continue;
    const uint32_t end = k + 1 < image.lines.size() ? image.lines[k + 1].code
                                                    : static_cast<uint32_t>(image.code.size());
    for (uint32_t pc = image.lines[k].code; pc < end;
         pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
      out.emplace_back(bytecode::op_name(bytecode::word_op(image.code[pc])));
  }
  return out;
}
// The last `n` instructions the line table gives `line` (or fewer), as assembly names them:
// ".eol" on one that carries the line-end mark.
std::string last_ops(const bytecode::Image& image, uint32_t line, size_t n) {
  std::vector<std::string> ops;
  for (size_t k = 0; k < image.lines.size(); ++k) {
    if (image.lines[k].line != line) continue;
    const uint32_t end = k + 1 < image.lines.size() ? image.lines[k + 1].code
                                                    : static_cast<uint32_t>(image.code.size());
    for (uint32_t pc = image.lines[k].code; pc < end;
         pc += bytecode::op_length(bytecode::word_op(image.code[pc])))
      ops.push_back(std::string(bytecode::op_name(bytecode::word_op(image.code[pc]))) +
                    (bytecode::word_ends_line(image.code[pc]) ? ".eol" : ""));
  }
  std::string out;
  for (size_t k = ops.size() < n ? 0 : ops.size() - n; k < ops.size(); ++k)
    out += (out.empty() ? "" : " ") + ops[k];
  return out;
}

// Nothing the programs below do reaches the drive.
class NoDrive final : public vm::Host {
 public:
  vm::CommandStatus read(uint32_t, int32_t, Value&) override { return vm::kCommandUnsupported; }
  vm::CommandStatus write(uint32_t, int32_t, Value) override { return vm::kCommandUnsupported; }
  vm::CommandStatus execute(uint32_t, int32_t, const Value*, uint32_t) override {
    return vm::kCommandUnsupported;
  }
  uint32_t now_us() override { return 0; }
};

struct LineRun {
  // Where each one-line slice begins, in order: "7" at the start of source line 7, "(7)" inside
  // the code the line table gives line 7 (a FOR's step after its body's last line, say), which
  // is where a held thread is shown.
  std::string slices;
  std::unique_ptr<dialect::LoadedProgram> program;
  int32_t global(const std::string& name) const {
    const bytecode::Image& image = program->image();
    for (uint32_t g = 0; g < image.globals.size(); ++g) {
      Value v;
      if (image.globals[g].name == name && program->machine().read_global(g, 0, v)) return v.i;
    }
    ADD_FAILURE() << "no global " << name;
    return 0;
  }
};

std::string place(const bytecode::Image& image, uint32_t pc) {
  const bytecode::LineEntry* at = image.line_at(pc);
  if (at == nullptr) return "?";
  const std::string line = std::to_string(at->line);
  return at->code == pc ? line : "(" + line + ")";
}

// Runs FUNCTION `name` a line a slice, as the drive's schedule does when a budget ends after
// every line: a line that ended twice on some path would take a slice of its own, one that did
// not end would run on into the next line's slice.
LineRun run_line_by_line(const bytecode::Image& image, const std::string& name) {
  static NoDrive host;
  LineRun run;
  vm::MachineConfig config;
  config.threads = 1;
  config.stack = 512;
  std::string error;
  run.program = dialect::LoadedProgram::load(bytecode::encode(image), config, host, &error);
  if (!run.program) {
    ADD_FAILURE() << error;
    return run;
  }
  vm::Machine& m = run.program->machine();
  EXPECT_EQ(m.start(0, static_cast<uint32_t>(image.find_routine(name))), vm::RunError::None);
  for (int slices = 0; slices < 1000; ++slices) {
    run.slices += (run.slices.empty() ? "" : " ") + place(image, m.pc(0));
    const vm::SliceResult r = m.run_slice(0, vm::Budget::of_lines(1));
    if (r.end != vm::SliceEnd::LineEnd) {
      EXPECT_EQ(r.end, vm::SliceEnd::Finished);
      break;
    }
  }
  return run;
}

// Each construct's condition on a global against a constant, or a global alone.
const char* kConditions = R"(LONG A, N, S;
FUNCTION F
  IF A = 3 THEN
    S := 1;
  ELSE
    S := 2;
  END_IF;
  WHILE N < 10 DO
    N := N + 1;
  END_WHILE;
  REPEAT
    N := N - 1;
  UNTIL N = 0
  FOR A := 1 TO 30000000 DO
    S := S + A;
  END_FOR;
  IF S THEN
    RETURN;
  END_IF;
END_FUNCTION
)";

// What the pass makes of the rest of the code may change; a condition's line ends in its
// compare-and-jump, which ends the line on both paths.
TEST(st_codegen, AConditionsLineIsOneBranchThatEndsIt) {
  const bytecode::Image image = compiled(kConditions);
  EXPECT_EQ(last_ops(image, 3, 3), "LDG PUSHI JNEI.eol");  // IF A = 3: to the ELSE side unless
  EXPECT_EQ(last_ops(image, 8, 3), "LDG PUSHI JGEI.eol");  // WHILE N < 10: out unless
  // UNTIL N = 0: out if (a test against 0) to the line's EOL there, else back, the line ending
  // in the jump back.
  EXPECT_EQ(last_ops(image, 13, 4), "LDG JZ JMP.eol EOL");
  EXPECT_EQ(last_ops(image, 17, 2), "LDG JZ.eol");  // IF S
  // FOR, inverted: the bound into the hidden local and the test on the FOR line, once a loop:
  // into the body through the EOL at its top, or (no pass) past the loop by the jump that ends
  // the line. After the body's last line, on every pass, the step and the same test, nothing
  // between them that control enters, so that the VM fuses them into one INCGJLEGL at load;
  // that branch back ends the line itself and jumps past the EOL.
  EXPECT_EQ(last_ops(image, 14, 100), "PUSHI STG PUSHK STL LDG LDL JLEI JMP.eol EOL");
  EXPECT_EQ(last_ops(image, 15, 7), "LDG PUSHI ADDI STG LDG LDL JLEI.eol");
  // (UNTIL's line keeps the EOL at its way out.)
  for (uint32_t line : {3u, 8u, 15u, 17u})
    for (const std::string& op : ops_on_line(image, line))
      EXPECT_TRUE(op != "EOL" && op != "CMPI")
          << "line " << line << ": a comparison or a line end apart from the branch";
}

// Every shape, fused or not: the branches on a constant, a two globals' comparison and an AND
// (no ending form: the EOLs stay apart), a FOR with a negative step and one with a bound that is
// evaluated once. Each line takes one slice each time it runs.
const char* kPaths = R"(LONG A, B, N, S, K;
FUNCTION F
  FOR A := 1 TO 3 DO
    IF A = 2 THEN
      S := S + A;
    ELSE
      K := K + 1;
    END_IF;
  END_FOR;
  WHILE N < 2 DO
    N := N + 1;
  END_WHILE;
  REPEAT
    N := N - 1;
  UNTIL N = 0
  FOR B := N TO A BY 2 DO
    IF B > A THEN
      S := 100;
    END_IF;
  END_FOR;
  FOR N := 3 TO 1 BY -1 DO
  END_FOR;
  IF S <> 0 AND K <> 0 THEN
    S := S + 1;
  END_IF;
  IF S = 0 THEN
  END_IF;
END_FUNCTION
)";

TEST(st_codegen, EveryPathEndsEachLineOnce) {
  const LineRun run = run_line_by_line(compiled(kPaths), "F");
  // FOR A: 1 (ELSE), 2 (THEN), 3 (ELSE); each pass's step and test end the FOR line again.
  const std::string for_a = "3 4 7 (7) 4 5 (7) 4 7 (7)";
  const std::string while_n = "10 11 10 11 10";  // twice, then out
  // N 2 -> 1 -> 0; the UNTIL line's way back is a jump that ends the line (its EOL and JMP
  // merged), so the slice after it starts at line 14 again.
  const std::string repeat_n = "14 15 14 15";
  // FOR B := 0 TO 4 BY 2 (a bound in the hidden local): the IF's false side ends its line at
  // its target's EOL, then the step.
  const std::string for_b = "16 17 (18) 17 (18) 17 (18)";
  const std::string for_n = "21 (21) (21) (21)";  // 3, 2, 1, out: an empty body
  const std::string ifs = "23 24 26 (26)";        // the AND true; S = 0 false, then the RET
  EXPECT_EQ(run.slices,
            for_a + " " + while_n + " " + repeat_n + " " + for_b + " " + for_n + " " + ifs);
  EXPECT_EQ(run.global("A"), 4);
  EXPECT_EQ(run.global("B"), 6);
  EXPECT_EQ(run.global("N"), 0);
  EXPECT_EQ(run.global("S"), 3);
  EXPECT_EQ(run.global("K"), 2);
}

// AND, OR and NOT in a condition: a compare-and-jump on each side when the right side shows
// nothing (no DIV or MOD, which may raise Overflow), no truths, no AND, no -1; every path ends
// the condition's line once. Each IF runs three times (K = 0, 1, 2: A = -1, 0, 1 and B = 2, 1,
// 0), so that each side decides: line 6 is true at K = 1 only, line 9 at K = 0 and 2, line 12
// at K = 1 and 2. G's right side divides: it is evaluated as before, and its quotient beyond
// 16 bits stops G with Overflow though the left side is 0.
const char* kLogic = R"(LONG K, A, B, R1, R2, R3, Q;
FUNCTION F
  FOR K := 0 TO 2 DO
    A := K - 1;
    B := 2 - K;
    IF A = 0 AND B = 1 THEN
      R1 := R1 + 1;
    END_IF;
    IF A < 0 OR B < 1 THEN
      R2 := R2 + 1;
    END_IF;
    IF NOT (A < 0) THEN
      R3 := R3 + 1;
    END_IF;
  END_FOR;
END_FUNCTION
FUNCTION G
  IF 0 AND 100000 / (K - 2) THEN
    Q := 1;
  END_IF;
END_FUNCTION
)";

TEST(st_codegen, AndOrAndNotJumpOnEachSide) {
  const bytecode::Image image = compiled(kLogic);
  for (uint32_t line : {6u, 9u, 12u})
    for (const std::string& op : ops_on_line(image, line))
      EXPECT_TRUE(op != "ANDI" && op != "ORI" && op != "NEGI" && op != "LNOT" && op != "CMPI")
          << "line " << line << ": " << op;
  const LineRun run = run_line_by_line(image, "F");
  // Each IF line one slice on every path, its body's line when true; the FOR's step and test
  // in (13), the body's last line, and the RET after the loop there too.
  EXPECT_EQ(run.slices, "3 4 5 6 9 10 12 (13) 4 5 6 7 9 12 13 (13) 4 5 6 9 10 12 13 (13) (13)");
  EXPECT_EQ(run.global("R1"), 1);
  EXPECT_EQ(run.global("R2"), 2);
  EXPECT_EQ(run.global("R3"), 2);
  vm::Machine& m = run.program->machine();  // K is 3 now: 100000 / 1
  ASSERT_EQ(m.start(0, static_cast<uint32_t>(image.find_routine("G"))), vm::RunError::None);
  EXPECT_EQ(m.run_slice(0, vm::Budget::unlimited()).end, vm::SliceEnd::Error);
  EXPECT_EQ(m.last_error(0), vm::RunError::Overflow);
  EXPECT_EQ(run.global("Q"), 0);
}

}  // namespace
}  // namespace uprog
