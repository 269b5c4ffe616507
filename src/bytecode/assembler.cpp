// Reads uprog assembly (docs/assembly.md) into an Image. Two steps: parse every line, recording
// labels and names; then resolve label and name operands and sort the line table.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>

#include "bytecode/assembly.h"
#include "bytecode/code_builder.h"
#include "bytecode/intrinsics.h"
#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

bool op_from_name(const std::string& name, Op& out) {
  for (uint32_t i = 0; i < kOpCount; ++i) {
    if (name == kOpNames[i]) {
      out = static_cast<Op>(i);
      return true;
    }
  }
  return false;
}

struct Token {
  std::string text;
  bool quoted = false;
  int column = 0;
};

class Assembler {
 public:
  Assembler(const std::string& file, Image& out, std::vector<Diagnostic>& errors)
      : file_(file), image_(out), errors_(errors) {}

  bool run(const std::string& text) {
    image_ = Image{};
    size_t start = 0;
    int line = 0;
    while (start <= text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      ++line;
      line_ = line;
      std::vector<Token> tokens;
      if (tokenize(text.substr(start, end - start), tokens) && !tokens.empty()) statement(tokens);
      start = end + 1;
    }
    resolve();
    std::stable_sort(errors_.begin(), errors_.end(), [](const Diagnostic& a, const Diagnostic& b) {
      return a.where.line < b.where.line;
    });
    std::stable_sort(image_.lines.begin(), image_.lines.end(),
                     [](const LineEntry& a, const LineEntry& b) { return a.code < b.code; });
    return errors_.empty();
  }

 private:
  struct Fixup {
    size_t pc;  // the word to patch
    bool whole_word;
    Operand kind;
    std::string name;
    int line, column;
  };

  void error(int column, const std::string& message) {
    Diagnostic d;
    d.scheme = "asm";
    d.code = 1;
    d.message = message;
    d.where = {file_, line_, column};
    errors_.push_back(std::move(d));
  }

