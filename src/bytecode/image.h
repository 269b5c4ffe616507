// The hosted form of an image, built by compilers and the assembler, and its binary codec.
// encode() writes the binary form of format.h; decode() reads it back through load_image().
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "bytecode/format.h"
#include "support/value.h"

namespace uprog::bytecode {

struct Constant {
  ValueType type = ValueType::Int;
  uint32_t bits = 0;
  bool operator==(const Constant&) const = default;
};

struct Global {
  std::string name;
  ValueType type = ValueType::Int;
  uint32_t length = 1;
  bool operator==(const Global&) const = default;
};

struct Local {
  std::string name;
  ValueType type = ValueType::Int;
  bool operator==(const Local&) const = default;
};

struct Routine {
  std::string name;
  RoutineKind kind = RoutineKind::Function;
  uint32_t inputs = 0;
  uint32_t outputs = 0;
  std::vector<Local> locals;  // inputs first, then outputs, then the others
  uint32_t entry = 0;
  bool operator==(const Routine&) const = default;
};

struct Event {
  uint32_t event = 0;
  uint32_t routine = 0;
  bool operator==(const Event&) const = default;
};

struct LineEntry {
  uint32_t code = 0;
  std::string file;
  uint32_t line = 0;
  bool operator==(const LineEntry&) const = default;
};

// A task routine and how the dialect's scheduler runs it (format.h, TaskRecord).
struct Task {
  uint32_t routine = 0;
  uint32_t number = 0;
  uint32_t period_ns = 0;
  uint32_t priority = 0;
  bool starts_at_reset = false;
  bool operator==(const Task&) const = default;
};

struct Image {
  uint64_t created_unix_s = 0;
  std::string source_name;
  std::string dialect;  // the compiler's dialect ("gold", ...); "" for hand-made images
  std::vector<uint32_t> code;
  std::vector<Constant> constants;
  std::vector<Global> globals;
  std::vector<Routine> routines;
  std::vector<Event> events;
  std::vector<std::string> info;
  std::vector<LineEntry> lines;
  std::vector<std::string> texts;  // what MSG sends, by index
  std::vector<Task> tasks;
  bool operator==(const Image&) const = default;

  // -1 when there is none.
  int find_routine(const std::string& name) const;
  int find_global(const std::string& name) const;
  // The index of constant `c` in the table, added at its end when the image has none.
  uint32_t constant_index(Constant c);
  // The source line of code word `pc`, or nullptr.
  const LineEntry* line_at(uint32_t pc) const;
};

std::vector<uint8_t> encode(const Image& image);
// False with `error` set when the bytes are not a sound image (the code is not verified here).
bool decode(const uint8_t* bytes, size_t size, Image& out, std::string& error);

}  // namespace uprog::bytecode
