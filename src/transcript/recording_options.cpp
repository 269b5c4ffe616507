// Recorder settings from words (recording_options.h), shared by `uprog run` and transcripts.
#include "transcript/recording_options.h"

#include <charconv>
#include <filesystem>
#include <sstream>
#include <vector>

#include "drive/axis.h"
#include "drive/recording_csv.h"
#include "support/files.h"

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
  const std::string bad = "trigger '" + spec +
                          "': expected immediate, begin, rising:CH:LEVEL, falling:CH:LEVEL, "
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
    out.kind =
        kind == "leave" ? drive::TriggerKind::kWindowLeave : drive::TriggerKind::kWindowEnter;
    if (!parse_double(p[2], out.low) || !parse_double(p[3], out.level) || out.low > out.level)
      return bad;
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

std::string record_directive(controller::Controller& drive, const std::string& arg) {
  std::istringstream words(arg);
  RecordRequest request;
  request.early_trigger = true;
  if (!(words >> request.channels))
    return "expected 'record CHANNELS [trigger=SPEC] [pretrigger=P] [length=N] [gap=N]'";
  for (std::string w; words >> w;) {
    const size_t eq = w.find('=');
    const std::string key = w.substr(0, eq),
                      value = eq == std::string::npos ? std::string() : w.substr(eq + 1);
    bool ok = true;
    if (key == "trigger")
      request.trigger = value;
    else if (key == "pretrigger")
      ok = parse_count(value, 100, request.pretrigger_percent);
    else if (key == "length")
      ok = parse_count(value, UINT32_MAX, request.length) && request.length > 0;
    else if (key == "gap")
      ok = parse_count(value, 1u << 20, request.gap_cycles) && request.gap_cycles > 0;
    else
      return "unknown setting '" + w + "' (trigger=, pretrigger=, length=, gap=)";
    if (!ok || value.empty()) return "'" + w + "' needs a whole number in range";
  }
  drive::RecorderSettings settings;
  if (std::string why = recorder_settings(drive, request, settings); !why.empty()) return why;
  std::string why;
  return drive.recorder().arm(settings, &why) ? std::string() : why;
}

std::string expect_directive(controller::Controller& drive, const std::string& arg,
                             const std::string& base_dir) {
  std::istringstream words(arg);
  std::string file;
  if (!(words >> file)) return "needs a recording's CSV file: 'expect FILE.csv [CH=TOLERANCE ...]'";
  std::vector<drive::Tolerance> tolerances;
  for (std::string w; words >> w;) {
    drive::Tolerance t;
    if (!parse_tolerance(w, t)) return file + ": '" + w + "' is no CHANNEL=TOLERANCE";
    tolerances.push_back(t);
  }
  const std::filesystem::path path = std::filesystem::path(file).is_absolute()
                                         ? std::filesystem::path(file)
                                         : std::filesystem::path(base_dir) / file;
  std::string error;
  const std::optional<std::string> text = read_text_file(path.string(), &error);
  const std::optional<drive::Recording> expected =
      text ? drive::read_recording_csv(*text, &error) : std::nullopt;
  if (!expected) return file + ": " + error;
  const std::optional<drive::Recording> actual =
      drive.recorder().recording(drive.axis().period_us());
  if (!actual)
    return file + ": the recorder has not been triggered (is a 'record' line before it?)";
  const std::optional<drive::Difference> d = drive::compare(*actual, *expected, tolerances);
  return d ? file + ": " + d->text : std::string();
}

}  // namespace uprog::transcript