  bool tokenize(const std::string& line, std::vector<Token>& tokens) {
    size_t i = 0;
    while (i < line.size()) {
      const char c = line[i];
      if (c == ';') break;
      if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
        ++i;
        continue;
      }
      Token t;
      t.column = static_cast<int>(i) + 1;
      if (c == '"') {
        t.quoted = true;
        ++i;
        bool closed = false;
        while (i < line.size()) {
          const char d = line[i++];
          if (d == '"') {
            closed = true;
            break;
          }
          if (d != '\\') {
            t.text += d;
            continue;
          }
          if (i >= line.size()) break;
          const char e = line[i++];
          if (e == 'n') {
            t.text += '\n';
          } else if (e == 'x' && i + 2 <= line.size()) {
            const std::string hex = line.substr(i, 2);
            char* endp = nullptr;
            const long v = std::strtol(hex.c_str(), &endp, 16);
            if (endp != hex.c_str() + 2) {
              error(t.column, "bad \\x escape");
              return false;
            }
            t.text += static_cast<char>(v);
            i += 2;
          } else {
            t.text += e;
          }
        }
        if (!closed) {
          error(t.column, "unterminated string");
          return false;
        }
      } else {
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',' &&
               line[i] != ';' && line[i] != '\r')
          t.text += line[i++];
      }
      tokens.push_back(std::move(t));
    }
    return true;
  }

  bool number(const Token& t, int64_t& out, int64_t lo, int64_t hi) {
    if (t.quoted || t.text.empty()) {
      error(t.column, fmt::format("a number is expected, not '{}'", t.text));
      return false;
    }
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(t.text.c_str(), &end, 0);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
      error(t.column, fmt::format("'{}' is not a number in [{}, {}]", t.text, lo, hi));
      return false;
    }
    out = v;
    return true;
  }

  bool type(const Token& t, ValueType& out) {
    if (t.text == "int")
      out = ValueType::Int;
    else if (t.text == "float")
      out = ValueType::Float;
    else {
      error(t.column, fmt::format("'{}' is not a type (int or float)", t.text));
      return false;
    }
    return true;
  }

  bool want(const std::vector<Token>& ts, size_t n, const char* what) {
    if (ts.size() == n) return true;
    error(ts[0].column, fmt::format("{} takes {} operand(s)", what, n - 1));
    return false;
  }

  // "key=value" → value, or an error.
  bool keyed(const Token& t, const char* key, Token& value) {
    const std::string prefix = std::string(key) + "=";
    if (t.text.rfind(prefix, 0) != 0) {
      error(t.column, fmt::format("'{}' expected", prefix));
      return false;
    }
    value = t;
    value.text = t.text.substr(prefix.size());
    value.column = t.column + static_cast<int>(prefix.size());
    return true;
  }

  void statement(const std::vector<Token>& ts) {
    const Token& head = ts[0];
    if (!head.quoted && head.text.size() > 1 && head.text.back() == ':') {
      const std::string name = head.text.substr(0, head.text.size() - 1);
      if (labels_.count(name)) error(head.column, fmt::format("label '{}' defined twice", name));
      labels_[name] = static_cast<uint32_t>(image_.code.size());
      if (ts.size() > 1) statement(std::vector<Token>(ts.begin() + 1, ts.end()));
      return;
    }
    if (head.text[0] == '.' && !head.quoted) return directive(ts);
    instruction(ts);
  }

  void directive(const std::vector<Token>& ts) {
    const std::string& d = ts[0].text;
    int64_t n = 0;
    if (d == ".source") {
      if (want(ts, 2, d.c_str())) image_.source_name = ts[1].text;
    } else if (d == ".dialect") {
      if (want(ts, 2, d.c_str())) image_.dialect = ts[1].text;
    } else if (d == ".text") {
      if (want(ts, 2, d.c_str())) image_.texts.push_back(ts[1].text);
    } else if (d == ".task") {
      task(ts);
    } else if (d == ".created") {
      if (want(ts, 2, d.c_str()) && number(ts[1], n, 0, INT64_MAX))
        image_.created_unix_s = static_cast<uint64_t>(n);
    } else if (d == ".info") {
      if (want(ts, 2, d.c_str())) image_.info.push_back(ts[1].text);
    } else if (d == ".const") {
      constant(ts);
    } else if (d == ".global") {
      Global g;
      if (want(ts, 4, d.c_str()) && type(ts[1], g.type) && number(ts[3], n, 1, UINT32_MAX)) {
        g.name = ts[2].text;
        g.length = static_cast<uint32_t>(n);
        image_.globals.push_back(g);
      }
    } else if (d == ".routine") {
      routine(ts);
    } else if (d == ".local") {
      Local l;
      if (!want(ts, 3, d.c_str()) || !type(ts[1], l.type)) return;
      if (image_.routines.empty()) return error(ts[0].column, ".local before any .routine");
      l.name = ts[2].text;
      image_.routines.back().locals.push_back(l);
    } else if (d == ".event") {
      int64_t r = 0;
      if (want(ts, 3, d.c_str()) && number(ts[1], n, 0, UINT32_MAX) &&
          number(ts[2], r, 0, UINT32_MAX))
        image_.events.push_back({static_cast<uint32_t>(n), static_cast<uint32_t>(r)});
    } else if (d == ".line") {
      line_directive(ts);
    } else if (d == ".word") {
      if (want(ts, 2, d.c_str()) && number(ts[1], n, 0, UINT32_MAX))
        image_.code.push_back(static_cast<uint32_t>(n));
    } else {
      error(ts[0].column, fmt::format("unknown directive '{}'", d));
    }
  }

  void constant(const std::vector<Token>& ts) {
    Constant c;
    if (ts.size() < 3 || !type(ts[1], c.type)) {
      if (ts.size() < 3) error(ts[0].column, ".const takes a type and a value");
      return;
    }
    int64_t n = 0;
    if (ts[2].text == "bits") {
      if (want(ts, 4, ".const") && number(ts[3], n, 0, UINT32_MAX)) {
        c.bits = static_cast<uint32_t>(n);
        image_.constants.push_back(c);
      }
      return;
    }
    if (!want(ts, 3, ".const")) return;
    if (c.type == ValueType::Int) {
      if (!number(ts[2], n, INT32_MIN, INT32_MAX)) return;
      c.bits = static_cast<uint32_t>(static_cast<int32_t>(n));
    } else {
      char* end = nullptr;
      const float f = std::strtof(ts[2].text.c_str(), &end);
      if (ts[2].quoted || ts[2].text.empty() || *end != '\0')
        return error(ts[2].column, fmt::format("'{}' is not a float", ts[2].text));
      std::memcpy(&c.bits, &f, 4);
    }
    image_.constants.push_back(c);
  }

  void routine(const std::vector<Token>& ts) {
    if (!want(ts, 6, ".routine")) return;
    static const std::map<std::string, RoutineKind> kinds = {{"function", RoutineKind::Function},
                                                             {"label", RoutineKind::Label},
                                                             {"auto", RoutineKind::AutoRoutine},
                                                             {"task", RoutineKind::Task}};
    const auto kind = kinds.find(ts[1].text);
    if (kind == kinds.end())
      return error(ts[1].column, fmt::format("unknown routine kind '{}'", ts[1].text));
    Routine r;
    r.kind = kind->second;
    r.name = ts[2].text;
    Token in, out, entry;
    int64_t n = 0;
    if (!keyed(ts[3], "in", in) || !number(in, n, 0, UINT32_MAX)) return;
    r.inputs = static_cast<uint32_t>(n);
    if (!keyed(ts[4], "out", out) || !number(out, n, 0, UINT32_MAX)) return;
    r.outputs = static_cast<uint32_t>(n);
    if (!keyed(ts[5], "entry", entry)) return;
    image_.routines.push_back(r);
    routine_entries_.push_back({entry.text, line_, entry.column});
  }

  // .task ROUTINE number=N period_ns=P priority=K start_at_reset=0|1
  void task(const std::vector<Token>& ts) {
    if (!want(ts, 6, ".task")) return;
    Task t;
    Token v;
    int64_t n = 0;
    if (!keyed(ts[2], "number", v) || !number(v, n, 0, UINT32_MAX)) return;
    t.number = static_cast<uint32_t>(n);
    if (!keyed(ts[3], "period_ns", v) || !number(v, n, 0, UINT32_MAX)) return;
    t.period_ns = static_cast<uint32_t>(n);
    if (!keyed(ts[4], "priority", v) || !number(v, n, 0, UINT32_MAX)) return;
    t.priority = static_cast<uint32_t>(n);
    if (!keyed(ts[5], "start_at_reset", v) || !number(v, n, 0, 1)) return;
    t.starts_at_reset = n == 1;
    const Token& r = ts[1];
    if (!r.quoted && !r.text.empty() && std::isdigit(static_cast<unsigned char>(r.text[0]))) {
      if (!number(r, n, 0, UINT32_MAX)) return;
      t.routine = static_cast<uint32_t>(n);
    } else {
      task_routines_.push_back({r.text, line_, r.column, image_.tasks.size()});
    }
    image_.tasks.push_back(t);
  }

  void line_directive(const std::vector<Token>& ts) {
    int64_t n = 0, at = 0;
    if (ts.size() == 4) {
      if (ts[1].text.empty() || ts[1].text[0] != '@')
        return error(ts[1].column, "'@offset' expected");
      Token offset = ts[1];
      offset.text = offset.text.substr(1);
      if (!number(offset, at, 0, UINT32_MAX) || !number(ts[3], n, 0, UINT32_MAX)) return;
      image_.lines.push_back({static_cast<uint32_t>(at), ts[2].text, static_cast<uint32_t>(n)});
      return;
    }
    if (!want(ts, 3, ".line") || !number(ts[2], n, 0, UINT32_MAX)) return;
    image_.lines.push_back(
        {static_cast<uint32_t>(image_.code.size()), ts[1].text, static_cast<uint32_t>(n)});
  }

  void instruction(const std::vector<Token>& ts) {
    Op op;
    // `OP.eol`: the instruction carries the line-end mark.
    const std::string_view suffix = ".eol";
    std::string name = ts[0].text;
    const bool ends_line = name.size() > suffix.size() && name.ends_with(suffix);
    if (ends_line) name.resize(name.size() - suffix.size());
    if (ts[0].quoted || !op_from_name(name, op))
      return error(ts[0].column, fmt::format("unknown opcode '{}'", ts[0].text));
    if (ends_line && !may_end_line(op))
      return error(ts[0].column, fmt::format("{} cannot carry a line end", op_name(op)));
    const OpInfo& info = op_info(op);
    const size_t operands = (info.a != Operand::None) + (info.b != Operand::None);
    if (ts.size() != operands + 1)
      return error(ts[0].column, fmt::format("{} takes {} operand(s)", op_name(op), operands));
    const size_t pc = image_.code.size();
    image_.code.push_back(static_cast<uint32_t>(op) | (ends_line ? kLineEndBit : 0u));
    if (info.a != Operand::None) operand_a(ts[1], info.a, pc);
    if (info.b != Operand::None) {
      int64_t n = 0;
      const bool is_signed = info.b == Operand::Imm;
      const Token& b = ts[info.a != Operand::None ? 2 : 1];
      const bool is_name =
          !b.text.empty() &&
          (b.quoted || std::isalpha(static_cast<unsigned char>(b.text[0])) || b.text[0] == '_');
      if (info.b == Operand::Global && is_name) {
        // A global as the second word (STGJEOL, LDG2) may be its name too.
        fixups_.push_back({pc + 1, true, Operand::Global, b.text, line_, b.column});
        image_.code.push_back(0);
      } else if (number(b, n, is_signed ? INT32_MIN : 0, is_signed ? INT32_MAX : UINT32_MAX))
        image_.code.push_back(static_cast<uint32_t>(n));
      else
        image_.code.push_back(0);
    }
  }

  void operand_a(const Token& t, Operand kind, size_t pc) {
    const bool is_name = !t.text.empty() && !t.quoted &&
                         (std::isalpha(static_cast<unsigned char>(t.text[0])) || t.text[0] == '_');
    if (kind == Operand::Target && !t.text.empty() && t.text[0] == '@') {
      Token raw = t;
      raw.text = t.text.substr(1);
      int64_t n = 0;
      if (number(raw, n, 0, kOperandMax)) image_.code[pc] |= a_field(static_cast<uint32_t>(n));
      return;
    }
    if (kind == Operand::Intrinsic && is_name) return intrinsic(t, pc);
    if (is_name || t.quoted) {
      if (kind != Operand::Target && kind != Operand::Routine && kind != Operand::Global)
        return error(t.column, fmt::format("'{}': a number is expected", t.text));
      fixups_.push_back({pc, false, kind, t.text, line_, t.column});
      return;
    }
    int64_t n = 0;
    const bool is_signed = kind == Operand::Imm;
    if (!number(t, n, is_signed ? kImmMin : 0, is_signed ? kImmMax : kOperandMax)) return;
    image_.code[pc] |= a_field(static_cast<uint32_t>(n));
  }

  // INTRIN's function by its name (DIVU); a number is read as any other operand.
  void intrinsic(const Token& t, size_t pc) {
    for (uint32_t i = 0; i < kIntrinsicCount; ++i) {
      if (t.text == kIntrinsicNames[i]) {
        image_.code[pc] |= a_field(i);
        return;
      }
    }
    error(t.column, fmt::format("unknown intrinsic '{}'", t.text));
  }

  bool lookup(Operand kind, const std::string& name, uint32_t& out) {
    if (kind == Operand::Target) {
      auto it = labels_.find(name);
      if (it == labels_.end()) return false;
      out = it->second;
      return true;
    }
    const int i = kind == Operand::Routine ? image_.find_routine(name) : image_.find_global(name);
    if (i < 0) return false;
    out = static_cast<uint32_t>(i);
    return true;
  }

  void resolve() {
    for (const Fixup& f : fixups_) {
      uint32_t value = 0;
      if (!lookup(f.kind, f.name, value)) {
        line_ = f.line;
        error(f.column, fmt::format("unknown name '{}'", f.name));
        continue;
      }
      if (f.whole_word)
        image_.code[f.pc] = value;
      else
        image_.code[f.pc] |= a_field(value);
    }
    for (size_t i = 0; i < routine_entries_.size(); ++i) {
      const auto& e = routine_entries_[i];
      line_ = e.line;
      if (!e.label.empty() && e.label[0] == '@') {
        Token raw{e.label.substr(1), false, e.column};
        int64_t n = 0;
        if (number(raw, n, 0, UINT32_MAX)) image_.routines[i].entry = static_cast<uint32_t>(n);
        continue;
      }
      uint32_t entry = 0;
      if (!lookup(Operand::Target, e.label, entry)) {
        error(e.column, fmt::format("unknown label '{}'", e.label));
        continue;
      }
      image_.routines[i].entry = entry;
    }
    for (const TaskName& t : task_routines_) {
      uint32_t routine = 0;
      if (!lookup(Operand::Routine, t.name, routine)) {
        line_ = t.line;
        error(t.column, fmt::format("unknown routine '{}'", t.name));
        continue;
      }
      image_.tasks[t.task].routine = routine;
    }
    for (auto& r : image_.routines) {
      if (r.inputs + static_cast<uint64_t>(r.outputs) > r.locals.size()) {
        line_ = 0;
        error(0, fmt::format("routine '{}' declares fewer locals than inputs and outputs", r.name));
      }
    }
  }

  struct Entry {
    std::string label;
    int line, column;
  };
  struct TaskName {
    std::string name;
    int line, column;
    size_t task;
  };
  std::string file_;
  Image& image_;
  std::vector<Diagnostic>& errors_;
  int line_ = 0;
  std::map<std::string, uint32_t> labels_;
  std::vector<Fixup> fixups_;
  std::vector<Entry> routine_entries_;
  std::vector<TaskName> task_routines_;
};

}  // namespace

bool assemble(const std::string& text, const std::string& file, Image& out,
              std::vector<Diagnostic>& errors) {
  return Assembler(file, out, errors).run(text);
}

}  // namespace uprog::bytecode
