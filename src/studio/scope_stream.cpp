// The live scope's recorder stream (scope_stream.h).
#include "studio/scope_stream.h"

#include <bit>
#include <cstring>

#include "drive/axis.h"
#include "drive/recorder.h"

namespace uprog::studio {

std::string ScopeStream::choose(const std::vector<std::string>& names) {
  if (names.size() > kMaxChannels) return "at most " + std::to_string(kMaxChannels) + " channels";
  std::vector<drive::Channel> chosen;
  for (const std::string& name : names) {
    std::string why;
    auto channel = drive_.recorder_channel(name, &why);
    if (!channel) return name + ": " + why;
    chosen.push_back(std::move(*channel));
  }
  if (chosen.empty() && !channels_.empty()) drive_.recorder().kill();
  channels_ = std::move(chosen);
  return {};
}

std::string ScopeStream::prepare(uint64_t ns) {
  if (channels_.empty()) return {};
  drive::RecorderSettings settings;
  settings.channels = channels_;
  settings.gap_cycles = 1;
  const uint64_t period_ns = uint64_t{drive_.axis().period_us()} * 1000;
  // Every cycle that can start within `ns`, and a margin for a cycle on either edge.
  settings.length = static_cast<uint32_t>(ns / period_ns + 4);
  settings.trigger.kind = drive::TriggerKind::kImmediate;
  settings.early_trigger = true;
  std::string why;
  if (!drive_.recorder().arm(settings, &why)) return why;
  return {};
}

std::optional<ScopeBlock> ScopeStream::collect() {
  if (channels_.empty()) return std::nullopt;
  const auto recording = drive_.recorder().recording(drive_.axis().period_us());
  if (!recording || recording->samples() == 0) return std::nullopt;
  ScopeBlock block;
  block.period_us = recording->sample_period_us;
  block.first_time_us = recording->trigger_time_us - recording->trigger_index * block.period_us;
  block.channels = static_cast<uint32_t>(recording->channels.size());
  const size_t samples = recording->samples();
  block.values.resize(samples * block.channels);
  for (size_t c = 0; c < block.channels; ++c) {
    const auto& values = recording->channels[c].values;
    for (size_t i = 0; i < samples; ++i) block.values[i * block.channels + c] = values[i];
  }
  return block;
}

std::string encode_block(const ScopeBlock& block) {
  std::vector<double> words = {
      static_cast<double>(block.first_time_us), static_cast<double>(block.period_us),
      static_cast<double>(block.channels), static_cast<double>(block.samples())};
  words.insert(words.end(), block.values.begin(), block.values.end());
  static_assert(std::endian::native == std::endian::little, "the page reads little-endian words");
  std::string bytes(words.size() * sizeof(double), '\0');
  std::memcpy(bytes.data(), words.data(), bytes.size());
  return bytes;
}

}  // namespace uprog::studio
