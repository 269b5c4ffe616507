// The Gold syntax tree. The parser builds it; the checker fills in what each name means and
// each expression's type; the code generator reads it. Offsets point into the lexer's text.
#pragma once
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "dialects/gold/token.h"
#include "support/value.h"

namespace uprog::gold {

struct CommandInfo;

// The static kind of a value. Dynamic is Gold's int product, known to be an int or a float only
// at run time (manual 1.5): it travels as a [value, tag] pair.
enum class Kind : uint8_t { Int, Float, Dynamic, None };

enum class VarType : uint8_t { Int, Float };

inline Kind kind_of(VarType t) { return t == VarType::Int ? Kind::Int : Kind::Float; }
inline Kind kind_of(ValueType t) { return t == ValueType::Int ? Kind::Int : Kind::Float; }

struct Expr;
// Nodes belong to an AstArena (below); these pointers never own.
using ExprPtr = Expr*;

// What a name turned out to be, filled in by the checker.
enum class RefKind : uint8_t { Unresolved, Local, Global, Function, Builtin, Command, Nargout };

enum class Builtin : uint8_t {
  Sin,
  Cos,
  Abs,
  Sqrt,
  Fix,
  Rnd,
  Sign,
  Real,
  Tdif,
  Prgerr,
  Tick,
  Tock,
  Utick,
  Utock
};

enum class ExprKind : uint8_t { IntLit, FloatLit, Ref, Unary, Binary, Nargout };

struct Expr {
  ExprKind kind;
  uint32_t offset = 0;
  Tok op = Tok::Eof;  // Unary / Binary
  int32_t int_value = 0;
  float float_value = 0.0f;
  ExprPtr lhs = nullptr, rhs = nullptr;  // Unary uses lhs
  // Ref: a name, maybe with [index] or (arguments). Names view into the lexer's text.
  std::string_view name;
  bool has_index = false;     // name[...]
  bool has_parens = false;    // name(...)
  std::vector<ExprPtr> args;  // the index (one) or the call's arguments
  // Filled by the checker.
  Kind type = Kind::None;
  RefKind ref = RefKind::Unresolved;
  int32_t slot = -1;  // local or global index, function index, builtin
  const CommandInfo* command = nullptr;
  Builtin builtin = Builtin::Sin;
};

struct Stmt;
using StmtPtr = Stmt*;
using Block = std::vector<StmtPtr>;

enum class StmtKind : uint8_t {
  Expr,    // a call, a drive action (BG), or a value (shown on the command line)
  Assign,  // targets = value; several targets for [a,b] = f(x)
  IncDec,  // i++ / i--
  If,
  While,
  For,
  Until,
  Wait,
  Switch,
  Try,
  Break,
  Continue,
  Return,
  Exit,
  Goto,
  Reset,
  Label,
};

struct IfArm {
  ExprPtr cond = nullptr;  // null for else
  Block body;
};

struct SwitchCase {
  ExprPtr value = nullptr;  // null for otherwise
  Block body;
  uint32_t offset = 0;
};

struct Stmt {
  StmtKind kind;
  uint32_t offset = 0;
  bool ends_line = false;        // the last statement on its source line: an EOL follows it
  ExprPtr value = nullptr;       // Expr, Assign, While, Until, Wait, Switch (subject), For (start)
  std::vector<ExprPtr> targets;  // Assign, IncDec, For (the iteration variable)
  ExprPtr step = nullptr, end = nullptr;  // For
  int delta = 0;                          // IncDec
  std::vector<IfArm> arms;                // If
  std::vector<SwitchCase> cases;          // Switch
  Block body, handler;                    // While/For body; Try body and catch
  std::string_view name;                  // Goto/Reset/Label target
  bool auto_label = false;                // #@ rather than ##
  bool bracketed = false;                 // Assign: [a, b] = ...
  uint32_t end_offset = 0;                // the line of the block's `end`
};

struct VarDecl {
  std::string_view name;
  VarType type = VarType::Int;
  int32_t length = 0;  // 0 for a scalar, else the array's dimension
  uint32_t offset = 0;
  bool is_global_redecl = false;  // `global int x` inside a function
};

struct Param {
  std::string_view name;
  VarType type = VarType::Int;
  uint32_t offset = 0;
};

struct FunctionDef {
  std::string_view name;
  uint32_t offset = 0;
  std::vector<Param> inputs, outputs;
  bool has_body = false;
  bool is_auto = false;         // named like an auto-routine (function AUTOEXEC())
  std::vector<VarDecl> locals;  // declared locals and global re-declarations, in order
  Block body;                   // empty when the parser handed the body to a FunctionBodySink
  LexState body_start;          // where the body begins, to parse it again
  uint32_t end_offset = 0;      // the closing return
};

// Takes each function body from the parser as soon as it is parsed, so that a program's tree
// never holds more than one body. `f` is null when the header was refused (the body was parsed
// for its errors only). The body's nodes live in `scratch()`, which the sink may reset.
class AstArena;
struct Program;
class FunctionBodySink {
 public:
  virtual ~FunctionBodySink() = default;
  virtual AstArena& scratch() = 0;
  // `program` holds what is parsed so far, `f` last among its functions.
  virtual void body(Program& program, FunctionDef* f, Block& body) = 0;
};

// Top-level code: labels, auto-routines and their statements, in source order. A Label
// statement opens a routine; a top-level Return closes it.
struct Program {
  std::vector<VarDecl> globals;
  std::deque<FunctionDef>
      functions;  // definitions and prototypes, in source order (stable addresses)
  Block top;
  bool empty = true;  // nothing but blanks and comments
};

}  // namespace uprog::gold

