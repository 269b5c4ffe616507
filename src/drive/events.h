// Drive-side events, reported as a bitmask by each servo step. The controller turns them into
// auto-routines (AUTO_RLS, AUTO_FLS, AUTO_STOP, AUTO_ENA, AUTO_BG, AUTO_HM, AUTO_I1..6, AUTO_ER).
#pragma once
#include <cstdint>

namespace uprog::drive {

enum Event : uint32_t {
  kEventReverseLimit = 1u << 0,     // an RLS input became active
  kEventForwardLimit = 1u << 1,     // an FLS input became active
  kEventHardStop = 1u << 2,         // a hard-stop input became active
  kEventInhibitReleased = 1u << 3,  // an inhibit input went from active to inactive
  kEventBegin = 1u << 4,            // a begin input became active (the BG was performed)
  kEventHome = 1u << 5,             // a home input became active
  kEventFault = 1u << 6,            // a fault was latched (MF went from 0 to non-zero)
  kEventGeneralInput1 = 1u << 8,    // general-purpose input n became active: bit 8 + n - 1
};

constexpr uint32_t general_input_event(int n) { return kEventGeneralInput1 << (n - 1); }

}  // namespace uprog::drive
