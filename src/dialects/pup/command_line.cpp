// The AG300 command line: a host line split at `;` into messages, each checked against its
// keyword's attributes (C, U, M), then read, assigned or run; CUP keywords sent over the line
// work on thread 0's own expression stack. One message is served per servo cycle.
#include <fmt/core.h>

#include "dialects/pup/cup_math.h"
#include "dialects/pup/download.h"
#include "dialects/pup/errors.h"
#include "dialects/pup/firmware.h"
#include "drive/axis.h"

namespace uprog::pup {
namespace {

dialect::Answer refusal(int32_t code) {
  for (const dialect::ErrorInfo& e : interpreter_error_table())
    if (e.code == code) return {std::string(e.text), code};
  return {"error", code};
}

std::string trim(std::string_view s) {
  const size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string_view::npos) return "";
  return std::string(s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1));
}

class Session final : public dialect::Session {
 public:
  explicit Session(Firmware& f) : firmware_(f) {}
  std::vector<dialect::Answer> send(std::string_view line) override {
    return firmware_.send(line, true, &download_);
  }

 private:
  Firmware& firmware_;
  DownloadState download_;
};

// "ADownloadUProg[k],arg" (any case, blanks around the tokens) → {k, arg}.
std::optional<std::pair<int32_t, std::optional<std::string>>> parse_download(
    std::string_view text) {
  constexpr std::string_view kKey = "adownloaduprog";
  if (text.size() < kKey.size()) return std::nullopt;
  for (size_t i = 0; i < kKey.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) != kKey[i]) return std::nullopt;
  }
  std::string rest = trim(text.substr(kKey.size()));
  if (rest.size() < 3 || rest[0] != '[' || rest[2] != ']' || rest[1] < '1' || rest[1] > '3')
    return std::nullopt;
  const int32_t step = rest[1] - '0';
  rest = trim(std::string_view(rest).substr(3));
  if (rest.empty() || rest[0] != ',') return std::pair{step, std::optional<std::string>()};
  return std::pair{step, std::optional<std::string>(trim(std::string_view(rest).substr(1)))};
}

// `AProgInfo` alone, which answers several times (info()); with an index or an argument it is
// refused as any keyword is.
bool is_info_request(std::string_view text) {
  const auto m = parse_message(text, nullptr);
  if (!m || m->tail != Message::Tail::None || m->target.has_index) return false;
  const Keyword* k = find_keyword(m->target.key);
  return k != nullptr && k->id == KeywordId::ProgInfo;
}

}  // namespace

std::unique_ptr<dialect::Session> Firmware::open_session() {
  return std::make_unique<Session>(*this);
}

std::vector<dialect::Answer> Firmware::send(std::string_view line, bool takes_time,
                                            DownloadState* download) {
  std::vector<dialect::Answer> answers;
  size_t start = 0;
  while (start <= line.size()) {
    const size_t end = std::min(line.find(';', start), line.size());
    const std::string text = trim(line.substr(start, end - start));
    if (!text.empty()) {
      if (is_info_request(text)) {
        for (dialect::Answer& a : info()) answers.push_back(std::move(a));
      } else {
        answers.push_back(serve_message(text, download));
      }
      // A refused message is the host's error: AErrLog's source 0, line 0.
      if (answers.back().is_error()) log_error(answers.back().error, 0, 0);
      if (takes_time) runtime_.advance_ns(cycle_ns());
    }
    start = end + 1;
  }
  return answers;
}

dialect::Answer Firmware::serve_message(std::string_view text, DownloadState* download) {
  int32_t code = 0;
  // ADownloadUProg[2]'s argument is hex data, no number: read apart from the other messages.
  if (auto dl = parse_download(text)) {
    if (download == nullptr) return refusal(13);
    return download_message(dl->first, dl->second, *download);
  }
  const auto m = parse_message(text, &code);
  if (!m) return refusal(code);
  const Keyword* k = find_keyword(m->target.key);
  if (k == nullptr) return refusal(1);
  if ((k->attrs & kOverLine) == 0) return refusal(13);
  if (k->indexed() != m->target.has_index) return refusal(k->indexed() ? 3 : 5);
  const int32_t index = m->target.index;
  if (k->indexed() && (index < k->index_min || index > k->index_max)) return refusal(4);
  if ((k->attrs & kNeedsProgram) != 0 && !program_) return refusal(15);
  if ((k->attrs & kNotInMotion) != 0 && axis_->profiler_moving() &&
      m->tail == Message::Tail::Assign)
    return refusal(20);
  if (k->kind == KeywordKind::Cup) return line_stack(*m, *k);
  const bool has_arg = m->tail == Message::Tail::Argument;
  if (m->tail == Message::Tail::Assign) {
    if (k->kind != KeywordKind::Param) return refusal(k->kind == KeywordKind::ReadOnly ? 11 : 12);
    code = write_key(k->id, index, m->value);
    return code == 0 ? dialect::Answer{} : refusal(code);
  }
  if (has_arg && m->tail_is_name && k->arg == ArgKind::Number) return refusal(6);  // `,abc`
  if (k->kind == KeywordKind::Command) {
    if ((k->arg != ArgKind::None) != has_arg) return refusal(has_arg ? 8 : 9);
    code = run_key(k->id, index, has_arg, m->value, 0);
    return code == 0 ? dialect::Answer{} : refusal(code);
  }
  if (k->id == KeywordId::UploadUProg) return has_arg ? upload(m->value) : refusal(9);
  if (has_arg) return refusal(8);
  if (k->id == KeywordId::ErrLog) {
    if (static_cast<size_t>(index) > err_log_.size()) return {"0,0,0", 0};
    const auto& e = err_log_[static_cast<size_t>(index - 1)];
    return {fmt::format("{},{},{}", e[0], e[1], e[2]), 0};
  }
  if (k->id == KeywordId::ProgBreaks) return {breaks_list(static_cast<uint32_t>(index)), 0};
  if (k->id == KeywordId::ProgCallStack) return {call_stack(static_cast<uint32_t>(index)), 0};
  if (k->id == KeywordId::ProgExpStack) {
    std::string list;
    code = expression_stack(static_cast<uint32_t>(index), list);
    return code == 0 ? dialect::Answer{list, 0} : refusal(code);
  }
  int32_t v = 0;
  code = read_key(k->id, index, v);
  return code == 0 ? dialect::Answer{std::to_string(v), 0} : refusal(code);
}

