// The HM[3] table: one row per homing event number (docs/dialects/gold.md, "Homing").
#include "dialects/gold/homing_events.h"

#include <array>

namespace uprog::gold {
namespace {

using drive::HomeSwitch;
using drive::HomeTrigger;

struct HomeEventRow {
  int32_t code;
  HomeTrigger trigger;
  HomeSwitch home_switch;
  int32_t input;  // kInput's input, else 0
  bool on_release;
};

constexpr HomeTrigger kAtOnce = HomeTrigger::kImmediate, kEdge = HomeTrigger::kHomeInput,
                      kIndex = HomeTrigger::kIndex,
                      kEdgeThenIndex = HomeTrigger::kHomeInputThenIndex;
constexpr HomeSwitch kHome = HomeSwitch::kMainHome, kFls = HomeSwitch::kForwardLimit,
                     kRls = HomeSwitch::kReverseLimit, kIn = HomeSwitch::kInput;
constexpr bool kActive = false, kInactive = true;

// Codes 10..12 are reserved (no event); 13 + n - 1 is digital input n becoming active (MBARI's
// HOMING_EVENT_DIN5 = 17), 19 + n - 1 the same input becoming inactive.
constexpr std::array<HomeEventRow, 22> kHomeEvents{{
    {0, kAtOnce, kHome, 0, kActive}, {1, kEdge, kHome, 0, kActive},
    {2, kIndex, kHome, 0, kActive},  {3, kEdgeThenIndex, kHome, 0, kActive},
    {4, kEdge, kHome, 0, kInactive}, {5, kEdgeThenIndex, kHome, 0, kInactive},
    {6, kEdge, kFls, 0, kActive},    {7, kEdge, kRls, 0, kActive},
    {8, kEdge, kFls, 0, kInactive},  {9, kEdge, kRls, 0, kInactive},
    {13, kEdge, kIn, 1, kActive},    {14, kEdge, kIn, 2, kActive},
    {15, kEdge, kIn, 3, kActive},    {16, kEdge, kIn, 4, kActive},
    {17, kEdge, kIn, 5, kActive},    {18, kEdge, kIn, 6, kActive},
    {19, kEdge, kIn, 1, kInactive},  {20, kEdge, kIn, 2, kInactive},
    {21, kEdge, kIn, 3, kInactive},  {22, kEdge, kIn, 4, kInactive},
    {23, kEdge, kIn, 5, kInactive},  {24, kEdge, kIn, 6, kInactive},
}};

bool same_event(const HomeEventRow& row, const drive::HomingSettings& h) {
  if (row.trigger != h.trigger) return false;
  if (row.trigger == kAtOnce || row.trigger == kIndex) return true;
  if (row.home_switch != h.home_switch || row.on_release != h.on_release) return false;
  return row.home_switch != kIn || row.input == h.input;
}

}  // namespace

bool set_home_event(int32_t code, drive::HomingSettings& h) {
  for (const HomeEventRow& row : kHomeEvents) {
    if (row.code != code) continue;
    h.trigger = row.trigger;
    h.home_switch = row.home_switch;
    h.input = row.input == 0 ? 1 : row.input;
    h.on_release = row.on_release;
    return true;
  }
  return false;
}

int32_t home_event_code(const drive::HomingSettings& h) {
  for (const HomeEventRow& row : kHomeEvents) {
    if (same_event(row, h)) return row.code;
  }
  return 0;  // the drive's settings hold only what set_home_event put there
}

}  // namespace uprog::gold
