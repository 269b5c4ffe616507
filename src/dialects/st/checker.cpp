// Whole-file checks (checker.h).
#include "dialects/st/checker.h"

#include <algorithm>
#include <map>
#include <set>

#include "dialects/st/ascii_table.h"
#include "dialects/st/names.h"

namespace uprog::st {
namespace {

constexpr ProgramKind kReportOrder[] = {ProgramKind::Init, ProgramKind::Plc62, ProgramKind::Plc250,
                                        ProgramKind::Plc1, ProgramKind::Plc4,  ProgramKind::Plc16,
                                        ProgramKind::Main};

class Checker {
 public:
  Checker(const Program& p, Reporter& r) : p_(p), r_(r) {
    for (size_t i = 0; i < p.routines.size(); ++i)
      if (p.routines[i].kind == ProgramKind::Function) functions_[p.routines[i].name] = i;
  }

  CheckResult run() {
    for (const Stmt& s : p_.stmts)
      if (s.kind == Stmt::Kind::Builtin) builtin(s);
    resolve_calls();
    CheckResult out;
    for (ProgramKind kind : kReportOrder) {
      for (size_t i = 0; i < p_.routines.size(); ++i) {
        if (p_.routines[i].kind != kind) continue;
        const std::vector<size_t> reach = reachable(i);
        placement(p_.routines[i], reach);
        std::set<int> lines;
        for (size_t k : reach) {
          // Lines are told apart by routine: a function's lines count once per program.
          for (int l : p_.routines[k].code_lines) lines.insert(l);
        }
        out.sizes.push_back({kind, p_.routines[i].name, static_cast<uint32_t>(lines.size())});
        out.load += uint64_t{lines.size()} * load_factor(kind);
      }
    }
    if (out.load > kMaxLoad) {
      size_t at = 0;
      for (const Routine& r : p_.routines)
        if (load_factor(r.kind) != 0) {
          at = r.offset;
          break;
        }
      r_.error(Error::LoadTooHigh, at,
               "load factor " + std::to_string(out.load) + " > " + std::to_string(kMaxLoad));
    }
    return out;
  }

 private:
  void resolve_calls() {
    for (const Routine& r : p_.routines)
      for (const auto& [name, at] : r.calls)
        if (functions_.count(name) == 0)
          r_.error(Error::FunctionUnknown, at, "no function '" + name + "'");
    // Recursion: a call that closes a cycle.
    std::vector<int> state(p_.routines.size(), 0);
    for (size_t i = 0; i < p_.routines.size(); ++i) visit(i, state);
  }

  void visit(size_t i, std::vector<int>& state) {
    state[i] = 1;
    for (const auto& [name, at] : p_.routines[i].calls) {
      auto it = functions_.find(name);
      if (it == functions_.end()) continue;
      if (state[it->second] == 1)
        r_.error(Error::Recursion, at, "'" + name + "' calls itself");
      else if (state[it->second] == 0)
        visit(it->second, state);
    }
    state[i] = 2;
  }

  // The routine and every function it calls, directly or not; each once.
  std::vector<size_t> reachable(size_t start) const {
    std::vector<size_t> out{start};
    std::set<size_t> seen{start};
    for (size_t k = 0; k < out.size(); ++k) {
      for (const auto& [name, at] : p_.routines[out[k]].calls) {
        auto it = functions_.find(name);
        if (it != functions_.end() && seen.insert(it->second).second) out.push_back(it->second);
      }
    }
    return out;
  }

  void placement(const Routine& program, const std::vector<size_t>& reach) {
    const bool main = program.kind == ProgramKind::Main;
    const bool init = program.kind == ProgramKind::Init;
    for (size_t k : reach) {
      const Routine& r = p_.routines[k];
      const std::string via =
          &r == &program ? std::string() : " (called from " + program.name + ")";
      if (!main && r.loop_at >= 0)
        once(Error::LoopMisplaced, static_cast<size_t>(r.loop_at), program.name + via);
      if (!main && !init && r.access_at >= 0)
        once(Error::AccessMisplaced, static_cast<size_t>(r.access_at), program.name + via);
      if (!main && r.printf_at >= 0)
        once(Error::PrintfMisplaced, static_cast<size_t>(r.printf_at), program.name + via);
    }
  }

  void once(Error e, size_t at, const std::string& where) {
    if (reported_.insert({static_cast<int>(e), at}).second) r_.error(e, at, "in " + where);
  }

  // --- built-ins ---
  VarType type_of(const Arg& a) const { return p_.globals[a.global].type; }

