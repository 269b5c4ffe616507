// The ST code generator (codegen.h). The page's operator rules: `*` multiplies the operands'
// low 16 bits; `/` and MOD divide by the divisor's low 16 bits and fail with Overflow when the
// quotient leaves 16 bits; relations and AND/OR/XOR/NOT give TRUE = -1; unary minus wraps.
#include "dialects/st/codegen.h"

#include <map>

#include "bytecode/code_builder.h"
#include "dialects/st/ascii_table.h"
#include "dialects/st/names.h"
#include "vm/run_error.h"

namespace uprog::st {
namespace {

using bytecode::CodeBuilder;

using L = CodeBuilder::Label;

constexpr uint32_t kScratchA = 0, kScratchB = 1, kFirstForLocal = 2;

class Generator {
 public:
  Generator(const Program& p, const preproc::SourceLocator& locator)
      : p_(p), locator_(locator), b_(image_.code) {}

  bytecode::Image run(const std::string& source_name) {
    image_.dialect = "st";
    image_.source_name = source_name;
    for (const GlobalVar& g : p_.globals)
      image_.globals.push_back({g.name, ValueType::Int, g.type == VarType::Dlong ? 2u : 1u});
    for (size_t i = 0; i < p_.routines.size(); ++i)
      routine_index_[p_.routines[i].name] = static_cast<uint32_t>(i);
    for (size_t i = 0; i < p_.routines.size(); ++i)
      routine(p_.routines[i], static_cast<uint32_t>(i));
    // A file of declarations only still makes a loadable image: the loader wants code.
    if (image_.code.empty()) b_.emit(bytecode::Op::RET);
    b_.finish();
    return std::move(image_);
  }

 private:
  void routine(const Routine& r, uint32_t index) {
    bytecode::Routine out;
    out.name = r.name;
    out.kind = r.kind == ProgramKind::Function ? bytecode::RoutineKind::Function
                                               : bytecode::RoutineKind::Task;
    out.entry = b_.here();
    out.locals.push_back({"$A", ValueType::Int});
    out.locals.push_back({"$B", ValueType::Int});
    for (int k = 0; k < r.for_count; ++k)
      out.locals.push_back({"$FOR" + std::to_string(k + 1), ValueType::Int});
    image_.routines.push_back(std::move(out));
    if (r.kind != ProgramKind::Function) {
      bytecode::Task t;
      t.routine = index;
      t.number = static_cast<uint32_t>(r.kind);
      t.period_ns = period_ns(r.kind);
      t.starts_at_reset = r.kind == ProgramKind::Init || r.kind == ProgramKind::Main;
      image_.tasks.push_back(t);
    }
    labels_.clear();
    if (r.kind == ProgramKind::Main) {
      main_loop(r, image_.routines.back());
      return;
    }
    uses_scratch_ = false;
    for (int s : r.body) statement(s);
    b_.emit(bytecode::Op::RET);
    // A routine that needs no local has none: a cyclic task's every run zeroes its locals.
    if (!uses_scratch_ && r.for_count == 0) image_.routines.back().locals.clear();
  }

  // A load or store of a scratch local.
  void scratch(bytecode::Op op, uint32_t local) {
    uses_scratch_ = true;
    b_.emit(op, local);
  }

  // PLCMAIN restarts at its top when it ends: the routine loops by itself, counting its passes
  // in its last local at the top (the drive's TASK reads them), so that the background runs
  // whole slices in the machine and never returns to be started again. A pass without a line
  // still costs one, as the bare end of an empty program does. The count stands on the
  // PROGRAM line, so that a thread at the top of a pass is shown there, not on the line before.
  void main_loop(const Routine& r, bytecode::Routine& out) {
    const auto passes = static_cast<uint32_t>(out.locals.size());
    out.locals.push_back({std::string(kMainPassesLocal), ValueType::Int});
    const L top = b_.new_label();
    b_.bind(top);
    line(r.offset);
    const size_t lines_before = image_.lines.size();
    b_.emit_imm(bytecode::Op::INCL, static_cast<int32_t>(passes), 1u);
    for (int s : r.body) statement(s);
    if (image_.lines.size() == lines_before) eol();
    b_.emit_to(bytecode::Op::JMP, top);
  }

