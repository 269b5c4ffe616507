// The dialects this build of uprog knows, in one explicit list (registry.def): the tools choose
// one by name or by a file's extension; the controller and the transports never name one.
#pragma once
#include <span>
#include <string_view>

#include "dialect/dialect.h"

namespace uprog::dialects {

std::span<const dialect::Dialect* const> all();
// nullptr when no dialect has that name.
const dialect::Dialect* find(std::string_view name);
// The dialect whose source extension `path` ends with; nullptr when none does.
const dialect::Dialect* for_file(std::string_view path);
// Gold, the dialect of a file no extension names and of a transcript without `dialect`.
const dialect::Dialect& default_dialect();

}  // namespace uprog::dialects
