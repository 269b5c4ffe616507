// Recorder settings from words (recording_options.h), shared by `uprog run` and transcripts.
#include "transcript/recording_options.h"

#include <charconv>
#include <vector>

namespace uprog::transcript {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  size_t start = 0;
  for (;;) {
    const size_t p = s.find(sep, start);
    out.push_back(s.substr(start, p == std::string::npos ? std::string::npos : p - start));
    if (p == std::string::npos) return out;
    start = p + 1;
  }
}

bool parse_double(const std::string& s, double& out) {
  const auto [p, e] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && e == std::errc() && p == s.data() + s.size();
}

std::string channel(controller::Controller& drive, const std::string& name, drive::Channel& out) {
  std::string why;
  if (std::optional<drive::Channel> c = drive.recorder_channel(name, &why)) {
    out = std::move(*c);
    return {};
  }
  return why.empty() ? "no channel '" + name + "'" : why;
}

std::string trigger(controller::Controller& drive, const std::string& spec, drive::Trigger& out) {
  const std::vector<std::string> p = split(spec, ':');
  const std::string& kind = p[0];
  const std::string bad = "trigger '" + spec + "': expected immediate, begin, rising:CH:LEVEL, falling:CH:LEVEL, "
                          "leave:CH:LOW:HIGH, enter:CH:LOW:HIGH or input:N:rise|fall";
  if ((kind == "immediate" || kind == "begin") && p.size() == 1) {
    out.kind = kind == "begin" ? drive::TriggerKind::kBeginMotion : drive::TriggerKind::kImmediate;
    return {};
  }
  if ((kind == "rising" || kind == "falling") && p.size() == 3) {
    out.kind = kind == "rising" ? drive::TriggerKind::kRising : drive::TriggerKind::kFalling;
    if (!parse_double(p[2], out.level)) return bad;
    return channel(drive, p[1], out.source);
  }
  if ((kind == "leave" || kind == "enter") && p.size() == 4) {
    out.kind = kind == "leave" ? drive::TriggerKind::kWindowLeave : drive::TriggerKind::kWindowEnter;
    if (!parse_double(p[2], out.low) || !parse_double(p[3], out.level) || out.low > out.level) return bad;
    return channel(drive, p[1], out.source);
  }
  if (kind == "input" && p.size() == 3 && p[1].size() == 1 && p[1][0] >= '1' && p[1][0] <= '6' &&
      (p[2] == "rise" || p[2] == "fall")) {
    out.kind = drive::TriggerKind::kInput;
    out.input_mask = 1u << (p[1][0] - '1');
    out.input_polarity = p[2] == "rise" ? out.input_mask : 0u;
    return {};
  }
  return bad;
}

}  // namespace

std::string recorder_settings(controller::Controller& drive, const RecordRequest& request,
                              drive::RecorderSettings& out) {
  out = {};
  if (request.channels.empty()) return "no channels to record";
  for (const std::string& name : split(request.channels, ',')) {
    drive::Channel c;
    if (std::string why = channel(drive, name, c); !why.empty()) return why;
    out.channels.push_back(std::move(c));
  }
  if (std::string why = trigger(drive, request.trigger, out.trigger); !why.empty()) return why;
  out.pretrigger_percent = request.pretrigger_percent;
  out.gap_cycles = request.gap_cycles;
  out.length = request.length;
  out.early_trigger = request.early_trigger;
  return {};
}

bool parse_tolerance(const std::string& text, drive::Tolerance& out) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) return false;
  out.channel = text.substr(0, eq);
  return parse_double(text.substr(eq + 1), out.value) && out.value >= 0;
}

bool parse_count(const std::string& text, uint32_t max, uint32_t& out) {
  const auto [p, e] = std::from_chars(text.data(), text.data() + text.size(), out);
  return !text.empty() && e == std::errc() && p == text.data() + text.size() && out <= max;
}

}  // namespace uprog::transcript
