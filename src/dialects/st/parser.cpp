// The ST parser (parser.h). Precedence, lowest first: OR, AND, XOR, |, ^, &, = <>,
// > >= < <=, >> <<, + -, * / MOD, unary - NOT BNOT; all left-associative.
#include "dialects/st/parser.h"

#include <map>

#include "dialects/st/ascii_table.h"
#include "dialects/st/names.h"

namespace uprog::st {
namespace {

struct Level {
  Tok tok;
  const char* word;  // a keyword operator instead of a token
  Op op;
};

// Binary operators by level, lowest first.
const std::vector<std::vector<Level>> kLevels = {
    {{Tok::Ident, "OR", Op::Or}},
    {{Tok::Ident, "AND", Op::And}},
    {{Tok::Ident, "XOR", Op::Xor}},
    {{Tok::Bar, nullptr, Op::BOr}},
    {{Tok::Caret, nullptr, Op::BXor}},
    {{Tok::Amp, nullptr, Op::BAnd}},
    {{Tok::Eq, nullptr, Op::Eq}, {Tok::Ne, nullptr, Op::Ne}},
    {{Tok::Gt, nullptr, Op::Gt},
     {Tok::Ge, nullptr, Op::Ge},
     {Tok::Lt, nullptr, Op::Lt},
     {Tok::Le, nullptr, Op::Le}},
    {{Tok::Shr, nullptr, Op::Shr}, {Tok::Shl, nullptr, Op::Shl}},
    {{Tok::Plus, nullptr, Op::Add}, {Tok::Minus, nullptr, Op::Sub}},
    {{Tok::Star, nullptr, Op::Mul}, {Tok::Slash, nullptr, Op::Div}, {Tok::Ident, "MOD", Op::Mod}},
};

struct Failed {};  // unwinds one statement after a reported syntax error

class Parser {
 public:
  Parser(const std::vector<Token>& tokens, Reporter& reporter) : t_(tokens), reporter_(reporter) {
    for (int n = 1; n <= kUserVariables; ++n) declare_predefined(user_variable_name(n));
  }

  Program run() {
    while (peek().kind != Tok::End) top_level();
    return std::move(p_);
  }

 private:
  // --- tokens ---
  const Token& peek(size_t k = 0) const { return t_[std::min(i_ + k, t_.size() - 1)]; }
  const Token& next() {
    const Token& t = peek();
    if (i_ < t_.size() - 1) ++i_;
    return t;
  }
  std::string word(size_t k = 0) const {
    return peek(k).kind == Tok::Ident ? upper(peek(k).text) : std::string();
  }
  bool at_word(const char* w) const { return word() == w; }
  bool accept(Tok k) {
    if (peek().kind != k) return false;
    next();
    return true;
  }
  bool accept_word(const char* w) {
    if (!at_word(w)) return false;
    next();
    return true;
  }
  // A syntax error right after a line that has an error already is its consequence: not
  // reported again.
  [[noreturn]] void fail(Error e, size_t offset, const std::string& note = {}) {
    if (!(e == Error::Syntax && i_ > 0 && reporter_.line_has_error(t_[i_ - 1].line)))
      reporter_.error(e, offset, note);
    throw Failed{};
  }
  // A missing THEN or DO: reported, and the body parsed as if it were there.
  void want_word(const char* w) {
    if (!accept_word(w))
      reporter_.error(Error::Syntax, peek().offset, std::string("expected ") + w);
  }
  void expect(Tok k, const char* what) {
    if (!accept(k)) fail(Error::Syntax, peek().offset, std::string("expected ") + what);
  }
  void expect_word(const char* w) {
    if (!accept_word(w)) fail(Error::Syntax, peek().offset, std::string("expected ") + w);
  }
  // After a syntax error: on to the first token of a later line.
  void recover(int line) {
    while (peek().kind != Tok::End && peek().line == line) next();
  }

