// The parsed ST program: globals (resolved while parsing, in source order), the programs and
// functions with their statements, in arenas addressed by index.
#pragma once
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace uprog::st {

enum class VarType : uint8_t { Byte, Word, Long, Dlong };

struct GlobalVar {
  std::string name;
  VarType type = VarType::Long;
  bool predefined = false;  // DPRVARn, DPVn: the drive's saved parameters
};

enum class Op : uint8_t {
  Neg,
  Not,
  Bnot,  // unary
  Mul,
  Div,
  Mod,
  Add,
  Sub,
  Shr,
  Shl,
  Gt,
  Ge,
  Lt,
  Le,
  Eq,
  Ne,
  BAnd,
  BXor,
  BOr,
  Xor,
  And,
  Or,
};

struct Expr {
  enum class Kind : uint8_t { Const, Var, Unary, Binary } kind = Kind::Const;
  Op op = Op::Add;
  int32_t value = 0;    // Const
  uint32_t global = 0;  // Var
  int a = -1, b = -1;   // operands (Unary: a)
  size_t offset = 0;
};

// An argument of a built-in: a variable, a constant or a string, as written.
struct Arg {
  enum class Kind : uint8_t { Var, Const, String, Other } kind = Kind::Other;
  uint32_t global = 0;
  int32_t value = 0;
  std::string text;
  size_t offset = 0;
};

enum class Builtin : uint8_t {
  Clrdlong,
  Setdlong,
  Adddlong,
  Subdlong,
  Muldiv,
  Limitw,
  Xread,
  Xwrite,
  Command,
  Printf
};

struct Stmt {
  enum class Kind : uint8_t {
    Assign,
    If,
    While,
    Repeat,
    For,
    Goto,
    Label,
    Return,
    Call,
    Builtin
  } kind = Kind::Assign;
  size_t offset = 0;
  int line = 0;               // the line of the statement (for If/While/For: of its condition)
  int cond_line = 0;          // Repeat: the UNTIL line
  uint32_t target = 0;        // Assign, For: the variable
  int expr = -1, expr2 = -1;  // Assign: value; If/While/Repeat: condition; For: from, to
  int32_t step = 1;           // For
  std::vector<int> body, else_body;
  std::string name;  // Goto/Label: the label; Call: the function
  st::Builtin builtin = st::Builtin::Clrdlong;
  std::vector<Arg> args;
  int scratch = -1;  // For: the local that keeps the bound
};

enum class ProgramKind : uint8_t { Init, Main, Plc62, Plc250, Plc1, Plc4, Plc16, Function };

struct Routine {
  std::string name;
  ProgramKind kind = ProgramKind::Function;
  size_t offset = 0;
  int line = 0;
  std::vector<int> body;
  std::set<int> code_lines;  // source lines holding code (a statement or a condition)
  int for_count = 0;         // FOR statements: each keeps its bound in a local
  // What the placement rules look at, the first of each (offset), -1 for none.
  long loop_at = -1, access_at = -1, printf_at = -1;
  std::vector<std::pair<std::string, size_t>> calls;  // FUNCTION (NAME): name, offset
};

struct Program {
  std::vector<GlobalVar> globals;
  std::vector<Expr> exprs;
  std::vector<Stmt> stmts;
  std::vector<Routine> routines;  // programs and functions in source order
};

}  // namespace uprog::st
