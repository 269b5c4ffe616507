// The dialects' stop lines (stop_lines.h).
#include "studio/stop_lines.h"

namespace uprog::studio {

std::vector<std::string> stop_lines(std::string_view dialect_name,
                                    const std::vector<dialect::ThreadInfo>& threads) {
  // Gold: KL kills the program and stops the motion (docs/dialects/gold.md, "KL, HP").
  if (dialect_name == "gold") return {"KL"};
  // S300: PLCSTOP stops every macro program (docs/dialects/st.md).
  if (dialect_name == "st") return {"PLCSTOP"};
  std::vector<std::string> lines;
  for (const dialect::ThreadInfo& t : threads) {
    // PDL: kill/t for tasks 1..3 (host_lines.cpp); task 0 is the host's own line.
    if (dialect_name == "pdl" && t.thread >= 1 && t.thread <= 3)
      lines.push_back("kill/" + std::to_string(t.thread));
    // AG300: AProgHalt[n] halts thread n (docs/dialects/pup.md, "AProgHalt[n]'s index").
    if (dialect_name == "pup" && t.thread >= 1)
      lines.push_back("AProgHalt[" + std::to_string(t.thread) + "]");
  }
  return lines;
}

}  // namespace uprog::studio
