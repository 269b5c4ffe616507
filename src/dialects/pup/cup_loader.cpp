// The CUP loader (cup_loader.h): each line parsed and checked, the stack depths proved at the
// CUP level (so a refusal names its line), then the code emitted, one EOL per executed line.
#include "dialects/pup/cup_loader.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <map>

#include "bytecode/code_builder.h"
#include "dialects/pup/cup_code.h"
#include "dialects/pup/cup_math.h"
#include "dialects/pup/line_op.h"
#include "dialects/pup/line_runs.h"
#include "dialects/pup/message.h"

namespace uprog::pup {
namespace {

using bytecode::Op;

constexpr int32_t kMaxDepth = 50;

struct Refusal {
  uint32_t line;
  std::string why;
};

// Parses and checks one line alone; the why on a refusal.
std::optional<std::string> parse_line(const std::string& text, LineOp& op, size_t line_count) {
  if (text.empty()) return "empty line";
  // No blanks, but one after a comma, as the manual's Demo1 listing and the vendor's compiler
  // write it (`AWaitTime, 3000`).
  for (size_t at = text.find_first_of(" \t"); at != std::string::npos;
       at = text.find_first_of(" \t", at + 1)) {
    const bool after_comma = text[at] == ' ' && at > 0 && text[at - 1] == ',';
    if (!after_comma) return "blanks in a program line";
  }
  int32_t code = 0;
  auto m = parse_message(text, &code);
  if (!m) return fmt::format("syntax (error {})", code);
  op.msg = *m;
  op.key = find_keyword(m->target.key);
  if (op.key == nullptr) return "unknown keyword '" + m->target.key + "'";
  const Keyword& k = *op.key;
  if ((k.attrs & kInProgram) == 0)
    return fmt::format("'{}' is not allowed in a program (error 14)", k.name);
  if (k.indexed() != m->target.has_index)
    return fmt::format("'{}' {}", k.name, k.indexed() ? "needs an index" : "takes no index");
  if (k.indexed() && (m->target.index < k.index_min || m->target.index > k.index_max)) {
    return fmt::format("index {} of '{}' out of range", m->target.index, k.name);
  }
  const bool has_arg = m->tail == Message::Tail::Argument;
  if (m->tail == Message::Tail::Assign) {
    if (k.kind != KeywordKind::Param) return fmt::format("'{}' is not assignable", k.name);
    return std::nullopt;
  }
  if (k.kind == KeywordKind::Param || k.kind == KeywordKind::ReadOnly) {
    return fmt::format("a bare read of '{}'", k.name);
  }
  if ((k.arg != ArgKind::None) != has_arg)
    return fmt::format("'{}' {}", k.name, has_arg ? "takes no argument" : "needs an argument");
  if (k.arg == ArgKind::Name) {
    if (!m->tail_is_name) return fmt::format("'{}' needs a parameter's name", k.name);
    op.name_key = find_keyword(m->name.key);
    const Keyword* n = op.name_key;
    if (n == nullptr || (n->kind != KeywordKind::Param && n->kind != KeywordKind::ReadOnly)) {
      return "no parameter named '" + m->name.key + "'";
    }
    if (n->indexed() != m->name.has_index)
      return fmt::format("'{}' {}", n->name, n->indexed() ? "needs an index" : "takes no index");
    if (n->indexed() && (m->name.index < n->index_min || m->name.index > n->index_max)) {
      return fmt::format("index {} of '{}' out of range", m->name.index, n->name);
    }
    const bool pop = k.id == KeywordId::PopParam || k.id == KeywordId::PopParamIdx;
    if (pop && n->kind != KeywordKind::Param) return fmt::format("'{}' is read only", n->name);
    if (k.id == KeywordId::PushParamIdx || k.id == KeywordId::PopParamIdx) {
      if (!n->indexed() || m->name.index + m->target.index - 1 > n->index_max) {
        return fmt::format("'{}[{}]' has no {} elements", n->name, m->name.index, m->target.index);
      }
    }
  } else if (has_arg && m->tail_is_name) {
    return fmt::format("'{}' needs a number", k.name);
  }
  const int32_t i = m->target.index, v = m->value;
  switch (k.id) {
    case KeywordId::PushConstant:
    case KeywordId::PushParam:
    case KeywordId::GetStatus:
      op.pushes = 1;
      break;
    case KeywordId::PopParam:
      op.pops = 1;
      break;
    case KeywordId::PushParamIdx:
      op.pops = 1, op.pushes = 1;
      break;
    case KeywordId::PopParamIdx:
      op.pops = 2;
      break;
    case KeywordId::Math:
      if (math_arity(i) == 0) return fmt::format("no AMath[{}]", i);
      op.pops = math_arity(i), op.pushes = 1;
      break;
    case KeywordId::Compare:
      if (condition_arity(i) == 0) return fmt::format("no ACompare[{}]", i);
      op.pops = condition_arity(i), op.pushes = 1;
      break;
    case KeywordId::Jump:
      op.pops = condition_arity(i);
      op.falls_through = i != 1;
      if (v < 1 || static_cast<size_t>(v) > line_count + 1)
        return fmt::format("jump to line {}, which is not there", v);
      op.target = static_cast<uint32_t>(v);
      break;
    case KeywordId::Return:
      op.falls_through = false;
      break;
    case KeywordId::WaitTime:
      if (v < 0) return "a negative wait";
      break;
    default:
      break;
  }
  return std::nullopt;
}

class Loader {
 public:
  explicit Loader(const CupProgram& p) : p_(p), ops_(p.lines.size() + 1) {}

