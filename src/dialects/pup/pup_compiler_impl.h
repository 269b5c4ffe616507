// The PUP compiler's state, shared by its two halves: pup_source.cpp (files, #include, the
// directives, #define at token level) and pup_statements.cpp (statements, flow control, labels).
#pragma once
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dialects/pup/errors.h"
#include "dialects/pup/pup_compiler.h"
#include "dialects/pup/pup_expr.h"

namespace uprog::pup {

constexpr size_t kMaxNesting = 32;

struct OutLine {
  std::string text;  // the CUP line, or its part before a jump target
  Location where;
  int label = -1;     // a jump target to append: a label's line
  int task_ref = -1;  // a jump target to append: task n's marker line (GoTo)
};

struct Define {
  std::vector<Token> tokens;
  std::string text;
  Location where;
};

enum class BlockKind { If, While, For, Switch };

struct Block {
  Block(BlockKind k, Location at) : kind(k), where(std::move(at)) {}
  BlockKind kind;
  Location where;
  int next = -1;  // If: where a false condition goes; Switch: the dispatch code
  int end = -1;   // the line after the block
  int cont = -1;  // While/For: where `continue` goes
  bool seen_else = false;
  Code step;  // For: the step's lines; Switch: the selector's lines
  std::vector<std::pair<int32_t, int>> cases;  // Switch: value, label
  int default_label = -1;
};

class PupCompiler {
 public:
  PupCompiler(uint64_t created_unix_s, const IncludeSearch& includes) : includes_(includes) {
    out_.program.date = cup_date(created_unix_s);
  }
  PupOutput run(const std::string& path, const std::string& text);

 private:
  // --- pup_source.cpp ---
  void read_text(const std::string& path, const std::string& text, bool header);
  void line(const std::string& raw, const Location& at, bool header, const std::string& path);
  void directive(const std::string& text, const Location& at, const std::string& path);
  void include(const std::string& name, const Location& at, const std::string& path);
  void define(const std::string& rest, const Location& at);
  void definevar(const std::string& rest, const Location& at);
  void event(const std::string& rest, const Location& at);
  std::optional<std::vector<Token>> tokens_of(const std::string& text, const Location& at);
  void expand(std::vector<Token>& tokens, int depth);
  void error(Error e, const Location& at, const std::string& detail = {});

  // --- pup_statements.cpp ---
  void statement(std::vector<Token>& tokens, const Location& at);
  void flow(const std::string& word, TokenCursor& cur, const Location& at);
  void close_block(const Location& at);
  void message(TokenCursor& cur, const Location& at);
  void assignment(TokenCursor& cur, const Location& at);
  void marker(const Keyword& k, int32_t index, const Location& at);
  bool expression(TokenCursor& cur, ExprTree& tree, int& node, bool needs_end);
  std::optional<int32_t> constant(TokenCursor& cur, const char* what, bool needs_end);
  void condition_false_jump(const ExprTree& tree, int node, int label, const Location& at);
  void emit(std::string text, const Location& at, int label = -1);
  // The code's lines, its labels made fresh; label0 (when given) stands for its label 0.
  void place_code(const Code& code, const Location& at, int label0 = -1);
  Code take_code(size_t first_line, size_t first_label);
  int new_label();
  void bind(int label);
  Block* innermost(bool loops_only);
  void close_function();
  void finish();
  void refuse_what_the_loader_refuses(const std::string& path);

  PupOutput out_;
  std::vector<OutLine> lines_;
  std::vector<uint32_t> labels_;  // line of each label, 0 while unbound
  std::vector<Block> blocks_;
  std::map<std::string, Define> defines_;
  VarTable vars_;
  std::vector<std::string> include_stack_;
  const IncludeSearch& includes_;
  std::map<int32_t, Location> tasks_, functions_;
  std::vector<std::pair<int32_t, Location>> calls_, events_;
  std::optional<std::pair<int32_t, Location>> open_function_;
  bool function_returned_ = false;
};

}  // namespace uprog::pup
