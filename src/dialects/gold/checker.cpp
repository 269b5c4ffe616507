// Name resolution, kinds and semantic errors for Gold programs and command lines.
#include "dialects/gold/checker.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "dialects/gold/builtins.h"
#include "dialects/gold/commands.h"
#include "dialects/gold/ranges.h"

namespace uprog::gold {

Kind binary_kind(Tok op, Kind a, Kind b) {
  switch (op) {
    case Tok::Plus:
    case Tok::Minus:
    case Tok::Slash:
      if (a == Kind::Float || b == Kind::Float) return Kind::Float;
      if (a == Kind::Dynamic || b == Kind::Dynamic) return Kind::Dynamic;
      return Kind::Int;
    case Tok::Star:
      // int * int is exact when it fits and a float when it does not (manual 1.5).
      if (a == Kind::Float || b == Kind::Float) return Kind::Float;
      return Kind::Dynamic;
    default:
      return Kind::Int;  // %, bitwise, shifts, comparisons, logic
  }
}

Kind unary_kind(Tok op, Kind a) { return op == Tok::Minus ? a : Kind::Int; }

namespace {

// The manual's limits (2.17): 92 locals, 2040 words of globals.
constexpr size_t kMaxLocals = 92;
constexpr int64_t kMaxGlobalWords = 2040;

// Where an expression begins (a binary expression's own offset is its operator's).
uint32_t start_of(const Expr& e) {
  const Expr* x = &e;
  while (x->kind == ExprKind::Binary) x = x->lhs;
  return x->offset;
}

// find_command scans the whole table, case-insensitively; the checker asks about every declared
// name and every name that is not a variable, so it looks in an index of upper-case names.
const CommandInfo* command_named(std::string_view name) {
  struct Index {
    std::unordered_map<std::string, const CommandInfo*> by_name;  // upper case
    size_t longest = 0;
  };
  static const Index index = [] {
    Index x;
    for (const CommandInfo& c : all_commands()) {
      std::string key(c.name);
      for (char& ch : key) ch = ch >= 'a' && ch <= 'z' ? static_cast<char>(ch - 'a' + 'A') : ch;
      x.by_name.emplace(std::move(key), &c);
      x.longest = std::max(x.longest, c.name.size());
    }
    return x;
  }();
  if (name.size() > index.longest || name.size() > 16) return nullptr;
  char upper[16];
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    upper[i] = c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
  }
  const auto it = index.by_name.find(std::string(upper, name.size()));
  return it == index.by_name.end() ? nullptr : it->second;
}

bool const_index(const Expr& e, int32_t& out) {
  if (e.kind == ExprKind::IntLit) {
    out = e.int_value;
    return true;
  }
  return false;
}

}  // namespace

namespace detail {

// A function's own names (locals, local labels): few, looked up often, cleared for every function.
// A short list searched in order beats a hash table that allocates a node per name.
class NameList {
 public:
  size_t count(std::string_view name) const { return find(name) != nullptr ? 1 : 0; }
  const int* find(std::string_view name) const {
    for (const auto& [n, v] : items_)
      if (n == name) return &v;
    return nullptr;
  }
  int& operator[](std::string_view name) {
    for (auto& [n, v] : items_)
      if (n == name) return v;
    items_.emplace_back(name, 0);
    return items_.back().second;
  }
  void insert(std::string_view name) { (*this)[name]; }
  void clear() { items_.clear(); }

 private:
  std::vector<std::pair<std::string_view, int>> items_;
};

class Checker {
 public:
  explicit Checker(Reporter& r) : r_(r) {}

  // ---- the whole program, as the streaming driver runs it (program_compiler.cpp)

  void declare(Program& p) {
    declare_globals(p.globals, 0);
    for (FunctionDef& f : p.functions) declare_function(f);
    declare_top_labels(p.top, 0);
  }

