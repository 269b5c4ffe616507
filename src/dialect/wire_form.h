// How a dialect's drive talks on the wire: how the bytes a host sends are cut into lines, and how
// answers, the end of a typed line and unsolicited output are written back. The transports ask
// the controller's firmware for its WireForm and know no dialect's syntax.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "dialect/answer.h"
#include "dialect/line_framer.h"

namespace uprog::dialect {

class WireForm {
 public:
  virtual ~WireForm() = default;
  virtual FramerOptions framing() const = 0;
  // Appends one answer to a line.
  virtual void write_answer(const Answer& answer, std::string& out) const = 0;
  // Appends what a line that gave no answer gets, so a host still sees the line was taken.
  virtual void write_silent_line(std::string& out) const = 0;
  // Appends what follows the answers to one physical line (CR LF, a prompt).
  virtual void write_line_end(std::string& out) const = 0;
  // Appends text the drive sends on its own (a program's message); it starts and ends a line.
  virtual void write_output(std::string_view text, std::string& out) const = 0;
  // Appends what tells a host that `count` of the drive's own texts were dropped because it read
  // none of them while they piled up (PDL's `%L n`); nothing by default.
  virtual void write_lost_output(uint64_t count, std::string& out) const {
    (void)count;
    (void)out;
  }
  // Appends what the drive sends back the moment it receives `bytes` (a real Elmo drive echoes
  // every character while EO=1); nothing by default.
  virtual void write_echo(std::string_view bytes, std::string& out) const {
    (void)bytes;
    (void)out;
  }
  // True while write_echo() may append something, so the transport hands it bytes one by one.
  virtual bool echoes() const { return false; }
  // The answer to a line the framer refused before any command line saw it (too long, a bad
  // byte); `standard` is the transport's own (docs/protocol.md: 900, 901).
  virtual Answer framing_error(const Answer& standard) const { return standard; }
};

// How a host reads a drive that ends the answers to each line with a prompt and sends an error
// as a prefix, a code and a text (the S300's `-->` and BEL `ERR n text`, each answer a line of
// its own, the host's line echoed first). `start_line` is sent once on connecting so that the
// drive prompts (the S300's `PROMPT 1`).
struct PromptWire {
  std::string prompt;
  std::string error_prefix;
  std::string start_line;
};

// Which of a drive's wire forms a firmware speaks, where its dialect has two: the bytes the
// vendor's drive sends (the default: host software written for the real drive runs unchanged),
// or uprog's readable form (error texts, a line end after each typed line) for people and tests.
enum class WireStyle : std::uint8_t { kDrive, kReadable };

}  // namespace uprog::dialect