  L label_of(const std::string& name) {
    auto it = labels_.find(name);
    if (it != labels_.end()) return it->second;
    const L l = b_.new_label();
    labels_.emplace(name, l);
    return l;
  }

  void line(size_t offset) {
    const Location at = locator_.locate(offset);
    image_.lines.push_back({b_.here(), at.file, static_cast<uint32_t>(at.line)});
  }
  void eol() { b_.emit(bytecode::Op::EOL); }

  void push(int32_t v) {
    if (bytecode::fits_imm(v)) {
      b_.emit_imm(bytecode::Op::PUSHI, v);
      return;
    }
    image_.constants.push_back({ValueType::Int, static_cast<uint32_t>(v)});
    b_.emit(bytecode::Op::PUSHK, static_cast<uint32_t>(image_.constants.size() - 1));
  }

  void store(uint32_t global) {
    const VarType t = p_.globals[global].type;
    if (t == VarType::Byte) b_.emit(bytecode::Op::SEXT, 8);
    if (t == VarType::Word) b_.emit(bytecode::Op::SEXT, 16);
    b_.emit(bytecode::Op::STG, global);
  }

  uint32_t text(const std::string& s) {
    image_.texts.push_back(s);
    return static_cast<uint32_t>(image_.texts.size() - 1);
  }

  // --- expressions ---
  const Expr& ex(int i) const { return p_.exprs[static_cast<size_t>(i)]; }

  static bool is_relation(Op op) { return op >= Op::Gt && op <= Op::Ne; }

  void relation(const Expr& e) {
    expression(e.a);
    expression(e.b);
    switch (e.op) {
      case Op::Gt:
        b_.emit(bytecode::Op::CMPI, bytecode::kRelGt);
        break;
      case Op::Ge:
        b_.emit(bytecode::Op::CMPI, bytecode::kRelGe);
        break;
      case Op::Lt:
        b_.emit(bytecode::Op::CMPI, bytecode::kRelLt);
        break;
      case Op::Le:
        b_.emit(bytecode::Op::CMPI, bytecode::kRelLe);
        break;
      case Op::Eq:
        b_.emit(bytecode::Op::CMPI, bytecode::kRelEq);
        break;
      default:
        b_.emit(bytecode::Op::CMPI, bytecode::kRelNe);
        break;
    }
  }

  // A condition: any non-zero value is true; a relation's 0/1 need not become -1.
  void condition(int i) {
    const Expr& e = ex(i);
    if (e.kind == Expr::Kind::Binary && is_relation(e.op)) return relation(e);
    expression(i);
  }

  // Whether evaluating expression i shows nothing but its value: only DIV and MOD raise
  // (Overflow, a quotient beyond 16 bits), and nothing else has an effect.
  bool shows_nothing(int i) const {
    const Expr& e = ex(i);
    switch (e.kind) {
      case Expr::Kind::Const:
      case Expr::Kind::Var:
        return true;
      case Expr::Kind::Unary:
        return shows_nothing(e.a);
      case Expr::Kind::Binary:
        return e.op != Op::Div && e.op != Op::Mod && shows_nothing(e.a) && shows_nothing(e.b);
    }
    return false;
  }