namespace uprog::gold {

// A node made again from a recycled one: its list emptied but its storage kept, so that a
// function's nodes reuse the allocations of the function before (uprog check of 100 000 lines:
// 255 530 allocations and as many frees -> 188 886; 537 M -> 524 M host instructions).
template <auto list, typename Node>
void reset_keeping_storage(Node& node) {
  auto kept = std::move(node.*list);
  kept.clear();
  node = Node{};
  node.*list = std::move(kept);
}
inline void recycle(Expr& e) { reset_keeping_storage<&Expr::args>(e); }
// (A statement's blocks are made apart and moved in: only its targets are worth keeping.)
inline void recycle(Stmt& s) { reset_keeping_storage<&Stmt::targets>(s); }

// Makes nodes in blocks and frees them all at once: a parse costs a few large allocations
// instead of one per node, and no recursive teardown. The arena must outlive its nodes' users.
// reset() recycles the blocks, so one function body after another reuses the same memory.
template <class T>
class NodePool {
 public:
  T* make() {
    if (used_ == kBlock) {
      if (++current_ == blocks_.size()) blocks_.push_back(std::make_unique<T[]>(kBlock));
      used_ = 0;
    }
    T* t = &blocks_[current_][used_++];
    if (recycled_) recycle(*t);
    return t;
  }
  void reset() {
    current_ = static_cast<size_t>(-1);
    used_ = kBlock;
    recycled_ = true;
  }

 private:
  static constexpr size_t kBlock = 256;
  std::vector<std::unique_ptr<T[]>> blocks_;
  size_t current_ = static_cast<size_t>(-1);
  size_t used_ = kBlock;
  bool recycled_ = false;
};

class AstArena {
 public:
  Expr* expr(ExprKind k, uint32_t offset) {
    Expr* e = exprs_.make();
    e->kind = k;
    e->offset = offset;
    return e;
  }
  Stmt* stmt(StmtKind k, uint32_t offset) {
    Stmt* s = stmts_.make();
    s->kind = k;
    s->offset = offset;
    return s;
  }
  // Every node made so far is dead; their memory serves the next ones.
  void reset() {
    exprs_.reset();
    stmts_.reset();
  }

 private:
  NodePool<Expr> exprs_;
  NodePool<Stmt> stmts_;
};

}  // namespace uprog::gold
