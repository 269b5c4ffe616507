// The binary codec of the hosted Image, and its lookups.
#include "bytecode/image.h"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "bytecode/image_view.h"
#include "support/crc32.h"

namespace uprog::bytecode {
namespace {

class Writer {
 public:
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<uint8_t>(v >> (8 * i)));
  }
  void u16(uint16_t v) {
    bytes.push_back(static_cast<uint8_t>(v));
    bytes.push_back(static_cast<uint8_t>(v >> 8));
  }
  void put_u32(size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i)
      bytes[at + static_cast<size_t>(i)] = static_cast<uint8_t>(v >> (8 * i));
  }
  std::vector<uint8_t> bytes;
};

class StringTable {
 public:
  StringTable() { intern(""); }
  uint32_t intern(const std::string& s) {
    auto it = offsets_.find(s);
    if (it != offsets_.end()) return it->second;
    const auto offset = static_cast<uint32_t>(blob_.size());
    blob_.insert(blob_.end(), s.begin(), s.end());
    blob_.push_back('\0');
    offsets_.emplace(s, offset);
    return offset;
  }
  const std::vector<char>& blob() const { return blob_; }

 private:
  std::vector<char> blob_;
  std::unordered_map<std::string, uint32_t> offsets_;
};

uint32_t type_word(ValueType t) { return static_cast<uint32_t>(t); }

}  // namespace

int Image::find_routine(const std::string& name) const {
  for (size_t i = 0; i < routines.size(); ++i)
    if (routines[i].name == name) return static_cast<int>(i);
  return -1;
}

uint32_t Image::constant_index(Constant c) {
  for (size_t k = 0; k < constants.size(); ++k)
    if (constants[k] == c) return static_cast<uint32_t>(k);
  constants.push_back(c);
  return static_cast<uint32_t>(constants.size() - 1);
}

int Image::find_global(const std::string& name) const {
  for (size_t i = 0; i < globals.size(); ++i)
    if (globals[i].name == name) return static_cast<int>(i);
  return -1;
}

const LineEntry* Image::line_at(uint32_t pc) const {
  auto it = std::upper_bound(lines.begin(), lines.end(), pc,
                             [](uint32_t p, const LineEntry& e) { return p < e.code; });
  if (it == lines.begin()) return nullptr;
  return &*std::prev(it);
}

std::vector<uint8_t> encode(const Image& image) {
  StringTable strings;
  const uint32_t source_name = strings.intern(image.source_name);
  const uint32_t dialect = strings.intern(image.dialect);

  // Each section's records as words, in Section order.
  std::vector<std::pair<Section, std::vector<uint32_t>>> sections;
  auto add = [&](Section s) -> std::vector<uint32_t>& {
    sections.emplace_back(s, std::vector<uint32_t>{});
    return sections.back().second;
  };
  std::vector<uint32_t> counts;
  add(Section::Code) = image.code;
  counts.push_back(static_cast<uint32_t>(image.code.size()));
  {
    auto& w = add(Section::Constants);
    for (const auto& c : image.constants) {
      w.push_back(c.bits);
      w.push_back(type_word(c.type));
    }
    counts.push_back(static_cast<uint32_t>(image.constants.size()));
  }
  {
    auto& w = add(Section::Globals);
    for (const auto& g : image.globals) {
      w.push_back(strings.intern(g.name));
      w.push_back(type_word(g.type));
      w.push_back(g.length);
    }
    counts.push_back(static_cast<uint32_t>(image.globals.size()));
  }
  std::vector<uint32_t> local_words;
  uint32_t local_count = 0;
  {
    auto& w = add(Section::Routines);
    for (const auto& r : image.routines) {
      w.push_back(strings.intern(r.name));
      w.push_back(static_cast<uint32_t>(r.kind));
      w.push_back(r.inputs);
      w.push_back(r.outputs);
      w.push_back(static_cast<uint32_t>(r.locals.size()));
      w.push_back(r.entry);
      w.push_back(local_count);
      for (const auto& l : r.locals) {
        local_words.push_back(strings.intern(l.name));
        local_words.push_back(type_word(l.type));
        ++local_count;
      }
    }
    counts.push_back(static_cast<uint32_t>(image.routines.size()));
  }
  add(Section::Locals) = local_words;
  counts.push_back(local_count);
  {
    auto& w = add(Section::Events);
    for (const auto& e : image.events) {
      w.push_back(e.event);
      w.push_back(e.routine);
    }
    counts.push_back(static_cast<uint32_t>(image.events.size()));
  }
  {
    auto& w = add(Section::Info);
    for (const auto& s : image.info) w.push_back(strings.intern(s));
    counts.push_back(static_cast<uint32_t>(image.info.size()));
  }
  {
    auto& w = add(Section::Lines);
    for (const auto& l : image.lines) {
      w.push_back(l.code);
      w.push_back(strings.intern(l.file));
      w.push_back(l.line);
    }
    counts.push_back(static_cast<uint32_t>(image.lines.size()));
  }
  {
    auto& w = add(Section::Texts);
    for (const auto& s : image.texts) w.push_back(strings.intern(s));
    counts.push_back(static_cast<uint32_t>(image.texts.size()));
  }
  {
    auto& w = add(Section::Tasks);
    for (const auto& t : image.tasks) {
      w.push_back(t.routine);
      w.push_back(t.number);
      w.push_back(t.period_ns);
      w.push_back(t.priority);
      w.push_back(t.starts_at_reset ? kTaskStartsAtReset : 0u);
    }
    counts.push_back(static_cast<uint32_t>(image.tasks.size()));
  }

  const auto section_count = static_cast<uint32_t>(sections.size() + 1);  // + strings
  Writer out;
  out.bytes.insert(out.bytes.end(), kMagic, kMagic + 4);
  out.u16(kFormatVersion);
  out.u16(static_cast<uint16_t>(kHeaderSize));
  out.u32(0);  // total size, patched below
  out.u32(0);  // crc, patched below
  out.u32(static_cast<uint32_t>(image.created_unix_s));
  out.u32(static_cast<uint32_t>(image.created_unix_s >> 32));
  out.u32(source_name);
  out.u32(section_count);
  out.u32(dialect);

  size_t offset = kHeaderSize + static_cast<size_t>(section_count) * kSectionEntrySize;
  for (size_t i = 0; i < sections.size(); ++i) {
    const auto length = static_cast<uint32_t>(sections[i].second.size() * 4);
    out.u32(static_cast<uint32_t>(sections[i].first));
    out.u32(static_cast<uint32_t>(offset));
    out.u32(length);
    out.u32(counts[i]);
    offset += length;
  }
  const auto strings_size = static_cast<uint32_t>(strings.blob().size());
  out.u32(static_cast<uint32_t>(Section::Strings));
  out.u32(static_cast<uint32_t>(offset));
  out.u32(strings_size);
  out.u32(strings_size);

  for (const auto& s : sections)
    for (uint32_t w : s.second) out.u32(w);
  out.bytes.insert(out.bytes.end(), strings.blob().begin(), strings.blob().end());
  while (out.bytes.size() % 4 != 0) out.bytes.push_back(0);  // keeps images word-sized

  out.put_u32(8, static_cast<uint32_t>(out.bytes.size()));
  out.put_u32(12, crc32(out.bytes.data() + kCrcStart, out.bytes.size() - kCrcStart));
  return out.bytes;
}

