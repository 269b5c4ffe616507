// The PDL compiler's state: one pass over the tokens, emitting code as it parses (names are
// known from where they are declared, procedures from their definition or prototype), with the
// return sites, indirect gotos and entry routines resolved at the end. A procedure is a VM
// routine (CALL/RET) whose frame words are on the task's stack in the data memory. Split over
// compiler*.cpp: declarations and structure, commands, expressions and conditions, memory.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bytecode/code_builder.h"
#include "bytecode/image.h"
#include "dialects/pdl/debug_info.h"
#include "dialects/pdl/errors.h"
#include "dialects/pdl/layout.h"
#include "dialects/pdl/lexer.h"
#include "dialects/pdl/system_names.h"
#include "support/diagnostic.h"

namespace uprog::pdl {

using bytecode::CodeBuilder;
using bytecode::Op;

bool is_builtin_function(std::string_view name);  // max, min, abs, …, sizeof, memsum (2.3)

// An expression's type: an integer, a float, or an address of either.
enum class Ty : uint8_t { Int, Float, PtrInt, PtrFloat };
inline bool is_float(Ty t) { return t == Ty::Float; }

enum class Kind : uint8_t { Long, Short, Float };

struct Var {
  std::string name;
  Kind kind = Kind::Long;
  bool pointer = false;
  uint32_t length = 1;
  bool local = false;
  int32_t address = 0;  // global: word 0..399; local: words from the frame's start
  int32_t global = -1;  // the image's global
  Ty type() const {
    if (pointer) return kind == Kind::Float ? Ty::PtrFloat : Ty::PtrInt;
    return kind == Kind::Float ? Ty::Float : Ty::Int;
  }
};

struct Param {
  std::string name;
  Kind kind = Kind::Long;
  bool pointer = false;
  bool operator==(const Param& o) const { return kind == o.kind && pointer == o.pointer; }
};

struct Proc {
  std::string name;
  std::vector<Param> params;
  CodeBuilder::Label entry{};  // its body's first command, where its routine starts
  int routine = -1;            // its image routine, called with CALLFEOL
  bool defined = false;
  size_t declared_at = 0;               // token offset
  int32_t frame_words = -1;             // 2 + parameters + locals, once its definition is compiled
  std::vector<uint32_t> frame_patches;  // CALLFEOLs compiled before that, their B patched then
};

struct LabelInfo {
  CodeBuilder::Label label{};
  bool defined = false;
  uint32_t slot = 0;
  size_t first_use = 0;  // offset of the first goto/call naming it
  int loop_depth = 0;    // the loops open where it is defined
  int routine = -1;      // global labels: its entry routine
};

struct CommandStart {
  uint32_t slot;
  CodeBuilder::Label label;
  int scope;
  int loop_depth;  // the loops open around the command
};

// `var = <label>` (2.1 form 5): a constant that becomes the label's slot once it is defined.
struct LabelValue {
  int scope;
  std::string label;
  uint32_t constant;
};

struct IndirectGoto {
  int scope;
  std::string label;
  CodeBuilder::Label stub;
  size_t offset;
  int loop_depth;  // the loops open around the goto
};

// Where a value is read or stored (parse_place()).
struct Place {
  enum class Form : uint8_t {
    Global,   // LDG/STG of an image global, nothing on the stack
    Memory,   // a flat address is on the stack: LDM/STM
    Frame,    // a procedure's own word, fp + index: its address made where it is read or stored
    System,   // CMDGET/CMDSET at an immediate index
    SystemX,  // the index is on the stack
    State,    // a state by number (immediate)
    StateX,   // a state whose number is on the stack
  } form = Form::Global;
  Ty type = Ty::Int;
  bool is_short = false;
  int32_t global = 0;
  uint32_t command = 0;
  int32_t index = 0;
  const Var* var = nullptr;  // a user variable (for &, sizeof, memory blocks)
  const SystemVariable* system = nullptr;
  bool slave = false;
  std::vector<const Var*> post_increments;  // `[n+]`: after the access
};

class Compiler {
 public:
  Compiler(std::vector<Token> tokens, std::function<Location(size_t)> locate,
           std::string source_name);
  bool compile(bytecode::Image& image);  // false on errors
  std::vector<Diagnostic>& diagnostics() { return diagnostics_; }
  // The procedures, return sites and loops of the image compile() made, for the debugger.
  const DebugInfo& debug_info() const { return debug_info_; }

  // For the debugger (compile_evaluation() in compile.h): the tokens are one expression, condition
  // or assignment, seeing `globals` and the procedure frame's `locals` (none in task code); the
  // code stores its value in a last global, `(result)`, and ends. False on errors.
  enum class EvalForm : uint8_t { Expression, Condition, Assignment };
  bool compile_evaluation(EvalForm form, std::vector<Var> globals, std::vector<Var> locals,
                          const std::vector<bytecode::Global>& image_globals, bytecode::Image& out,
                          bool& is_float);

