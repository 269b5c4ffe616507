// A dialect that exists only in the tests, to prove the contract: everything a dialect is lives
// in this file and toy_dialect.cpp, and the controller runs it without knowing its name. Its
// "program" is text: the line `every N` makes the firmware count every N-th cycle. Its command
// line: `count` (the counter), `cycles`, `events` (the axis events it was given), `say TEXT` (sent
// as the drive's own output), `ticks` (the virtual time in ns), `hello` (one answer per session:
// which session), `program TEXT` (a download). tests/dialect registers it as a fifth dialect in
// one line (toy_registry.def) to prove that it then passes the conformance suite and is fuzzed.
#pragma once
#include "dialect/dialect.h"

namespace uprog::toy {

const dialect::Dialect& dialect();

}  // namespace uprog::toy
