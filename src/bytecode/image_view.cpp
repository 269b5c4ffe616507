// The container checks of a binary image: header, CRC, section table, record sizes, strings.
#include "bytecode/image_view.h"

#include "support/crc32.h"

namespace uprog::bytecode {
namespace {

uint32_t read_u32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
         (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}
uint16_t read_u16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }

constexpr uint32_t record_size(Section s) {
  switch (s) {
    case Section::Strings:
      return 1;
    case Section::Code:
      return 4;
    case Section::Constants:
      return sizeof(ConstantRecord);
    case Section::Globals:
      return sizeof(GlobalRecord);
    case Section::Routines:
      return sizeof(RoutineRecord);
    case Section::Locals:
      return sizeof(LocalRecord);
    case Section::Events:
      return sizeof(EventRecord);
    case Section::Info:
      return 4;
    case Section::Lines:
      return sizeof(LineRecord);
    case Section::Texts:
      return 4;
    case Section::Tasks:
      return sizeof(TaskRecord);
  }
  return 0;
}

bool host_is_little_endian() {
  const uint32_t probe = 1;
  uint8_t first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

}  // namespace

const char* load_error_text(LoadError e) {
  switch (e) {
    case LoadError::Ok:
      return "ok";
    case LoadError::TooShort:
      return "the image is shorter than its header";
    case LoadError::BadMagic:
      return "not a uprog image (bad magic)";
    case LoadError::BadVersion:
      return "unsupported image format version";
    case LoadError::BadSize:
      return "the image size does not match its header";
    case LoadError::BadCrc:
      return "the image is corrupt (CRC mismatch)";
    case LoadError::BadSectionTable:
      return "bad section table";
    case LoadError::BadSection:
      return "a section lies outside the image or has a bad size";
    case LoadError::BadString:
      return "a string reference is out of range";
    case LoadError::BadRecord:
      return "a record holds a value out of range";
  }
  return "unknown load error";
}

uint16_t image_format_version(const uint8_t* bytes, size_t size) {
  if (bytes == nullptr || size < 6 || std::memcmp(bytes, kMagic, 4) != 0) return 0;
  return read_u16(bytes + 4);
}

LoadError load_image(const uint8_t* bytes, size_t size, ImageView& out) {
  out = ImageView{};
  // Records are read field by field as little-endian words by memcpy; a big-endian host
  // would need a byte swap that no target of ours has asked for yet.
  if (!host_is_little_endian()) return LoadError::BadVersion;
  if (bytes == nullptr || size < kHeaderSize) return LoadError::TooShort;
  if (std::memcmp(bytes, kMagic, 4) != 0) return LoadError::BadMagic;
  const uint16_t version = read_u16(bytes + 4);
  if (version < kMinFormatVersion || version > kMaxFormatVersion ||
      read_u16(bytes + 6) != kHeaderSize)
    return LoadError::BadVersion;
  const uint32_t total = read_u32(bytes + 8);
  if (total != size) return LoadError::BadSize;
  if (read_u32(bytes + 12) != crc32(bytes + kCrcStart, size - kCrcStart)) return LoadError::BadCrc;
  out.created_unix_s = static_cast<uint64_t>(read_u32(bytes + 16)) |
                       (static_cast<uint64_t>(read_u32(bytes + 20)) << 32);
  out.source_name = read_u32(bytes + 24);
  const uint32_t sections = read_u32(bytes + 28);
  out.dialect = read_u32(bytes + 32);
  if (sections > kSectionKinds ||
      kHeaderSize + static_cast<size_t>(sections) * kSectionEntrySize > size)
    return LoadError::BadSectionTable;

  bool seen[kSectionKinds + 1] = {};
  for (uint32_t s = 0; s < sections; ++s) {
    const uint8_t* entry = bytes + kHeaderSize + s * kSectionEntrySize;
    const uint32_t kind = read_u32(entry);
    const uint32_t offset = read_u32(entry + 4);
    const uint32_t length = read_u32(entry + 8);
    const uint32_t count = read_u32(entry + 12);
    if (kind == 0 || kind > kSectionKinds || seen[kind]) return LoadError::BadSectionTable;
    seen[kind] = true;
    const uint32_t rsize = record_size(static_cast<Section>(kind));
    if (offset % 4 != 0 || offset > size || length > size - offset) return LoadError::BadSection;
    if (static_cast<uint64_t>(count) * rsize != length) return LoadError::BadSection;
    const uint8_t* data = bytes + offset;
    switch (static_cast<Section>(kind)) {
      case Section::Strings:
        out.strings = reinterpret_cast<const char*>(data);
        out.strings_size = length;
        break;
      case Section::Code:
        out.code = {data, count};
        break;
      case Section::Constants:
        out.constants = {data, count};
        break;
      case Section::Globals:
        out.globals = {data, count};
        break;
      case Section::Routines:
        out.routines = {data, count};
        break;
      case Section::Locals:
        out.locals = {data, count};
        break;
      case Section::Events:
        out.events = {data, count};
        break;
      case Section::Info:
        out.info = {data, count};
        break;
      case Section::Lines:
        out.lines = {data, count};
        break;
      case Section::Texts:
        out.texts = {data, count};
        break;
      case Section::Tasks:
        out.tasks = {data, count};
        break;
    }
  }
  // Every string must end inside the blob: then any offset below its size is a valid string.
  if (out.strings_size == 0 || out.strings[out.strings_size - 1] != '\0')
    return LoadError::BadString;

  const auto str_ok = [&](uint32_t offset) { return offset < out.strings_size; };
  const auto type_ok = [](uint32_t t) { return t <= 1; };
  if (!str_ok(out.source_name) || !str_ok(out.dialect)) return LoadError::BadString;
  for (uint32_t i = 0; i < out.constants.size(); ++i)
    if (!type_ok(out.constants[i].type)) return LoadError::BadRecord;
  for (uint32_t i = 0; i < out.globals.size(); ++i) {
    const GlobalRecord g = out.globals[i];
    if (!str_ok(g.name)) return LoadError::BadString;
    if (!type_ok(g.type) || g.length == 0) return LoadError::BadRecord;
  }
  for (uint32_t i = 0; i < out.locals.size(); ++i) {
    const LocalRecord l = out.locals[i];
    if (!str_ok(l.name)) return LoadError::BadString;
    if (!type_ok(l.type)) return LoadError::BadRecord;
  }
  for (uint32_t i = 0; i < out.routines.size(); ++i) {
    const RoutineRecord r = out.routines[i];
    if (!str_ok(r.name)) return LoadError::BadString;
    if (r.kind >= kRoutineKinds || r.entry >= out.code.size()) return LoadError::BadRecord;
    if (static_cast<uint64_t>(r.inputs) + r.outputs > r.locals) return LoadError::BadRecord;
    if (static_cast<uint64_t>(r.first_local) + r.locals > out.locals.size())
      return LoadError::BadRecord;
  }
  for (uint32_t i = 0; i < out.events.size(); ++i)
    if (out.events[i].routine >= out.routines.size()) return LoadError::BadRecord;
  for (uint32_t i = 0; i < out.info.size(); ++i)
    if (!str_ok(out.info[i])) return LoadError::BadString;
  for (uint32_t i = 0; i < out.texts.size(); ++i)
    if (!str_ok(out.texts[i])) return LoadError::BadString;
  for (uint32_t i = 0; i < out.tasks.size(); ++i) {
    const TaskRecord t = out.tasks[i];
    if (t.routine >= out.routines.size() || (t.flags & ~kTaskFlags) != 0)
      return LoadError::BadRecord;
  }
  for (uint32_t i = 0; i < out.lines.size(); ++i) {
    const LineRecord l = out.lines[i];
    if (!str_ok(l.file)) return LoadError::BadString;
    if (l.code > out.code.size()) return LoadError::BadRecord;
    if (i > 0 && out.lines[i - 1].code > l.code) return LoadError::BadRecord;
  }
  return LoadError::Ok;
}

}  // namespace uprog::bytecode