bool decode(const uint8_t* bytes, size_t size, Image& out, std::string& error) {
  ImageView view;
  const LoadError e = load_image(bytes, size, view);
  if (e != LoadError::Ok) {
    error = load_error_text(e);
    return false;
  }
  out = Image{};
  out.created_unix_s = view.created_unix_s;
  out.source_name = view.string(view.source_name);
  out.dialect = view.dialect_name();
  out.code.resize(view.code.size());
  for (uint32_t i = 0; i < view.code.size(); ++i) out.code[i] = view.code[i];
  for (uint32_t i = 0; i < view.constants.size(); ++i) {
    const auto c = view.constants[i];
    out.constants.push_back({static_cast<ValueType>(c.type), c.bits});
  }
  for (uint32_t i = 0; i < view.globals.size(); ++i) {
    const auto g = view.globals[i];
    out.globals.push_back({view.string(g.name), static_cast<ValueType>(g.type), g.length});
  }
  for (uint32_t i = 0; i < view.routines.size(); ++i) {
    const auto r = view.routines[i];
    Routine routine{
        view.string(r.name), static_cast<RoutineKind>(r.kind), r.inputs, r.outputs, {}, r.entry};
    for (uint32_t k = 0; k < r.locals; ++k) {
      const auto l = view.locals[r.first_local + k];
      routine.locals.push_back({view.string(l.name), static_cast<ValueType>(l.type)});
    }
    out.routines.push_back(std::move(routine));
  }
  for (uint32_t i = 0; i < view.events.size(); ++i)
    out.events.push_back({view.events[i].event, view.events[i].routine});
  for (uint32_t i = 0; i < view.info.size(); ++i) out.info.emplace_back(view.string(view.info[i]));
  for (uint32_t i = 0; i < view.lines.size(); ++i) {
    const auto l = view.lines[i];
    out.lines.push_back({l.code, view.string(l.file), l.line});
  }
  for (uint32_t i = 0; i < view.texts.size(); ++i) out.texts.emplace_back(view.text(i));
  for (uint32_t i = 0; i < view.tasks.size(); ++i) {
    const auto t = view.tasks[i];
    out.tasks.push_back(
        {t.routine, t.number, t.period_ns, t.priority, (t.flags & kTaskStartsAtReset) != 0});
  }
  return true;
}

}  // namespace uprog::bytecode
