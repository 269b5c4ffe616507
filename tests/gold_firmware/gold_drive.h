// Test support: a simulated drive running Gold's firmware, and the command-line actions the
// tests take on it (CC, XQ##, PS).
#pragma once
#include <string>

#include "controller/controller.h"
#include "dialects/gold/dialect.h"

namespace uprog::controller {

inline ControllerOptions gold_options() {
  ControllerOptions o;
  o.dialect = &gold::dialect();
  return o;
}

// CC, taking no time: true when the stored program is now in RAM.
inline bool load(Controller& c) {
  const auto answers = c.query("CC");
  return answers.empty();
}

// XQ##name, taking no time: 0, or the EC code of the refusal.
inline int32_t xq(Controller& c, const std::string& name) {
  const auto answers = c.query("XQ##" + name);
  return answers.empty() ? 0 : answers.front().error;
}

// PS: -2 no program, -1 loaded and never run, 0 stopped, 1 running.
inline int32_t ps(Controller& c) { return std::stoi(c.query("PS").front().text); }

}  // namespace uprog::controller