 private:
  // --- tokens and diagnostics (compiler.cpp)
  const Token& peek(size_t ahead = 0) const;
  const Token& next();
  bool at_op(std::string_view op, size_t ahead = 0) const;
  bool at_word(std::string_view word, size_t ahead = 0) const;  // a keyword, any case
  bool accept_op(std::string_view op);
  bool accept_word(std::string_view word);
  bool expect_op(std::string_view op);
  std::string expect_name();
  void error(Error e, size_t offset, std::string_view detail = {});
  void skip_to_command_end();
  bool is_keyword(std::string_view name) const;

  // --- program structure (compiler.cpp)
  void program();
  void statement_list(int depth, bool in_proc);
  bool at_block_end() const;
  void directive();
  void declaration(Kind kind);
  void task_directive(size_t at);
  void procedure();
  void finish_scope();
  void emit_return_dispatch(int scope);
  void emit_indirect_stubs(int scope);
  CodeBuilder::Label dispatch_label(int scope);
  Proc& proc_named(const std::string& name, const std::vector<Param>& params, size_t offset);
  void emit_dispatch(uint32_t local,
                     const std::vector<std::pair<int32_t, CodeBuilder::Label>>& cases);
  LabelInfo& label_named(const std::string& name, int scope, size_t offset);
  int routine_for_label(const std::string& name, size_t offset);

  // --- commands (compiler_commands.cpp)
  void command(int depth, bool in_proc);
  // A command starting at `offset` (default: the next token) taking `slots` slots.
  void begin_command(uint32_t slots, std::optional<size_t> offset = std::nullopt);
  void line_entry(size_t offset);
  void end_line() { code_.emit(Op::EOL); }
  void if_command(int depth, bool in_proc);
  void while_command(int depth, bool in_proc);
  void loop_command(int depth, bool in_proc);
  void till_command();
  void loop_end(CodeBuilder::Label body, CodeBuilder::Label exit);
  void wait_command();
  void sleep_command();
  void goto_command();
  void emit_loop_exit(const std::string& label);
  void patch_loop_exits(int scope);
  void call_command();
  void ret_command();
  void emit_ret();
  void proc_return();
  void run_command();
  void kill_command();
  void set_state_command(int mode);
  void printl_command(bool ret);
  void proc_call(Proc& proc);
  static uint32_t frame_shape(int32_t frame_words, int32_t params);
  void assignment();
  uint32_t short_command_slots();
  void check_code_size();
  bool is_literal(size_t first, size_t end) const;
  bool short_command_allowed() const;
  void simple_command(bool in_proc);

  // --- expressions and conditions (compiler_expr.cpp)
  Ty expr(bool in_condition = false, int level = 0);
  Ty unary(bool in_condition);
  Ty operand(bool in_condition);  // unary's body, one nesting level in
  Ty primary(bool in_condition);
  Ty builtin(const std::string& name, size_t at);
  Ty name_value(const Token& name_token, bool in_condition);
  void condition();
  void cond_and();
  void cond_not();
  void cond_atom();
  // A command's condition as jumps to `target` when its truth is `when` (compiler_jumps.cpp);
  // the token after its `(` is next.
  void jump_on_condition(bool when, CodeBuilder::Label target);
  bool quiet_condition(size_t first, size_t end) const;
  size_t next_outside_parentheses(size_t first, size_t end, std::string_view op) const;
  void jump_on_either(size_t first, size_t end, bool when, CodeBuilder::Label target);
  void jump_on_chain(size_t first, size_t end, std::string_view op, bool decides, bool when,
                     CodeBuilder::Label target);
  void jump_on_factor(size_t first, size_t end, bool when, CodeBuilder::Label target);
  void push_int(int32_t v);
  void push_float(float v);
  void convert(Ty from, Ty to, bool to_short);
  Ty arith(std::string_view op, Ty a, Ty b, size_t at);
  void emit_rounded_division();
  void emit_rounded_division_by(int32_t k);
  Ty int_operand(Ty t, size_t at);

  // --- the drive compiler's forms (compiler_forms.cpp), checked on the tokens
  size_t command_end(size_t first) const;  // the `;`, the next line's start or the end
  size_t closing(size_t open) const;       // the token after the bracket that closes `open`
  bool is_builtin_call(size_t at) const;
  bool is_variable(size_t first, size_t end) const;  // v, v[i], *p, *p[i]
  bool is_constant(size_t first, size_t end) const;  // a number, -number, sizeof(v)
  bool is_state_logic(size_t first, size_t end) const;
  std::string tokens_text(size_t first, size_t end) const;
  void check_assignment_form(size_t first, size_t end, bool operation_assignment);
  bool check_call_alone(size_t at);  // a built-in function's call at token `at`
  void check_function_argument(size_t first, size_t end, bool last);
  void check_proc_argument(size_t first, size_t end);