  // --- names ---
  void declare_predefined(const std::string& name) {
    globals_[name] = static_cast<uint32_t>(p_.globals.size());
    p_.globals.push_back({name, VarType::Long, true});
  }
  // A user's name: the spec's rules, or a failure.
  std::string user_name(const Token& t) {
    if (auto e = name_problem(t.text)) fail(*e, t.offset, "'" + t.text + "'");
    return t.text;
  }
  uint32_t variable(const Token& t) {
    const std::string u = upper(t.text);
    if (is_unsupported_word(u))
      fail(Error::Unsupported, t.offset, "'" + t.text + "' is not implemented");
    if (is_keyword(u) || builtin_of(u))
      fail(Error::Syntax, t.offset, "'" + t.text + "' is a keyword");
    auto it = globals_.find(t.text);
    if (it == globals_.end()) {
      if (auto e = name_problem(t.text); e && *e != Error::ReservedName)
        fail(*e, t.offset, "'" + t.text + "'");
      fail(Error::Undeclared, t.offset, "'" + t.text + "'");
    }
    return it->second;
  }

  // --- top level ---
  void top_level() {
    const Token& first = peek();
    const int line = first.line;
    try {
      const std::string w = word();
      if (w == "BYTE" || w == "WORD" || w == "LONG" || w == "DLONG") return declaration();
      if (w == "PROGRAM") return routine(true);
      if (w == "FUNCTION" && peek(1).kind != Tok::LParen) return routine(false);
      if (is_unsupported_word(w))
        fail(Error::Unsupported, first.offset, "'" + first.text + "' is not implemented");
      fail(Error::CodeOutsideProgram, first.offset);
    } catch (Failed&) {
      recover(line);
    }
  }

  void declaration() {
    const std::string w = word();
    next();
    const VarType type = w == "BYTE"   ? VarType::Byte
                         : w == "WORD" ? VarType::Word
                         : w == "LONG" ? VarType::Long
                                       : VarType::Dlong;
    // A bad name is reported and declared all the same, so its uses give no more errors.
    do {
      const Token& t = next();
      if (t.kind != Tok::Ident) fail(Error::Syntax, t.offset, "expected a variable name");
      if (globals_.count(t.text) != 0) {
        reporter_.error(Error::DeclaredTwice, t.offset, "'" + t.text + "'");
        continue;
      }
      if (functions_.count(t.text) != 0)
        reporter_.error(Error::DeclaredTwice, t.offset, "'" + t.text + "' is a function");
      else if (auto e = name_problem(t.text))
        reporter_.error(*e, t.offset, "'" + t.text + "'");
      globals_[t.text] = static_cast<uint32_t>(p_.globals.size());
      p_.globals.push_back({t.text, type, false});
    } while (accept(Tok::Comma));
    expect(Tok::Semi, "';' after the declaration");
  }

  void routine(bool is_program) {
    const Token& head = next();
    const Token& name_token = next();
    if (name_token.kind != Tok::Ident) fail(Error::Syntax, name_token.offset, "expected a name");
    Routine r;
    r.offset = head.offset;
    r.line = head.line;
    // A routine with a bad name is parsed all the same (its body is checked) and then dropped.
    bool keep = true;
    const auto refuse = [&](Error e, const std::string& note) {
      reporter_.error(e, name_token.offset, note);
      keep = false;
    };
    if (is_program) {
      const auto kind = program_of(name_token.text);
      if (!kind) refuse(Error::UnknownProgram, "'" + name_token.text + "'");
      for (const Routine& other : p_.routines)
        if (kind && other.kind == *kind) refuse(Error::ProgramTwice, "'" + name_token.text + "'");
      r.kind = kind.value_or(ProgramKind::Function);
      r.name = name_token.text;
    } else {
      r.name = name_token.text;
      if (auto e = name_problem(r.name))
        refuse(*e, "'" + r.name + "'");
      else if (functions_.count(r.name) != 0)
        refuse(Error::FunctionUnknown, "'" + r.name + "' defined twice");
      else if (globals_.count(r.name) != 0)
        refuse(Error::DeclaredTwice, "'" + r.name + "' is a variable");
      else
        functions_.insert(r.name);
    }
    const char* end = is_program ? "END_PROGRAM" : "END_FUNCTION";
    current_ = &r;
    labels_.clear();
    gotos_.clear();
    statement_count_ = 0;
    r.body = block({end});
    if (!accept_word(end))
      reporter_.error(Error::Syntax, peek().offset, std::string("expected ") + end);
    accept(Tok::Semi);
    resolve_gotos(r);
    current_ = nullptr;
    if (keep) p_.routines.push_back(std::move(r));
  }