  // Jumps to `target` when condition i is false (JZ) or true (JNZ). NOT is the other jump;
  // AND and OR whose right side shows nothing jump on each side, as a compiled C condition does,
  // instead of both truths, their AND or OR, its -1 and the jump: both sides are evaluated
  // otherwise, and with such a right side no program can tell.
  void branch(int i, bytecode::Op jump, L target) {
    const Expr& e = ex(i);
    const bytecode::Op other = jump == bytecode::Op::JZ ? bytecode::Op::JNZ : bytecode::Op::JZ;
    if (e.kind == Expr::Kind::Unary && e.op == Op::Not) return branch(e.a, other, target);
    if (e.kind == Expr::Kind::Binary && (e.op == Op::And || e.op == Op::Or) && shows_nothing(e.b)) {
      if ((e.op == Op::And) == (jump == bytecode::Op::JZ)) {  // either side false (AND), true (OR)
        branch(e.a, jump, target);
        branch(e.b, jump, target);
      } else {  // the right side decides once the left is true (AND) or false (OR)
        const L past = b_.new_label();
        branch(e.a, other, past);
        branch(e.b, jump, target);
        b_.bind(past);
      }
      return;
    }
    condition(i);
    b_.emit_to(jump, target);
  }

  void truth(int i) {
    expression(i);
    b_.emit(bytecode::Op::PUSHI, 0);
    b_.emit(bytecode::Op::CMPI, bytecode::kRelNe);
  }

  // The quotient on top must fit 16 bits, or the run stops with Overflow; it stays when kept.
  void check_quotient(bool keep) {
    const L ok = b_.new_label();
    if (keep) b_.emit(bytecode::Op::DUP);
    b_.emit(bytecode::Op::DUP);
    b_.emit(bytecode::Op::SEXT, 16);
    b_.emit(bytecode::Op::CMPI, bytecode::kRelEq);
    b_.emit_to(bytecode::Op::JNZ, ok);
    b_.emit(bytecode::Op::RAISE, static_cast<uint32_t>(vm::RunError::Overflow));
    b_.bind(ok);
  }

  // Expression i cut to its low 16 bits, sign-extended (`*`'s operands, `/`'s and MOD's
  // divisor): a constant's cut at compile time.
  void low16(int i) {
    const Expr& e = ex(i);
    if (e.kind == Expr::Kind::Const) return push(static_cast<int16_t>(e.value));
    expression(i);
    b_.emit(bytecode::Op::SEXT, 16);
  }
  bool is_leaf(int i) const {
    return ex(i).kind == Expr::Kind::Const || ex(i).kind == Expr::Kind::Var;
  }

  void expression(int i) {
    const Expr& e = ex(i);
    switch (e.kind) {
      case Expr::Kind::Const:
        push(e.value);
        return;
      case Expr::Kind::Var:
        b_.emit(bytecode::Op::LDG, e.global);
        return;
      case Expr::Kind::Unary:
        if (e.op == Op::Neg) {
          push(0);
          expression(e.a);
          b_.emit(bytecode::Op::SUBI);
        } else if (e.op == Op::Not) {
          expression(e.a);
          b_.emit(bytecode::Op::LNOT);
          b_.emit(bytecode::Op::NEGI);
        } else {
          expression(e.a);
          b_.emit(bytecode::Op::NOTI);
        }
        return;
      case Expr::Kind::Binary:
        binary(e);
        return;
    }
  }

