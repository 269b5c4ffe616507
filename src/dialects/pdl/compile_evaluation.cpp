// A PDL expression, condition or assignment compiled for the debugger (compile.h): the program's
// variables from its image (the "var" info lines in declaration order give their addresses), a
// procedure frame's from its debug info, and the drive's own compiler for the rest.
#include <cctype>

#include "dialects/pdl/compile.h"
#include "dialects/pdl/compiler.h"

namespace uprog::pdl {
namespace {

bool is_assignment_operator(const Token& t) {
  if (t.kind != Tok::Op) return false;
  for (std::string_view op : {"+=", "-=", "*=", "/=", "&=", "|=", "@=", "%=", "++", "--"})
    if (t.text == op) return true;
  return false;
}

bool is_relation(const Token& t) {
  if (t.kind != Tok::Op) return false;
  for (std::string_view op : {"=", "<>", "<", "<=", ">", ">="})
    if (t.text == op) return true;
  return false;
}

std::vector<Var> program_globals(const bytecode::Image& program) {
  std::vector<Var> out;
  int32_t address = 0;
  for (const std::string& info : program.info) {
    if (!info.starts_with("var ")) continue;
    const size_t a = 4, b = info.find(' ', a),
                 c = b == std::string::npos ? b : info.find(' ', b + 1);
    if (b == std::string::npos) continue;
    const std::string name = info.substr(a, b - a),
                      kind = info.substr(b + 1, c == std::string::npos ? c : c - b - 1);
    const int g = program.find_global(name);
    if (g < 0) continue;
    Var v;
    v.name = name;
    v.pointer = kind == "lptr" || kind == "fptr";
    v.kind = kind == "float" || kind == "fptr" ? Kind::Float
             : kind == "short"                 ? Kind::Short
                                               : Kind::Long;
    v.length = program.globals[static_cast<size_t>(g)].length;
    v.global = g;
    v.address = address;
    address += static_cast<int32_t>(v.length);
    out.push_back(v);
  }
  return out;
}

std::vector<Var> frame_locals(const ProcInfo* frame) {
  std::vector<Var> out;
  if (frame == nullptr) return out;
  for (const FrameVar& f : frame->vars) {
    Var v;
    v.name = f.name;
    v.kind = f.kind == 'f' ? Kind::Float : f.kind == 's' ? Kind::Short : Kind::Long;
    v.pointer = f.pointer;
    v.length = f.length;
    v.local = true;
    v.address = f.offset;
    out.push_back(v);
  }
  return out;
}

}  // namespace

EvaluationCode compile_evaluation(std::string_view text, const bytecode::Image& program,
                                  const ProcInfo* frame) {
  EvaluationCode out;
  std::vector<LexError> lex_errors;
  std::vector<Token> tokens = tokenize(text, lex_errors);
  if (!lex_errors.empty()) {
    out.error = make_diagnostic(lex_errors.front().error, Location{"expression", 1, 1},
                                lex_errors.front().detail)
                    .message;
    return out;
  }
  if (tokens.size() <= 1) {
    out.error = "an empty expression";
    return out;
  }
  using Form = Compiler::EvalForm;
  // `set PLACE = value` and PDL's own assignment commands assign; `=` alone compares, as in a
  // condition (a breakpoint's condition is one).
  std::vector<Form> forms;
  if (tokens[0].kind == Tok::Name && equal_ignoring_case(tokens[0].text, "set") &&
      tokens.size() > 2) {
    tokens.erase(tokens.begin());
    forms = {Form::Assignment};
  } else {
    int depth = 0;
    bool assigns = false, compares = false;
    for (const Token& t : tokens) {
      if (t.kind == Tok::Op && (t.text == "(" || t.text == "[")) ++depth;
      if (t.kind == Tok::Op && (t.text == ")" || t.text == "]")) --depth;
      if (depth == 0 && is_assignment_operator(t)) assigns = true;
      if (depth == 0 && is_relation(t)) compares = true;
    }
    forms = assigns    ? std::vector<Form>{Form::Assignment}
            : compares ? std::vector<Form>{Form::Condition, Form::Expression}
                       : std::vector<Form>{Form::Expression, Form::Condition};
  }
  const auto locate = [](size_t offset) {
    return Location{"expression", 1, static_cast<int>(offset) + 1};
  };
  for (Form form : forms) {
    Compiler compiler(tokens, locate, "expression");
    bytecode::Image image;
    bool is_float = false;
    const bool ok = compiler.compile_evaluation(form, program_globals(program), frame_locals(frame),
                                                program.globals, image, is_float);
    if (ok) {
      out.ok = true;
      out.image = std::move(image);
      out.is_float = is_float;
      out.error.clear();
      return out;
    }
    if (out.error.empty())
      out.error =
          compiler.diagnostics().empty() ? "syntax error" : compiler.diagnostics().front().message;
  }
  return out;
}

}  // namespace uprog::pdl
