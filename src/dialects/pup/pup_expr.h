// PUP expressions: parsed with the manual's precedence into a small tree, folded where constant
// (with the controller's integer rules), and emitted as CUP stack lines, each operator after
// its operands. Names are user variables (#definevar) or controller parameters.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dialects/pup/pup_lexer.h"

namespace uprog::pup {

struct Var {
  int32_t base = 1;  // AGenData[base]
  int32_t size = 1;
  bool array = false;
  Location defined_at;
};
using VarTable = std::map<std::string, Var>;

enum class NodeKind { Number, Param, Indexed, Unary, Binary, Call };

struct Node {
  NodeKind kind = NodeKind::Number;
  int32_t value = 0;  // Number: the value; Param: the index
  std::string
      key;  // Param, Indexed: the keyword's spelling ("AGenData"); Unary/Binary/Call: the operator
  bool has_index = false;
  int32_t base = 0, size = 0;  // Indexed: key[base + i - 1] for i in 1..size
  int a = -1, b = -1;          // operands (Indexed: a is the index)
  std::vector<int> args;       // Call
  Location where;
};

struct ExprTree {
  std::vector<Node> nodes;
  int add(Node n) {
    nodes.push_back(std::move(n));
    return static_cast<int>(nodes.size()) - 1;
  }
};

class TokenCursor {
 public:
  TokenCursor(const std::vector<Token>& tokens, Location end)
      : tokens_(tokens), end_(std::move(end)) {}
  bool at_end() const { return pos_ >= tokens_.size(); }
  const Token* peek(size_t ahead = 0) const {
    return pos_ + ahead < tokens_.size() ? &tokens_[pos_ + ahead] : nullptr;
  }
  bool is(const char* text, size_t ahead = 0) const {
    const Token* t = peek(ahead);
    return t != nullptr && t->text == text && t->kind != TokenKind::Number;
  }
  const Token& take() { return tokens_[pos_++]; }
  bool take_if(const char* text) {
    if (!is(text)) return false;
    ++pos_;
    return true;
  }
  Location where() const { return at_end() ? end_ : tokens_[pos_].where; }

 private:
  const std::vector<Token>& tokens_;
  Location end_;
  size_t pos_ = 0;
};

struct ExprContext {
  const VarTable& vars;
  std::vector<Diagnostic>& diagnostics;
};

// An expression from the cursor, up to a token no expression continues with; -1 after a
// diagnostic. Constant parts are folded.
int parse_expression(TokenCursor& cur, ExprContext& cx, ExprTree& tree);
// A place: a parameter, a variable or an array element (the left side of `=`, a name argument).
int parse_place(TokenCursor& cur, ExprContext& cx, ExprTree& tree);

std::optional<int32_t> constant_of(const ExprTree& tree, int node);
bool is_comparison(const Node& n);
// The Jump/Compare condition number of a comparison operator (3 EQ .. 8 LE), and its opposite.
int condition_of(const std::string& op);
int opposite_condition(int condition);

// "AGenData[200]", "ASpeed": a Param node as the CUP writes it.
std::string param_text(const Node& n);

// CUP lines whose jumps aim at labels of their own (0, 1, ...). Placing the code gives its labels
// line numbers (PupCompiler::place_code), fresh ones each time: the same code can be placed twice.
struct CodeLine {
  std::string text;  // a CUP line; empty where a label stands
  int target = -1;   // a jump: the label whose line number ends the line
  int label = -1;    // text empty: the label standing at the next line
};
struct Code {
  std::vector<CodeLine> lines;
  int labels = 0;
  void line(std::string text, int target = -1) { lines.push_back({std::move(text), target, -1}); }
  int new_label() { return labels++; }
  void bind(int label) { lines.push_back({{}, -1, label}); }
};

// Lines that leave the value of `node` on the stack.
void emit_value(const ExprTree& tree, int node, Code& out);
// Lines that jump to `label` when `node` is nonzero (`when_true`) or zero, else go on with the
// stack as before: a comparison jumps on its condition, and && and || skip their right side when
// the left decides (the manual's "similar implementation to C").
void emit_jump(const ExprTree& tree, int node, bool when_true, int label, Code& out);
// The value of `node` now, as the controller's CUP lines would compute it, with `read` giving a
// parameter's value (its spelling, its index or 0; a controller error in `*error`): for the
// debugger's watches and conditions. 0 with `*error` set (4, 30, 31, or what `read` set).
using ParamReader = std::function<int32_t(const std::string& key, int32_t index, int32_t* error)>;
int32_t evaluate_now(const ExprTree& tree, int node, const ParamReader& read, int32_t* error);
// The stack entries evaluating `node` needs at most.
int stack_need(const ExprTree& tree, int node);

}  // namespace uprog::pup