  std::optional<LoadedCup> run(std::string* error, uint32_t* refused_line) {
    if (auto r = parse(); r || (r = markers()) || (r = analyse())) {
      if (error) *error = fmt::format("line {}: {}", r->line, r->why);
      if (refused_line) *refused_line = r->line;
      return std::nullopt;
    }
    generate();
    return std::move(out_);
  }

 private:
  size_t count() const { return p_.lines.size(); }

  std::optional<Refusal> parse() {
    for (size_t i = 0; i < count(); ++i) {
      if (auto why = parse_line(p_.lines[i], ops_[i + 1], count()))
        return Refusal{static_cast<uint32_t>(i + 1), *why};
    }
    return std::nullopt;
  }

  std::optional<Refusal> markers() {
    out_.task_routine.assign(65, -1);
    out_.event_routine.assign(24, -1);
    for (uint32_t l = 1; l <= count(); ++l) {
      const LineOp& op = ops_[l];
      if (op.key->kind != KeywordKind::Marker) continue;
      auto& table = op.key->id == KeywordId::ProgTask ? tasks_ : functions_;
      if (!table.emplace(op.msg.target.index, l).second) return Refusal{l, "defined twice"};
    }
    for (uint32_t l = 1; l <= count(); ++l) {
      const LineOp& op = ops_[l];
      if ((op.key->id == KeywordId::ProgFuncCall || op.key->id == KeywordId::ProgCallFunc) &&
          functions_.count(op.msg.value) == 0) {
        return Refusal{l, fmt::format("no function {}", op.msg.value)};
      }
    }
    for (const CupEvent& e : p_.events) {
      if (e.event < 0 || e.event > 23) return Refusal{0, fmt::format("no event {}", e.event)};
      if (functions_.count(e.function) == 0)
        return Refusal{0, fmt::format("event {}: no function {}", e.event, e.function)};
    }
    return std::nullopt;
  }

