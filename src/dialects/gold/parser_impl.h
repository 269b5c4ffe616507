// The parser's state, shared by its statement half (parser.cpp) and expression half
// (parse_expr.cpp). Internal to the Gold front end.
#pragma once
#include <vector>

#include "dialects/gold/ast.h"
#include "dialects/gold/keywords.h"
#include "dialects/gold/lexer.h"
#include "dialects/gold/reporter.h"
#include "dialects/gold/token.h"

namespace uprog::gold::detail {

// Manual 1.9 and 2.7.2 (error 39): 16 levels of parentheses, 100 nested blocks.
constexpr int kMaxParenDepth = 16;
constexpr int kMaxBlockDepth = 100;
constexpr int kMaxUnaryChain = 64;
// Manual 2.7.2 errors 15 and 17: at most 16 inputs and 16 outputs.
constexpr size_t kMaxArguments = 16;
// Manual 2.7.2 error 11: names longer than 12 characters.
constexpr size_t kMaxNameLength = 12;

// What encloses the statement being parsed, innermost last.
enum class Nest : char { If = 'I', While = 'W', For = 'F', Switch = 'S', Try = 'T', Catch = 'C' };

enum Stop : unsigned {
  kStopEnd = 1,
  kStopElse = 2,
  kStopCase = 4,
  kStopCatch = 8,
  kStopReturn = 16,
  kStopFunction = 32,
};

class Parser {
 public:
  Parser(Lexer& lexer, Reporter& reporter, AstArena& arena)
      : lex_(lexer), r_(reporter), arena_(&arena) {}

  // `on_body`, when set, receives each function's body as soon as it is parsed (and the tree
  // keeps no body); without it every body stays in the tree.
  Program program(FunctionBodySink* on_body = nullptr);
  Block line();
  // A function body again, from where the first parse began it (FunctionDef::body_start).
  Block reparse_body(const LexState& start);

  // Expressions (parse_expr.cpp). A null result means an error was reported.
  ExprPtr expr();
  ExprPtr unary(bool under_minus);
  ExprPtr binary(int level);
  ExprPtr primary(bool under_minus);
  ExprPtr ref_after_name(const Token& name);
  bool const_int(const Expr& e, int32_t& out) const;

 private:
  // Statements (parser.cpp).
  Block block(unsigned stops, Keyword& stopped_by);
  StmtPtr statement();
  StmtPtr simple_statement();
  StmtPtr if_statement();
  StmtPtr while_statement();
  StmtPtr for_statement();
  StmtPtr switch_statement();
  StmtPtr try_statement();
  StmtPtr goto_or_reset(bool is_goto);
  void function_definition(Program& p, FunctionBodySink* on_body);
  bool param_list(std::vector<Param>& out, Tok close);
  bool type_keyword(VarType& type);
  void declaration(VarType type, std::vector<VarDecl>& out, bool global_redecl, bool local);
  bool check_name(const Token& t);
  ExprPtr condition();
  void statement_end();
  void alone_on_line(Error e);
  void finish(Stmt& s);
  // peek() past the buffered tokens: the lexer reads up to the k-th.
  [[gnu::noinline]] Token read_ahead(size_t k) {
    while (ahead_.size() - head_ <= k) ahead_.push_back({lex_.state(), lex_.next()});
    return ahead_[head_ + k].token;
  }

 public:
  // Tokens, by value: the lookahead buffer refills as the parser moves on.
  // Most peeks look again at a token already read: that one at once, inline; the lexer's call
  // out of line (uprog check of 100 000 lines: 564 M -> 537 M host instructions).
  Token peek(size_t k = 0) {
    if (ahead_.size() - head_ > k) [[likely]]
      return ahead_[head_ + k].token;
    return read_ahead(k);
  }
  Token next() {
    const Token t = peek();
    if (t.kind != Tok::Eof && ++head_ == ahead_.size()) {
      ahead_.clear();
      head_ = 0;
    }
    return t;
  }
  // The lexer's state before the next token.
  LexState mark() {
    peek();
    return ahead_[head_].before;
  }
  std::string_view text(const Token& t) const { return t.text(lex_.text()); }
  bool at(Tok k) { return peek().kind == k; }
  Keyword kw(size_t k = 0) {
    const Token t = peek(k);
    return t.kind == Tok::Ident ? t.kw : Keyword::None;
  }
  bool at_kw(Keyword k) { return kw() == k; }
  bool at_statement_end() {
    const Tok k = peek().kind;
    return k == Tok::Newline || k == Tok::Semicolon || k == Tok::Comma || k == Tok::Eof;
  }
  bool at_line_end() { return at(Tok::Newline) || at(Tok::Eof); }
  void skip_line() {
    while (!at_line_end()) next();
  }
  void skip_separators() {
    while (at(Tok::Newline) || at(Tok::Semicolon) || at(Tok::Comma)) next();
  }
  // `name`: what the error is about, quoted after the manual's text.
  void error(Error e, uint32_t offset, std::string_view name = {}) { r_.error(e, offset, name); }
  // The name a token spells (a name or a label), or nothing for any other token.
  std::string_view name_of(const Token& t) const {
    return t.kind == Tok::Ident || t.kind == Tok::Label || t.kind == Tok::AutoLabel
               ? text(t)
               : std::string_view{};
  }

  struct Ahead {
    LexState before;
    Token token;
  };
  Lexer& lex_;
  Reporter& r_;
  AstArena* arena_;
  std::vector<Ahead> ahead_;
  size_t head_ = 0;
  std::vector<Nest> nest_;
  bool in_function_ = false;
  int paren_depth_ = 0;
  int unary_chain_ = 0;
};

}  // namespace uprog::gold::detail
