// An answer as the transports carry it (dialect::Answer), and the errors the transport itself
// answers, numbered clear of every dialect's interpreter codes.
#pragma once
#include <cstdint>

#include "dialect/answer.h"

namespace uprog::transport {

using Reply = dialect::Answer;

inline constexpr std::int32_t kErrorLineTooLong = 900;
inline constexpr std::int32_t kErrorBadCharacter = 901;

}  // namespace uprog::transport