  // Every line's stack depth from every entry, one depth per line; AReturn at depth 0.
  std::optional<Refusal> analyse() {
    depth_.assign(count() + 2, -1);
    std::vector<uint32_t> work;  // lines whose depth is known and whose successors are not
    if (count() > 0 && ops_[1].key->id != KeywordId::ProgTask) work.push_back(1);
    for (const auto& [n, line] : tasks_) work.push_back(line);
    for (const auto& [n, line] : functions_) work.push_back(line);
    for (uint32_t line : work) depth_[line] = 0;
    while (!work.empty()) {
      const uint32_t l = work.back();
      work.pop_back();
      if (l > count()) continue;
      LineOp& op = ops_[l];
      const int32_t d = depth_[l];
      const int32_t after = d - op.pops + op.pushes;
      if (d < op.pops || after > kMaxDepth) {
        op.fails = d < op.pops ? 27 : 26;  // stack empty, stack full: when the line runs
        continue;
      }
      if (op.key->id == KeywordId::Return && d != 0)
        return Refusal{l, "AReturn with values on the stack"};
      auto flow = [&](uint32_t to) -> std::optional<Refusal> {
        if (depth_[to] >= 0 && depth_[to] != after)
          return Refusal{to, "reachable at two stack depths"};
        if (depth_[to] == after) return std::nullopt;
        depth_[to] = after;
        work.push_back(to);
        return std::nullopt;
      };
      if (op.falls_through) {
        if (auto r = flow(l + 1)) return r;
      }
      if (op.target != 0) {
        if (auto r = flow(op.target)) return r;
      }
    }
    return std::nullopt;
  }

  void push_constant(bytecode::CodeBuilder& b, int32_t v) {
    if (bytecode::fits_imm(v)) {
      b.emit_imm(Op::PUSHI, v);
      return;
    }
    out_.image.constants.push_back({ValueType::Int, static_cast<uint32_t>(v)});
    b.emit(Op::PUSHK, static_cast<uint32_t>(out_.image.constants.size() - 1));
  }

  uint32_t indexed(const LineOp& op) {
    out_.indexed.push_back({op.name_key->id, op.msg.name.index, op.msg.target.index});
    return kIndexedBase + static_cast<uint32_t>(out_.indexed.size() - 1);
  }

  // Every AMath[n] is VM code (the loader refused a number that is no operation).
  void math(bytecode::CodeBuilder& b, int32_t n) { emit_math(b, n); }

  void line_code(bytecode::CodeBuilder& b, uint32_t l,
                 std::vector<bytecode::CodeBuilder::Label>& at) {
    const LineOp& op = ops_[l];
    const Message& m = op.msg;
    const Keyword& k = *op.key;
    const uint32_t id = static_cast<uint32_t>(k.id);
    const int32_t i = m.target.index;
    const uint32_t start = b.here();
    if (op.fails != 0) {  // the thread stops here: nothing after it is reached from this line
      b.emit(Op::CMDRUN, kFailBase + static_cast<uint32_t>(op.fails), 0);
      return b.emit(Op::EXIT);
    }
    if (m.tail == Message::Tail::Assign) {
      push_constant(b, m.value);
      store(b, k.id, i);
      return b.end_line(start);
    }
    switch (k.id) {
      case KeywordId::ProgTask:
        return;
      case KeywordId::ProgFunc:
        return b.emit(Op::EOL);
      case KeywordId::PushConstant:
        push_constant(b, m.value);
        break;
      case KeywordId::PushParam:
        load(b, op.name_key->id, m.name.index);
        break;
      case KeywordId::PopParam:
        store(b, op.name_key->id, m.name.index);
        break;
      case KeywordId::PushParamIdx:
        if (op.name_key->id == KeywordId::GenData) {
          b.emit(Op::LDGW, gen_data_global(), gen_data_window(op.msg));
        } else {
          b.emit(Op::CMDGETX, indexed(op));
        }
        break;
      case KeywordId::PopParamIdx:
        if (op.name_key->id == KeywordId::GenData) {
          b.emit(Op::STGW, gen_data_global(), gen_data_window(op.msg));
        } else {
          b.emit(Op::SWAP), b.emit(Op::CMDSETX, indexed(op));
        }
        break;
      case KeywordId::Math:
        math(b, i);
        break;
      case KeywordId::Compare:
        emit_condition(b, i);
        break;
      case KeywordId::GetStatus:
        push_constant(b, m.value);
        b.emit(Op::CMDGETX, kStatusBase + static_cast<uint32_t>(i));
        break;
      case KeywordId::WaitStatus: {
        const auto top = b.new_label(), done = b.new_label();
        b.bind(top);
        push_constant(b, m.value);
        b.emit(Op::CMDGETX, kStatusBase + static_cast<uint32_t>(i));
        b.emit_to(Op::JNZ, done);
        b.emit(Op::YIELD);
        b.emit_to(Op::JMP, top);
        b.bind(done);
        break;
      }
      case KeywordId::Jump:
        return jump(b, i, at[op.target]);
      case KeywordId::ProgFuncCall:
      case KeywordId::ProgCallFunc:
        b.emit(Op::CALL, static_cast<uint32_t>(function_routine_.at(m.value)), 0);
        break;
      case KeywordId::Return:
        // A task may fall into a function (past its AProgHalt): whether there is a call to
        // return from is known only at run time.
        b.emit(Op::CMDRUN, kReturnCheck, 0);
        return b.emit(Op::RETEOL);
      case KeywordId::WaitTime:
        push_constant(b, m.value);
        b.emit(Op::WAIT, 1000);
        break;
      default:  // a command, with its index and argument
        push_constant(b, i);
        if (m.tail == Message::Tail::Argument) push_constant(b, m.value);
        b.emit(Op::CMDRUNX, id, m.tail == Message::Tail::Argument ? 1 : 0);
        break;
    }
    b.end_line(start);
  }

