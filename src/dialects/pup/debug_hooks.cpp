// What the AG300 firmware offers the debugger (dialect::Firmware's debug hooks): the program in
// RAM with the PUP source's line table from the debug map, a PUP expression evaluated on the
// controller's values now, and the #definevar variables by name (for the recorder too).
#include <fmt/core.h>

#include "dialects/pup/firmware.h"
#include "dialects/pup/pup_lexer.h"

namespace uprog::pup {
namespace {

constexpr size_t kShownElements = 32;  // an array's elements shown in its value, then "..."

}  // namespace

void Firmware::set_debug_map(std::string_view text) {
  debug_map_ = read_debug_map(text);
  if (!debug_map_ || !stored_) {
    if (!debug_map_) runtime_.log("debug map refused: not a PUP debug map");
    debug_map_.reset();
    return;
  }
  debug_map_cup_ = *stored_;
  // Just downloaded, nothing runs yet: loaded again, the image has the PUP places.
  if (const std::string why = install(*stored_, false); !why.empty())
    runtime_.log("debug map not applied: " + why);
}

// One line table entry per PUP line: the first code word of the first CUP line it became (a
// marker's empty line has none of its own).
void Firmware::apply_debug_map(const std::string& cup, bytecode::Image& image) const {
  if (!debug_map_ || cup != debug_map_cup_) return;
  const std::vector<Location>& places = debug_map_->places;
  if (places.size() != image.lines.size()) return;  // a map of another build: CUP lines it is
  std::vector<bytecode::LineEntry> lines;
  for (size_t i = 0; i < image.lines.size(); ++i) {
    const bytecode::LineEntry& e = image.lines[i];
    if (e.line == 0) continue;
    if (i + 1 < image.lines.size() && image.lines[i + 1].code == e.code) continue;
    const Location& at = places[e.line - 1];
    const auto line = static_cast<uint32_t>(at.line);
    if (!lines.empty() && lines.back().file == at.file && lines.back().line == line) continue;
    lines.push_back({e.code, at.file, line});
  }
  image.lines = std::move(lines);
}

dialect::Evaluation Firmware::evaluate(uint32_t, uint32_t, std::string_view expression) {
  dialect::Evaluation out;
  std::vector<Diagnostic> diagnostics;
  const Location at{"expression", 1, 1};
  const auto tokens = tokenize(std::string(expression), at, diagnostics);
  if (!tokens || tokens->empty()) {
    out.error = diagnostics.empty() ? "an empty expression" : diagnostics.front().message;
    return out;
  }
  static const VarTable kNoVariables;
  ExprContext cx{debug_map_ ? debug_map_->vars : kNoVariables, diagnostics};
  TokenCursor cursor(*tokens, at);
  ExprTree tree;
  const int node = parse_expression(cursor, cx, tree);
  if (node < 0 || !diagnostics.empty() || !cursor.at_end()) {
    out.error = !diagnostics.empty()
                    ? diagnostics.front().message
                    : "'" + cursor.peek()->text + "' does not continue the expression";
    return out;
  }
  int32_t error = 0;
  const int32_t value = evaluate_now(
      tree, node,
      [this](const std::string& key, int32_t index, int32_t* code) {
        const Keyword* k = find_keyword(key);
        if (k != nullptr && k->id == KeywordId::GetStatus) {  // AGetStatus[s] as compiled: v = 0
          const int32_t status = status_of(index, 0);
          *code = status < 0 ? -status : 0;
          return status < 0 ? 0 : status;
        }
        int32_t v = 0;
        *code = k == nullptr ? 2 : read_key(k->id, index, v);
        return v;
      },
      &error);
  if (error != 0) {
    out.error = fmt::format("controller error {}", error);
    return out;
  }
  out.ok = true;
  out.value = std::to_string(value);
  out.is_true = value != 0;
  return out;
}

// "AGenData[n]" (n from 1, as the manual counts), a #definevar name, or an element "arr[i]" of
// a #definevar array (i from 1): the word of the controller's general data it names.
std::optional<drive::ProgramWords::Word> Firmware::recorder_word(std::string_view name) const {
  const std::optional<drive::ElementName> element = drive::split_element_name(name);
  if (!element || element->index.value_or(1) > kGenDataSize) return std::nullopt;
  const std::string base(element->name);
  const auto index = static_cast<int32_t>(element->index.value_or(0));  // from 1; 0: none
  int32_t slot = 0;                                                     // AGenData[slot]
  const Keyword* k = find_keyword(base);
  if (k != nullptr && k->id == KeywordId::GenData && index >= 1) {
    slot = index;
  } else if (debug_map_) {
    const auto var = debug_map_->vars.find(base);
    if (var == debug_map_->vars.end()) return std::nullopt;
    const Var& v = var->second;
    if (v.array != (index != 0) || (v.array && index > v.size)) return std::nullopt;
    slot = v.base + (v.array ? index - 1 : 0);
  }
  if (slot < 1 || slot > static_cast<int32_t>(kGenDataSize)) return std::nullopt;
  drive::ProgramWords::Word word;
  word.bound = &gen_data_[static_cast<size_t>(slot - 1)];
  return word;
}

std::vector<dialect::DebugVariable> Firmware::debug_variables() {
  std::vector<dialect::DebugVariable> out;
  if (!debug_map_ || !program_) return out;
  auto element = [this](int32_t index) {
    int32_t v = 0;
    return read_key(KeywordId::GenData, index, v) == 0 ? std::to_string(v) : std::string("?");
  };
  for (const auto& [name, var] : debug_map_->vars) {
    dialect::DebugVariable d{name, {}, fmt::format("AGenData[{}]", var.base)};
    if (!var.array) {
      d.value = element(var.base);
    } else {
      d.type = fmt::format("AGenData[{}..{}]", var.base, var.base + var.size - 1);
      for (int32_t i = 0; i < var.size && static_cast<size_t>(i) < kShownElements; ++i)
        d.value += (i == 0 ? "" : ", ") + element(var.base + i);
      if (static_cast<size_t>(var.size) > kShownElements) d.value += ", ...";
      d.value = "[" + d.value + "]";
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace uprog::pup