  // A 32-bit variable (23 for anything else, 22 for a DLONG).
  bool plain_variable(const Arg& a) {
    if (a.kind != Arg::Kind::Var) return r_.error(Error::NotAVariable, a.offset), false;
    if (type_of(a) == VarType::Dlong) return r_.error(Error::DlongMisuse, a.offset), false;
    return true;
  }
  bool dlong_variable(const Arg& a) {
    if (a.kind != Arg::Kind::Var) return r_.error(Error::NotAVariable, a.offset), false;
    if (type_of(a) != VarType::Dlong)
      return r_.error(Error::DlongMisuse, a.offset, "a DLONG is needed here"), false;
    return true;
  }
  bool string_arg(const Arg& a) {
    if (a.kind == Arg::Kind::String) return true;
    r_.error(Error::Syntax, a.offset, "expected a string '…'");
    return false;
  }

  void builtin(const Stmt& s) {
    const std::vector<Arg>& a = s.args;
    const auto count = [&](size_t n) {
      if (a.size() == n) return true;
      r_.error(Error::ArgumentCount, s.offset, "takes " + std::to_string(n));
      return false;
    };
    switch (s.builtin) {
      case Builtin::Clrdlong:
        if (count(1)) dlong_variable(a[0]);
        return;
      case Builtin::Setdlong:
        if (count(2)) dlong_variable(a[0]), dlong_variable(a[1]);
        return;
      case Builtin::Adddlong:
      case Builtin::Subdlong:
        if (count(3)) dlong_variable(a[0]), dlong_variable(a[1]), plain_variable(a[2]);
        return;
      case Builtin::Muldiv:
        if (count(4))
          for (const Arg& x : a) plain_variable(x);
        return;
      case Builtin::Limitw:
        if (count(3))
          for (const Arg& x : a) plain_variable(x);
        return;
      case Builtin::Xread:
      case Builtin::Xwrite:
        if (!count(2) || !string_arg(a[0])) return;
        if (const std::string why = not_a_value(a[0].text, s.builtin == Builtin::Xread);
            !why.empty())
          r_.error(Error::UnknownParameter, a[0].offset, why);
        plain_variable(a[1]);
        return;
      case Builtin::Command:
        if (!count(1) || !string_arg(a[0])) return;
        command(a[0]);
        return;
      case Builtin::Printf:
        printf_args(s);
        return;
    }
  }

  // Why XREAD (or XWRITE) cannot take the parameter NAME, as the note says it; "" when it can.
  static std::string not_a_value(const std::string& name, bool read) {
    const AsciiEntry* e = find_ascii(name);
    const std::string quoted = "'" + name + "'";
    if (e == nullptr) return quoted;
    if (e->kind == AsciiKind::Command) return quoted + " is a command (COMMAND runs it)";
    if (e->kind == AsciiKind::Text) return quoted + " answers text, not a number";
    if (read && !readable(*e)) return quoted + " cannot be read";
    if (!read && !writable(*e)) return quoted + " is read-only";
    return "";
  }

  void command(const Arg& a) {
    const std::string& t = a.text;
    const size_t b = t.find_first_not_of(" \t");
    const size_t e = t.find_first_of(" \t", b);
    const std::string name =
        b == std::string::npos ? std::string() : t.substr(b, e == std::string::npos ? e : e - b);
    if (name.empty() || find_ascii(name) == nullptr)
      r_.error(Error::UnknownParameter, a.offset, "'" + name + "'");
  }

  void printf_args(const Stmt& s) {
    const std::vector<Arg>& a = s.args;
    if (a.empty()) return r_.error(Error::ArgumentCount, s.offset, "PRINTF needs a format");
    if (!string_arg(a[0])) return;
    if (a.size() > 4) return r_.error(Error::PrintfArgument, a[4].offset, "at most three");
    bool ok = true;
    for (size_t i = 1; i < a.size(); ++i) {
      if (a[i].kind != Arg::Kind::Var || type_of(a[i]) != VarType::Long) {
        r_.error(Error::PrintfArgument, a[i].offset, "a LONG variable is needed");
        ok = false;
      }
    }
    const int n = format_conversions(a[0].text);
    if (ok && n != static_cast<int>(a.size()) - 1)
      r_.error(Error::BadFormat, a[0].offset,
               n < 0 ? "only %d %u %x %X %% are known"
                     : "the format has " + std::to_string(n) + " conversions");
  }

  const Program& p_;
  Reporter& r_;
  std::map<std::string, size_t> functions_;
  std::set<std::pair<int, size_t>> reported_;
};

}  // namespace

int format_conversions(const std::string& f) {
  int n = 0;
  for (size_t i = 0; i < f.size(); ++i) {
    if (f[i] != '%') continue;
    ++i;
    if (i < f.size() && f[i] == '%') continue;
    while (i < f.size() && (f[i] == '-' || f[i] == '0')) ++i;
    while (i < f.size() && f[i] >= '0' && f[i] <= '9') ++i;
    if (i >= f.size() || (f[i] != 'd' && f[i] != 'u' && f[i] != 'x' && f[i] != 'X')) return -1;
    ++n;
  }
  return n;
}

CheckResult check(const Program& program, Reporter& reporter) {
  return Checker(program, reporter).run();
}

}  // namespace uprog::st