  // A keyword's value at an index: AGenData's in the image's global, any other's from the firmware.
  void load(bytecode::CodeBuilder& b, KeywordId key, int32_t index) {
    if (key == KeywordId::GenData)
      return b.emit(Op::LDGE, gen_data_global(), static_cast<uint32_t>(index - 1));
    b.emit(Op::CMDGET, static_cast<uint32_t>(key), static_cast<uint32_t>(index));
  }
  void store(bytecode::CodeBuilder& b, KeywordId key, int32_t index) {
    if (key == KeywordId::GenData)
      return b.emit(Op::STGE, gen_data_global(), static_cast<uint32_t>(index - 1));
    b.emit(Op::CMDSET, static_cast<uint32_t>(key), static_cast<uint32_t>(index));
  }
  uint32_t gen_data_global() { return pup::gen_data_global(out_.image); }

  // AJump[c]: one branch that ends the line whether it is taken or not.
  void jump(bytecode::CodeBuilder& b, int32_t c, bytecode::CodeBuilder::Label to) {
    static const Op kCompareJumps[] = {Op::JEQI, Op::JNEI, Op::JGTI, Op::JGEI, Op::JLTI, Op::JLEI};
    const uint32_t start = b.here();
    if (c == 2) b.emit_imm(Op::PUSHI, 0);
    const Op branch = c >= 3 && c <= 8 ? kCompareJumps[c - 3]
                      : c == 1         ? Op::JMP
                      : c == 2         ? Op::JGTI
                      : c == 9         ? Op::JZ
                                       : Op::JNZ;
    b.emit_to(branch, to);
    b.end_line(start);
  }

  // The lines control may arrive at other than from the line before: jump targets, task and
  // function starts, and a function's first line, where its events enter.
  std::vector<bool> entered_lines() const {
    std::vector<bool> entered(count() + 2, false);
    for (uint32_t l = 1; l <= count(); ++l) entered[ops_[l].target] = true;
    for (const auto& [n, l] : tasks_) entered[l] = true;
    for (const auto& [n, l] : functions_) entered[l] = entered[l + 1] = true;
    return entered;
  }

