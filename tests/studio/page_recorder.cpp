// The fake page (page_recorder.h).
#include "page_recorder.h"

#include <cstring>

namespace uprog::studio::testing {

PageSink PageRecorder::sink() {
  return PageSink{
      [this](const std::string& text) { messages.push_back(nlohmann::json::parse(text)); },
      [this](const std::string& bytes) { blocks.push_back(decode_block(bytes)); }};
}

nlohmann::json PageRecorder::last(const std::string& type) const {
  for (auto it = messages.rbegin(); it != messages.rend(); ++it) {
    if ((*it)["type"] == type) return *it;
  }
  return nullptr;
}

ScopeBlock decode_block(const std::string& bytes) {
  std::vector<double> words(bytes.size() / sizeof(double));
  std::memcpy(words.data(), bytes.data(), words.size() * sizeof(double));
  ScopeBlock block;
  if (words.size() < 4) return block;
  block.first_time_us = static_cast<uint64_t>(words[0]);
  block.period_us = static_cast<uint32_t>(words[1]);
  block.channels = static_cast<uint32_t>(words[2]);
  block.values.assign(words.begin() + 4, words.end());
  return block;
}

}  // namespace uprog::studio::testing