  void resolve_gotos(Routine& r) {
    for (const auto& [name, at] : gotos_) {
      auto it = labels_.find(name);
      if (it == labels_.end()) {
        reporter_.error(Error::BadLabel, at.offset, "no label '" + name + "' in " + r.name);
      } else if (it->second <= at.order && r.loop_at < 0) {
        r.loop_at = static_cast<long>(at.offset);
      }
    }
  }

  // --- statements ---
  // Statements up to (not including) one of the `ends` words, or the end of the file.
  std::vector<int> block(std::initializer_list<const char*> ends) {
    std::vector<int> out;
    while (peek().kind != Tok::End) {
      const std::string w = word();
      for (const char* e : ends)
        if (w == e) return out;
      if (w == "END_PROGRAM" || w == "END_FUNCTION" || w == "PROGRAM" ||
          (w == "FUNCTION" && peek(1).kind != Tok::LParen) || w == "BYTE" || w == "WORD" ||
          w == "LONG" || w == "DLONG") {
        return out;  // the caller reports what is missing
      }
      const int line = peek().line;
      try {
        out.push_back(statement());
      } catch (Failed&) {
        recover(line);
      }
    }
    return out;
  }

  int add(Stmt s) {
    p_.stmts.push_back(std::move(s));
    return static_cast<int>(p_.stmts.size() - 1);
  }
  Stmt begin(Stmt::Kind kind, const Token& t) {
    Stmt s;
    s.kind = kind;
    s.offset = t.offset;
    s.line = t.line;
    ++statement_count_;
    return s;
  }
  void code_line(int line) { current_->code_lines.insert(line); }
  void end_word(const char* w) {
    expect_word(w);
    accept(Tok::Semi);
  }

  // Blocks nest at most this deep: the checker and the code generator recurse over them.
  static constexpr int kMaxNesting = 64;
  struct Nest {
    explicit Nest(int& depth) : depth_(depth) { ++depth_; }
    ~Nest() { --depth_; }
    int& depth_;
  };

  int statement() {
    const Token& t = peek();
    const Nest nest(nesting_);
    if (nesting_ > kMaxNesting) fail(Error::Syntax, t.offset, "blocks nested too deeply");
    const std::string w = word();
    if (t.kind == Tok::Ident && peek(1).kind == Tok::Colon) return label();
    if (t.kind != Tok::Ident) fail(Error::Syntax, t.offset, "expected a statement");
    if (w == "IF") return if_statement();
    if (w == "WHILE") return while_statement();
    if (w == "REPEAT") return repeat_statement();
    if (w == "FOR") return for_statement();
    if (w == "GOTO") return goto_statement();
    if (w == "RETURN") {
      Stmt s = begin(Stmt::Kind::Return, next());
      code_line(s.line);
      expect(Tok::Semi, "';'");
      return add(std::move(s));
    }
    if (w == "FUNCTION") return call_statement();
    if (auto b = builtin_of(w)) return builtin_statement(*b);
    if (is_unsupported_word(w))
      fail(Error::Unsupported, t.offset, "'" + t.text + "' is not implemented");
    if (is_keyword(w)) fail(Error::Syntax, t.offset, "'" + t.text + "' cannot start a statement");
    return assignment();
  }

