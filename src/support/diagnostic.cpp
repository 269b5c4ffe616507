// Printing diagnostics as gcc does and as JSON.
#include "support/diagnostic.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace uprog {
namespace {

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

std::string place(const Location& w) {
  if (w.line <= 0) return w.file;
  if (w.column <= 0) return fmt::format("{}:{}", w.file, w.line);
  return fmt::format("{}:{}:{}", w.file, w.line, w.column);
}

}  // namespace

bool DiagnosticList::add(Diagnostic d) {
  if (full()) return false;
  items_.push_back(std::move(d));
  return true;
}

size_t DiagnosticList::error_count() const {
  size_t n = 0;
  for (const auto& d : items_) n += d.severity == Severity::Error ? 1 : 0;
  return n;
}

std::string format_text(const Diagnostic& d) {
  std::string out = fmt::format("{}: {}: {}", place(d.where), severity_name(d.severity), d.message);
  if (!d.scheme.empty()) out += fmt::format(" [{} {}]", d.scheme, d.code);
  out += '\n';
  for (const auto& n : d.notes) out += fmt::format("{}: note: {}\n", place(n.where), n.message);
  return out;
}

std::string format_text(const std::vector<Diagnostic>& ds) {
  std::string out;
  for (const auto& d : ds) out += format_text(d);
  return out;
}

std::string format_json(const std::vector<Diagnostic>& ds) {
  nlohmann::json array = nlohmann::json::array();
  for (const auto& d : ds) {
    nlohmann::json notes = nlohmann::json::array();
    for (const auto& n : d.notes) {
      notes.push_back({{"file", n.where.file}, {"line", n.where.line}, {"column", n.where.column},
                       {"message", n.message}});
    }
    array.push_back({{"file", d.where.file}, {"line", d.where.line}, {"column", d.where.column},
                     {"severity", severity_name(d.severity)}, {"code", d.code},
                     {"scheme", d.scheme}, {"message", d.message}, {"notes", notes}});
  }
  return array.dump(2) + "\n";
}

}  // namespace uprog
