// Gold auto-routine dispatch (manual 2.14): which routine answers which event, the MI mask,
// the precedence order, and which auto-routines are active on the program thread right now.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "bytecode/image_view.h"
#include "vm/machine.h"

namespace uprog::gold {

// Event numbers as the Gold code generator stores them (dialects/gold/keywords.cpp); the MI
// bit of event e is 1 << e.
enum AutoEvent : uint32_t {
  kAutoExec = 0,
  kAutoEr = 1,
  kAutoStop = 2,
  kAutoBg = 3,
  kAutoRls = 4,
  kAutoFls = 5,
  kAutoEna = 6,
  kAutoI1 = 7,
  kAutoHm = 13,
  kAutoHy = 14,
  kAutoPerr = 15,
};
constexpr uint32_t kAutoEventCount = 16;
const char* auto_event_name(uint32_t event);
// The auto-routine events a drive step's event bits (drive/events.h) raise.
uint32_t auto_events_of_drive_events(uint32_t drive_events);

class AutoRoutines {
 public:
  // Reads the image's event table; forgets all state.
  void bind(const bytecode::ImageView& image);
  void clear();  // no program
  std::optional<uint32_t> routine_of(uint32_t event) const;

  uint32_t mask() const { return mask_; }
  // MI assignment; it also lifts the block AUTO_PERR put on the other auto-routines.
  void set_mask(uint32_t mi) {
    mask_ = mi;
    perr_block_ = false;
  }

  // An event happened: remembered when the program has a routine for it and MI allows it.
  void raise(uint32_t event);
  // KL, XQ, RS: nothing pending, nothing active.
  void forget_activity();

  // Drops active auto-routines that have returned (or were abandoned by reset).
  void update_active(const vm::Machine& machine, uint32_t thread);
  // The pending event that may interrupt now (precedence above every active one), if any; it
  // is taken off the pending set.
  std::optional<uint32_t> take_next();
  // The routine for `event` was entered on `thread`.
  void entered(uint32_t event, const vm::Machine& machine, uint32_t thread);
  // AUTO_PERR started afresh on a failed thread: everything else is abandoned and blocked.
  void entered_perr(const vm::Machine& machine, uint32_t thread);
  bool perr_active() const;
  bool perr_block() const { return perr_block_; }
  // No event pending and no auto-routine active: update_active and take_next have nothing to do.
  bool quiet() const { return pending_ == 0 && active_.empty(); }

 private:
  struct Active {
    uint32_t event;
    uint32_t routine;
    uint32_t depth;  // frame count of the thread right after entry
  };
  static int precedence(uint32_t event);  // lower is more urgent

  std::array<int32_t, kAutoEventCount> routine_{};
  uint32_t mask_ = 0;
  uint32_t pending_ = 0;
  bool perr_block_ = false;
  std::vector<Active> active_;
};

}  // namespace uprog::gold