  int label() {
    // A label stands at the start of its line (shared/spec/s300-drive.md: `L:` at a line start).
    const bool first_on_line = i_ == 0 || t_[i_ - 1].line != peek().line;
    const Token& t = next();
    next();  // ':'
    Stmt s = begin(Stmt::Kind::Label, t);
    s.name = t.text;
    if (!first_on_line)
      fail(Error::BadLabel, t.offset, "'" + t.text + "' is not at the start of its line");
    if (labels_.count(t.text) != 0)
      fail(Error::BadLabel, t.offset, "'" + t.text + "' defined twice");
    if (auto e = name_problem(t.text); e && *e != Error::ReservedName)
      fail(*e, t.offset, "'" + t.text + "'");
    labels_[t.text] = statement_count_;
    return add(std::move(s));
  }

  int goto_statement() {
    Stmt s = begin(Stmt::Kind::Goto, next());
    const Token& name = next();
    if (name.kind != Tok::Ident) fail(Error::Syntax, name.offset, "expected a label");
    s.name = name.text;
    code_line(s.line);
    expect(Tok::Semi, "';'");
    gotos_.push_back({s.name, {s.offset, statement_count_}});
    return add(std::move(s));
  }

  int assignment() {
    const Token& t = next();
    Stmt s = begin(Stmt::Kind::Assign, t);
    s.target = variable(t);
    if (p_.globals[s.target].type == VarType::Dlong)
      fail(Error::DlongMisuse, t.offset, "'" + t.text + "'");
    expect(Tok::Assign, "':='");
    s.expr = expression();
    check_store(s.target, s.expr);
    code_line(s.line);
    expect(Tok::Semi, "';'");
    return add(std::move(s));
  }

  // A constant stored into a BYTE or WORD must fit it (error 27).
  void check_store(uint32_t target, int expr) {
    const Expr& e = p_.exprs[static_cast<size_t>(expr)];
    if (e.kind != Expr::Kind::Const) return;
    const VarType type = p_.globals[target].type;
    const int32_t lo = type == VarType::Byte ? -128 : type == VarType::Word ? -32768 : INT32_MIN;
    const int32_t hi = type == VarType::Byte ? 127 : type == VarType::Word ? 32767 : INT32_MAX;
    if (e.value < lo || e.value > hi)
      fail(Error::ConstantRange, e.offset,
           std::to_string(e.value) + " does not fit " + p_.globals[target].name);
  }

  // A condition that fails is reported and skipped up to `until` on its line, so the block
  // after it is still parsed as the block it is.
  int condition(const char* until) {
    const int line = peek().line;
    try {
      return expression();
    } catch (Failed&) {
      while (peek().kind != Tok::End && peek().line == line && !at_word(until)) next();
      Expr zero;
      zero.offset = peek().offset;
      return make(zero);
    }
  }

  int if_statement() {
    Stmt s = begin(Stmt::Kind::If, next());
    s.expr = condition("THEN");
    code_line(s.line);
    want_word("THEN");
    s.body = block({"ELSE", "END_IF"});
    if (accept_word("ELSE")) s.else_body = block({"END_IF"});
    end_word("END_IF");
    return add(std::move(s));
  }

  void loop_here(size_t offset) {
    if (current_->loop_at < 0) current_->loop_at = static_cast<long>(offset);
  }

  int while_statement() {
    Stmt s = begin(Stmt::Kind::While, next());
    loop_here(s.offset);
    s.expr = condition("DO");
    code_line(s.line);
    want_word("DO");
    s.body = block({"END_WHILE"});
    end_word("END_WHILE");
    return add(std::move(s));
  }

  int repeat_statement() {
    Stmt s = begin(Stmt::Kind::Repeat, next());
    loop_here(s.offset);
    s.body = block({"UNTIL"});
    const Token& until = peek();
    expect_word("UNTIL");
    s.cond_line = until.line;
    s.expr = expression();
    code_line(s.cond_line);
    accept(Tok::Semi);
    if (accept_word("END_REPEAT")) accept(Tok::Semi);
    return add(std::move(s));
  }