// Thread 0: APushConstant, APushParam, APopParam, AMath, ACompare, AGetStatus over the line.
dialect::Answer Firmware::line_stack(const Message& m, const Keyword& k) {
  auto pop = [&](int32_t& v) {
    if (line_stack_.empty()) return false;
    v = line_stack_.back();
    line_stack_.pop_back();
    return true;
  };
  auto push = [&](int32_t v) {
    if (line_stack_.size() >= 50) return refusal(26);
    line_stack_.push_back(v);
    return dialect::Answer{};
  };
  const Keyword* name = m.tail_is_name ? find_keyword(m.name.key) : nullptr;
  if (name != nullptr) {  // the parameter named after `,` has its own index rules
    if (name->indexed() != m.name.has_index) return refusal(name->indexed() ? 3 : 5);
    if (name->indexed() && (m.name.index < name->index_min || m.name.index > name->index_max))
      return refusal(4);
    if (name->kind != KeywordKind::Param && name->kind != KeywordKind::ReadOnly) return refusal(12);
  }
  int32_t a = 0, b = 0, code = 0;
  switch (k.id) {
    case KeywordId::PushConstant:
      if (m.tail != Message::Tail::Argument) return refusal(9);
      if (m.tail_is_name) return refusal(6);
      return push(m.value);
    case KeywordId::PushParam:
      if (name == nullptr) return refusal(m.tail_is_name ? 1 : 9);
      if (line_stack_.size() >= 50) return refusal(26);
      code = read_key(name->id, m.name.index, a);
      return code == 0 ? push(a) : refusal(code);
    case KeywordId::PopParam:
      if (name == nullptr) return refusal(m.tail_is_name ? 1 : 9);
      if (!pop(a)) return refusal(27);
      code = write_key(name->id, m.name.index, a);
      return code == 0 ? dialect::Answer{} : refusal(code);
    case KeywordId::Math: {
      const int arity = math_arity(m.target.index);
      if (arity == 0) return refusal(4);
      if (static_cast<int>(line_stack_.size()) < arity) return refusal(27);
      pop(a);
      if (arity == 2) pop(b);
      const int32_t r = apply_math(m.target.index, b, a, &code);
      return code == 0 ? push(r) : refusal(code);
    }
    case KeywordId::Compare: {
      const int arity = condition_arity(m.target.index);
      if (static_cast<int>(line_stack_.size()) < arity) return refusal(27);
      pop(a);
      if (arity == 2) pop(b);
      return push(condition_holds(m.target.index, b, a) ? 1 : 0);
    }
    case KeywordId::PushParamIdx:
    case KeywordId::PopParamIdx: {
      // Pop i (1..S, else 4) and use AKey[N+i-1]; APopParamIdx then pops the value.
      if (name == nullptr) return refusal(m.tail_is_name ? 1 : 9);
      if (!name->indexed()) return refusal(5);
      if (static_cast<int64_t>(m.name.index) + m.target.index - 1 > name->index_max)
        return refusal(4);  // as the loader
      if (!pop(a)) return refusal(27);
      const int64_t element = static_cast<int64_t>(m.name.index) + a - 1;
      if (a < 1 || a > m.target.index || element > name->index_max) return refusal(4);
      const int32_t at = static_cast<int32_t>(element);
      if (k.id == KeywordId::PushParamIdx) {
        code = read_key(name->id, at, b);
        return code == 0 ? push(b) : refusal(code);
      }
      if (!pop(b)) return refusal(27);
      code = write_key(name->id, at, b);
      return code == 0 ? dialect::Answer{} : refusal(code);
    }
    case KeywordId::GetStatus: {
      if (m.tail != Message::Tail::Argument) return refusal(9);
      if (m.tail_is_name) return refusal(6);
      const int32_t s = status_of(m.target.index, m.value);
      return s < 0 ? refusal(-s) : dialect::Answer{std::to_string(s), 0};
    }
    default:
      return refusal(13);
  }
}

}  // namespace uprog::pup
