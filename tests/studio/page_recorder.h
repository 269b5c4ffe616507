// A fake page for the studio's drive: it keeps every message the drive sends it, parsed.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "studio/scope_stream.h"
#include "studio/studio_drive.h"

namespace uprog::studio::testing {

struct PageRecorder {
  std::vector<nlohmann::json> messages;
  std::vector<ScopeBlock> blocks;

  PageSink sink();
  // The last message of `type`; a null json when none came.
  nlohmann::json last(const std::string& type) const;
  void clear() { messages.clear(), blocks.clear(); }
};

// A block as the page reads it back (encode_block's inverse).
ScopeBlock decode_block(const std::string& bytes);

}  // namespace uprog::studio::testing
