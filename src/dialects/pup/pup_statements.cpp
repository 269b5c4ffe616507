// The PUP compiler's statements: flow control into AJump lines and labels, messages copied or
// compiled, tasks and functions, and the checks made once the whole program is read.
#include <fmt/core.h>

#include "dialects/pup/keywords.h"
#include "dialects/pup/pup_compiler_impl.h"

namespace uprog::pup {
namespace {

constexpr const char* kFlowWords[] = {"if",     "else",   "end",     "while", "for",
                                      "switch", "case",   "default", "break", "continue",
                                      "return", "Return", "GoTo"};

bool is_flow_word(const std::string& s) {
  for (const char* w : kFlowWords) {
    if (s == w) return true;
  }
  return false;
}

}  // namespace

void PupCompiler::emit(std::string text, const Location& at, int label) {
  lines_.push_back(OutLine{std::move(text), at, label, -1});
}

void PupCompiler::place_code(const Code& code, const Location& at, int label0) {
  std::vector<int> labels;
  for (int i = 0; i < code.labels; ++i)
    labels.push_back(i == 0 && label0 >= 0 ? label0 : new_label());
  for (const CodeLine& l : code.lines) {
    if (l.label >= 0)
      bind(labels[static_cast<size_t>(l.label)]);
    else
      emit(l.text, at, l.target >= 0 ? labels[static_cast<size_t>(l.target)] : -1);
  }
}

// The lines emitted since `first_line` as code of their own, removed; the labels made since
// `first_label` become the code's (a for's step, placed again at the loop's end).
Code PupCompiler::take_code(size_t first_line, size_t first_label) {
  Code code;
  const auto local = [&](int label) { return label - static_cast<int>(first_label); };
  code.labels = static_cast<int>(labels_.size() - first_label);
  for (size_t i = first_line; i <= lines_.size(); ++i) {
    for (size_t l = first_label; l < labels_.size(); ++l) {
      if (labels_[l] == i + 1) code.bind(local(static_cast<int>(l)));
    }
    if (i == lines_.size()) break;
    const OutLine& line = lines_[i];
    code.line(line.text, line.label >= 0 ? local(line.label) : -1);
  }
  lines_.resize(first_line);
  labels_.resize(first_label);
  return code;
}

int PupCompiler::new_label() {
  labels_.push_back(0);
  return static_cast<int>(labels_.size()) - 1;
}

void PupCompiler::bind(int label) {
  labels_[static_cast<size_t>(label)] = static_cast<uint32_t>(lines_.size() + 1);
}

Block* PupCompiler::innermost(bool loops_only) {
  for (auto b = blocks_.rbegin(); b != blocks_.rend(); ++b) {
    if (b->kind == BlockKind::While || b->kind == BlockKind::For) return &*b;
    if (b->kind == BlockKind::Switch && !loops_only) return &*b;
  }
  return nullptr;
}

bool PupCompiler::expression(TokenCursor& cur, ExprTree& tree, int& node, bool needs_end) {
  ExprContext cx{vars_, out_.diagnostics};
  node = parse_expression(cur, cx, tree);
  if (node < 0) return false;
  if (needs_end && !cur.at_end()) {
    error(Error::Syntax, cur.where(), "unexpected '" + cur.peek()->text + "'");
    return false;
  }
  if (stack_need(tree, node) > 50) {
    error(Error::ExpressionTooDeep, tree.nodes[static_cast<size_t>(node)].where);
    return false;
  }
  return true;
}

std::optional<int32_t> PupCompiler::constant(TokenCursor& cur, const char* what, bool needs_end) {
  ExprTree tree;
  int node = -1;
  const Location at = cur.where();
  if (!expression(cur, tree, node, needs_end)) return std::nullopt;
  const auto v = constant_of(tree, node);
  if (!v) error(Error::NotConstant, at, std::string(what) + " must be a constant");
  return v;
}

void PupCompiler::statement(std::vector<Token>& tokens, const Location& at) {
  if (tokens.empty()) return;
  Location end = at;
  end.column = tokens.back().where.column + static_cast<int>(tokens.back().text.size());
  TokenCursor cur(tokens, end);
  const Token& first = *cur.peek();
  if (first.kind == TokenKind::Name && is_flow_word(first.text)) {
    cur.take();
    flow(first.text, cur, first.where);
    return;
  }
  if (first.kind != TokenKind::Name)
    return error(Error::Syntax, first.where, "a statement starts with a name");
  message(cur, first.where);
}

// The false side of a condition: jumps to `label` when it does not hold (pup_expr.h's emit_jump).
void PupCompiler::condition_false_jump(const ExprTree& tree, int node, int label,
                                       const Location& at) {
  Code code;
  emit_jump(tree, node, false, code.new_label(), code);  // the code's label 0 is `label`
  place_code(code, at, label);
}

void PupCompiler::flow(const std::string& word, TokenCursor& cur, const Location& at) {
  auto needs_end = [&] {
    if (cur.at_end()) return true;
    error(Error::Syntax, cur.where(), "unexpected '" + cur.peek()->text + "'");
    return false;
  };
  auto open = [&](Block b) {
    if (blocks_.size() >= kMaxNesting) return error(Error::NestingTooDeep, at);
    blocks_.push_back(std::move(b));
  };
  ExprTree tree;
  int node = -1;
  if (word == "if" || word == "while") {
    if (!expression(cur, tree, node, true)) return;
    Block b{word == "if" ? BlockKind::If : BlockKind::While, at};
    b.end = new_label();
    if (b.kind == BlockKind::While) {
      b.cont = new_label();
      bind(b.cont);
    } else {
      b.next = new_label();
    }
    condition_false_jump(tree, node, b.kind == BlockKind::If ? b.next : b.end, at);
    open(std::move(b));
  } else if (word == "else") {
    if (blocks_.empty() || blocks_.back().kind != BlockKind::If || blocks_.back().seen_else) {
      return error(Error::MisplacedElse, at);
    }
    Block& b = blocks_.back();
    emit("AJump[1],", at, b.end);
    bind(b.next);
    b.next = new_label();
    if (cur.take_if("if")) {
      if (!expression(cur, tree, node, true)) return;
      condition_false_jump(tree, node, b.next, at);
    } else {
      b.seen_else = true;
      needs_end();
    }
  } else if (word == "end") {
    if (needs_end()) close_block(at);
  } else if (word == "for") {
    if (!cur.take_if("(")) return error(Error::Syntax, cur.where(), "'(' is expected");
    assignment(cur, at);
    if (!cur.take_if(",")) return error(Error::Syntax, cur.where(), "',' is expected");
    if (!expression(cur, tree, node, false)) return;
    if (!cur.take_if(",")) return error(Error::Syntax, cur.where(), "',' is expected");
    Block b{BlockKind::For, at};
    b.end = new_label();
    b.cont = new_label();
    const int top = new_label();
    b.next = top;
    bind(top);
    condition_false_jump(tree, node, b.end, at);
    const size_t before = lines_.size(), labels_before = labels_.size();
    assignment(cur, at);  // the step, compiled now and moved to the end of the loop
    b.step = take_code(before, labels_before);
    if (!cur.take_if(")") || !needs_end())
      return error(Error::Syntax, cur.where(), "')' is expected");
    open(std::move(b));
  } else if (word == "switch") {
    if (!expression(cur, tree, node, true)) return;
    Block b{BlockKind::Switch, at};
    emit_value(tree, node, b.step);
    b.next = new_label();
    b.end = new_label();
    emit("AJump[1],", at, b.next);
    open(std::move(b));
  } else if (word == "case" || word == "default") {
    if (blocks_.empty() || blocks_.back().kind != BlockKind::Switch)
      return error(Error::MisplacedCase, at);
    Block& b = blocks_.back();
    const int label = new_label();
    bind(label);
    if (word == "default") {
      if (b.default_label >= 0) return error(Error::DuplicateCase, at, "default");
      b.default_label = label;
      needs_end();
      return;
    }
    const auto v = constant(cur, "a case value", true);
    if (!v) return;
    for (const auto& c : b.cases) {
      if (c.first == *v) return error(Error::DuplicateCase, at, std::to_string(*v));
    }
    b.cases.push_back({*v, label});
  } else if (word == "break" || word == "continue") {
    Block* b = innermost(word == "continue");
    if (b == nullptr)
      return error(word == "break" ? Error::MisplacedBreak : Error::MisplacedContinue, at);
    if (needs_end()) emit("AJump[1],", at, word == "break" ? b->end : b->cont);
  } else if (word == "return" || word == "Return") {
    if (!needs_end()) return;
    emit("AReturn", at);
    function_returned_ = true;
  } else if (word == "GoTo") {
    if (!cur.take_if(",")) return error(Error::Syntax, cur.where(), "GoTo, TaskNumber");
    const auto task = constant(cur, "a task number", true);
    if (!task) return;
    lines_.push_back(OutLine{"AJump[1],", at, -1, *task});
    calls_.push_back({-1 - *task, at});  // checked against the tasks in finish()
  }
}

void PupCompiler::close_block(const Location& at) {
  if (blocks_.empty()) return error(Error::EndWithoutBlock, at);
  Block b = std::move(blocks_.back());
  blocks_.pop_back();
  switch (b.kind) {
    case BlockKind::If:
      bind(b.next);
      bind(b.end);
      break;
    case BlockKind::While:
      emit("AJump[1],", at, b.cont);
      bind(b.end);
      break;
    case BlockKind::For:
      bind(b.cont);
      place_code(b.step, at);
      emit("AJump[1],", at, b.next);
      bind(b.end);
      break;
    case BlockKind::Switch:
      emit("AJump[1],", at, b.end);
      bind(b.next);
      for (const auto& [value, label] : b.cases) {
        place_code(b.step, b.where);
        emit(fmt::format("APushConstant,{}", value), b.where);
        emit("AJump[3],", b.where, label);
      }
      emit("AJump[1],", b.where, b.default_label >= 0 ? b.default_label : b.end);
      bind(b.end);
      break;
  }
}

// `place = expression`: copied as `place=value` when the value is a constant.
void PupCompiler::assignment(TokenCursor& cur, const Location& at) {
  ExprContext cx{vars_, out_.diagnostics};
  ExprTree tree;
  const int place = parse_place(cur, cx, tree);
  if (place < 0) return;
  const Node& p = tree.nodes[static_cast<size_t>(place)];
  const Keyword* k = find_keyword(p.key);
  if (k != nullptr && k->kind != KeywordKind::Param)
    return error(Error::NotAssignable, p.where, "'" + p.key + "'");
  if (!cur.take_if("=")) {
    if (cur.at_end()) return error(Error::BareRead, p.where, "'" + p.key + "'");
    return error(Error::Syntax, cur.where(), "'=' is expected");
  }
  int value = -1;
  if (!expression(cur, tree, value, false)) return;
  const Node& target = tree.nodes[static_cast<size_t>(place)];
  Code lines;
  const auto v = constant_of(tree, value);
  if (target.kind == NodeKind::Param) {
    if (v) {
      emit(fmt::format("{}={}", param_text(target), *v), at);
      return;
    }
    emit_value(tree, value, lines);
    lines.line("APopParam," + param_text(target));
  } else {  // an element at a computed index: the value, then the index
    emit_value(tree, value, lines);
    emit_value(tree, target.a, lines);
    lines.line(fmt::format("APopParamIdx[{}],{}[{}]", target.size, target.key, target.base));
  }
  place_code(lines, at);
}

void PupCompiler::marker(const Keyword& k, int32_t index, const Location& at) {
  const bool task = k.id == KeywordId::ProgTask;
  close_function();
  auto& table = task ? tasks_ : functions_;
  if (!table.emplace(index, at).second) {
    return error(task ? Error::DuplicateTask : Error::DuplicateFunction, at, std::to_string(index));
  }
  if (!task) {
    open_function_ = {index, at};
    function_returned_ = false;
  }
  emit(fmt::format("{}[{}]", k.name, index), at);
}

void PupCompiler::close_function() {
  if (open_function_ && !function_returned_) {
    error(Error::NoReturn, open_function_->second,
          fmt::format("AProgFunc[{}]", open_function_->first));
  }
  open_function_.reset();
}

// A controller message: an assignment, or a command or CUP keyword with its index and argument.
void PupCompiler::message(TokenCursor& cur, const Location& at) {
  const Token& name = *cur.peek();
  const Keyword* k = vars_.count(name.text) != 0 ? nullptr : find_keyword(name.text);
  if (k == nullptr || k->kind == KeywordKind::Param || k->kind == KeywordKind::ReadOnly) {
    const size_t before = out_.diagnostics.size();
    assignment(cur, at);
    // The rest of the line after an error in it would only repeat that error.
    if (out_.diagnostics.size() == before && !cur.at_end()) {
      error(Error::Syntax, cur.where(), "unexpected '" + cur.peek()->text + "'");
    }
    return;
  }
  cur.take();
  if ((k->attrs & kInProgram) == 0)
    return error(Error::NotInProgram, name.where, "'" + std::string(k->name) + "'");
  std::string text(k->name);
  int32_t index = 0;
  if (cur.take_if("[")) {
    if (!k->indexed()) return error(Error::IndexNotAllowed, name.where, "'" + text + "'");
    const Location index_at = cur.where();
    const auto i = constant(cur, "an index", false);
    if (!i) return;
    if (!cur.take_if("]")) return error(Error::Syntax, cur.where(), "']' is expected");
    if (*i < k->index_min || *i > k->index_max)
      return error(Error::IndexOutOfRange, index_at, std::to_string(*i));
    index = *i;
    text += fmt::format("[{}]", index);
  } else if (k->indexed()) {
    return error(Error::IndexMissing, name.where, "'" + text + "'");
  }
  if (k->kind == KeywordKind::Marker) {
    if (!cur.at_end())
      return error(Error::Syntax, cur.where(), "unexpected '" + cur.peek()->text + "'");
    return marker(*k, index, at);
  }
  if (!cur.take_if(",")) {
    if (!cur.at_end())
      return error(Error::Syntax, cur.where(), "unexpected '" + cur.peek()->text + "'");
    if (k->arg != ArgKind::None) return error(Error::ArgumentMissing, name.where, "'" + text + "'");
    if (k->id == KeywordId::Return) function_returned_ = true;
    return emit(text, at);
  }
  if (k->arg == ArgKind::None)
    return error(Error::ArgumentNotAllowed, name.where, "'" + text + "'");
  if (k->arg == ArgKind::Name) {
    ExprContext cx{vars_, out_.diagnostics};
    ExprTree tree;
    const int place = parse_place(cur, cx, tree);
    if (place < 0) return;
    const Node& p = tree.nodes[static_cast<size_t>(place)];
    if (p.kind != NodeKind::Param)
      return error(Error::NotConstant, p.where, "the parameter's index");
    const bool pop = k->id == KeywordId::PopParam || k->id == KeywordId::PopParamIdx;
    if (pop && find_keyword(p.key)->kind != KeywordKind::Param) {
      return error(Error::NotAssignable, p.where, "'" + p.key + "'");
    }
    if (!cur.at_end())
      return error(Error::Syntax, cur.where(), "unexpected '" + cur.peek()->text + "'");
    return emit(text + "," + param_text(p), at);
  }
  const Location arg_at = cur.where();
  const auto v = constant(cur, "the argument", true);
  if (!v) return;
  if (k->id == KeywordId::ProgFuncCall || k->id == KeywordId::ProgCallFunc)
    calls_.push_back({*v, arg_at});
  emit(fmt::format("{},{}", text, *v), at);
}

void PupCompiler::finish() {
  close_function();
  for (const Block& b : blocks_) error(Error::UnclosedBlock, b.where);
  for (const auto& [f, where] : calls_) {
    if (f >= 0 && functions_.count(f) == 0) error(Error::UnknownFunction, where, std::to_string(f));
    if (f < 0 && tasks_.count(-1 - f) == 0)
      error(Error::UnknownTask, where, std::to_string(-1 - f));
  }
  for (const auto& [f, where] : events_) {
    if (functions_.count(f) == 0) error(Error::UnknownFunction, where, std::to_string(f));
  }
  if (!out_.ok()) return;
  std::map<int32_t, uint32_t> task_lines;
  for (size_t i = 0; i < lines_.size(); ++i) {
    for (const auto& [n, where] : tasks_) {
      if (lines_[i].text == fmt::format("AProgTask[{}]", n))
        task_lines[n] = static_cast<uint32_t>(i + 1);
    }
  }
  for (const OutLine& l : lines_) {
    std::string text = l.text;
    if (l.label >= 0) text += std::to_string(labels_[static_cast<size_t>(l.label)]);
    if (l.task_ref >= 0) text += std::to_string(task_lines[l.task_ref]);
    out_.program.lines.push_back(std::move(text));
    out_.places.push_back(l.where);
  }
}

}  // namespace uprog::pup
