// Parsing, folding and emitting PUP expressions (pup_expr.h).
#include "dialects/pup/pup_expr.h"

#include <fmt/core.h>

#include <cstdint>

#include "dialects/pup/cup_math.h"
#include "dialects/pup/errors.h"
#include "dialects/pup/keywords.h"
#include "dialects/pup/message.h"

namespace uprog::pup {
namespace {

struct BinaryOp {
  const char* text;
  int level;  // binding strength: higher binds tighter
  int math;   // AMath[n], or 0 for a comparison
};

// The manual's precedence, lowest first: || && | ^ & (== !=) (< > <= >=) (<< >>) (+ -) (* / %).
constexpr BinaryOp kBinaryOps[] = {
    {"||", 1, 21}, {"&&", 2, 20}, {"|", 3, 11}, {"^", 4, 12}, {"&", 5, 10}, {"==", 6, 0},
    {"!=", 6, 0},  {"<", 7, 0},   {">", 7, 0},  {"<=", 7, 0}, {">=", 7, 0}, {"<<", 8, 14},
    {">>", 8, 15}, {"+", 9, 1},   {"-", 9, 3},  {"*", 10, 2}, {"/", 10, 4}, {"%", 10, 5},
};

struct MathFunction {
  const char* name;
  int math;
  size_t args;
};

constexpr MathFunction kFunctions[] = {
    {"log", 40, 1},  {"log10", 41, 1}, {"exp", 42, 1},  {"sin", 30, 1},  {"cos", 31, 1},
    {"tan", 32, 1},  {"asin", 33, 1},  {"acos", 34, 1}, {"atan", 35, 1}, {"atan2", 36, 2},
    {"power", 9, 2}, {"abs", 7, 1},    {"sqrt", 8, 1},
};

const BinaryOp* binary_op(const Token* t) {
  if (t == nullptr || t->kind != TokenKind::Op) return nullptr;
  for (const BinaryOp& op : kBinaryOps) {
    if (t->text == op.text) return &op;
  }
  return nullptr;
}

const MathFunction* function_named(const std::string& name) {
  for (const MathFunction& f : kFunctions) {
    if (name == f.name) return &f;
  }
  return nullptr;
}

int math_of_binary(const std::string& op) {
  for (const BinaryOp& b : kBinaryOps) {
    if (op == b.text) return b.math;
  }
  return 0;
}

// Parameters have a value, and AGetStatus[s] (the manual's "read-only parameter keyword"); a
// command, a CUP keyword or a marker has none.
bool has_value(const Keyword& k) {
  return k.kind == KeywordKind::Param || k.kind == KeywordKind::ReadOnly ||
         k.id == KeywordId::GetStatus;
}

bool is_logical(const Node& n) {
  return n.kind == NodeKind::Binary && (n.key == "&&" || n.key == "||");
}

int math_of_unary(const std::string& op) { return op == "-" ? 6 : op == "~" ? 13 : 22; }

class Parser {
 public:
  Parser(TokenCursor& cur, ExprContext& cx, ExprTree& tree) : cur_(cur), cx_(cx), tree_(tree) {}

  int expression(int min_level = 1) {
    if (++depth_ > kMaxDepth) return error(Error::ExpressionTooDeep, "nested too deeply");
    struct Leave {
      int& d;
      ~Leave() { --d; }
    } leave{depth_};
    int left = unary();
    while (left >= 0) {
      const BinaryOp* op = binary_op(cur_.peek());
      if (op == nullptr || op->level < min_level) break;
      Node n;
      n.kind = NodeKind::Binary;
      n.key = op->text;
      n.where = cur_.take().where;
      const int right = expression(op->level + 1);
      if (right < 0) return -1;
      n.a = left;
      n.b = right;
      left = fold(tree_.add(std::move(n)));
    }
    return left;
  }

  int place() {
    if (cur_.at_end() || cur_.peek()->kind != TokenKind::Name)
      return error(Error::Syntax, "a name is expected");
    const Token& name = cur_.take();
    return name_ref(name);
  }

 private:
  int error(Error e, const std::string& detail, std::optional<Location> at = std::nullopt) {
    cx_.diagnostics.push_back(make_error(e, at ? *at : cur_.where(), detail));
    return -1;
  }

