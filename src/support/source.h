// Source text and places in it. A Location names the original file, line and column (1-based),
// so that diagnostics point at what the user wrote, also after preprocessing.
#pragma once
#include <memory>
#include <string>

namespace uprog {

struct Location {
  std::string file;
  int line = 0;    // 1-based; 0 when unknown
  int column = 0;  // 1-based; 0 when unknown
};

struct SourceFile {
  std::string name;  // as the user gave it
  std::string text;
};

}  // namespace uprog