  int for_statement() {
    Stmt s = begin(Stmt::Kind::For, next());
    loop_here(s.offset);
    const Token& v = next();
    if (v.kind != Tok::Ident) fail(Error::Syntax, v.offset, "expected the loop variable");
    s.target = variable(v);
    if (p_.globals[s.target].type == VarType::Dlong)
      fail(Error::DlongMisuse, v.offset, "'" + v.text + "'");
    expect(Tok::Assign, "':='");
    s.expr = expression();
    expect_word("TO");
    s.expr2 = expression();
    if (accept_word("BY")) {
      const int e = expression();
      const Expr& step = p_.exprs[static_cast<size_t>(e)];
      if (step.kind != Expr::Kind::Const) fail(Error::Syntax, step.offset, "BY takes a constant");
      if (step.value == 0)
        reporter_.error(Error::ConstantRange, step.offset, "the step of FOR must not be 0");
      s.step = step.value == 0 ? 1 : step.value;
    }
    code_line(s.line);
    want_word("DO");
    s.scratch = current_->for_count++;
    s.body = block({"END_FOR"});
    end_word("END_FOR");
    return add(std::move(s));
  }

  int call_statement() {
    Stmt s = begin(Stmt::Kind::Call, next());
    expect(Tok::LParen, "'('");
    const Token& name = next();
    if (name.kind != Tok::Ident) fail(Error::Syntax, name.offset, "expected a function name");
    s.name = name.text;
    expect(Tok::RParen, "')'");
    code_line(s.line);
    expect(Tok::Semi, "';'");
    current_->calls.push_back({s.name, name.offset});
    return add(std::move(s));
  }

  Arg argument() {
    Arg a;
    const Token& t = peek();
    a.offset = t.offset;
    if (t.kind == Tok::String) {
      a.kind = Arg::Kind::String;
      a.text = next().text;
      return a;
    }
    if (t.kind == Tok::Ident && (peek(1).kind == Tok::Comma || peek(1).kind == Tok::RParen)) {
      const std::string u = upper(t.text);
      if (u == "TRUE" || u == "FALSE") {
        next();
        a.kind = Arg::Kind::Const;
        a.value = u == "TRUE" ? -1 : 0;
        return a;
      }
      a.kind = Arg::Kind::Var;
      a.global = variable(next());
      return a;
    }
    const int e = expression();
    const Expr& x = p_.exprs[static_cast<size_t>(e)];
    a.kind = x.kind == Expr::Kind::Const ? Arg::Kind::Const : Arg::Kind::Other;
    a.value = x.value;
    return a;
  }

  int builtin_statement(Builtin b) {
    Stmt s = begin(Stmt::Kind::Builtin, next());
    s.builtin = b;
    expect(Tok::LParen, "'('");
    if (peek().kind != Tok::RParen) {
      do s.args.push_back(argument());
      while (accept(Tok::Comma));
    }
    expect(Tok::RParen, "')'");
    code_line(s.line);
    expect(Tok::Semi, "';'");
    if (b == Builtin::Xread || b == Builtin::Xwrite || b == Builtin::Command) {
      if (current_->access_at < 0) current_->access_at = static_cast<long>(s.offset);
    }
    if (b == Builtin::Printf && current_->printf_at < 0)
      current_->printf_at = static_cast<long>(s.offset);
    return add(std::move(s));
  }

  // --- expressions ---
  int make(Expr e) {
    p_.exprs.push_back(e);
    return static_cast<int>(p_.exprs.size() - 1);
  }

  // An expression holds at most this many operators (a #DEFINE can make a long one).
  static constexpr int kMaxOperators = 400;
  int expression() {
    operators_ = 0;
    return binary(0);
  }

  const Level* match(size_t level) const {
    for (const Level& l : kLevels[level]) {
      if (l.word != nullptr ? (peek().kind == Tok::Ident && word() == l.word)
                            : peek().kind == l.tok)
        return &l;
    }
    return nullptr;
  }