  void binary(const Expr& e) {
    if (is_relation(e.op)) {
      relation(e);
      b_.emit(bytecode::Op::NEGI);
      return;
    }
    if (e.op == Op::And || e.op == Op::Or || e.op == Op::Xor) {
      truth(e.a);
      truth(e.b);
      b_.emit(e.op == Op::And  ? bytecode::Op::ANDI
              : e.op == Op::Or ? bytecode::Op::ORI
                               : bytecode::Op::XORI);
      b_.emit(bytecode::Op::NEGI);
      return;
    }
    switch (e.op) {
      case Op::Mul:
        low16(e.a);
        low16(e.b);
        b_.emit(bytecode::Op::MULI);
        return;
      case Op::Div:
        expression(e.a);
        low16(e.b);
        b_.emit(bytecode::Op::DIVI);
        check_quotient(true);
        return;
      case Op::Mod:
        if (is_leaf(e.a) && is_leaf(e.b)) {  // read twice rather than kept in the scratch locals
          expression(e.a);
          low16(e.b);
          b_.emit(bytecode::Op::DIVI);
          check_quotient(false);
          expression(e.a);
          low16(e.b);
          b_.emit(bytecode::Op::REMI);
          return;
        }
        expression(e.a);
        low16(e.b);
        scratch(bytecode::Op::STL, kScratchB);
        scratch(bytecode::Op::STL, kScratchA);
        scratch(bytecode::Op::LDL, kScratchA);
        scratch(bytecode::Op::LDL, kScratchB);
        b_.emit(bytecode::Op::DIVI);
        check_quotient(false);
        scratch(bytecode::Op::LDL, kScratchA);
        scratch(bytecode::Op::LDL, kScratchB);
        b_.emit(bytecode::Op::REMI);
        return;
      case Op::Shl:
      case Op::Shr:
        expression(e.a);
        push(ex(e.b).value);
        b_.emit(e.op == Op::Shl ? bytecode::Op::SHLI : bytecode::Op::SHRI);
        return;
      default:
        break;
    }
    expression(e.a);
    expression(e.b);
    switch (e.op) {
      case Op::Add:
        b_.emit(bytecode::Op::ADDI);
        break;
      case Op::Sub:
        b_.emit(bytecode::Op::SUBI);
        break;
      case Op::BAnd:
        b_.emit(bytecode::Op::ANDI);
        break;
      case Op::BOr:
        b_.emit(bytecode::Op::ORI);
        break;
      default:
        b_.emit(bytecode::Op::XORI);
        break;
    }
  }

  // --- statements ---
  const Stmt& st(int i) const { return p_.stmts[static_cast<size_t>(i)]; }
  void body(const std::vector<int>& list) {
    for (int s : list) statement(s);
  }

  void statement(int i) {
    const Stmt& s = st(i);
    switch (s.kind) {
      case Stmt::Kind::Assign:
        line(s.offset);
        expression(s.expr);
        store(s.target);
        eol();
        return;
      case Stmt::Kind::If:
        return if_statement(s);
      case Stmt::Kind::While:
        return while_loop(s);
      case Stmt::Kind::Repeat:
        return repeat_loop(s);
      case Stmt::Kind::For:
        return for_loop(s);
      case Stmt::Kind::Goto:
        line(s.offset);
        eol();
        b_.emit_to(bytecode::Op::JMP, label_of(s.name));
        return;
      case Stmt::Kind::Label:
        b_.bind(label_of(s.name));
        return;
      case Stmt::Kind::Return:
        line(s.offset);
        eol();
        b_.emit(bytecode::Op::RET);
        return;
      case Stmt::Kind::Call:
        line(s.offset);
        b_.emit(bytecode::Op::CALL, routine_index_.at(s.name), 0);
        eol();
        return;
      case Stmt::Kind::Builtin:
        line(s.offset);
        builtin(s);
        eol();
        return;
    }
  }

  // A condition's line ends after its branch, on both paths: here when the branch falls
  // through, and at its target by an EOL there (taken_path_ends_line). The peephole makes the
  // comparison, the branch and both ends one instruction (JxxGKEOL, JZGEOL: ending_line_form in
  // bytecode/peephole.cpp); an EOL before the branch would keep the comparison apart from it.
  void branch_ending_line(bytecode::Op branch, L target) {
    b_.emit_to(branch, target);
    eol();
  }
  void branch_ending_line(int condition, bytecode::Op jump, L target) {
    branch(condition, jump, target);
    eol();
  }
  // The taken branch's end of the condition's line: bound before the EOL, which starts no
  // source line, so the fused branch jumps past it.
  void taken_path_ends_line(L target) {
    b_.bind(target);
    eol();
  }