  // The symbol whose body `f` is, or -1 when its body is not checked (refused, or a second body).
  int symbol_for_body(const FunctionDef& f) const {
    if (!f.has_body) return -1;
    auto it = function_index_.find(f.name);
    if (it == function_index_.end()) return -1;  // refused when declared
    return syms_.functions[static_cast<size_t>(it->second)].def == &f ? it->second : -1;
  }

  // Checks a body against what `p` declares so far, keeping every error and effect in `out`.
  void speculate(Program& p, FunctionDef& f, Block& body, CheckedBody& out,
                 std::vector<uint32_t>& queried) {
    // Declarations met since the last body; their errors belong to the final pass.
    std::vector<CapturedError> ignored;
    capture_ = &ignored;
    declare_globals(p.globals, globals_seen_);
    globals_seen_ = p.globals.size();
    for (; functions_seen_ < p.functions.size(); ++functions_seen_)
      declare_function(p.functions[functions_seen_]);
    declare_top_labels(p.top, top_seen_);
    top_seen_ = p.top.size();
    out.symbol = symbol_for_body(f);
    out.checked = out.symbol >= 0;
    if (out.checked) {
      capture_ = &out.errors;
      queried_ = &queried;
      queries_begin_ = queried.size();
      poisoned_added_ = &out.poisoned;
      const size_t labels = syms_.labels.size();
      function_body(f, out.symbol, body);
      out.labels.assign(syms_.labels.begin() + static_cast<std::ptrdiff_t>(labels),
                        syms_.labels.end());
    }
    capture_ = nullptr;
    queried_ = nullptr;
    poisoned_added_ = nullptr;
  }

  // A speculative check that still holds: its errors and effects as if checked here.
  void accept(int symbol, CheckedBody& spec) {
    for (const CapturedError& e : spec.errors) r_.error(e.code, e.offset, e.name);
    for (LabelSym& l : spec.labels) {
      l.function = symbol;
      syms_.labels.push_back(std::move(l));
    }
    for (std::string_view n : spec.poisoned) poisoned_.insert(n);
  }

  // A body's locals are needed until it is generated, then no more (its code keeps them).
  void forget_locals(int symbol) {
    std::vector<LocalSym>().swap(syms_.functions[static_cast<size_t>(symbol)].locals);
  }

  void check_body(FunctionDef& f, int symbol, Block& body) { function_body(f, symbol, body); }

  void check_top(Program& p) {
    current_ = -1;
    locals_.clear();
    block(p.top);
  }

  Symbols& symbols() { return syms_; }

  void line(Block& b, const std::vector<KnownGlobal>& known) {
    for (const KnownGlobal& g : known) {
      global_index_[g.name] = static_cast<int>(syms_.globals.size());
      syms_.globals.push_back({g.name, g.type, g.length, 0});
    }
    current_ = -1;
    block(b);
  }

 private:
  // `name`: what the error is about, quoted after the manual's text. Cold: kept out of the
  // checking paths it is called from.
  [[gnu::cold, gnu::noinline]] void error(Error e, uint32_t offset, std::string_view name = {}) {
    if (capture_)
      capture_->push_back({e, offset, name});
    else
      r_.error(e, offset, name);
  }

  // A name whose meaning a later declaration could change (a function, a label): while
  // speculating, the driver must know it was asked about.
  void note(std::string_view name) {
    if (queried_ == nullptr) return;
    const uint32_t h = name_hash(name);
    for (size_t i = queried_->size(), k = 0; i-- > queries_begin_ && k < 8; ++k)  // this body's
      if ((*queried_)[i] == h) return;
    queried_->push_back(h);
  }

  void poison(std::string_view name) {
    if (poisoned_.insert(name).second && poisoned_added_) poisoned_added_->push_back(name);
  }

  bool clashes_with_system(std::string_view name) {
    return command_named(name) != nullptr || find_builtin(name) != nullptr;
  }

