// A loaded image: checked views into the bytes of a binary image, without copying or allocating.
// load_image() proves the container sound (header, CRC, section bounds, strings); verify()
// (verifier.h) then proves the code safe to run.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "bytecode/format.h"

namespace uprog::bytecode {

enum class LoadError : uint8_t {
  Ok = 0,
  TooShort,
  BadMagic,
  BadVersion,
  BadSize,
  BadCrc,
  BadSectionTable,
  BadSection,
  BadString,
  BadRecord,
};
const char* load_error_text(LoadError e);

template <typename Record>
class RecordView {
 public:
  RecordView() = default;
  RecordView(const uint8_t* data, uint32_t count) : data_(data), count_(count) {}
  uint32_t size() const { return count_; }
  // The caller keeps i < size().
  Record operator[](uint32_t i) const {
    Record r;
    std::memcpy(&r, data_ + static_cast<size_t>(i) * sizeof(Record), sizeof(Record));
    return r;
  }

 private:
  const uint8_t* data_ = nullptr;
  uint32_t count_ = 0;
};

struct ImageView {
  uint64_t created_unix_s = 0;
  uint32_t source_name = 0;
  uint32_t dialect = 0;
  const char* strings = nullptr;
  uint32_t strings_size = 0;
  RecordView<uint32_t> code;
  RecordView<ConstantRecord> constants;
  RecordView<GlobalRecord> globals;
  RecordView<RoutineRecord> routines;
  RecordView<LocalRecord> locals;
  RecordView<EventRecord> events;
  RecordView<uint32_t> info;
  RecordView<LineRecord> lines;
  RecordView<uint32_t> texts;
  RecordView<TaskRecord> tasks;

  // A string offset that load_image() has checked; "" for an offset out of range.
  const char* string(uint32_t offset) const {
    return offset < strings_size ? strings + offset : "";
  }
  // The name of the dialect that made the image ("gold", ...); "" for hand-made images.
  const char* dialect_name() const { return string(dialect); }
  // Text `i` (what MSG i sends); "" when there is none.
  const char* text(uint32_t i) const { return i < texts.size() ? string(texts[i]) : ""; }
};

// The format version an image's header names, whether this loader reads it or not (the
// message of a BadVersion refusal names it beside [kMinFormatVersion, kMaxFormatVersion]);
// 0 when the bytes are no uprog image's header.
uint16_t image_format_version(const uint8_t* bytes, size_t size);

// Checks and maps `size` bytes. The bytes must outlive the view.
LoadError load_image(const uint8_t* bytes, size_t size, ImageView& out);

}  // namespace uprog::bytecode