  int unary() {
    // `-2147483648`: the literal is the int32 minimum, whose digits alone do not fit.
    if (cur_.is("-") && cur_.peek(1) != nullptr && cur_.peek(1)->kind == TokenKind::Number) {
      if (const auto v = parse_number("-" + cur_.peek(1)->text); v && *v == INT32_MIN) {
        Node n;
        n.value = *v;
        n.where = cur_.take().where;
        cur_.take();
        return tree_.add(std::move(n));
      }
    }
    if (cur_.is("-") || cur_.is("~") || cur_.is("!")) {
      if (++depth_ > kMaxDepth) return error(Error::ExpressionTooDeep, "nested too deeply");
      Node n;
      n.kind = NodeKind::Unary;
      n.where = cur_.peek()->where;
      n.key = cur_.take().text;
      n.a = unary();
      --depth_;
      if (n.a < 0) return -1;
      return fold(tree_.add(std::move(n)));
    }
    return primary();
  }

  int primary() {
    if (cur_.at_end()) return error(Error::Syntax, "a value is expected");
    const Token& t = cur_.take();
    if (t.kind == TokenKind::Number) {
      const auto v = parse_number(t.text, true);
      if (!v) return error(Error::BadNumber, "'" + t.text + "'", t.where);
      Node n;
      n.value = *v;
      n.where = t.where;
      return tree_.add(std::move(n));
    }
    if (t.text == "(") {
      const int inner = expression();
      if (inner < 0) return -1;
      if (!cur_.take_if(")")) return error(Error::Syntax, "')' is expected");
      return inner;
    }
    if (t.kind != TokenKind::Name)
      return error(Error::Syntax, "a value is expected, not '" + t.text + "'", t.where);
    if (const MathFunction* f = function_named(t.text); f != nullptr && cur_.is("("))
      return call(t, *f);
    return name_ref(t);
  }

  int call(const Token& name, const MathFunction& f) {
    cur_.take();  // (
    Node n;
    n.kind = NodeKind::Call;
    n.key = name.text;
    n.value = f.math;
    n.where = name.where;
    if (!cur_.is(")")) {
      do {
        const int arg = expression();
        if (arg < 0) return -1;
        n.args.push_back(arg);
      } while (cur_.take_if(","));
    }
    if (!cur_.take_if(")")) return error(Error::Syntax, "')' is expected");
    if (n.args.size() != f.args) {
      return error(Error::BadArgumentCount, fmt::format("{} takes {}", name.text, f.args),
                   name.where);
    }
    return fold(tree_.add(std::move(n)));
  }

  // `[expr]` after a name, or -2 when there is none.
  int index_expression() {
    if (!cur_.take_if("[")) return -2;
    const int index = expression();
    if (index < 0) return -1;
    if (!cur_.take_if("]")) return error(Error::Syntax, "']' is expected");
    return index;
  }

  int name_ref(const Token& t) {
    Node n;
    n.where = t.where;
    if (auto v = cx_.vars.find(t.text); v != cx_.vars.end()) {
      const Var& var = v->second;
      n.key = "AGenData";
      if (!var.array) {
        n.kind = NodeKind::Param;
        n.has_index = true;
        n.value = var.base;
        return tree_.add(std::move(n));
      }
      const int index = index_expression();
      if (index == -1) return -1;
      if (index == -2) return error(Error::IndexMissing, "'" + t.text + "' is an array", t.where);
      return indexed(std::move(n), index, var.base, var.size, t.text);
    }
    const Keyword* k = find_keyword(t.text);
    if (k == nullptr) {
      return error(
          t.text.size() > 1 && t.text[0] == 'A' ? Error::UnknownKeyword : Error::UnknownName,
          "'" + t.text + "'", t.where);
    }
    n.key = std::string(k->name);
    if (!has_value(*k)) return error(Error::NotAValue, "'" + n.key + "'", t.where);
    const int index = index_expression();
    if (index == -1) return -1;
    if (index == -2) {
      if (k->indexed()) return error(Error::IndexMissing, "'" + n.key + "'", t.where);
      n.kind = NodeKind::Param;
      return tree_.add(std::move(n));
    }
    if (!k->indexed()) return error(Error::IndexNotAllowed, "'" + n.key + "'", t.where);
    if (k->id == KeywordId::GetStatus && !constant_of(tree_, index)) {
      return error(Error::NotConstant, "a status number",
                   tree_.nodes[static_cast<size_t>(index)].where);
    }
    const std::string key = n.key;
    return indexed(std::move(n), index, k->index_min, k->index_max - k->index_min + 1, key);
  }