  void declare_globals(const std::vector<VarDecl>& globals, size_t from) {
    int64_t& words = global_words_;
    for (size_t i = from; i < globals.size(); ++i) {
      const VarDecl& d = globals[i];
      if (global_index_.count(d.name) || clashes_with_system(d.name)) {
        error(Error::NameIsNotDistinct, d.offset, d.name);
        continue;
      }
      words += d.length == 0 ? 1 : d.length;
      if (words > kMaxGlobalWords) {
        error(Error::OutOfDataMemory, d.offset, d.name);
        continue;
      }
      global_index_[d.name] = static_cast<int>(syms_.globals.size());
      syms_.globals.push_back({std::string(d.name), d.type, d.length, d.offset});
    }
  }

  static bool same_signature(const FunctionDef& a, const FunctionDef& b) {
    auto same = [](const std::vector<Param>& x, const std::vector<Param>& y) {
      if (x.size() != y.size()) return false;
      for (size_t i = 0; i < x.size(); ++i)
        if (x[i].type != y[i].type) return false;
      return true;
    };
    return same(a.inputs, b.inputs) && same(a.outputs, b.outputs);
  }

  void declare_function(FunctionDef& f) {
    {
      auto it = function_index_.find(f.name);
      if (it == function_index_.end()) {
        if (global_index_.count(f.name) || clashes_with_system(f.name)) {
          error(Error::NameIsNotDistinct, f.offset, f.name);  // "int func / function func(int a)"
          return;
        }
        function_index_[f.name] = static_cast<int>(syms_.functions.size());
        FunctionSym s;
        s.name = std::string(f.name);
        s.def = &f;
        s.has_body = f.has_body;
        s.is_auto = f.is_auto;
        s.inputs = f.inputs.size();
        s.outputs = f.outputs.size();
        syms_.functions.push_back(std::move(s));
        return;
      }
      FunctionSym& s = syms_.functions[static_cast<size_t>(it->second)];
      if (!same_signature(*s.def, f)) {
        error(Error::BadFunctionFormat, f.offset,
              f.name);  // the definition differs from its prototype
        return;
      }
      if (f.has_body && s.has_body) {
        error(Error::FunctionAlreadyHasBody, f.offset, f.name);
        return;
      }
      if (f.has_body) {
        s.def = &f;
        s.has_body = true;
      }
    }
  }

  void declare_top_labels(const std::vector<StmtPtr>& top, size_t from) {
    for (size_t i = from; i < top.size(); ++i) {
      const StmtPtr& s = top[i];
      if (s->kind != StmtKind::Label) continue;
      if (top_labels_.count(s->name) || (!s->auto_label && function_index_.count(s->name))) {
        error(Error::NameIsNotDistinct, s->offset, s->name);
        continue;
      }
      if (s->auto_label) {
        auto it = function_index_.find(s->name);
        if (it != function_index_.end()) {
          error(Error::NameIsNotDistinct, s->offset,
                s->name);  // both #@AUTO_I1 and function AUTO_I1()
          continue;
        }
      }
      top_labels_[s->name] = static_cast<int>(syms_.labels.size());
      syms_.labels.push_back({std::string(s->name), s->auto_label, -1, s->offset});
    }
  }

  void collect_local_labels(const Block& b, int function) {
    for (const StmtPtr& s : b) {
      if (s->kind != StmtKind::Label) continue;
      if (local_labels_.count(s->name)) {
        error(Error::NameIsNotDistinct, s->offset, s->name);
        continue;
      }
      local_labels_[s->name] = static_cast<int>(syms_.labels.size());
      syms_.labels.push_back({std::string(s->name), false, function, s->offset});
    }
  }

