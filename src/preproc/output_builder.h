// Appends the preprocessor's output and records, as it goes, where each stretch came from:
// a Segment where the origin stops advancing one column per character, an Expansion per macro use.
#pragma once
#include <string>
#include <string_view>

#include "preproc/preprocess.h"

namespace uprog::preproc {

class OutputBuilder {
 public:
  OutputBuilder(std::string file, size_t expected_size) : file_(std::move(file)) {
    result_.map.file = file_;
    result_.text.reserve(expected_size);
  }

  // Output that follows comes from `line`, starting at `column` (1-based).
  void mark(int line, int column) {
    auto& segs = result_.map.segments;
    const size_t at = result_.text.size();
    if (!segs.empty() && segs.back().out_begin == at) segs.pop_back();  // nothing written since
    if (!segs.empty()) {
      // Continuing the previous segment needs no new entry.
      const auto& last = segs.back();
      if (last.line == line && last.file == file_index_ &&
          static_cast<size_t>(last.column) + (at - last.out_begin) == static_cast<size_t>(column))
        return;
    }
    segs.push_back({at, line, column, file_index_});
  }
  // Output that follows comes from `name` (an included file; "" for the source itself).
  // Returns the index of the file that was current, to come back to.
  uint32_t enter_file(const std::string& name) {
    const uint32_t previous = file_index_;
    result_.map.included.push_back(name);
    file_index_ = static_cast<uint32_t>(result_.map.included.size());
    return previous;
  }
  void leave_file(uint32_t previous) { file_index_ = previous; }
  void append(std::string_view s) { result_.text.append(s); }
  void append(char c) { result_.text.push_back(c); }
  size_t size() const { return result_.text.size(); }

  void add_expansion(Expansion e) { result_.map.expansions.push_back(std::move(e)); }
  const std::string& file() const { return file_; }
  Preprocessed take() { return std::move(result_); }

 private:
  std::string file_;
  uint32_t file_index_ = 0;
  Preprocessed result_;
};

}  // namespace uprog::preproc
