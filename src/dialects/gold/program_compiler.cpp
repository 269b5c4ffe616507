// The streaming driver. Gold lets a function call functions defined further down, and a later
// declaration can change what a name in an earlier body means (a function defined later, a
// label, a global that takes a function's name). So each body is first checked against what is
// declared so far, noting every name it asked about, and generated at once; when the whole file
// is parsed, the declarations are made as a compiler holding the whole tree would make them, and
// a body's first check stands only if none of its names was declared after it. Otherwise (a
// call of a function defined further down, say) the body is parsed and checked again. Either
// way its errors are reported in the order a whole-tree checker gives them.
#include "dialects/gold/program_compiler.h"

#include <algorithm>
#include <memory>
#include <unordered_map>

#include "dialects/gold/checker.h"
#include "dialects/gold/codegen.h"
#include "dialects/gold/parser.h"

namespace uprog::gold {

namespace {

// One function body: its first check, the names it asked about, its code.
struct BodyRecord {
  CheckedBody first;
  size_t queries_begin = 0, queries_end = 0;
  bool generated = false;
  uint32_t words = 0;  // code size, also when the code itself is not kept
  bool code_ok = true;
  std::unique_ptr<FunctionCode> code;  // when kept
};

class Driver : public FunctionBodySink {
 public:
  Driver(Lexer& lexer, Reporter& reporter, const Locator& locator, bool keep_code)
      : lexer_(lexer),
        reporter_(reporter),
        locator_(locator),
        keep_code_(keep_code),
        first_(reporter) {}

  AstArena& scratch() override { return scratch_; }

  void body(Program& program, FunctionDef* f, Block& body) override {
    if (f != nullptr) {
      records_.emplace_back();
      BodyRecord& r = records_.back();
      r.queries_begin = queried_.size();
      first_.speculate(program, *f, body, r.first, queried_);
      r.queries_end = queried_.size();
      // A program with syntax errors gets no image: no need for code then.
      if (r.first.checked && r.first.errors.empty() && !reporter_.has_errors())
        generate(r, first_.symbols(), r.first.symbol, body, *f);
      if (r.first.checked) first_.forget_locals(r.first.symbol);
    }
    scratch_.reset();
  }

  bytecode::Image run() {
    Program program = parse_program(lexer_, reporter_, tree_, this);
    if (program.empty && !reporter_.has_errors()) reporter_.error(Error::EmptyProgram, 0);
    reporter_.set_stage(Stage::Check);
    ProgramChecker checker(reporter_);
    checker.declare(program);

    // Where each name was last declared: a body checked before that may have read it otherwise.
    std::unordered_map<uint32_t, uint32_t> declared;  // name_hash -> offset
    auto declare = [&](std::string_view name, uint32_t offset) {
      uint32_t& at = declared[name_hash(name)];
      at = std::max(at, offset);
    };
    for (const VarDecl& g : program.globals) declare(g.name, g.offset);
    for (const FunctionDef& f : program.functions) declare(f.name, f.offset);
    for (const StmtPtr& s : program.top)
      if (s->kind == StmtKind::Label) declare(s->name, s->offset);

    std::vector<const FunctionCode*> bodies(checker.symbols().functions.size(), nullptr);
    uint32_t words = 0;
    bool code_ok = true;
    // Once one body is checked where its first check did not (or the other way round), the
    // local labels and undefined loop variables that later bodies see differ: check them again.
    bool diverged = false;
    size_t next_record = 0;
    for (FunctionDef& f : program.functions) {
      if (!f.has_body) continue;
      BodyRecord& r = records_[next_record++];
      const int symbol = checker.symbol_for_body(f);
      if (symbol < 0) {
        diverged = diverged || r.first.checked;
        continue;
      }
      bool holds = r.first.checked && !diverged;
      for (size_t q = r.queries_begin; holds && q < r.queries_end; ++q) {
        const auto it = declared.find(queried_[q]);
        holds = it == declared.end() || it->second <= f.end_offset;
      }
      if (holds) {
        checker.accept(symbol, r.first);
      } else {
        diverged = diverged || !r.first.checked;
        r = BodyRecord{};
        reporter_.set_muted(true);  // its syntax errors are reported already
        Block body = reparse_body(lexer_, reporter_, scratch_, f);
        reporter_.set_muted(false);
        checker.check_body(f, symbol, body);
        if (!reporter_.has_errors()) generate(r, checker.symbols(), symbol, body, f);
        scratch_.reset();
      }
      if (!r.generated) continue;
      words += r.words;
      code_ok = code_ok && r.code_ok;
      if (keep_code_) bodies[static_cast<size_t>(symbol)] = r.code.get();
    }
    checker.check_top(program);
    if (reporter_.has_errors()) return {};
    // With no error, every body that has a symbol was generated (first or second time).
    return generate_program(program, checker.symbols(), bodies, keep_code_ ? 0 : words, code_ok,
                            locator_, reporter_, constants_, !keep_code_);
  }

 private:
  void generate(BodyRecord& r, const Symbols& symbols, int symbol, const Block& body,
                const FunctionDef& f) {
    generate_function(symbols, symbol, body, f.end_offset, locator_, constants_, keep_code_, code_);
    r.generated = true;
    r.words = static_cast<uint32_t>(code_.code.size());
    r.code_ok = code_.ok;
    if (keep_code_) r.code = std::make_unique<FunctionCode>(std::move(code_));
  }

  Lexer& lexer_;
  Reporter& reporter_;
  const Locator& locator_;
  bool keep_code_;
  AstArena tree_;     // globals and the top level: kept to the end
  AstArena scratch_;  // one function body at a time
  ProgramChecker first_;
  std::vector<uint32_t> queried_;  // name_hash of the names each body asked about
  std::deque<BodyRecord> records_;
  ConstantTable constants_;
  FunctionCode code_;  // the body being generated; a check reuses its buffers
};

}  // namespace

bytecode::Image compile_program(Lexer& lexer, Reporter& reporter, const Locator& locator,
                                bool keep_code) {
  Driver driver(lexer, reporter, locator, keep_code);
  return driver.run();
}

}  // namespace uprog::gold