  void function_body(FunctionDef& f, int index, Block& body) {
    current_ = index;
    current_def_ = &f;
    locals_.clear();
    local_labels_.clear();
    redeclared_.clear();
    FunctionSym& s = syms_.functions[static_cast<size_t>(index)];
    s.locals.clear();
    auto add_local = [&](std::string_view name, VarType type, uint32_t offset) {
      if (locals_.count(name) || redeclared_.count(name)) {
        error(Error::NameIsNotDistinct, offset, name);  // "function func(int a) / int a"
        return;
      }
      if (clashes_with_system(name)) {
        error(Error::NameIsNotDistinct, offset, name);
        return;
      }
      note(name);
      if (function_index_.count(name)) {
        error(Error::NameIsNotDistinct, offset, name);
        return;
      }
      if (s.locals.size() == kMaxLocals) {
        error(Error::TooManyVariables, offset);
        return;
      }
      locals_[name] = static_cast<int>(s.locals.size());
      s.locals.push_back({std::string(name), type});
    };
    for (const Param& p : f.inputs) add_local(p.name, p.type, p.offset);
    for (const Param& p : f.outputs) add_local(p.name, p.type, p.offset);
    // Inputs and outputs keep their slots even after an error, so calls still line up.
    while (s.locals.size() < f.inputs.size() + f.outputs.size())
      s.locals.push_back({"", VarType::Int});
    for (const VarDecl& d : f.locals) {
      if (d.is_global_redecl) {
        auto it = global_index_.find(d.name);
        const GlobalSym* g =
            it == global_index_.end() ? nullptr : &syms_.globals[static_cast<size_t>(it->second)];
        if (g == nullptr || g->offset > f.offset || g->type != d.type || g->length != d.length) {
          error(Error::IllegalGlobal, d.offset, d.name);  // not defined before, or another type
          continue;
        }
        if (locals_.count(d.name)) {
          error(Error::NameIsNotDistinct, d.offset, d.name);
          continue;
        }
        redeclared_.insert(d.name);
        continue;
      }
      add_local(d.name, d.type, d.offset);
    }
    collect_local_labels(body, index);
    block(body);
    current_def_ = nullptr;
  }

  // ---- statements

  void block(Block& b) {
    for (StmtPtr& s : b) statement(*s);
  }

  void statement(Stmt& s) {
    switch (s.kind) {
      case StmtKind::Expr:
        expression_statement(s);
        break;
      case StmtKind::Assign:
        assignment(s);
        break;
      case StmtKind::IncDec:
        lvalue(*s.targets[0]);
        break;
      case StmtKind::If:
        for (IfArm& a : s.arms) {
          if (a.cond) value(*a.cond);
          block(a.body);
        }
        break;
      case StmtKind::While:
        if (s.value) value(*s.value);
        block(s.body);
        break;
      case StmtKind::For:
        for_loop(s);
        break;
      case StmtKind::Until:
      case StmtKind::Wait:
        value(*s.value);
        break;
      case StmtKind::Switch:
        if (s.value) value(*s.value);
        for (SwitchCase& c : s.cases) {
          if (c.value) value(*c.value);
          block(c.body);
        }
        break;
      case StmtKind::Try:
        block(s.body);
        block(s.handler);
        break;
      case StmtKind::Goto:
        jump(s);
        break;
      case StmtKind::Reset:
        reset(s);
        break;
      case StmtKind::Break:
      case StmtKind::Continue:
      case StmtKind::Return:
      case StmtKind::Exit:
      case StmtKind::Label:
        break;
    }
  }

  void expression_statement(Stmt& s) {
    Expr& e = *s.value;
    if (e.kind == ExprKind::Ref) {
      resolve(e);
      if (e.ref == RefKind::Function) {
        call(e, 0);
        return;
      }
      if (e.ref == RefKind::Command && e.command && (e.command->flags & kAction)) {
        command_use(e, false);
        return;
      }
    }
    value(e);
  }

