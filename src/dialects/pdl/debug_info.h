// What the debugger needs of a PDL program beyond the image's line table, written by the compiler
// into the image's info lines and read by the firmware: each procedure's code range and frame
// (its parameters and locals by word), the code word of each return site (the return ids a
// `call` pushes), and each loop's body range (where its count is on the task stack). From these
// and the VM's frames (a procedure's routine each) the firmware walks a task's frames
// (debug_hooks.cpp).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace uprog::pdl {

struct FrameVar {
  std::string name;
  char kind = 'l';  // 'l' long, 'f' float, 's' short (a pointer only)
  bool pointer = false;
  uint32_t length = 1;
  int32_t offset = 0;  // words from the frame's first (the return id)
};

struct ProcInfo {
  std::string name;
  uint32_t first = 0;  // its body's first code word
  uint32_t end = 0;    // the code word after its code (its RET, dispatches, locals' zeroing)
  int32_t frame_words = 2;
  uint32_t params = 0;
  std::vector<FrameVar> vars;  // the parameters, then the locals
};

struct LoopRange {
  uint32_t body = 0;  // its body's first code word: the count has been pushed
  uint32_t exit = 0;  // the code word that pops it (still on the stack there)
};

struct DebugInfo {
  std::vector<ProcInfo> procs;
  std::vector<uint32_t> return_sites;  // by return id
  std::vector<LoopRange> loops;

  // "proc NAME FIRST END WORDS PARAMS var:K:P:LEN:OFF…", "rets PC…", "loops BODY EXIT…".
  std::vector<std::string> info_lines() const;
  // From an image's info lines; lines of another kind are skipped, a malformed one ends nothing
  // worse than the frames it would have described.
  static DebugInfo read(const std::vector<std::string>& info);
  // Every code word it names, for moving them with the code (compile.cpp's peephole pass).
  std::vector<uint32_t*> code_words();
  const ProcInfo* proc_at(uint32_t pc) const;
  // The loops of pc's own procedure (or of the task code) whose count is on the stack at pc.
  uint32_t loops_open(uint32_t pc) const;
};

}  // namespace uprog::pdl
