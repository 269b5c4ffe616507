// The PDL debug info lines (debug_info.h).
#include "dialects/pdl/debug_info.h"

#include <sstream>

namespace uprog::pdl {

std::vector<std::string> DebugInfo::info_lines() const {
  std::vector<std::string> out;
  for (const ProcInfo& p : procs) {
    std::string line = "proc " + p.name + " " + std::to_string(p.first) + " " +
                       std::to_string(p.end) + " " + std::to_string(p.frame_words) + " " +
                       std::to_string(p.params);
    for (const FrameVar& v : p.vars) {
      line += " " + v.name + ":" + v.kind + ":" + (v.pointer ? "1" : "0") + ":" +
              std::to_string(v.length) + ":" + std::to_string(v.offset);
    }
    out.push_back(std::move(line));
  }
  std::string rets = "rets";
  for (uint32_t pc : return_sites) rets += " " + std::to_string(pc);
  out.push_back(std::move(rets));
  std::string loop_line = "loops";
  for (const LoopRange& l : loops)
    loop_line += " " + std::to_string(l.body) + " " + std::to_string(l.exit);
  out.push_back(std::move(loop_line));
  return out;
}

namespace {

bool parse_var(const std::string& text, FrameVar& v) {
  std::istringstream in(text);
  std::string kind, pointer, length, offset;
  if (!std::getline(in, v.name, ':') || !std::getline(in, kind, ':') ||
      !std::getline(in, pointer, ':') || !std::getline(in, length, ':') ||
      !std::getline(in, offset))
    return false;
  if (kind.size() != 1 || (kind[0] != 'l' && kind[0] != 'f' && kind[0] != 's')) return false;
  v.kind = kind[0];
  v.pointer = pointer == "1";
  try {
    v.length = static_cast<uint32_t>(std::stoul(length));
    v.offset = std::stoi(offset);
  } catch (...) {
    return false;
  }
  return v.length >= 1 && v.length <= 256 && v.offset >= 0 && v.offset < 256;
}

}  // namespace

DebugInfo DebugInfo::read(const std::vector<std::string>& info) {
  DebugInfo d;
  for (const std::string& line : info) {
    std::istringstream in(line);
    std::string kind;
    in >> kind;
    if (kind == "proc") {
      ProcInfo p;
      if (!(in >> p.name >> p.first >> p.end >> p.frame_words >> p.params)) continue;
      std::string var;
      bool ok = true;
      while (in >> var) {
        FrameVar v;
        if (!parse_var(var, v))
          ok = false;
        else
          p.vars.push_back(std::move(v));
      }
      if (ok && p.frame_words >= 2 && p.frame_words <= 256) d.procs.push_back(std::move(p));
    } else if (kind == "rets") {
      uint32_t pc = 0;
      while (in >> pc) d.return_sites.push_back(pc);
    } else if (kind == "loops") {
      LoopRange l;
      while (in >> l.body >> l.exit) d.loops.push_back(l);
    }
  }
  return d;
}

std::vector<uint32_t*> DebugInfo::code_words() {
  std::vector<uint32_t*> out;
  for (ProcInfo& p : procs) {
    out.push_back(&p.first);
    out.push_back(&p.end);
  }
  for (uint32_t& pc : return_sites) out.push_back(&pc);
  for (LoopRange& l : loops) {
    out.push_back(&l.body);
    out.push_back(&l.exit);
  }
  return out;
}

const ProcInfo* DebugInfo::proc_at(uint32_t pc) const {
  for (const ProcInfo& p : procs)
    if (pc >= p.first && pc < p.end) return &p;
  return nullptr;
}

uint32_t DebugInfo::loops_open(uint32_t pc) const {
  const ProcInfo* own = proc_at(pc);
  uint32_t n = 0;
  for (const LoopRange& l : loops)
    if (pc >= l.body && pc <= l.exit && proc_at(l.body) == own) ++n;
  return n;
}

}  // namespace uprog::pdl