  void assignment(Stmt& s) {
    Expr& rhs = *s.value;
    if (s.bracketed) {
      // [a, b] = f(x): the right side must be one call of a function with enough outputs.
      const size_t n = s.targets.size();
      if (rhs.kind == ExprKind::Ref) {
        resolve(rhs);
        if (rhs.ref == RefKind::Function)
          call(rhs, n);
        else if (n > 1 && rhs.ref != RefKind::Unresolved)
          error(Error::SidesMismatch, rhs.offset);
        else
          value(rhs);
      } else if (rhs.kind == ExprKind::Unary && rhs.op == Tok::Minus &&
                 rhs.lhs->kind == ExprKind::Ref && rhs.lhs->has_parens) {
        value(rhs);  // "[a, b] = -func(c)": a minus before a call of several outputs is 34
        const Expr& x = *rhs.lhs;
        const bool several =
            x.ref == RefKind::Function && syms_.functions[static_cast<size_t>(x.slot)].outputs > 1;
        if (!several && n > 1) error(Error::SidesMismatch, start_of(rhs));
      } else {
        const Expr* left = &rhs;
        while (left->kind == ExprKind::Binary) left = left->lhs;
        if (left->kind == ExprKind::Ref && left->has_parens) note(left->name);
        const bool call_first = left->kind == ExprKind::Ref && left->has_parens &&
                                function_index_.count(left->name) > 0;
        if (call_first)
          error(Error::BadFunctionCall, start_of(rhs), left->name);  // "[a,b] = f(x) + 5"
        else if (n > 1)
          error(Error::SidesMismatch, start_of(rhs));  // "[a,b] = 12 + c"
        else
          value(rhs);
      }
    } else {
      value(rhs);
    }
    for (ExprPtr& t : s.targets) lvalue(*t);
  }

  void for_loop(Stmt& s) {
    if (!s.targets.empty()) {
      Expr& v = *s.targets[0];
      resolve(v, /*quiet=*/true);
      if (v.ref != RefKind::Local && v.ref != RefKind::Global) {
        error(Error::VariableIsUndefined, v.offset, v.name);
        poison(v.name);  // one error for the loop, not one per use
        v.ref = RefKind::Unresolved;
      } else if (v.has_index || v.has_parens ||
                 (v.ref == RefKind::Global && global(v).length > 0)) {
        error(Error::VariableIsArray, v.offset, v.name);  // "for k[10]=1:10"
        v.ref = RefKind::Unresolved;
      } else {
        v.type = variable_kind(v);
      }
    }
    if (s.value) value(*s.value);
    if (s.step) value(*s.step);
    if (s.end) value(*s.end);
    // Inside the body a local int loop variable with constant bounds stays within them, unless
    // the body assigns it (only its own frame can: it is a local).
    IntRange r;
    const bool known = !s.targets.empty() && s.targets[0]->ref == RefKind::Local &&
                       s.targets[0]->type == Kind::Int && !s.targets[0]->has_index &&
                       !s.targets[0]->has_parens && constant_loop_range(s, r) &&
                       !block_assigns(s.body, s.targets[0]->name);
    if (known) loops_.push_back({s.targets[0]->name, r});
    block(s.body);
    if (known) loops_.pop_back();
  }

  // goto: ##name to a label of the same scope, #@name to an auto-routine (top level only).
  void jump(Stmt& s) {
    const bool in_function = current_ >= 0;
    note(s.name);
    if (in_function && !s.auto_label && local_labels_.count(s.name)) return;
    if (!in_function && top_labels_.count(s.name) &&
        syms_.labels[static_cast<size_t>(top_labels_[s.name])].is_auto == s.auto_label)
      return;
    if (!in_function && s.auto_label && function_index_.count(s.name) &&
        syms_.functions[static_cast<size_t>(function_index_[s.name])].is_auto)
      return;
    const bool known =
        top_labels_.count(s.name) || function_index_.count(s.name) || any_local_label(s.name);
    error(known ? Error::BadJumpToLabel : Error::NoSuchFunction, s.offset, s.name);
  }

