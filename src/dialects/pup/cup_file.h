// The CUP file: its header (CRC, date, name, the offsets of the tables and the program), the
// information, task and event tables, and the program lines; written with CR line ends, read back
// strictly (what a download gives the controller) or leniently (a hand-written .cup to rebuild).
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace uprog::pup {

// The flash sector's size: ADownloadUProg[1] takes at most this many characters.
constexpr size_t kMaxProgramBytes = 262144;
// Why a CUP file of `size` characters does not fit the flash sector; "" when it does.
std::string flash_refusal(size_t size);

struct CupTask {
  int32_t task = 0;
  uint32_t line = 0;  // the program line of its marker, from 1
};

struct CupEvent {
  int32_t event = 0;
  int32_t function = 0;
};

struct CupProgram {
  std::string date = "01/01/00";  // DD/MM/YY
  std::string name;
  std::vector<std::string> info;   // the #information strings
  std::vector<CupTask> tasks;      // from the AProgTask markers
  std::vector<CupEvent> events;    // the #event links
  std::vector<std::string> lines;  // the program, line 1 first
};

// "DD/MM/YY" of a Unix time; 0 (a reproducible build) gives 01/01/00.
std::string cup_date(uint64_t unix_s);

// The task table of `lines`: each AProgTask[n] marker and its line.
std::vector<CupTask> task_table(const std::vector<std::string>& lines);

// The file's bytes; the task table is taken from the markers of `program.lines`.
std::string write_cup(const CupProgram& program);

struct CupReadError {
  int32_t code = 0;  // 43 CRC, 44 header
  std::string text;
};

// The CRC a CUP file's first line declares: eight hex digits, checked (CRC-32 of all after the
// first line), or the six digits `000000` of the manual's listing and the vendor's compiler, which
// say "not checked" (value 0). nullopt when line 1 is neither.
struct DeclaredCrc {
  uint32_t value = 0;
  bool checked = false;
  size_t line_size = 0;  // the first line and its CR
};
std::optional<DeclaredCrc> declared_crc(const std::string& bytes);
// What the file's CRC must be: the CRC-32 of all after its first line when checked, else 0; a
// file whose first line is no CRC has CRC 0.
uint32_t expected_crc(const std::string& bytes);

// Strict: CR line ends, the header as write_cup makes it or as the manual's listing and the
// vendor write it (a CRC of six digits; an empty table's offset anywhere before the program), its
// CRC and offsets right (byte offsets: the program's first character, past its last).
std::optional<CupProgram> read_cup(const std::string& bytes, CupReadError* error);
// Lenient: any line ends; a header, where there is one, is read for its name and tables only.
CupProgram read_cup_text(const std::string& text, const std::string& default_name);

}  // namespace uprog::pup