  // key[base + i - 1], i in 1..size: a fixed parameter when i is a constant.
  int indexed(Node n, int index, int32_t base, int32_t size, const std::string& what) {
    if (auto i = constant_of(tree_, index)) {
      if (*i < 1 || *i > size) {
        return error(Error::IndexOutOfRange, fmt::format("'{}[{}]'", what, *i),
                     tree_.nodes[static_cast<size_t>(index)].where);
      }
      n.kind = NodeKind::Param;
      n.has_index = true;
      n.value = base + *i - 1;
      return tree_.add(std::move(n));
    }
    n.kind = NodeKind::Indexed;
    n.base = base;
    n.size = size;
    n.a = index;
    return tree_.add(std::move(n));
  }

  // Replaces a node whose operands are constants by its value.
  int fold(int node) {
    Node& n = tree_.nodes[static_cast<size_t>(node)];
    int32_t value = 0, err = 0;
    if (n.kind == NodeKind::Unary) {
      const auto a = constant_of(tree_, n.a);
      if (!a) return node;
      value = apply_math(math_of_unary(n.key), 0, *a, &err);
    } else if (n.kind == NodeKind::Binary) {
      const auto a = constant_of(tree_, n.a), b = constant_of(tree_, n.b);
      if (a && is_logical(n) && (*a != 0) == (n.key == "||")) {
        value = *a != 0 ? 1 : 0;  // the left side decides: the right is never computed
      } else if (!a || !b) {
        return node;
      } else if (is_comparison(n)) {
        value = condition_holds(condition_of(n.key), *a, *b) ? 1 : 0;
      } else {
        value = apply_math(math_of_binary(n.key), *a, *b, &err);
      }
      if (err == 30) return error(Error::DivisionByZero, "", n.where);
    } else {
      return node;  // math functions are the controller's to compute
    }
    n = Node{NodeKind::Number, value, {}, false, 0, 0, -1, -1, {}, n.where};
    return node;
  }