  // A run's fused copy after the code, its exits at their lines' code, its JLINES pointed at it.
  void place_copy(const LineRun& run, uint32_t guard) {
    std::vector<uint32_t>& code = out_.image.code;
    const auto start = static_cast<uint32_t>(code.size());
    code[guard] = bytecode::with_a(code[guard], start);
    for (uint32_t pc = 0; pc < run.code.size(); ++pc) {
      uint32_t word = run.code[pc];
      const Op op = bytecode::word_op(word);
      if (bytecode::op_info(op).a == bytecode::Operand::Target) {
        const uint32_t to = bytecode::word_a(word);
        word = bytecode::with_a(word, to >= kRunExit ? out_.line_pc[to - kRunExit] : start + to);
      }
      code.push_back(word);
      if (bytecode::op_length(op) == 2) code.push_back(run.code[++pc]);
    }
    for (const auto& [pc, line] : run.lines) out_.copy_lines.emplace_back(start + pc, line);
  }

  void add_routine(std::string name, bytecode::RoutineKind kind, uint32_t entry) {
    bytecode::Routine r;
    r.name = std::move(name);
    r.kind = kind;
    r.entry = entry;
    out_.image.routines.push_back(std::move(r));
  }

  void generate() {
    bytecode::Image& image = out_.image;
    image.dialect = "pup";
    image.source_name = p_.name + ".cup";
    image.info = p_.info;
    bytecode::CodeBuilder b(image.code);
    std::vector<bytecode::CodeBuilder::Label> at;
    for (size_t l = 0; l <= count() + 1; ++l) at.push_back(b.new_label());
    // Function routines first: a call names its routine before the code is emitted.
    uint32_t next = 0;
    for (const auto& [n, l] : functions_) function_routine_[n] = static_cast<int32_t>(next++);
    out_.line_pc.assign(count() + 2, 0);
    const std::vector<LineRun> runs = fuse_line_runs(ops_, depth_, entered_lines(), image);
    std::vector<uint32_t> run_guard;  // each run's JLINES
    auto run = runs.begin();
    for (uint32_t l = 1; l <= count(); ++l) {
      b.bind(at[l]);
      out_.line_pc[l] = b.here();
      if (run != runs.end() && run->first == l) {
        run_guard.push_back(b.here());
        b.emit(Op::JLINES, 0, run->most);
        ++run;
      }
      if (depth_[l] < 0 && ops_[l].key->kind != KeywordKind::Marker) {
        b.emit(Op::EOL);  // never reached: kept so that every line has its code word
      } else {
        line_code(b, l, at);
      }
      image.lines.push_back({out_.line_pc[l], image.source_name, l});
    }
    b.bind(at[count() + 1]);
    out_.line_pc[count() + 1] = b.here();
    b.emit(Op::EXIT);
    b.finish();
    for (size_t r = 0; r < runs.size(); ++r) place_copy(runs[r], run_guard[r]);
    for (const auto& [n, l] : functions_)
      add_routine(fmt::format("func {}", n), bytecode::RoutineKind::Function, out_.line_pc[l]);
    auto task_entry = [&](uint32_t l) { return out_.line_pc[l]; };
    if (count() == 0 || ops_[1].key->id != KeywordId::ProgTask) {
      out_.task_routine[0] = static_cast<int32_t>(image.routines.size());
      add_routine("task 0", bytecode::RoutineKind::Task, 0);
    }
    for (const auto& [n, l] : tasks_) {
      out_.task_routine[static_cast<size_t>(n)] = static_cast<int32_t>(image.routines.size());
      image.tasks.push_back(
          {static_cast<uint32_t>(image.routines.size()), static_cast<uint32_t>(n), 0, 1, false});
      add_routine(fmt::format("task {}", n), bytecode::RoutineKind::Task, task_entry(l));
    }
    for (const CupEvent& e : p_.events) {
      const uint32_t l = functions_.at(e.function);
      out_.event_routine[static_cast<size_t>(e.event)] =
          static_cast<int32_t>(image.routines.size());
      image.events.push_back(
          {static_cast<uint32_t>(e.event), static_cast<uint32_t>(image.routines.size())});
      // An event enters after the marker's EOL, so that the function's first line runs in the cycle
      // it is taken.
      add_routine(fmt::format("event {}", e.event), bytecode::RoutineKind::AutoRoutine,
                  out_.line_pc[l] + 1);
    }
    out_.line_depth = depth_;
    out_.waits.assign(count() + 2, false);
    out_.timed_waits.assign(count() + 2, false);
    for (uint32_t l = 1; l <= count(); ++l) {
      out_.waits[l] = ops_[l].key->id == KeywordId::WaitStatus;
      out_.timed_waits[l] = ops_[l].key->id == KeywordId::WaitTime;
    }
  }