  // The THEN arm always jumps over the ELSE side's EOL: its condition's line has ended already.
  void if_statement(const Stmt& s) {
    const L other = b_.new_label(), end = b_.new_label();
    line(s.offset);
    branch_ending_line(s.expr, bytecode::Op::JZ, other);
    body(s.body);
    b_.emit_to(bytecode::Op::JMP, end);
    taken_path_ends_line(other);
    body(s.else_body);
    b_.bind(end);
  }

  void while_loop(const Stmt& s) {
    const L top = b_.new_label(), done = b_.new_label();
    b_.bind(top);
    line(s.offset);
    branch_ending_line(s.expr, bytecode::Op::JZ, done);
    body(s.body);
    b_.emit_to(bytecode::Op::JMP, top);
    taken_path_ends_line(done);
  }

  // The UNTIL line goes back to the body by a JMP after its end: a branch back that ended the
  // line would need an EOL before the body, and the loop would be entered by a jump over it, a
  // place between lines that is no line start (where a held thread would be shown at the line
  // before the loop).
  void repeat_loop(const Stmt& s) {
    const L top = b_.new_label(), done = b_.new_label();
    b_.bind(top);
    body(s.body);
    line(s.offset);
    image_.lines.back().line = static_cast<uint32_t>(s.cond_line);
    branch_ending_line(s.expr, bytecode::Op::JNZ, done);
    b_.emit_to(bytecode::Op::JMP, top);
    taken_path_ends_line(done);
  }

  // The loop is inverted: the test runs once on the FOR line before the body (a loop whose
  // bound is passed already runs no pass, its line ending before the jump past the loop) and
  // again at the bottom after the step, with no place between them that control arrives at,
  // so that a pass counting up pays one fused step-and-test, INCGJLEGL (docs/architecture.md,
  // "Fusion at load"). The FOR line ends once on every path: the top test goes into the body
  // through the EOL at `again`, or (no pass) past the loop by a jump that ends the line; the
  // bottom one ends it on both paths itself (the peephole's JNZ.eol, which jumps past that
  // EOL). The bound, literal or not, goes once into the loop's hidden local, so that every FOR
  // has the one shape.
  void for_loop(const Stmt& s) {
    const uint32_t bound = kFirstForLocal + static_cast<uint32_t>(s.scratch);
    const L again = b_.new_label(), done = b_.new_label();
    line(s.offset);
    expression(s.expr);
    store(s.target);
    expression(s.expr2);
    b_.emit(bytecode::Op::STL, bound);
    for_test(s, bound);
    branch_ending_line(bytecode::Op::JNZ, again);
    b_.emit_to(bytecode::Op::JMP, done);
    taken_path_ends_line(again);
    body(s.body);
    b_.emit(bytecode::Op::LDG, s.target);
    push(s.step);
    b_.emit(bytecode::Op::ADDI);
    store(s.target);
    for_test(s, bound);
    branch_ending_line(bytecode::Op::JNZ, again);
    b_.bind(done);
  }
  // Whether a FOR loop's variable is still within its bound (1 on the stack when it is).
  void for_test(const Stmt& s, uint32_t bound) {
    b_.emit(bytecode::Op::LDG, s.target);
    b_.emit(bytecode::Op::LDL, bound);
    b_.emit(bytecode::Op::CMPI, s.step > 0 ? bytecode::kRelLe : bytecode::kRelGe);
  }

  void ldg(const Arg& a) { b_.emit(bytecode::Op::LDG, a.global); }
  void high_word(uint32_t global) {
    push(1);
    b_.emit(bytecode::Op::LDGX, global);
  }
  // The 64-bit pair on the stack (high on top) into DLONG `global`.
  void store_pair(uint32_t global) {
    scratch(bytecode::Op::STL, kScratchA);
    b_.emit(bytecode::Op::STG, global);
    push(1);
    scratch(bytecode::Op::LDL, kScratchA);
    b_.emit(bytecode::Op::STGX, global);
  }