  static constexpr int kMaxDepth = 200;  // keeps the parser's recursion finite on hostile lines
  TokenCursor& cur_;
  ExprContext& cx_;
  ExprTree& tree_;
  int depth_ = 0;
};

// `a && b`, `a || b` as a value: the jumps of emit_jump, then 1 or 0.
void emit_logical_value(const ExprTree& tree, int node, Code& out) {
  const bool is_or = tree.nodes[static_cast<size_t>(node)].key == "||";
  const int decided = out.new_label(), end = out.new_label();
  emit_jump(tree, node, is_or, decided, out);
  out.line(fmt::format("APushConstant,{}", is_or ? 0 : 1));
  out.line("AJump[1],", end);
  out.bind(decided);
  out.line(fmt::format("APushConstant,{}", is_or ? 1 : 0));
  out.bind(end);
}

}  // namespace

void emit_value(const ExprTree& tree, int node, Code& out) {
  const Node& n = tree.nodes[static_cast<size_t>(node)];
  switch (n.kind) {
    case NodeKind::Number:
      out.line(fmt::format("APushConstant,{}", n.value));
      return;
    case NodeKind::Param:
      if (const Keyword* k = find_keyword(n.key); k != nullptr && k->id == KeywordId::GetStatus) {
        out.line(fmt::format("{},0", param_text(n)));  // a status as a value: v = 0
        return;
      }
      out.line("APushParam," + param_text(n));
      return;
    case NodeKind::Indexed:
      emit_value(tree, n.a, out);
      out.line(fmt::format("APushParamIdx[{}],{}[{}]", n.size, n.key, n.base));
      return;
    case NodeKind::Unary:
      emit_value(tree, n.a, out);
      out.line(fmt::format("AMath[{}]", math_of_unary(n.key)));
      return;
    case NodeKind::Binary:
      if (is_logical(n)) return emit_logical_value(tree, node, out);
      emit_value(tree, n.a, out);
      emit_value(tree, n.b, out);
      if (is_comparison(n))
        out.line(fmt::format("ACompare[{}]", condition_of(n.key)));
      else
        out.line(fmt::format("AMath[{}]", math_of_binary(n.key)));
      return;
    case NodeKind::Call:
      for (int a : n.args) emit_value(tree, a, out);
      out.line(fmt::format("AMath[{}]", n.value));
      return;
  }
}

void emit_jump(const ExprTree& tree, int node, bool when_true, int label, Code& out) {
  const Node& n = tree.nodes[static_cast<size_t>(node)];
  if (const auto v = constant_of(tree, node)) {
    if ((*v != 0) == when_true) out.line("AJump[1],", label);
    return;
  }
  if (is_comparison(n)) {
    emit_value(tree, n.a, out);
    emit_value(tree, n.b, out);
    const int c = condition_of(n.key);
    out.line(fmt::format("AJump[{}],", when_true ? c : opposite_condition(c)), label);
    return;
  }
  if (is_logical(n)) {
    // The left side jumps out when it decides the outcome; the right decides otherwise.
    const bool decides_when = n.key == "||";
    if (decides_when == when_true) {
      emit_jump(tree, n.a, when_true, label, out);
    } else {
      const int right_not_needed = out.new_label();
      emit_jump(tree, n.a, decides_when, right_not_needed, out);
      emit_jump(tree, n.b, when_true, label, out);
      out.bind(right_not_needed);
      return;
    }
    emit_jump(tree, n.b, when_true, label, out);
    return;
  }
  emit_value(tree, node, out);
  out.line(when_true ? "AJump[10]," : "AJump[9],", label);
}

int parse_expression(TokenCursor& cur, ExprContext& cx, ExprTree& tree) {
  return Parser(cur, cx, tree).expression();
}
int parse_place(TokenCursor& cur, ExprContext& cx, ExprTree& tree) {
  return Parser(cur, cx, tree).place();
}

std::optional<int32_t> constant_of(const ExprTree& tree, int node) {
  if (node < 0) return std::nullopt;
  const Node& n = tree.nodes[static_cast<size_t>(node)];
  if (n.kind != NodeKind::Number) return std::nullopt;
  return n.value;
}

bool is_comparison(const Node& n) { return n.kind == NodeKind::Binary && condition_of(n.key) != 0; }

int condition_of(const std::string& op) {
  if (op == "==") return 3;
  if (op == "!=") return 4;
  if (op == ">") return 5;
  if (op == ">=") return 6;
  if (op == "<") return 7;
  if (op == "<=") return 8;
  return 0;
}

int opposite_condition(int c) {
  switch (c) {
    case 3:
      return 4;
    case 4:
      return 3;
    case 5:
      return 8;
    case 6:
      return 7;
    case 7:
      return 6;
    case 8:
      return 5;
    default:
      return 0;
  }
}

std::string param_text(const Node& n) {
  return n.has_index ? fmt::format("{}[{}]", n.key, n.value) : n.key;
}

int32_t evaluate_now(const ExprTree& tree, int node, const ParamReader& read, int32_t* error) {
  const Node& n = tree.nodes[static_cast<size_t>(node)];
  auto value = [&](int child) { return *error == 0 ? evaluate_now(tree, child, read, error) : 0; };
  switch (n.kind) {
    case NodeKind::Number:
      return n.value;
    case NodeKind::Param:
      return read(n.key, n.has_index ? n.value : 0, error);
    case NodeKind::Indexed: {
      const int32_t i = value(n.a);
      if (*error != 0) return 0;
      if (i < 1 || i > n.size) {
        *error = 4;
        return 0;
      }
      return read(n.key, n.base + i - 1, error);
    }
    case NodeKind::Unary: {
      const int32_t a = value(n.a);
      return *error != 0 ? 0 : apply_math(math_of_unary(n.key), 0, a, error);
    }
    case NodeKind::Binary: {
      const int32_t a = value(n.a);
      if (*error == 0 && is_logical(n) && (a != 0) == (n.key == "||")) return a != 0 ? 1 : 0;
      const int32_t b = value(n.b);
      if (*error != 0) return 0;
      if (is_comparison(n)) return condition_holds(condition_of(n.key), a, b) ? 1 : 0;
      return apply_math(math_of_binary(n.key), a, b, error);
    }
    case NodeKind::Call: {
      // As AMath[n] pops them: the last argument is the top (first), the one before it second.
      std::vector<int32_t> args;
      for (int a : n.args) args.push_back(value(a));
      if (*error != 0 || args.empty()) return 0;
      return apply_math(n.value, args.size() > 1 ? args[args.size() - 2] : 0, args.back(), error);
    }
  }
  return 0;
}

int stack_need(const ExprTree& tree, int node) {
  const Node& n = tree.nodes[static_cast<size_t>(node)];
  switch (n.kind) {
    case NodeKind::Number:
    case NodeKind::Param:
      return 1;
    case NodeKind::Indexed:
    case NodeKind::Unary:
      return stack_need(tree, n.a);
    case NodeKind::Binary:
      // && and || pop their left side before they compute the right.
      if (is_logical(n)) return std::max(stack_need(tree, n.a), stack_need(tree, n.b));
      return std::max(stack_need(tree, n.a), 1 + stack_need(tree, n.b));
    case NodeKind::Call: {
      int need = 0;
      for (size_t i = 0; i < n.args.size(); ++i)
        need = std::max(need, static_cast<int>(i) + stack_need(tree, n.args[i]));
      return need;
    }
  }
  return 1;
}

}  // namespace uprog::pup
