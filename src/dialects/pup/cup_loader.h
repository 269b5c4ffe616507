// The controller's loader: a CUP program (its lines and tables) checked and translated into the
// project's verified image, each CUP line its own line of code (EOL), so that the threads run
// one CUP line per turn and program keywords speak in CUP lines.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bytecode/image.h"
#include "dialects/pup/cup_file.h"
#include "dialects/pup/keywords.h"
#include "dialects/pup/message.h"
#include "vm/machine.h"

namespace uprog::pup {

// Host command numbers of the image, beyond the keywords' own (KeywordId): what the firmware
// computes for a line that the VM has no opcode for.
constexpr uint32_t kIndexedBase = 0x1000;  // + k: indexed access k (APushParamIdx / APopParamIdx)
constexpr uint32_t kFailBase = 0x3000;     // + code: the line fails with this controller error
constexpr uint32_t kReturnCheck = 0x3FFF;  // AReturn: error 29 when the thread is in no call
constexpr uint32_t kStatusBase = 0x4000;   // + s: AGetStatus[s] of the index v, 1 or 0

// AGenData[1..1000]: the controller's general data, which the firmware keeps (0 at boot, kept
// across downloads). A line naming AGenData[n] loads or stores element n - 1 of the image's global
// "AGenData", which the firmware places on its own words (bind_gen_data).
constexpr size_t kGenDataSize = 1000;
constexpr const char* kGenDataGlobal = "AGenData";

struct IndexedAccess {
  KeywordId key;
  int32_t base = 0;  // key[base + i - 1]
  int32_t size = 0;  // i in 1..size, else error 4
};

struct LoadedCup {
  bytecode::Image image;
  std::vector<uint32_t>
      line_pc;  // per CUP line from 1 (index 0 unused), its first code word; one more: the end
  std::vector<IndexedAccess> indexed;
  std::vector<int32_t> task_routine;   // by task number 0..64, -1 for none
  std::vector<int32_t> event_routine;  // by event ID 0..23, -1 for none
  std::vector<int32_t> line_depth;     // stack depth before each line, -1 unreachable
  std::vector<bool> waits;             // per line: an AWaitStatus (a thread in it is waiting)
  std::vector<bool> timed_waits;       // per line: an AWaitTime
  // Past the lines' code, the fused copies (line_runs.h): the CUP line of each copy's start and
  // of each of its instructions that may fail, by code word, in code order.
  std::vector<std::pair<uint32_t, uint32_t>> copy_lines;
  // The CUP line of a code word (0 for none).
  uint32_t line_of(uint32_t pc) const;
};

// The index of the image's global "AGenData", added the first time it is asked for.
uint32_t gen_data_global(bytecode::Image& image);
// The index of the one-word global "AGenData[n]" (a fused copy's name for element n, placed on
// the same word by bind_gen_data), added the first time.
uint32_t gen_data_element_global(bytecode::Image& image, int32_t n);
// LDGW's and STGW's window of AGenData for APushParamIdx[k],AGenData[n] (elements n..n+k-1).
uint32_t gen_data_window(const Message& m);

// nullopt with `error` "line N: why" (the download's error 45) when the program is unsafe;
// `refused_line` gets N (0 for the program's tables), so that a compiler can name its source.
std::optional<LoadedCup> load_cup(const CupProgram& program, std::string* error,
                                  uint32_t* refused_line = nullptr);

// Places the image's AGenData (if it has one) on the general data the host keeps.
bool bind_gen_data(vm::Machine& machine, const LoadedCup& cup,
                   std::array<Value, kGenDataSize>& gen_data);

}  // namespace uprog::pup
