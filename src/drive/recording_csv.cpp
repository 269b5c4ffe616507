// The recording's CSV form (recording_csv.h): `# key: value` header lines in a fixed order, the
// column names, then one row per sample, time in microseconds from the trigger sample. Values
// are written in their shortest exact form (int32, or float32), so reading gives them back.
#include "drive/recording_csv.h"

#include <charconv>
#include <cstdint>
#include <vector>

namespace uprog::drive {
namespace {

constexpr std::string_view kMagic = "# uprog recording 1";

std::string number(double v, bool is_float) {
  char buf[48];
  const auto r = is_float ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(v))
                          : std::to_chars(buf, buf + sizeof buf, static_cast<int64_t>(v));
  return std::string(buf, r.ptr);
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  for (;;) {
    const size_t p = s.find(sep);
    out.push_back(s.substr(0, p));
    if (p == std::string_view::npos) return out;
    s.remove_prefix(p + 1);
  }
}

template <typename T>
bool parse_whole(std::string_view s, T& out) {
  const auto [p, e] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && e == std::errc() && p == s.data() + s.size();
}

bool parse_value(std::string_view s, bool is_float, double& out) {
  if (is_float) {
    float f = 0;
    if (!parse_whole(s, f)) return false;
    out = f;
    return true;
  }
  int64_t i = 0;
  if (!parse_whole(s, i) || i < INT32_MIN || i > INT32_MAX) return false;
  out = static_cast<double>(i);
  return true;
}

// The reader: lines one by one, each error naming its line.
class Reader {
 public:
  explicit Reader(std::string_view text) : lines_(split(text, '\n')) {
    if (!lines_.empty() && lines_.back().empty()) lines_.pop_back();  // the last line's end
  }
  std::optional<Recording> read(std::string* error);

 private:
  bool fail(const std::string& what) {
    error_ = "line " + std::to_string(line_ + 1) + ": " + what;
    return false;
  }
  bool next(std::string_view& line) {
    if (line_ + 1 >= lines_.size() && started_) {
      line_ = lines_.size();
      return fail("the file ends early");
    }
    line_ = started_ ? line_ + 1 : 0;
    started_ = true;
    line = lines_[line_];
    return true;
  }
  bool header(std::string_view key, std::string_view& value);
  template <typename T>
  bool header_number(std::string_view key, T& out) {
    std::string_view v;
    if (!header(key, v)) return false;
    return parse_whole(v, out) ||
           fail("'" + std::string(key) + "' needs a whole number, not '" + std::string(v) + "'");
  }
  bool rows(Recording& r);

  std::vector<std::string_view> lines_;
  size_t line_ = 0;
  bool started_ = false;
  std::string error_;
};

bool Reader::header(std::string_view key, std::string_view& value) {
  std::string_view line;
  if (!next(line)) return false;
  const std::string prefix = "# " + std::string(key) + ": ";
  if (line.substr(0, prefix.size()) != prefix && line != "# " + std::string(key) + ":")
    return fail("expected '" + prefix + "…'");
  value = line.size() > prefix.size() ? line.substr(prefix.size()) : std::string_view{};
  return true;
}

bool Reader::rows(Recording& r) {
  for (RecordedChannel& c : r.channels) c.values.clear();
  for (size_t i = 0; line_ + 1 < lines_.size(); ++i) {
    std::string_view line;
    next(line);
    const std::vector<std::string_view> cells = split(line, ',');
    if (cells.size() != r.channels.size() + 1)
      return fail("expected " + std::to_string(r.channels.size() + 1) + " cells, found " +
                  std::to_string(cells.size()));
    int64_t t = 0;
    if (!parse_whole(cells[0], t) || t != r.time_us(i))
      return fail("time '" + std::string(cells[0]) + "', expected " + std::to_string(r.time_us(i)) +
                  " (sample " + std::to_string(i) + ")");
    for (size_t c = 0; c < r.channels.size(); ++c) {
      double v = 0;
      if (!parse_value(cells[c + 1], r.channels[c].is_float, v))
        return fail("'" + std::string(cells[c + 1]) + "' is no " +
                    (r.channels[c].is_float ? "float" : "int32") + " (channel " +
                    r.channels[c].name + ")");
      r.channels[c].values.push_back(v);
    }
  }
  if (r.trigger_index > r.samples()) return fail("trigger_index lies past the last sample");
  return true;
}

std::optional<Recording> Reader::read(std::string* error) {
  Recording r;
  std::string_view line, trigger, units, types, columns;
  const bool ok = [&] {
    if (lines_.empty()) return fail("the file is empty");
    if (!next(line)) return false;
    if (line != kMagic) return fail("expected '" + std::string(kMagic) + "'");
    if (!header_number("sample_period_us", r.sample_period_us) || !header("trigger", trigger) ||
        !header_number("pretrigger_percent", r.pretrigger_percent) ||
        !header_number("trigger_index", r.trigger_index) ||
        !header_number("trigger_time_us", r.trigger_time_us) || !header("units", units) ||
        !header("types", types) || !next(columns))
      return false;
    r.trigger = std::string(trigger);
    const std::vector<std::string_view> names = split(columns, ',');
    if (names.size() < 2 || names[0] != "time_us")
      return fail("expected 'time_us,' and the channels' names");
    const std::vector<std::string_view> u = split(units, ','), ty = split(types, ',');
    if (u.size() != names.size() - 1 || ty.size() != names.size() - 1) {
      line_ -= 1;
      return fail("units and types need one entry per channel");
    }
    for (size_t c = 0; c + 1 < names.size(); ++c) {
      if (ty[c] != "int" && ty[c] != "float")
        return --line_, fail("type '" + std::string(ty[c]) + "' is neither int nor float");
      if (names[c + 1].empty()) return fail("channel " + std::to_string(c + 1) + " has no name");
      r.channels.push_back({std::string(names[c + 1]), std::string(u[c]), ty[c] == "float", {}});
    }
    return rows(r);
  }();
  if (!ok) {
    if (error) *error = error_;
    return std::nullopt;
  }
  return r;
}

}  // namespace

std::string write_recording_csv(const Recording& r) {
  std::string out(kMagic);
  out += "\n# sample_period_us: " + std::to_string(r.sample_period_us);
  out += "\n# trigger: " + r.trigger;
  out += "\n# pretrigger_percent: " + std::to_string(r.pretrigger_percent);
  out += "\n# trigger_index: " + std::to_string(r.trigger_index);
  out += "\n# trigger_time_us: " + std::to_string(r.trigger_time_us);
  std::string units, types, names = "time_us";
  for (size_t c = 0; c < r.channels.size(); ++c) {
    const char* sep = c == 0 ? "" : ",";
    units += sep + r.channels[c].unit;
    types += std::string(sep) + (r.channels[c].is_float ? "float" : "int");
    names += "," + r.channels[c].name;
  }
  out += "\n# units: " + units + "\n# types: " + types + "\n" + names + "\n";
  for (size_t i = 0; i < r.samples(); ++i) {
    out += std::to_string(r.time_us(i));
    for (const RecordedChannel& c : r.channels) out += "," + number(c.values[i], c.is_float);
    out += "\n";
  }
  return out;
}

std::optional<Recording> read_recording_csv(std::string_view text, std::string* error) {
  return Reader(text).read(error);
}

}  // namespace uprog::drive