  // --- places and memory (compiler_memory.cpp)
  std::optional<Place> parse_place(bool for_store);
  void emit_load(const Place& p, bool keep_prefix);
  void emit_store(const Place& p);
  void emit_post_increments(const Place& p);
  void emit_increment(const Var& v, int32_t by);
  void emit_pointer_check(bool float_address);  // a program's address, bit 29 cleared (checked)
  void emit_word_check(bool ignore_float_bit);
  void add_base_address(const Var& v);   // index on the stack + array v's address
  void emit_user_check();                // flat address in user memory (checked)
  bool logical_address(bool for_store);  // pushes a memory place's logical address
  void read_var(const Var& v);
  void emit_frame_address(int32_t index);
  void emit_stack_address(uint32_t reg, int32_t offset);
  const Var* find_var(const std::string& name) const;
  void memory_block_assignment(size_t lhs_start);
  void emit_copy_loop(bool set, bool is_float, uint32_t dst, uint32_t src, uint32_t n);
  void emit_phase_yields(uint32_t n_local, int32_t per_phase);
  Ty memory_reduction(const std::string& name, size_t at, CodeBuilder::Label skip, bool has_prefix);
  bool has_prefix(const Place& p) const;
  uint32_t scratch();
  void release(uint32_t count) { scratch_next_ -= count; }
  int32_t add_constant(ValueType type, uint32_t bits);

  std::vector<Token> toks_;
  size_t pos_ = 0;
  std::function<Location(size_t)> locate_;
  std::string source_name_;
  std::vector<Diagnostic> diagnostics_;
  size_t error_count_ = 0;
  static constexpr int kMaxExpressionDepth = 200;  // [pdl 67]
  int expression_depth_ = 0;
  bool expression_abandoned_ = false;  // [pdl 67] reported: the open levels' ')' are not

  bytecode::Image image_;
  CodeBuilder code_{image_.code};

  // Where the debug info's code words are, bound once the code is finished.
  struct ProcMark {
    ProcInfo info;
    CodeBuilder::Label entry{}, after{};
  };
  std::vector<ProcMark> proc_marks_;
  std::vector<std::pair<CodeBuilder::Label, CodeBuilder::Label>> loop_marks_;
  DebugInfo debug_info_;

  std::vector<Var> globals_;
  std::vector<Var> locals_;  // the current procedure's parameters and locals
  int32_t user_words_ = 0;
  std::map<std::string, Proc> procs_;
  std::vector<std::map<std::string, LabelInfo>> scopes_{1};
  int scope_ = 0;
  Proc* current_proc_ = nullptr;
  int32_t frame_words_ = 0;  // 2 + parameters + locals of the current procedure
  std::vector<CodeBuilder::Label> return_sites_;   // of `call`s, by return id
  std::vector<int> return_scopes_;                 // the scope of each
  std::map<int, CodeBuilder::Label> dispatchers_;  // each scope's dispatch over its return ids
  std::vector<CommandStart> commands_;
  std::vector<IndirectGoto> indirect_;
  std::vector<LabelValue> label_values_;
  CodeBuilder::Label proc_end_{};  // the current procedure's RET
  bool tasks_seen_[kTasks + 1] = {};
  uint32_t slots_ = 0;
  size_t text_bytes_ = 0;
  uint32_t scratch_next_ = kFirstScratch;
  uint32_t scratch_high_ = kFirstScratch;  // one past the highest scratch local of the procedure
  bool in_lock_ = false;
  // The drive compiler's forms are checked (compile()), not the debugger's evaluations.
  bool strict_forms_ = true;
  // The right side of the `=` being compiled: a function's call may be all of it.
  size_t call_first_ = SIZE_MAX, call_end_ = 0;
  // An integer assignment's `/` of two integers rounds exactly (2.3.6), not through a float.
  bool integer_quotient_ = false;
  int loop_depth_ = 0;  // the loops open around the command, in its scope (their counts)
  struct LoopExit {
    uint32_t code;  // the INCL kSp whose immediate drops the counts the target is not in
    int scope;
    std::string label;
    int depth;
  };
  std::vector<LoopExit> loop_exits_;
  int32_t slave_reads_ = 0;
  int32_t operations_ = 0;
  bool in_short_if_ = false;
  bool size_reported_ = false;
  bool address_float_ = false;  // the last logical_address() was a float's
  bool address_short_ = false;
};

}  // namespace uprog::pdl
