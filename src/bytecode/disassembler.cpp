// Prints an image as uprog assembly: directives first, then the code with labels at jump
// targets and routine entries, and comments naming what the numbers refer to.
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <set>

#include "bytecode/assembly.h"
#include "bytecode/intrinsics.h"
#include "bytecode/opcodes.h"

namespace uprog::bytecode {
namespace {

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c < 0x20 || c >= 0x7F) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

const char* type_name(ValueType t) { return t == ValueType::Float ? "float" : "int"; }

const char* kind_name(RoutineKind k) {
  switch (k) {
    case RoutineKind::Function:
      return "function";
    case RoutineKind::Label:
      return "label";
    case RoutineKind::AutoRoutine:
      return "auto";
    case RoutineKind::Task:
      return "task";
  }
  return "function";
}

std::string float_text(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, 4);
  if (!std::isfinite(f)) return fmt::format("bits 0x{:08x}", bits);
  return fmt::format("{:.9g}", f);
}

// True when every instruction from 0 decodes; such code prints as instructions.
bool is_instruction_start(const std::vector<bool>& starts, uint32_t pc) {
  return pc < starts.size() && starts[pc];
}

}  // namespace

std::string disassemble(const Image& image, std::span<const std::string> notes) {
  const auto size = static_cast<uint32_t>(image.code.size());
  std::vector<bool> starts(size, false);
  std::vector<bool> printed(size + 1, false);  // where the listing can attach a .line
  printed[size] = true;
  std::set<uint32_t> labels;
  for (uint32_t pc = 0; pc < size;) {
    printed[pc] = true;
    const uint32_t word = image.code[pc];
    if ((word & 0xFFu) >= kOpCount || op_length(word_op(word)) > size - pc) {
      ++pc;  // printed as a raw .word
      continue;
    }
    starts[pc] = true;
    if (op_info(word_op(word)).a == Operand::Target) labels.insert(word_a(word));
    pc += op_length(word_op(word));
  }
  for (const auto& r : image.routines) labels.insert(r.entry);
  const auto label_ref = [&](uint32_t pc) {
    return is_instruction_start(starts, pc) ? fmt::format("L{}", pc) : fmt::format("@{}", pc);
  };

  std::string out = "; uprog assembly\n";
  out += fmt::format(".source {}\n.created {}\n.dialect {}\n", quote(image.source_name),
                     image.created_unix_s, quote(image.dialect));
  for (const auto& s : image.info) out += fmt::format(".info {}\n", quote(s));
  for (size_t i = 0; i < image.texts.size(); ++i)
    out += fmt::format(".text {}  ; t{}\n", quote(image.texts[i]), i);
  for (size_t i = 0; i < image.constants.size(); ++i) {
    const auto& c = image.constants[i];
    const std::string value = c.type == ValueType::Float
                                  ? float_text(c.bits)
                                  : fmt::format("{}", static_cast<int32_t>(c.bits));
    out += fmt::format(".const {} {}  ; k{}\n", type_name(c.type), value, i);
  }
  for (size_t i = 0; i < image.globals.size(); ++i) {
    const auto& g = image.globals[i];
    out += fmt::format(".global {} {} {}  ; g{}\n", type_name(g.type), quote(g.name), g.length, i);
  }
  for (size_t i = 0; i < image.routines.size(); ++i) {
    const auto& r = image.routines[i];
    out += fmt::format(".routine {} {} in={} out={} entry={}  ; r{}\n", kind_name(r.kind),
                       quote(r.name), r.inputs, r.outputs, label_ref(r.entry), i);
    for (const auto& l : r.locals)
      out += fmt::format(".local {} {}\n", type_name(l.type), quote(l.name));
  }
  for (const auto& e : image.events) out += fmt::format(".event {} {}\n", e.event, e.routine);
  for (const auto& t : image.tasks) {
    out += fmt::format(".task {} number={} period_ns={} priority={} start_at_reset={}", t.routine,
                       t.number, t.period_ns, t.priority, t.starts_at_reset ? 1 : 0);
    if (t.routine < image.routines.size()) out += "  ; " + quote(image.routines[t.routine].name);
    out += "\n";
  }

  size_t next_line = 0;
  // Line records not at an instruction start keep their explicit offset.
  for (const auto& l : image.lines) {
    if (l.code > size || !printed[l.code])
      out += fmt::format(".line @{} {} {}\n", l.code, quote(l.file), l.line);
  }
  const auto lines_at = [&](uint32_t pc) {
    while (next_line < image.lines.size() && image.lines[next_line].code <= pc) {
      const auto& l = image.lines[next_line++];
      if (l.code == pc) out += fmt::format(".line {} {}\n", quote(l.file), l.line);
    }
  };

  out += "\n";
  for (uint32_t pc = 0; pc < size;) {
    lines_at(pc);
    if (!starts[pc]) {
      out += fmt::format("  .word 0x{:08x}\n", image.code[pc]);
      ++pc;
      continue;
    }
    if (labels.count(pc)) out += fmt::format("L{}:\n", pc);
    const uint32_t word = image.code[pc];
    const Op op = word_op(word);
    const OpInfo& info = op_info(op);
    std::string text = fmt::format("  {}{}", op_name(op), word_ends_line(word) ? ".eol" : "");
    std::string comment;
    switch (info.a) {
      case Operand::None:
        break;
      case Operand::Imm:
        text += fmt::format(" {}", word_imm(word));
        break;
      case Operand::Target:
        text += " " + label_ref(word_a(word));
        break;
      default:
        text += fmt::format(" {}", word_a(word));
        break;
    }
    const uint32_t a = word_a(word);
    if (info.a == Operand::Global && a < image.globals.size()) comment = image.globals[a].name;
    if (info.a == Operand::Routine && a < image.routines.size()) comment = image.routines[a].name;
    if (info.a == Operand::Text && a < image.texts.size()) comment = quote(image.texts[a]);
    if (info.a == Operand::Intrinsic && a < kIntrinsicCount) comment = kIntrinsicNames[a];
    if (info.a == Operand::Const && a < image.constants.size()) {
      const auto& c = image.constants[a];
      comment = c.type == ValueType::Float ? float_text(c.bits)
                                           : fmt::format("{}", static_cast<int32_t>(c.bits));
    }
    if (info.b == Operand::Imm) {
      text += fmt::format(" {}", static_cast<int32_t>(image.code[pc + 1]));
    } else if (info.b != Operand::None) {
      text += fmt::format(" {}", image.code[pc + 1]);
    }
    if ((info.a == Operand::None && word_a(word) != 0) ||
        (word_ends_line(word) && !may_end_line(op))) {
      // A stray operand on an opcode without one, or a line end where none may be: keep the
      // word exact.
      text = fmt::format("  .word 0x{:08x}", word);
      if (info.b != Operand::None) text += fmt::format("\n  .word 0x{:08x}", image.code[pc + 1]);
      comment.clear();
    }
    if (pc < notes.size() && !notes[pc].empty())
      comment = comment.empty() ? notes[pc] : comment + "; " + notes[pc];
    out += text;
    if (!comment.empty()) out += "  ; " + comment;
    out += "\n";
    pc += op_length(op);
  }
  lines_at(size);
  return out;
}

}  // namespace uprog::bytecode