  const CupProgram& p_;
  std::vector<LineOp> ops_;
  std::map<int32_t, uint32_t> tasks_, functions_;
  std::map<int32_t, int32_t> function_routine_;
  std::vector<int32_t> depth_;
  LoadedCup out_;
};

// The general data's words where a global of the image lies: all of them for "AGenData",
// element n on for "AGenData[n]" (a line run's copy); nullopt for any other global.
std::optional<size_t> gen_data_offset(const std::string& name) {
  const std::string whole = kGenDataGlobal;
  if (name == whole) return 0;
  if (name.size() < whole.size() + 3 || name.compare(0, whole.size() + 1, whole + "[") != 0 ||
      name.back() != ']') {
    return std::nullopt;
  }
  size_t n = 0;
  const char* first = name.data() + whole.size() + 1;
  const char* last = name.data() + name.size() - 1;
  const auto [end, ec] = std::from_chars(first, last, n);
  if (ec != std::errc() || end != last || n < 1 || n > kGenDataSize) return std::nullopt;
  return n - 1;
}

}  // namespace

uint32_t gen_data_element_global(bytecode::Image& image, int32_t n) {
  const std::string name = fmt::format("{}[{}]", kGenDataGlobal, n);
  if (const int g = image.find_global(name); g >= 0) return static_cast<uint32_t>(g);
  image.globals.push_back({name, ValueType::Int, 1});
  return static_cast<uint32_t>(image.globals.size() - 1);
}

// The parse checked that the window lies within the 1000 words.
uint32_t gen_data_window(const Message& m) {
  return bytecode::pack_window(static_cast<uint32_t>(m.name.index - 1),
                               static_cast<uint32_t>(m.target.index));
}

uint32_t gen_data_global(bytecode::Image& image) {
  if (const int g = image.find_global(kGenDataGlobal); g >= 0) return static_cast<uint32_t>(g);
  image.globals.push_back({kGenDataGlobal, ValueType::Int, static_cast<uint32_t>(kGenDataSize)});
  return static_cast<uint32_t>(image.globals.size() - 1);
}

bool bind_gen_data(vm::Machine& machine, const LoadedCup& cup,
                   std::array<Value, kGenDataSize>& gen_data) {
  const auto& globals = cup.image.globals;
  for (size_t g = 0; g < globals.size(); ++g) {
    const auto offset = gen_data_offset(globals[g].name);
    if (offset && !machine.bind_global(static_cast<uint32_t>(g), gen_data.data() + *offset,
                                       static_cast<uint32_t>(kGenDataSize - *offset))) {
      return false;
    }
  }
  return true;
}

uint32_t LoadedCup::line_of(uint32_t pc) const {
  if (!copy_lines.empty() && pc >= copy_lines.front().first) {
    const auto after =
        std::upper_bound(copy_lines.begin(), copy_lines.end(), std::pair{pc, UINT32_MAX});
    return std::prev(after)->second;
  }
  uint32_t line = 0;
  for (uint32_t l = 1; l + 1 < line_pc.size(); ++l) {
    if (line_pc[l] <= pc) line = l;
  }
  return line;
}

std::optional<LoadedCup> load_cup(const CupProgram& program, std::string* error,
                                  uint32_t* refused_line) {
  return Loader(program).run(error, refused_line);
}

}  // namespace uprog::pup