  bool any_local_label(std::string_view name) const {
    for (const LabelSym& l : syms_.labels)
      if (l.function >= 0 && l.name == name) return true;
    return false;
  }

  // reset: an auto-routine, a global label or a function without inputs.
  void reset(Stmt& s) {
    note(s.name);
    if (top_labels_.count(s.name)) return;
    auto it = function_index_.find(s.name);
    if (it != function_index_.end()) {
      if (syms_.functions[static_cast<size_t>(it->second)].inputs > 0)
        error(Error::BadFunctionAfterReset, s.offset, s.name);
      return;
    }
    error(any_local_label(s.name) || local_labels_.count(s.name) ? Error::BadJumpToLabel
                                                                 : Error::NoSuchFunction,
          s.offset, s.name);
  }

  // ---- names

  const GlobalSym& global(const Expr& e) const {
    return syms_.globals[static_cast<size_t>(e.slot)];
  }

  Kind variable_kind(const Expr& e) const {
    if (e.ref == RefKind::Local)
      return kind_of(
          syms_.functions[static_cast<size_t>(current_)].locals[static_cast<size_t>(e.slot)].type);
    return kind_of(global(e).type);
  }

  // Decides what a name is; reports 12 when it is nothing (unless `quiet`).
  void resolve(Expr& e, bool quiet = false) {
    if (e.ref != RefKind::Unresolved) return;
    if (current_ >= 0) {
      if (const int* local = locals_.find(e.name)) {
        e.ref = RefKind::Local;
        e.slot = *local;
        return;
      }
    }
    auto g = global_index_.find(e.name);
    if (g != global_index_.end()) {
      const GlobalSym& sym = syms_.globals[static_cast<size_t>(g->second)];
      // A global is seen after its declaration (manual 2.6.2); inside a function also without
      // a `global` line, as the manual's own example in 1.11 does.
      if (sym.offset <= e.offset || redeclared_.count(e.name)) {
        e.ref = RefKind::Global;
        e.slot = g->second;
        return;
      }
    }
    auto f = function_index_.find(e.name);
    if (f != function_index_.end()) {
      note(e.name);
      e.ref = RefKind::Function;
      e.slot = f->second;
      return;
    }
    if (const BuiltinInfo* b = find_builtin(e.name)) {
      e.ref = RefKind::Builtin;
      e.builtin = b->id;
      return;
    }
    if (const CommandInfo* c = command_named(e.name)) {
      e.ref = RefKind::Command;
      e.command = c;
      return;
    }
    note(e.name);  // a function declared later would be this name
    if (!quiet && !poisoned_.count(e.name)) error(Error::NoSuchVariable, e.offset, e.name);
  }

  // A variable's [index] or (index): one value; a scalar takes only index 0.
  void variable_index(Expr& e, bool is_array) {
    if (e.has_parens && e.args.size() != 1) {
      error(Error::BadIndexExpression, e.offset, e.name);
      return;
    }
    if (!e.has_index && !e.has_parens) {
      if (is_array) error(Error::VariableIsArray, e.offset, e.name);  // "arr = 0"
      return;
    }
    Expr& index = *e.args[0];
    value(index);
    if (!is_array) {
      int32_t k = 0;
      const bool constant = const_index(index, k);
      // A scalar global indexed [0] is the scalar. Inside a function any other index of a
      // global scalar is checked when it runs: manual 1.11's note and example 2 ("the compiler
      // will not report about any error. The program will be terminated"). In global code a
      // constant one is error 58, the table's example (`##START a1[1] = 0`); a local scalar
      // takes no other index (docs/dialects/gold.md, decision 8).
      const bool run_time = e.ref == RefKind::Global && (!constant || current_ >= 0);
      if (constant && k != 0 && !run_time) error(Error::VariableIsNotArray, e.offset, e.name);
      if (!constant && e.ref == RefKind::Local) error(Error::VariableIsNotArray, e.offset, e.name);
    }
  }