  void builtin(const Stmt& s) {
    const std::vector<Arg>& a = s.args;
    switch (s.builtin) {
      case Builtin::Clrdlong:
        push(0);
        push(0);
        store_pair(a[0].global);
        return;
      case Builtin::Setdlong:
        ldg(a[1]);
        high_word(a[1].global);
        store_pair(a[0].global);
        return;
      case Builtin::Adddlong:
      case Builtin::Subdlong:
        ldg(a[1]);
        high_word(a[1].global);
        ldg(a[2]);
        b_.emit(bytecode::Op::I2W);
        b_.emit(s.builtin == Builtin::Adddlong ? bytecode::Op::ADDW : bytecode::Op::SUBW);
        store_pair(a[0].global);
        return;
      case Builtin::Muldiv:
        ldg(a[0]);
        ldg(a[1]);
        ldg(a[2]);
        b_.emit(bytecode::Op::MULDIV);
        store(a[3].global);
        return;
      case Builtin::Limitw:
        return limitw(a[0].global, a[1].global, a[2].global);
      case Builtin::Xread:
        b_.emit(bytecode::Op::CMDGET, ascii_id(*find_ascii(a[0].text)), 0);
        store(a[1].global);
        return;
      case Builtin::Xwrite:
        ldg(a[1]);
        b_.emit(bytecode::Op::CMDSET, ascii_id(*find_ascii(a[0].text)), 0);
        return;
      case Builtin::Command:
        push(static_cast<int32_t>(text(a[0].text)));
        b_.emit(bytecode::Op::CMDRUN, kCommandAction, 1);
        return;
      case Builtin::Printf:
        for (size_t k = 1; k < a.size(); ++k) ldg(a[k]);
        b_.emit(bytecode::Op::MSG, text(a[0].text), static_cast<uint32_t>(a.size() - 1));
        return;
    }
  }

  // OUT := IN clamped to -MAX … MAX, inline.
  void limitw(uint32_t out, uint32_t in, uint32_t max) {
    const L below = b_.new_label(), done = b_.new_label();
    b_.emit(bytecode::Op::LDG, in);
    scratch(bytecode::Op::STL, kScratchA);
    scratch(bytecode::Op::LDL, kScratchA);
    b_.emit(bytecode::Op::LDG, max);
    b_.emit(bytecode::Op::CMPI, bytecode::kRelGt);
    b_.emit_to(bytecode::Op::JZ, below);
    b_.emit(bytecode::Op::LDG, max);
    scratch(bytecode::Op::STL, kScratchA);
    b_.bind(below);
    push(0);
    b_.emit(bytecode::Op::LDG, max);
    b_.emit(bytecode::Op::SUBI);
    scratch(bytecode::Op::STL, kScratchB);
    scratch(bytecode::Op::LDL, kScratchA);
    scratch(bytecode::Op::LDL, kScratchB);
    b_.emit(bytecode::Op::CMPI, bytecode::kRelLt);
    b_.emit_to(bytecode::Op::JZ, done);
    scratch(bytecode::Op::LDL, kScratchB);
    scratch(bytecode::Op::STL, kScratchA);
    b_.bind(done);
    scratch(bytecode::Op::LDL, kScratchA);
    store(out);
  }

  const Program& p_;
  const preproc::SourceLocator& locator_;
  bytecode::Image image_;
  CodeBuilder b_;
  std::map<std::string, uint32_t> routine_index_;
  std::map<std::string, L> labels_;
  bool uses_scratch_ = false;  // the routine being generated loads or stores a scratch local
};

}  // namespace

bytecode::Image generate(const Program& program, const preproc::SourceLocator& locator,
                         const std::string& source_name) {
  return Generator(program, locator).run(source_name);
}

}  // namespace uprog::st
