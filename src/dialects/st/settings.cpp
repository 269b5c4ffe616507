// The S300's parameters (firmware.h): their defaults (RSTVAR), and SAVE/LOAD into the flash
// record "st_parameters.txt", a `NAME value` line each, replaced atomically as every record.
#include <sstream>

#include "dialects/st/firmware.h"
#include "dialects/st/names.h"

namespace uprog::st {
namespace {

constexpr std::string_view kSettingsRecord = "st_parameters.txt";

}  // namespace

void Firmware::defaults() {
  values_.clear();
  for (const AsciiEntry& e : ascii_table()) {
    if (e.kind == AsciiKind::Int && e.access == AsciiAccess::ReadWrite && e.saved)
      values_[std::string(e.name)] = e.default_value;
  }
  user_vars_.fill(0);
  msg_ = 0;
  prompt_ = 1;  // the reference's default: echo and `-->` (docs/dialects/st.md, "Echo")
  opmode_ = 8;
}

std::string Firmware::saved_text() const {
  std::ostringstream out;
  for (const auto& [name, value] : values_) {
    if (name == "MSG")
      out << name << ' ' << msg_ << '\n';
    else if (name == "PROMPT")
      out << name << ' ' << prompt_ << '\n';
    else if (name == "OPMODE")
      out << name << ' ' << opmode_ << '\n';
    else
      out << name << ' ' << value << '\n';
  }
  for (int n = 1; n <= kUserVariables; ++n)
    out << user_variable_name(n) << ' ' << user_vars_[static_cast<size_t>(n - 1)] << '\n';
  for (const auto& [nr, t] : tasks_) {
    if (nr >= 1 && nr <= 180)
      out << "ORDER " << nr << ' ' << t.p << ' ' << t.v << ' ' << t.c << ' ' << t.acc << ' '
          << t.dec << ' ' << t.a2 << ' ' << t.d2 << ' ' << t.fn << ' ' << t.ft << '\n';
  }
  return out.str();
}

void Firmware::apply_saved(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    if (name == "ORDER") {
      int32_t nr = 0;
      MotionTask t;
      if (words >> nr >> t.p >> t.v >> t.c >> t.acc >> t.dec >> t.a2 >> t.d2 >> t.fn >> t.ft &&
          nr >= 1 && nr <= 180) {
        t.defined = true;
        tasks_[nr] = t;
      }
      continue;
    }
    int32_t value = 0;
    if (!(words >> value)) continue;
    if (name == "MSG")
      msg_ = value >= 0 && value <= 2 ? value : 0;
    else if (name == "PROMPT")
      prompt_ = value != 0 ? 1 : 0;
    else if (name == "OPMODE")
      opmode_ = value;
    else if (auto n = user_variable_number(name))
      user_vars_[static_cast<size_t>(*n - 1)] = value;
    else if (values_.count(name) != 0)
      values_[name] = value;
  }
}

int32_t Firmware::save() {
  sync_user_variables_out();
  const std::string text = saved_text();
  std::string error;
  if (!runtime_.flash().write(kSettingsRecord,
                              std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()),
                              &error)) {
    return kErrStorage;
  }
  return 0;
}

int32_t Firmware::load() {
  std::string error;
  auto bytes = runtime_.flash().read(kSettingsRecord, &error);
  if (!bytes) return error.empty() ? 0 : kErrStorage;
  apply_saved(std::string(bytes->begin(), bytes->end()));
  if (program_) {
    for (size_t i = 0; i < kUserVariables; ++i)
      program_->machine().write_global(static_cast<uint32_t>(i), 0, Value::of_int(user_vars_[i]));
  }
  return 0;
}

}  // namespace uprog::st