  void command_use(Expr& e, bool assigned) {
    const CommandInfo& c = *e.command;
    if (c.flags & kNotProgram) {
      error(Error::CommandNotProgram, e.offset, e.name);
      return;
    }
    if (assigned && (c.flags & (kNotAssignable | kReadOnly | kAction))) {
      error(Error::CommandNotAssign, e.offset, e.name);  // "BG=10"
      return;
    }
    if (e.has_parens) {
      error(Error::BadIndexExpression, e.offset, e.name);
      return;
    }
    if (c.flags & kIndexed) {
      if (e.has_index)
        value(*e.args[0]);
      else if (!(c.flags & kIndexOptional))
        error(Error::BadIndexExpression, e.offset, e.name);
    } else if (e.has_index) {
      error(Error::VariableIsNotArray, e.offset, e.name);
    }
    e.type = kind_of(c.type);
  }

  // A call of a user function used for `wanted` outputs.
  void call(Expr& e, size_t wanted) {
    FunctionSym& f = syms_.functions[static_cast<size_t>(e.slot)];
    for (ExprPtr& a : e.args) value(*a);
    if (e.has_index) {
      error(Error::BadIndexExpression, e.offset, e.name);
      return;
    }
    if (e.args.size() != f.inputs) error(Error::BadNumberOfInputs, e.offset, e.name);
    if (wanted > f.outputs) error(Error::TooManyOutputs, e.offset, e.name);
    if (!f.has_body) error(Error::FunctionWithoutBody, e.offset, e.name);
    e.type = f.outputs > 0 ? kind_of(f.def->outputs[0].type) : Kind::None;
    e.int_value = static_cast<int32_t>(wanted);  // nargout of this call
  }

  void lvalue(Expr& e) {
    if (e.kind != ExprKind::Ref) {
      error(Error::BadFormat, e.offset);
      return;
    }
    resolve(e);
    switch (e.ref) {
      case RefKind::Local:
        variable_index(e, false);
        e.type = variable_kind(e);
        break;
      case RefKind::Global:
        variable_index(e, global(e).length > 0);
        e.type = variable_kind(e);
        break;
      case RefKind::Command:
        command_use(e, true);
        break;
      case RefKind::Function:
      case RefKind::Builtin:
        error(Error::NoSuchVariable, e.offset, e.name);
        break;
      default:
        break;
    }
  }

