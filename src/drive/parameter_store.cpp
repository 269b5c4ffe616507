// Parameters as text: every field is named, so the file reads well and an old file with
// fewer fields still loads (missing fields keep their defaults).
#include "drive/parameter_store.h"

#include <charconv>
#include <cstdio>
#include <functional>
#include <string_view>
#include <vector>

#include "support/crc32.h"
#include "support/files.h"

namespace uprog::drive {
namespace {

constexpr std::string_view kHeader = "uprog-drive-parameters 1\n";
constexpr std::string_view kCrcPrefix = "crc32 ";

// One named field: its key ("UI[3]") and a pointer to the int or float it stores.
struct Field {
  std::string key;
  int32_t* i = nullptr;
  float* f = nullptr;
};

std::vector<Field> fields_of(Parameters& p) {
  std::vector<Field> out;
  auto add_int = [&](std::string key, int32_t& v) { out.push_back({std::move(key), &v, nullptr}); };
  auto add_float = [&](std::string key, float& v) { out.push_back({std::move(key), nullptr, &v}); };
  auto indexed = [](std::string_view name, int n) {
    return std::string(name) + "[" + std::to_string(n) + "]";
  };
  add_int("UM", p.unit_mode);
  add_int("TS", p.servo_period_us);
  add_int("SP", p.speed_counts_per_s);
  add_int("AC", p.accel_counts_per_s2);
  add_int("DC", p.decel_counts_per_s2);
  add_int("SD", p.stop_decel_counts_per_s2);
  add_int("SF", p.smoothing_ms);
  add_int("JV", p.jog_velocity_counts_per_s);
  add_int("ER[2]", p.max_velocity_error_counts_per_s);
  add_int("ER[3]", p.max_position_error_counts);
  add_int("VH[2]", p.velocity_high_counts_per_s);
  add_int("VL[2]", p.velocity_low_counts_per_s);
  add_int("VH[3]", p.position_high_counts);
  add_int("VL[3]", p.position_low_counts);
  add_int("XM[1]", p.modulo_low_counts);
  add_int("XM[2]", p.modulo_high_counts);
  add_int("HL[2]", p.speed_fault_high_counts_per_s);
  add_int("LL[2]", p.speed_fault_low_counts_per_s);
  add_int("HL[3]", p.position_fault_high_counts);
  add_int("LL[3]", p.position_fault_low_counts);
  add_int("TR[1]", p.target_radius_counts);
  add_int("TR[2]", p.target_time_ms);
  add_int("PM", p.profiler_mode);
  add_int("SF[2]", p.smoothing2_ms);
  add_int("FS", p.final_speed_counts_per_s);
  add_int("RM", p.reference_mode);
  for (int n = 1; n <= 2; ++n)
    add_int(indexed("BP", n), p.brake_delay_ms[static_cast<size_t>(n - 1)]);
  for (int n = 1; n <= 12; ++n)
    add_int(indexed("FC", n), p.feedback_config[static_cast<size_t>(n - 1)]);
  for (int n = 1; n <= 16; ++n)
    add_int(indexed("SC", n), p.stop_config[static_cast<size_t>(n - 1)]);
  add_float("CL[1]", p.continuous_current_a);
  add_float("PL[1]", p.peak_current_a);
  for (int n = 1; n <= 3; ++n) add_float(indexed("KP", n), p.gains.kp[n]);
  for (int n = 1; n <= 3; ++n) add_float(indexed("KI", n), p.gains.ki[n]);
  for (int n = 1; n <= 2; ++n) add_float(indexed("KV", n), p.gains.kv[n]);
  for (int n = 1; n <= kInputCount; ++n)
    add_int(indexed("IL", n), p.input_logic[static_cast<size_t>(n - 1)]);
  for (int n = 1; n <= kCommutationCount; ++n)
    add_int(indexed("CA", n), p.commutation[static_cast<size_t>(n - 1)]);
  for (int n = 1; n <= kUserVariableCount; ++n)
    add_int(indexed("UI", n), p.user_ints[static_cast<size_t>(n - 1)]);
  for (int n = 1; n <= kUserVariableCount; ++n)
    add_float(indexed("UF", n), p.user_floats[static_cast<size_t>(n - 1)]);
  return out;
}

uint32_t crc_of(std::string_view text) {
  return crc32(reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

}  // namespace

std::string serialize_parameters(const Parameters& params) {
  Parameters copy = params;
  std::string text(kHeader);
  for (const Field& f : fields_of(copy)) {
    char buf[32];
    // to_chars gives the shortest text that reads back to the same float, bit for bit.
    const auto r = f.i ? std::to_chars(buf, buf + sizeof buf, *f.i)
                       : std::to_chars(buf, buf + sizeof buf, *f.f);
    text += f.key + "=" + std::string(buf, r.ptr) + "\n";
  }
  char crc[16];
  std::snprintf(crc, sizeof crc, "%08x", crc_of(text));
  text += std::string(kCrcPrefix) + crc + "\n";
  return text;
}

std::optional<Parameters> parse_parameters(const std::string& text, std::string* error) {
  auto fail = [&](std::string why) -> std::optional<Parameters> {
    if (error) *error = std::move(why);
    return std::nullopt;
  };
  if (!text.starts_with(kHeader)) return fail("not a parameter file");
  const size_t crc_at = text.rfind(kCrcPrefix);
  if (crc_at == std::string::npos || (crc_at > 0 && text[crc_at - 1] != '\n'))
    return fail("parameter file has no CRC");
  const std::string_view body(text.data(), crc_at);
  uint32_t stored = 0;
  const char* crc_begin = text.data() + crc_at + kCrcPrefix.size();
  const auto crc_parsed = std::from_chars(crc_begin, text.data() + text.size(), stored, 16);
  if (crc_parsed.ec != std::errc{} || crc_parsed.ptr != crc_begin + 8 || stored != crc_of(body))
    return fail("parameter file is corrupt (CRC mismatch)");

  Parameters params;
  std::vector<Field> fields = fields_of(params);
  size_t pos = kHeader.size();
  while (pos < body.size()) {
    const size_t end = body.find('\n', pos);
    if (end == std::string_view::npos) return fail("unterminated line");
    const std::string_view line = body.substr(pos, end - pos);
    pos = end + 1;
    const size_t eq = line.find('=');
    if (eq == std::string_view::npos) return fail("bad line: " + std::string(line));
    const std::string_view key = line.substr(0, eq);
    const std::string_view value = line.substr(eq + 1);
    Field* field = nullptr;
    for (Field& f : fields)
      if (f.key == key) field = &f;
    if (!field) return fail("unknown parameter: " + std::string(key));
    const char* first = value.data();
    const char* last = value.data() + value.size();
    const auto r = field->i ? std::from_chars(first, last, *field->i)
                            : std::from_chars(first, last, *field->f);
    if (r.ec != std::errc{} || r.ptr != last) return fail("bad value: " + std::string(line));
  }
  return params;
}

bool save_parameters(const Parameters& params, const std::string& path, std::string* error) {
  const std::string text = serialize_parameters(params);
  return write_file_atomically(path, text.data(), text.size(), error);
}

std::optional<Parameters> load_parameters(const std::string& path, std::string* error) {
  const std::optional<std::string> text = read_text_file(path, error);
  if (!text) return std::nullopt;
  return parse_parameters(*text, error);
}

}  // namespace uprog::drive
