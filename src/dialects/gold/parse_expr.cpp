// Expressions: precedence climbing over the manual's table (1.4), names with an index or
// arguments, and the manual's expression errors (1, 2, 3, 4, 6, 7, 13, 34).
#include "dialects/gold/parser_impl.h"
#include "support/arith.h"

namespace uprog::gold::detail {

namespace {

// Binary operator levels, lowest first: || && | & (== !=) (< <= > >=) (<< >>) (+ -) (* / %).
int level_of(Tok t) {
  switch (t) {
    case Tok::OrOr:
      return 0;
    case Tok::AndAnd:
      return 1;
    case Tok::Pipe:
      return 2;
    case Tok::Amp:
      return 3;
    case Tok::EqEq:
    case Tok::Ne:
      return 4;
    case Tok::Lt:
    case Tok::Le:
    case Tok::Gt:
    case Tok::Ge:
      return 5;
    case Tok::Shl:
    case Tok::Shr:
      return 6;
    case Tok::Plus:
    case Tok::Minus:
      return 7;
    case Tok::Star:
    case Tok::Slash:
    case Tok::Percent:
      return 8;
    default:
      return -1;
  }
}

}  // namespace

ExprPtr Parser::expr() { return binary(0); }

// Precedence climbing as one loop per level actually used: an operand is parsed once, then
// operators of level >= `min_level` fold to the left (all of Gold's operators are left-assoc).
ExprPtr Parser::binary(int min_level) {
  ExprPtr left = unary(false);
  if (!left) return nullptr;
  while (true) {
    const int level = level_of(peek().kind);
    if (level < min_level) return left;
    const Token& op = next();
    ExprPtr right = binary(level + 1);
    if (!right) return nullptr;
    ExprPtr b = arena_->expr(ExprKind::Binary, op.offset);
    b->op = op.kind;
    b->lhs = std::move(left);
    b->rhs = std::move(right);
    left = std::move(b);
  }
}

ExprPtr Parser::unary(bool under_minus) {
  const Tok k = peek().kind;
  if (k == Tok::Minus || k == Tok::Bang || k == Tok::Tilde) {
    const Token& op = next();
    if (++unary_chain_ > kMaxUnaryChain) {
      error(Error::StackIsFull, op.offset);
      return nullptr;
    }
    ExprPtr operand = unary(k == Tok::Minus);
    --unary_chain_;
    if (!operand) return nullptr;
    ExprPtr u = arena_->expr(ExprKind::Unary, op.offset);
    u->op = k;
    u->lhs = std::move(operand);
    return u;
  }
  return primary(under_minus);
}

ExprPtr Parser::primary(bool under_minus) {
  const Token& t = peek();
  switch (t.kind) {
    case Tok::Int: {
      next();
      ExprPtr e = arena_->expr(ExprKind::IntLit, t.offset);
      e->int_value = t.int_value;
      return e;
    }
    case Tok::Float: {
      next();
      ExprPtr e = arena_->expr(ExprKind::FloatLit, t.offset);
      e->float_value = t.float_value;
      return e;
    }
    case Tok::Ident: {
      const Keyword k = t.kw;
      if (k == Keyword::Nargout) {
        next();
        return arena_->expr(ExprKind::Nargout, t.offset);
      }
      if (k != Keyword::None) {
        error(Error::ValueIsExpected, t.offset);
        return nullptr;
      }
      next();
      return ref_after_name(t);
    }
    case Tok::LParen: {
      next();
      if (at(Tok::RParen)) {
        error(Error::BadFormat, t.offset);  // "b = a + ( )": nothing inside the parentheses
        return nullptr;
      }
      if (++paren_depth_ > kMaxParenDepth) {
        error(Error::StackIsFull, t.offset);
        return nullptr;
      }
      ExprPtr inner = expr();
      --paren_depth_;
      if (!inner) return nullptr;
      if (at(Tok::Comma)) {
        // "-(2+3, c/5)": several values in one pair of parentheses.
        error(under_minus ? Error::IllegalMinus : Error::BadFormat,
              under_minus ? t.offset : peek().offset);
        return nullptr;
      }
      if (!at(Tok::RParen)) {
        error(Error::ParenthesesMismatch, peek().offset);
        return nullptr;
      }
      next();
      return inner;
    }
    case Tok::Newline:
    case Tok::Eof:
    case Tok::Semicolon:
      error(Error::ValueIsExpected, t.offset);
      return nullptr;
    default:
      error(Error::ValueIsExpected, t.offset);
      return nullptr;
  }
}

// A name, then maybe [index] or (arguments). The checker decides what the name is.
ExprPtr Parser::ref_after_name(const Token& name) {
  ExprPtr e = arena_->expr(ExprKind::Ref, name.offset);
  e->name = text(name);
  if (at(Tok::LBracket)) {
    const Token& open = next();
    e->has_index = true;
    if (at(Tok::RBracket)) {
      error(Error::BadIndexExpression, open.offset, e->name);
      return nullptr;
    }
    if (++paren_depth_ > kMaxParenDepth) {
      error(Error::StackIsFull, open.offset);
      return nullptr;
    }
    ExprPtr index = expr();
    --paren_depth_;
    if (!index) return nullptr;
    if (at(Tok::Comma)) {
      error(Error::BadIndexExpression, peek().offset, e->name);
      return nullptr;
    }
    if (!at(Tok::RBracket)) {
      error(Error::ParenthesesMismatch, peek().offset);
      return nullptr;
    }
    next();
    if (at(Tok::LBracket)) {
      error(Error::TooManyDimensions, peek().offset, e->name);
      return nullptr;
    }
    e->args.push_back(std::move(index));
    return e;
  }
  if (at(Tok::LParen)) {
    const Token& open = next();
    e->has_parens = true;
    if (++paren_depth_ > kMaxParenDepth) {
      error(Error::StackIsFull, open.offset);
      return nullptr;
    }
    if (!at(Tok::RParen)) {
      while (true) {
        ExprPtr a = expr();
        if (!a) return nullptr;
        e->args.push_back(std::move(a));
        if (!at(Tok::Comma)) break;
        next();
      }
    }
    --paren_depth_;
    if (!at(Tok::RParen)) {
      error(Error::ParenthesesMismatch, peek().offset);
      return nullptr;
    }
    next();
  }
  return e;
}

// Folds an integer constant (dimensions); floats are truncated as the manual says for
// dimensions (2.6: "float w[2.8] // dimension will be truncated to 2").
bool Parser::const_int(const Expr& e, int32_t& out) const {
  switch (e.kind) {
    case ExprKind::IntLit:
      out = e.int_value;
      return true;
    case ExprKind::FloatLit:
      out = arith::trunc_to_int(e.float_value);
      return true;
    case ExprKind::Unary:
      if (e.op == Tok::Minus && const_int(*e.lhs, out)) {
        out = out == INT32_MIN ? INT32_MAX : -out;
        return true;
      }
      return false;
    default:
      return false;
  }
}

}  // namespace uprog::gold::detail
