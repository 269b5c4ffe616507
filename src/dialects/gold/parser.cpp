// Statements, blocks, declarations, functions and the top level of a Gold program.
#include "dialects/gold/parser.h"

#include <algorithm>

#include "dialects/gold/parser_impl.h"

namespace uprog::gold {

namespace detail {

namespace {
bool is_ref(const Expr* e) { return e != nullptr && e->kind == ExprKind::Ref; }
}  // namespace

// After a statement: the end of the line, ';' or ',' (which separate statements on one line).
void Parser::statement_end() {
  if (at_statement_end()) return;
  const Token& t = peek();
  if (t.kind == Tok::RParen || t.kind == Tok::RBracket)
    error(Error::ParenthesesMismatch, t.offset);
  else if (t.kind == Tok::Colon)
    error(Error::BadFormat, t.offset);  // "k = 1:2:20"
  else
    error(Error::OperatorIsExpected, t.offset);
  skip_line();
}

// else, otherwise and end stand alone on their line (manual 2.11.1 and error 44); try and catch
// too (error 85). A ';' after them is not code.
void Parser::alone_on_line(Error e) {
  while (at(Tok::Semicolon)) next();
  if (at_line_end()) return;
  error(e, peek().offset);
  skip_line();
}

// Marks the statement that ends its source line: the code generator puts an EOL after it.
void Parser::finish(Stmt& s) {
  size_t k = 0;
  while (peek(k).kind == Tok::Semicolon || peek(k).kind == Tok::Comma) ++k;
  const Tok after = peek(k).kind;
  s.ends_line = after == Tok::Newline || after == Tok::Eof;
}

bool Parser::type_keyword(VarType& type) {
  const Keyword k = kw();
  if (k == Keyword::Int)
    type = VarType::Int;
  else if (k == Keyword::Float)
    type = VarType::Float;
  else
    return false;
  next();
  return true;
}

// A name being declared: a letter first, then letters, digits, underscores; not a keyword, not
// an auto-routine name; at most 12 characters.
bool Parser::check_name(const Token& t) {
  if (t.kind != Tok::Ident || text(t).empty() || text(t)[0] == '_') {
    error(Error::InvalidName, t.offset, name_of(t));
    return false;
  }
  if (t.kw != Keyword::None || find_auto_routine(text(t)) != nullptr) {
    error(Error::NameIsKeyword, t.offset, text(t));
    return false;
  }
  if (text(t).size() > kMaxNameLength) {
    error(Error::NameIsTooLong, t.offset, text(t));
    return false;
  }
  return true;
}

// "int a, b[3]" after the type keyword. Errors 26, 27, 13, 32, 60 (`local`: no arrays).
void Parser::declaration(VarType type, std::vector<VarDecl>& out, bool global_redecl, bool local) {
  while (true) {
    if (at_statement_end() && !at(Tok::Comma)) {
      error(Error::InvalidName,
            peek().offset);  // "int a, b," : the name after the comma is missing
      return;
    }
    const Token& name = next();
    if (!check_name(name)) {
      skip_line();
      return;
    }
    VarDecl d;
    d.name = text(name);
    d.type = type;
    d.offset = name.offset;
    d.is_global_redecl = global_redecl;
    if (at(Tok::LBracket)) {
      const Token& open = next();
      paren_depth_ = 0;
      ExprPtr dim = at(Tok::RBracket) ? nullptr : expr();
      int32_t n = 0;
      if (!dim || !const_int(*dim, n) || n < 1) {
        if (dim || at(Tok::RBracket)) error(Error::BadDimension, open.offset, text(name));
        skip_line();
        return;
      }
      if (!at(Tok::RBracket)) {
        error(Error::ParenthesesMismatch, peek().offset);
        skip_line();
        return;
      }
      next();
      if (at(Tok::LBracket)) {
        error(Error::TooManyDimensions, peek().offset, text(name));
        skip_line();
        return;
      }
      if (local) {
        error(Error::IllegalLocalArray, name.offset, text(name));
        n = 0;
      }
      d.length = n;
    }
    out.push_back(std::move(d));
    if (at(Tok::Comma)) {
      next();
      continue;
    }
    if (at_statement_end()) return;
    error(Error::BadSeparator, peek().offset);
    skip_line();
    return;
  }
}

// "(int a, float b)" or "[int x, int y]": typed names. False after an error (reported).
bool Parser::param_list(std::vector<Param>& out, Tok close) {
  next();  // the opening bracket
  if (at(close)) {
    next();
    return true;
  }
  while (true) {
    VarType type;
    if (!type_keyword(type)) {
      error(Error::BadVariableType, peek().offset, name_of(peek()));
      skip_line();
      return false;
    }
    const Token& name = next();
    if (!check_name(name)) {
      skip_line();
      return false;
    }
    if (out.size() == kMaxArguments) {
      error(Error::TooManyArguments, name.offset);
      skip_line();
      return false;
    }
    out.push_back({text(name), type, name.offset});
    if (at(Tok::Comma)) {
      next();
      continue;
    }
    if (at(close)) {
      next();
      return true;
    }
    error(at_line_end() ? Error::ParenthesesMismatch : Error::BadSeparator, peek().offset);
    skip_line();
    return false;
  }
}

ExprPtr Parser::condition() {
  if (at_statement_end()) {
    error(Error::ExpressionIsExpected, peek().offset);
    return nullptr;
  }
  ExprPtr c = expr();
  if (c && at(Tok::Assign)) {
    error(Error::ExpressionIsExpected, peek().offset);  // "if a = 0": an assignment is no condition
    skip_line();
    return nullptr;
  }
  if (!c) skip_line();
  return c;
}

// Parses statements until one of `stops` (not consumed) or the end of the file.
Block Parser::block(unsigned stops, Keyword& stopped_by) {
  Block out;
  // Past the nesting limit (error 39, already reported) the block is skipped to its own `end`
  // by counting, not parsed: recursing on would let hostile input exhaust the stack.
  if (nest_.size() > static_cast<size_t>(kMaxBlockDepth)) {
    int depth = 0;
    for (; !at(Tok::Eof); next()) {
      const Keyword k = kw();
      if (k == Keyword::If || k == Keyword::While || k == Keyword::For || k == Keyword::Switch ||
          k == Keyword::Try) {
        ++depth;
      } else if (k == Keyword::End && depth-- == 0) {
        stopped_by = Keyword::End;
        return out;
      }
    }
    stopped_by = Keyword::None;
    return out;
  }
  while (true) {
    skip_separators();
    if (at(Tok::Eof)) {
      stopped_by = Keyword::None;
      return out;
    }
    const Keyword k = kw();
    const Token& t = peek();
    switch (k) {
      case Keyword::End:
        if (stops & kStopEnd) {
          stopped_by = k;
          return out;
        }
        error(Error::BadNesting, t.offset);
        next();
        alone_on_line(Error::CodeIsNotExpected);
        continue;
      case Keyword::Else:
      case Keyword::Elseif:
      case Keyword::Case:
      case Keyword::Otherwise:
      case Keyword::Catch: {
        // The keywords that continue an enclosing block: its stop, or misplaced here.
        const unsigned stop = k == Keyword::Catch                             ? kStopCatch
                              : k == Keyword::Case || k == Keyword::Otherwise ? kStopCase
                                                                              : kStopElse;
        if (stops & stop) {
          stopped_by = k;
          return out;
        }
        error(Error::BadNesting, t.offset);
        skip_line();
        continue;
      }
      case Keyword::Function:
        if (stops & kStopFunction) {
          stopped_by = k;
          return out;
        }
        error(Error::FunctionInsideBlock, t.offset);
        skip_line();
        continue;
      case Keyword::Return:
        if ((stops & kStopReturn) && nest_.empty()) {
          stopped_by = k;
          return out;
        }
        break;
      default:
        break;
    }
    if ((stops & kStopFunction) && nest_.empty() && !in_function_ &&
        (t.kind == Tok::Label || t.kind == Tok::AutoLabel || k == Keyword::Int ||
         k == Keyword::Float || k == Keyword::Global)) {
      stopped_by = Keyword::None;  // the top level handles its own labels
      return out;
    }
    if (StmtPtr s = statement()) out.push_back(std::move(s));
  }
}

StmtPtr Parser::statement() {
  paren_depth_ = 0;
  unary_chain_ = 0;
  const Token& t = peek();
  if (t.kind == Tok::Label || t.kind == Tok::AutoLabel) {
    next();
    StmtPtr s = arena_->stmt(StmtKind::Label, t.offset);
    s->name = text(t);
    s->auto_label = t.kind == Tok::AutoLabel;
    if (s->name.empty() || s->name[0] == '_' || (s->name[0] >= '0' && s->name[0] <= '9')) {
      error(Error::InvalidName, t.offset, s->name);
      return nullptr;
    }
    if (!nest_.empty()) {
      error(Error::LabelInsideBlock, t.offset, s->name);
      return nullptr;
    }
    if (s->auto_label && in_function_) {
      error(Error::AutoRoutineIsLocal, t.offset, s->name);
      return nullptr;
    }
    if (s->auto_label && find_auto_routine(s->name) == nullptr) {
      error(Error::InvalidName, t.offset, s->name);
      return nullptr;
    }
    finish(*s);
    return s;
  }
  const Keyword k = kw();
  switch (k) {
    case Keyword::If:
      return if_statement();
    case Keyword::While:
      return while_statement();
    case Keyword::For:
      return for_statement();
    case Keyword::Switch:
      return switch_statement();
    case Keyword::Try:
      return try_statement();
    case Keyword::Goto:
      return goto_or_reset(true);
    case Keyword::Reset:
      return goto_or_reset(false);
    case Keyword::Until:
    case Keyword::Wait: {
      next();
      ExprPtr c = condition();
      if (!c) return nullptr;
      StmtPtr s = arena_->stmt(k == Keyword::Until ? StmtKind::Until : StmtKind::Wait, t.offset);
      s->value = std::move(c);
      statement_end();
      finish(*s);
      return s;
    }
    case Keyword::Break:
    case Keyword::Continue:
    case Keyword::Exit:
    case Keyword::Return: {
      next();
      StmtKind sk = StmtKind::Exit;
      if (k == Keyword::Break) {
        const bool ok = std::any_of(nest_.begin(), nest_.end(), [](Nest n) {
          return n == Nest::While || n == Nest::For || n == Nest::Switch;
        });
        if (!ok) error(Error::MisplacedBreak, t.offset);
        sk = StmtKind::Break;
      } else if (k == Keyword::Continue) {
        // The innermost loop must lie inside any try...catch around the continue (2.11.4).
        bool ok = false;
        for (auto it = nest_.rbegin(); it != nest_.rend(); ++it) {
          if (*it == Nest::While || *it == Nest::For) {
            ok = true;
            break;
          }
          if (*it == Nest::Try || *it == Nest::Catch) break;
        }
        if (!ok) error(Error::MisplacedContinue, t.offset);
        sk = StmtKind::Continue;
      } else if (k == Keyword::Return) {
        const bool in_try = std::any_of(nest_.begin(), nest_.end(),
                                        [](Nest n) { return n == Nest::Try || n == Nest::Catch; });
        if (in_try) error(Error::MisplacedReturn, t.offset);
        sk = StmtKind::Return;
      }
      StmtPtr s = arena_->stmt(sk, t.offset);
      statement_end();
      finish(*s);
      return s;
    }
    case Keyword::Int:
    case Keyword::Float:
    case Keyword::Global: {
      // Declarations belong before the code (error 29); parse them anyway to avoid follow-ups.
      error(in_function_ || !nest_.empty() ? Error::BadVariableDefinition : Error::IllegalGlobal,
            t.offset);
      skip_line();
      return nullptr;
    }
    case Keyword::Function:
      error(Error::FunctionInsideBlock, t.offset);
      skip_line();
      return nullptr;
    case Keyword::Else:
    case Keyword::Elseif:
    case Keyword::End:
    case Keyword::Case:
    case Keyword::Otherwise:
    case Keyword::Catch:
      error(Error::BadNesting, t.offset);
      skip_line();
      return nullptr;
    default:
      break;
  }
  // XQ##name in a program (the spec's program command, "start the program at a function, label
  // or auto-routine"): the stack is cleared and the program goes on there, as reset does
  // (docs/dialects/gold.md, decision 45).
  if (t.kind == Tok::Ident && text(t).size() == 2 && (text(t)[0] | 0x20) == 'x' &&
      (text(t)[1] | 0x20) == 'q' && peek(1).kind == Tok::Label)
    return goto_or_reset(false);
  return simple_statement();
}

// Assignments, multiple assignments, i++/i--, calls, drive actions and bare values.
StmtPtr Parser::simple_statement() {
  const Token& first = peek();
  if (first.kind == Tok::LBracket) {
    next();
    StmtPtr s = arena_->stmt(StmtKind::Assign, first.offset);
    s->bracketed = true;
    while (true) {
      const Token& name = peek();
      if (name.kind != Tok::Ident || name.kw != Keyword::None) {
        error(name.kind == Tok::RBracket ? Error::BadNumberOfOutputs : Error::InvalidName,
              name.offset);
        skip_line();
        return nullptr;
      }
      next();
      ExprPtr target = ref_after_name(name);
      if (!target) {
        skip_line();
        return nullptr;
      }
      s->targets.push_back(std::move(target));
      if (at(Tok::Comma)) {
        next();
        continue;
      }
      if (at(Tok::RBracket)) {
        next();
        break;
      }
      error(Error::ParenthesesMismatch, peek().offset);
      skip_line();
      return nullptr;
    }
    if (s->targets.size() > kMaxArguments) {
      error(Error::BadNumberOfOutputs, first.offset);
      skip_line();
      return nullptr;
    }
    if (!at(Tok::Assign)) {
      // "[a,b,c] - func(x,y) + 5": outputs in brackets must be assigned from a call.
      error(Error::BadFunctionCall, peek().offset);
      skip_line();
      return nullptr;
    }
    const Token& eq = next();
    if (at_statement_end()) {
      error(Error::EmptyExpression, eq.offset);
      skip_line();
      return nullptr;
    }
    s->value = expr();
    if (!s->value) {
      skip_line();
      return nullptr;
    }
    statement_end();
    finish(*s);
    return s;
  }

  ExprPtr e = expr();
  if (!e) {
    skip_line();
    return nullptr;
  }
  if (at(Tok::Assign)) {
    const Token& eq = next();
    if (!is_ref(e)) {
      error(Error::BadFormat, e->offset);
      skip_line();
      return nullptr;
    }
    if (at_statement_end()) {
      error(Error::EmptyExpression, eq.offset);
      skip_line();
      return nullptr;
    }
    StmtPtr s = arena_->stmt(StmtKind::Assign, e->offset);
    s->targets.push_back(std::move(e));
    s->value = expr();
    if (!s->value) {
      skip_line();
      return nullptr;
    }
    statement_end();
    finish(*s);
    return s;
  }
  if (at(Tok::PlusPlus) || at(Tok::MinusMinus)) {
    const Token& op = next();
    if (!is_ref(e)) {
      error(Error::BadFormat, op.offset);
      skip_line();
      return nullptr;
    }
    StmtPtr s = arena_->stmt(StmtKind::IncDec, e->offset);
    s->delta = op.kind == Tok::PlusPlus ? 1 : -1;
    s->targets.push_back(std::move(e));
    statement_end();
    finish(*s);
    return s;
  }
  if (at(Tok::Comma) && is_ref(e)) {
    // "a, b = func(1,2)": several outputs need brackets (error 15).
    for (size_t k = 0; peek(k).kind != Tok::Newline && peek(k).kind != Tok::Eof; ++k) {
      if (peek(k).kind == Tok::Assign) {
        error(Error::BadNumberOfOutputs, e->offset);
        skip_line();
        return nullptr;
      }
      if (peek(k).kind == Tok::Semicolon) break;
    }
  }
  StmtPtr s = arena_->stmt(StmtKind::Expr, e->offset);
  s->value = std::move(e);
  statement_end();
  finish(*s);
  return s;
}

StmtPtr Parser::if_statement() {
  const Token& kw_if = next();
  StmtPtr s = arena_->stmt(StmtKind::If, kw_if.offset);
  ExprPtr c = condition();
  if (c) statement_end();
  finish(*s);
  nest_.push_back(Nest::If);
  if (nest_.size() > static_cast<size_t>(kMaxBlockDepth))
    error(Error::CodeIsTooComplex, kw_if.offset);
  Keyword stopped = Keyword::None;
  IfArm arm;
  arm.cond = std::move(c);
  arm.body = block(kStopEnd | kStopElse, stopped);
  s->arms.push_back(std::move(arm));
  bool seen_else = false;
  while (stopped == Keyword::Elseif || stopped == Keyword::Else) {
    const Token& t = next();
    IfArm a;
    if (stopped == Keyword::Elseif) {
      if (seen_else) error(Error::BadNesting, t.offset);
      a.cond = condition();
      if (a.cond) statement_end();
    } else {
      if (seen_else) error(Error::BadNesting, t.offset);
      seen_else = true;
      alone_on_line(Error::CodeIsNotExpected);
    }
    a.body = block(kStopEnd | kStopElse, stopped);
    s->arms.push_back(std::move(a));
  }
  nest_.pop_back();
  if (stopped != Keyword::End) {
    error(Error::BadNesting, kw_if.offset);  // an if block without end
    return s;
  }
  s->end_offset = next().offset;
  alone_on_line(Error::CodeIsNotExpected);
  return s;
}

StmtPtr Parser::while_statement() {
  const Token& kw_while = next();
  StmtPtr s = arena_->stmt(StmtKind::While, kw_while.offset);
  s->value = condition();
  if (s->value) statement_end();
  finish(*s);
  nest_.push_back(Nest::While);
  if (nest_.size() > static_cast<size_t>(kMaxBlockDepth))
    error(Error::CodeIsTooComplex, kw_while.offset);
  Keyword stopped = Keyword::None;
  s->body = block(kStopEnd, stopped);
  nest_.pop_back();
  if (stopped != Keyword::End) {
    error(Error::BadNesting, kw_while.offset);
    return s;
  }
  s->end_offset = next().offset;
  alone_on_line(Error::CodeIsNotExpected);
  return s;
}

// for k = a:b or k = a:step:b (manual 2.12.2); errors 10, 45, 1.
StmtPtr Parser::for_statement() {
  const Token& kw_for = next();
  StmtPtr s = arena_->stmt(StmtKind::For, kw_for.offset);
  bool ok = true;
  const Token& name = peek();
  if (name.kind != Tok::Ident || name.kw != Keyword::None) {
    error(Error::BadFlowControlExpression, name.offset, name_of(name));
    ok = false;
  } else {
    next();
    ExprPtr var = ref_after_name(name);
    if (!var)
      ok = false;
    else
      s->targets.push_back(std::move(var));
  }
  if (ok && !at(Tok::Assign)) {
    error(Error::BadFlowControlExpression, peek().offset);  // "for k a = 0"
    ok = false;
  }
  if (ok) {
    next();
    std::vector<ExprPtr> parts;
    while (ok) {
      if (at(Tok::Colon)) {
        error(Error::BadFormat, peek().offset);  // "for k = 1::10"
        ok = false;
        break;
      }
      ExprPtr p = expr();
      if (!p) {
        ok = false;
        break;
      }
      parts.push_back(std::move(p));
      if (!at(Tok::Colon)) break;
      const Token& colon = next();
      if (parts.size() == 3) {
        error(Error::BadColonExpression, colon.offset);  // "for k = 10:-1:5:9"
        ok = false;
      }
    }
    if (ok && parts.size() < 2) {
      error(Error::BadColonExpression,
            parts.empty() ? kw_for.offset : parts[0]->offset);  // "for k = a"
      ok = false;
    }
    if (ok) {
      s->value = std::move(parts[0]);
      if (parts.size() == 3) {
        s->step = std::move(parts[1]);
        s->end = std::move(parts[2]);
      } else {
        s->end = std::move(parts[1]);
      }
      statement_end();
    }
  }
  if (!ok) skip_line();
  finish(*s);
  nest_.push_back(Nest::For);
  if (nest_.size() > static_cast<size_t>(kMaxBlockDepth))
    error(Error::CodeIsTooComplex, kw_for.offset);
  Keyword stopped = Keyword::None;
  s->body = block(kStopEnd, stopped);
  nest_.pop_back();
  if (stopped != Keyword::End) {
    error(Error::BadNesting, kw_for.offset);
    return ok ? std::move(s) : nullptr;
  }
  s->end_offset = next().offset;
  alone_on_line(Error::CodeIsNotExpected);
  return ok ? std::move(s) : nullptr;
}

// switch / case / otherwise / end (2.11.3): first match wins; errors 41, 42, 48.
StmtPtr Parser::switch_statement() {
  const Token& kw_switch = next();
  StmtPtr s = arena_->stmt(StmtKind::Switch, kw_switch.offset);
  s->value = condition();
  if (s->value) statement_end();
  finish(*s);
  nest_.push_back(Nest::Switch);
  if (nest_.size() > static_cast<size_t>(kMaxBlockDepth))
    error(Error::CodeIsTooComplex, kw_switch.offset);
  Keyword stopped = Keyword::None;
  // Between switch and the first case only a case may stand.
  skip_separators();
  if (at_kw(Keyword::Otherwise)) {
    error(Error::OtherwiseWithoutCase, peek().offset);
  } else if (!at_kw(Keyword::Case) && !at_kw(Keyword::End) && !at(Tok::Eof)) {
    error(Error::CaseMustFollowSwitch, peek().offset);
  }
  block(kStopEnd | kStopCase, stopped);  // whatever stands there is checked, then dropped
  bool seen_otherwise = false;
  while (stopped == Keyword::Case || stopped == Keyword::Otherwise) {
    const Token& t = next();
    SwitchCase c;
    c.offset = t.offset;
    if (stopped == Keyword::Case) {
      if (seen_otherwise) error(Error::CaseAfterOtherwise, t.offset);
      c.value = condition();
      if (c.value) statement_end();
    } else {
      if (seen_otherwise) error(Error::BadNesting, t.offset);
      seen_otherwise = true;
      alone_on_line(Error::CodeIsNotExpected);
    }
    c.body = block(kStopEnd | kStopCase, stopped);
    s->cases.push_back(std::move(c));
  }
  nest_.pop_back();
  if (stopped != Keyword::End) {
    error(Error::BadNesting, kw_switch.offset);
    return s;
  }
  s->end_offset = next().offset;
  alone_on_line(Error::CodeIsNotExpected);
  return s;
}

StmtPtr Parser::try_statement() {
  const Token& kw_try = next();
  StmtPtr s = arena_->stmt(StmtKind::Try, kw_try.offset);
  alone_on_line(Error::TryCatchNotAlone);
  s->ends_line = true;
  nest_.push_back(Nest::Try);
  if (nest_.size() > static_cast<size_t>(kMaxBlockDepth))
    error(Error::CodeIsTooComplex, kw_try.offset);
  Keyword stopped = Keyword::None;
  s->body = block(kStopEnd | kStopCatch, stopped);
  if (stopped == Keyword::Catch) {
    next();
    alone_on_line(Error::TryCatchNotAlone);
    nest_.back() = Nest::Catch;
    s->handler = block(kStopEnd, stopped);
  }
  nest_.pop_back();
  if (stopped != Keyword::End) {
    error(Error::BadNesting, kw_try.offset);
    return s;
  }
  s->end_offset = next().offset;
  alone_on_line(Error::CodeIsNotExpected);
  return s;
}

// goto ##NAME / goto #@NAME (2.11.2, errors 77) and reset NAME (errors 73).
StmtPtr Parser::goto_or_reset(bool is_goto) {
  const Token& k = next();
  StmtPtr s = arena_->stmt(is_goto ? StmtKind::Goto : StmtKind::Reset, k.offset);
  const Token& target = peek();
  if (is_goto) {
    if (target.kind != Tok::Label && target.kind != Tok::AutoLabel) {
      error(Error::BadGoto, target.offset, name_of(target));  // "goto START"
      skip_line();
      return nullptr;
    }
    if (std::find(nest_.begin(), nest_.end(), Nest::For) != nest_.end()) {
      error(Error::BadGoto, k.offset, text(target));  // no goto out of a for loop
    }
  } else if (target.kind != Tok::Ident && target.kind != Tok::Label &&
             target.kind != Tok::AutoLabel) {
    error(Error::NoSuchFunction, target.offset, name_of(target));
    skip_line();
    return nullptr;
  }
  next();
  s->name = text(target);
  s->auto_label = target.kind == Tok::AutoLabel;
  if (!is_goto && at(Tok::LParen)) {
    error(Error::BadFunctionAfterReset, target.offset, text(target));  // "reset func(12)"
    skip_line();
    return nullptr;
  }
  statement_end();
  finish(*s);
  return s;
}

// function [int x, int y] = f(int a, float b) / function int Err=Move(int index) / function f()
void Parser::function_definition(Program& p, FunctionBodySink* on_body) {
  const Token& kw_function = next();
  FunctionDef f;
  f.offset = kw_function.offset;
  bool ok = true;
  if (at(Tok::LBracket)) {
    ok = param_list(f.outputs, Tok::RBracket);
    if (ok && !at(Tok::Assign)) {
      error(Error::BadFunctionFormat, peek().offset);
      skip_line();
      ok = false;
    }
    if (ok) next();
  } else if ((at_kw(Keyword::Int) || at_kw(Keyword::Float)) && peek(1).kind == Tok::LParen) {
    error(Error::NameIsKeyword, peek().offset, text(peek()));  // "function int()": error 24
    skip_line();
    ok = false;
  } else if (at_kw(Keyword::Int) || at_kw(Keyword::Float)) {
    VarType type;
    type_keyword(type);
    const Token& out = next();
    if (!check_name(out)) {
      skip_line();
      ok = false;
    } else {
      f.outputs.push_back({text(out), type, out.offset});
      if (!at(Tok::Assign)) {
        error(Error::BadFunctionFormat, peek().offset);
        skip_line();
        ok = false;
      } else {
        next();
      }
    }
  }
  if (ok) {
    const Token& name = peek();
    f.offset = name.offset;
    if (name.kind == Tok::Ident && find_auto_routine(text(name)) != nullptr) {
      f.is_auto = true;  // "function AUTOEXEC()" defines the auto-routine
      next();
    } else if (!check_name(name)) {
      skip_line();
      ok = false;
    } else {
      next();
    }
    if (ok) f.name = text(name);
  }
  if (ok && at(Tok::LParen)) ok = param_list(f.inputs, Tok::RParen);
  if (ok) statement_end();
  if (f.is_auto && (!f.inputs.empty() || !f.outputs.empty()))
    error(Error::AutoRoutineHasArgument, f.offset, f.name);

  // A header followed by another function or the end of the file is a prototype.
  skip_separators();
  if (at_kw(Keyword::Function) || at(Tok::Eof)) {
    if (ok) p.functions.push_back(std::move(f));
    return;
  }
  f.has_body = true;
  in_function_ = true;
  FunctionBodySink* sink = on_body;
  AstArena* const kept = arena_;
  if (sink) arena_ = &sink->scratch();
  // Locals and global re-declarations open the function (2.6.2, error 29 for later ones).
  while (true) {
    skip_separators();
    VarType type;
    if (at_kw(Keyword::Global)) {
      next();
      if (!type_keyword(type)) {
        error(Error::BadVariableType, peek().offset, name_of(peek()));  // "global floa a"
        skip_line();
        continue;
      }
      declaration(type, f.locals, true, false);
      continue;
    }
    if (type_keyword(type)) {
      declaration(type, f.locals, false, true);
      continue;
    }
    break;
  }
  Keyword stopped = Keyword::None;
  f.body_start = mark();
  Block body = block(kStopReturn | kStopFunction, stopped);
  in_function_ = false;
  if (stopped == Keyword::Return) {
    const Token& ret = next();
    f.end_offset = ret.offset;
    statement_end();
  } else {
    error(Error::FunctionWithoutReturn, f.offset, f.name);
    f.end_offset = peek().offset;
  }
  arena_ = kept;
  if (!sink) {
    f.body = std::move(body);
    if (ok) p.functions.push_back(std::move(f));
    return;
  }
  if (ok) p.functions.push_back(std::move(f));
  sink->body(p, ok ? &p.functions.back() : nullptr, body);
}

Block Parser::reparse_body(const LexState& start) {
  lex_.restore(start);
  ahead_.clear();
  head_ = 0;
  nest_.clear();
  in_function_ = true;
  Keyword stopped = Keyword::None;
  Block body = block(kStopReturn | kStopFunction, stopped);
  in_function_ = false;
  return body;
}

Program Parser::program(FunctionBodySink* on_body) {
  Program p;
  bool in_section = false;  // after a label, before its closing return
  bool reported_outside = false;
  while (true) {
    skip_separators();
    if (at(Tok::Eof)) break;
    p.empty = false;
    const Token& t = peek();
    const Keyword k = kw();
    if (k == Keyword::Function) {
      if (in_section) {
        StmtPtr r =
            arena_->stmt(StmtKind::Return, t.offset);  // a routine ends where a function begins
        r->ends_line = true;
        p.top.push_back(std::move(r));
        in_section = false;
      }
      function_definition(p, on_body);
      reported_outside = false;
      continue;
    }
    if (k == Keyword::Int || k == Keyword::Float) {
      VarType type{};
      type_keyword(type);
      declaration(type, p.globals, false, false);
      continue;
    }
    if (k == Keyword::Global) {
      error(Error::IllegalGlobal, t.offset);  // global belongs inside a function
      skip_line();
      continue;
    }
    if (t.kind == Tok::Label || t.kind == Tok::AutoLabel) {
      if (StmtPtr s = statement()) {
        p.top.push_back(std::move(s));
        in_section = true;
        reported_outside = false;
      }
      continue;
    }
    if (k == Keyword::Return) {
      const Token& r = next();
      if (!in_section) error(Error::ExpressionOutOfFunction, r.offset);
      StmtPtr s = arena_->stmt(StmtKind::Return, r.offset);
      statement_end();
      finish(*s);
      if (in_section) p.top.push_back(std::move(s));
      in_section = false;
      continue;
    }
    if (!in_section && !reported_outside) {
      error(Error::ExpressionOutOfFunction, t.offset);  // code before any label or function
      reported_outside = true;
    }
    Keyword stopped = Keyword::None;
    Block b = block(kStopReturn | kStopFunction, stopped);
    if (in_section)
      for (StmtPtr& s : b) p.top.push_back(std::move(s));
  }
  if (in_section) {
    StmtPtr r = arena_->stmt(StmtKind::Return, static_cast<uint32_t>(peek().offset));
    r->ends_line = true;
    p.top.push_back(std::move(r));
  }
  return p;
}

Block Parser::line() {
  Keyword stopped = Keyword::None;
  Block b;
  while (true) {
    Block part = block(kStopReturn, stopped);
    for (StmtPtr& s : part) b.push_back(std::move(s));
    if (at(Tok::Eof)) break;
    const Token& r = next();  // a return on the command line ends it
    StmtPtr s = arena_->stmt(StmtKind::Return, r.offset);
    b.push_back(std::move(s));
  }
  return b;
}

}  // namespace detail

Program parse_program(Lexer& lexer, Reporter& reporter, AstArena& arena,
                      FunctionBodySink* on_body) {
  return detail::Parser(lexer, reporter, arena).program(on_body);
}

Block reparse_body(Lexer& lexer, Reporter& reporter, AstArena& arena, const FunctionDef& f) {
  return detail::Parser(lexer, reporter, arena).reparse_body(f.body_start);
}

Block parse_line(Lexer& lexer, Reporter& reporter, AstArena& arena) {
  return detail::Parser(lexer, reporter, arena).line();
}

}  // namespace uprog::gold