  int binary(size_t level) {
    if (level == kLevels.size()) return unary();
    int left = binary(level + 1);
    while (const Level* l = match(level)) {
      const size_t at = next().offset;
      if (++operators_ > kMaxOperators) fail(Error::Syntax, at, "expression too long");
      const int right = binary(level + 1);
      Expr e;
      e.kind = Expr::Kind::Binary;
      e.op = l->op;
      e.a = left;
      e.b = right;
      e.offset = at;
      check_operands(e);
      left = make(e);
    }
    return left;
  }

  // Shifts take a constant count (21); a constant divisor must not be 0 in its low 16 bits (29).
  void check_operands(const Expr& e) {
    const Expr& right = p_.exprs[static_cast<size_t>(e.b)];
    const bool constant = right.kind == Expr::Kind::Const;
    if ((e.op == Op::Shl || e.op == Op::Shr) && (!constant || right.value < 0 || right.value > 31))
      fail(Error::BadShift, right.offset);
    if ((e.op == Op::Div || e.op == Op::Mod) && constant && (right.value & 0xFFFF) == 0)
      fail(Error::ConstantDivisionByZero, right.offset);
  }

  int unary() {
    const Token& t = peek();
    Op op;
    if (t.kind == Tok::Minus)
      op = Op::Neg;
    else if (word() == "NOT")
      op = Op::Not;
    else if (word() == "BNOT")
      op = Op::Bnot;
    else
      return primary();
    next();
    if (op == Op::Neg && peek().kind == Tok::Number) {
      const Token& n = next();
      if (n.value > 2147483648ll || n.number_too_big) fail(Error::ConstantRange, n.offset, n.text);
      Expr c;
      c.kind = Expr::Kind::Const;
      c.value = static_cast<int32_t>(static_cast<uint32_t>(-n.value));
      c.offset = t.offset;
      return make(c);
    }
    if (++depth_ > 200) fail(Error::Syntax, t.offset, "expression nested too deeply");
    Expr e;
    e.kind = Expr::Kind::Unary;
    e.op = op;
    e.a = unary();
    --depth_;
    e.offset = t.offset;
    return make(e);
  }

  int primary() {
    const Token& t = next();
    Expr e;
    e.offset = t.offset;
    switch (t.kind) {
      case Tok::Number:
        if (t.number_too_big || t.value > INT32_MAX) fail(Error::ConstantRange, t.offset);
        e.kind = Expr::Kind::Const;
        e.value = static_cast<int32_t>(t.value);
        return make(e);
      case Tok::LParen: {
        if (++depth_ > 200) fail(Error::Syntax, t.offset, "expression nested too deeply");
        const int inner = expression();
        --depth_;
        expect(Tok::RParen, "')'");
        return inner;
      }
      case Tok::Ident: {
        const std::string u = upper(t.text);
        if (u == "TRUE" || u == "FALSE") {
          e.kind = Expr::Kind::Const;
          e.value = u == "TRUE" ? -1 : 0;
          return make(e);
        }
        e.kind = Expr::Kind::Var;
        e.global = variable(t);
        if (p_.globals[e.global].type == VarType::Dlong)
          fail(Error::DlongMisuse, t.offset, "'" + t.text + "'");
        return make(e);
      }
      case Tok::String:
        fail(Error::Syntax, t.offset, "a string is no value");
      default:
        fail(Error::Syntax, t.offset, "expected a value");
    }
  }

  struct GotoAt {
    size_t offset;
    int order;
  };

  const std::vector<Token>& t_;
  Reporter& reporter_;
  size_t i_ = 0;
  int depth_ = 0;
  int nesting_ = 0;
  int operators_ = 0;
  Program p_;
  std::map<std::string, uint32_t> globals_;
  std::set<std::string> functions_;
  Routine* current_ = nullptr;
  std::map<std::string, int> labels_;
  std::vector<std::pair<std::string, GotoAt>> gotos_;
  int statement_count_ = 0;
};

}  // namespace

Program parse(const std::vector<Token>& tokens, Reporter& reporter) {
  return Parser(tokens, reporter).run();
}

}  // namespace uprog::st