  // An expression used for its value.
  void value(Expr& e) {
    switch (e.kind) {
      case ExprKind::IntLit:
        e.type = Kind::Int;
        return;
      case ExprKind::FloatLit:
        e.type = Kind::Float;
        return;
      case ExprKind::Nargout:
        if (current_ < 0) error(Error::IllegalNargout, e.offset);
        e.type = Kind::Int;
        return;
      case ExprKind::Unary: {
        value(*e.lhs);
        const Expr& x = *e.lhs;
        if (e.op == Tok::Minus && x.kind == ExprKind::Ref && x.ref == RefKind::Function &&
            syms_.functions[static_cast<size_t>(x.slot)].outputs > 1)
          error(Error::IllegalMinus, e.offset);  // "[ab] = -func(c)"
        e.type = unary_kind(e.op, x.type == Kind::None ? Kind::Int : x.type);
        return;
      }
      case ExprKind::Binary: {
        value(*e.lhs);
        value(*e.rhs);
        if ((e.op == Tok::Slash || e.op == Tok::Percent) &&
            ((e.rhs->kind == ExprKind::IntLit && e.rhs->int_value == 0) ||
             (e.rhs->kind == ExprKind::FloatLit && e.rhs->float_value == 0.0f)))
          error(Error::DivisionByZero, e.rhs->offset);
        const Kind a = e.lhs->type == Kind::None ? Kind::Int : e.lhs->type;
        const Kind b = e.rhs->type == Kind::None ? Kind::Int : e.rhs->type;
        e.type = binary_kind(e.op, a, b);
        // int * int is a pair only because it may overflow (1.5): not when it provably fits.
        if (e.op == Tok::Star && a == Kind::Int && b == Kind::Int &&
            product_fits(*e.lhs, *e.rhs, loops_))
          e.type = Kind::Int;
        return;
      }
      case ExprKind::Ref:
        break;
    }
    resolve(e);
    e.type = Kind::Int;
    switch (e.ref) {
      case RefKind::Local:
        variable_index(e, false);
        e.type = variable_kind(e);
        return;
      case RefKind::Global:
        variable_index(e, global(e).length > 0);
        e.type = variable_kind(e);
        return;
      case RefKind::Function:
        call(e, 1);
        if (e.type == Kind::None) e.type = Kind::Int;
        return;
      case RefKind::Builtin: {
        const BuiltinInfo& b = *builtin_info(e.builtin);
        for (ExprPtr& a : e.args) value(*a);
        if (!e.has_parens || e.args.size() != 1) {
          error(e.has_index ? Error::BadIndexExpression : Error::BadNumberOfInputs, e.offset,
                e.name);
          return;
        }
        e.type = b.result == BuiltinResult::SameAsInput ? e.args[0]->type : b.kind;
        if (e.type == Kind::None) e.type = Kind::Int;
        return;
      }
      case RefKind::Command:
        if (e.command->flags & kAction) {
          if (e.command->flags & kNotProgram)
            error(Error::CommandNotProgram, e.offset, e.name);
          else
            error(Error::ValueIsExpected, e.offset, e.name);  // an action has no value
          return;
        }
        command_use(e, false);
        return;
      default:
        return;
    }
  }

  Reporter& r_;
  Symbols syms_;
  std::unordered_map<std::string_view, int> global_index_, function_index_, top_labels_;
  NameList local_labels_, locals_, redeclared_;
  std::unordered_set<std::string_view> poisoned_;
  int current_ = -1;
  const FunctionDef* current_def_ = nullptr;
  std::vector<LoopRange> loops_;  // the enclosing loops whose variable's range is known
  int64_t global_words_ = 0;
  // Speculation: how far the declarations were taken in, where errors and names go.
  size_t globals_seen_ = 0, functions_seen_ = 0, top_seen_ = 0;
  std::vector<CapturedError>* capture_ = nullptr;
  std::vector<uint32_t>* queried_ = nullptr;
  size_t queries_begin_ = 0;
  std::vector<std::string_view>* poisoned_added_ = nullptr;
};

}  // namespace detail

ProgramChecker::ProgramChecker(Reporter& reporter)
    : c_(std::make_unique<detail::Checker>(reporter)) {}
ProgramChecker::~ProgramChecker() = default;
void ProgramChecker::declare(Program& p) { c_->declare(p); }
int ProgramChecker::symbol_for_body(const FunctionDef& f) const { return c_->symbol_for_body(f); }
void ProgramChecker::speculate(Program& p, FunctionDef& f, Block& body, CheckedBody& out,
                               std::vector<uint32_t>& queried) {
  c_->speculate(p, f, body, out, queried);
}
void ProgramChecker::accept(int symbol, CheckedBody& spec) { c_->accept(symbol, spec); }
void ProgramChecker::check_body(FunctionDef& f, int symbol, Block& body) {
  c_->check_body(f, symbol, body);
}
void ProgramChecker::check_top(Program& p) { c_->check_top(p); }
void ProgramChecker::forget_locals(int symbol) { c_->forget_locals(symbol); }
Symbols& ProgramChecker::symbols() { return c_->symbols(); }

void check_line(Block& block, const std::vector<KnownGlobal>& known, Reporter& reporter) {
  detail::Checker c(reporter);
  c.line(block, known);
}

}  // namespace uprog::gold
