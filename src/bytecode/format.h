// The binary image layout (little-endian, versioned): a header, a section table, and sections
// of fixed-size records. Every field is a 32-bit word but for the header's creation time.
#pragma once
#include <cstdint>

namespace uprog::bytecode {

constexpr uint8_t kMagic[4] = {'U', 'P', 'R', 'G'};
// The format's history. Images are durable from format 6, the first format of a release: a drive's
// flash keeps an image across firmware updates, so a released version's meaning never changes
// (its opcode numbers, opcodes.def, pinned by tests/bytecode/opcode_numbers_test.cpp; its header
// and its records). Base opcodes are only ever added, at the end of the base set; anything else
// is a new version, added at the end of this list, and the loader reads every version in
// [kMinFormatVersion, kMaxFormatVersion] and refuses the others, naming both (LoadError
// BadVersion, image_format_version()). Versions 1 to 5 were made only by development builds
// (no release was ever made of them) and are not read.
//   1  the header, the sections and the first 90 opcodes
//   2  the dialect's name, texts (MSG) and tasks
//   3  the line-end mark (EOL's place in every line)
//   4  CALLFEOL; JCMPMKEOL and ADDMLK in the numbers of DIVU and REMU; the six JNxxFEOL as
//      JNCMPFEOL (the numbers after it moved: images made before that commit are not format 4)
//   5  INCMLKEOL (252), a frame's word stepped by a constant; format 4 images mean the same
//   6  the base instruction set only (113 opcodes, renumbered): the fused instructions left the
//      stored format for the VM, which forms them when it loads an image (vm/fused.def); one
//      comparison a type with the relation as its operand (CMPI, CMPF, as CMPU and CMPD); INTRIN
//      for rare functions (intrinsics.def: DIVU, REMU, PUP's sqrt, power and fixed-point reals)
constexpr uint16_t kMinFormatVersion = 6;
constexpr uint16_t kMaxFormatVersion = 6;
constexpr uint16_t kFormatVersion = kMaxFormatVersion;  // the version the image writer makes
constexpr uint32_t kHeaderSize = 36;
constexpr uint32_t kCrcStart = 16;  // the CRC covers every byte from here to total_size
constexpr uint32_t kSectionEntrySize = 16;

// Header: magic[4], u16 version, u16 header_size, u32 total_size, u32 crc32,
//         u64 created_unix_s, u32 source_name (string), u32 section_count,
//         u32 dialect (string: the name of the dialect whose compiler made the image).
// Section entry: u32 kind, u32 offset, u32 size (bytes), u32 count (records).
enum class Section : uint32_t {
  Strings = 1,    // NUL-terminated strings; other records refer to them by byte offset
  Code = 2,       // u32 instruction words
  Constants = 3,  // ConstantRecord
  Globals = 4,    // GlobalRecord
  Routines = 5,   // RoutineRecord
  Locals = 6,     // LocalRecord: the names and types of every routine's locals
  Events = 7,     // EventRecord
  Info = 8,       // u32 string offsets: information strings ("key=value")
  Lines = 9,      // LineRecord, sorted by code offset
  Texts = 10,     // u32 string offsets: the texts MSG sends (formats) and commands may name
  Tasks = 11,     // TaskRecord: how a dialect's scheduler runs the task routines
};
constexpr uint32_t kSectionKinds = 11;

enum class RoutineKind : uint32_t { Function = 0, Label = 1, AutoRoutine = 2, Task = 3 };
constexpr uint32_t kRoutineKinds = 4;

struct ConstantRecord {
  uint32_t bits;
  uint32_t type;  // ValueType: 0 int, 1 float
};
struct GlobalRecord {
  uint32_t name;
  uint32_t type;
  uint32_t length;  // elements; 1 for a scalar
};
struct RoutineRecord {
  uint32_t name;
  uint32_t kind;
  uint32_t inputs;       // locals [0, inputs) are the inputs
  uint32_t outputs;      // locals [inputs, inputs + outputs) are the outputs
  uint32_t locals;       // all locals, inputs and outputs included
  uint32_t entry;        // code word index
  uint32_t first_local;  // index of its first LocalRecord
};
struct LocalRecord {
  uint32_t name;
  uint32_t type;
};
struct EventRecord {
  uint32_t event;  // a dialect-defined event number (Gold: an auto-routine)
  uint32_t routine;
};
struct LineRecord {
  uint32_t code;  // first code word of the line
  uint32_t file;  // string
  uint32_t line;
};
// A routine that a dialect's scheduler runs as a task. The VM does not read these: it runs
// whatever routine it is told to; the firmware reads them to know what to start when.
struct TaskRecord {
  uint32_t routine;
  uint32_t number;     // the dialect's task number (PDL's #task/n, Akribis' AProgTask[n])
  uint32_t period_ns;  // a cyclic task's period (ST's PLC62: 62 500); 0 when not cyclic
  uint32_t priority;   // the dialect's meaning (a rate, an order); 0 when it has none
  uint32_t flags;      // kTaskStartsAtReset; no other bit is defined
};
constexpr uint32_t kTaskStartsAtReset = 1u;  // started when the drive resets or boots
constexpr uint32_t kTaskFlags = kTaskStartsAtReset;

}  // namespace uprog::bytecode
