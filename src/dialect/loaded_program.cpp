// Loading an image into a machine (loaded_program.h).
#include "dialect/loaded_program.h"

#include "bytecode/image_view.h"

namespace uprog::dialect {
namespace {

// Why the loader refused the bytes; a version outside the range names both (format.h).
std::string load_refusal(const std::vector<uint8_t>& bytes, bytecode::LoadError e) {
  std::string why = std::string("not a valid image: ") + bytecode::load_error_text(e);
  if (e != bytecode::LoadError::BadVersion) return why;
  const uint16_t version = bytecode::image_format_version(bytes.data(), bytes.size());
  if (version >= bytecode::kMinFormatVersion && version <= bytecode::kMaxFormatVersion)
    return why + " " + std::to_string(version) + " (its header has another size)";
  return why + " " + std::to_string(version) + "; this firmware reads versions " +
         std::to_string(bytecode::kMinFormatVersion) + " to " +
         std::to_string(bytecode::kMaxFormatVersion);
}

}  // namespace

std::unique_ptr<LoadedProgram> LoadedProgram::load(std::vector<uint8_t> bytes,
                                                   const vm::MachineConfig& config, vm::Host& host,
                                                   std::string* error, bool decode,
                                                   std::string_view dialect) {
  auto fail = [error](std::string why) {
    if (error) *error = std::move(why);
    return nullptr;
  };
  std::unique_ptr<LoadedProgram> p(new LoadedProgram());
  p->bytes_ = std::move(bytes);
  bytecode::ImageView view;
  if (const auto le = bytecode::load_image(p->bytes_.data(), p->bytes_.size(), view);
      le != bytecode::LoadError::Ok) {
    return fail(load_refusal(p->bytes_, le));
  }
  const std::string_view made_for = view.dialect_name();
  if (!dialect.empty() && !made_for.empty() && made_for != dialect) {
    return fail("the program is for the " + std::string(made_for) + " dialect; this drive runs " +
                std::string(dialect));
  }
  p->memory_.assign((vm::Machine::memory_needed(view, config) + 7) / 8, 0);
  const vm::LoadStatus s = p->machine_.load(p->bytes_.data(), p->bytes_.size(), config,
                                            p->memory_.data(), p->memory_.size() * 8, host);
  if (!s.ok()) {
    if (s.load != bytecode::LoadError::Ok) return fail(load_refusal(p->bytes_, s.load));
    if (s.verify != bytecode::VerifyError::Ok) {
      return fail(std::string("the verifier refused it: ") + bytecode::verify_error_text(s.verify) +
                  " at code word " + std::to_string(s.pc));
    }
    return fail("it needs more memory than the drive has");
  }
  std::string why;
  if (decode && !bytecode::decode(p->bytes_.data(), p->bytes_.size(), p->image_, why)) {
    return fail("not a valid image: " + why);
  }
  return p;
}

std::string LoadedProgram::where(uint32_t pc) const {
  if (const bytecode::LineEntry* line = image_.line_at(pc))
    return line->file + ":" + std::to_string(line->line);
  return "code word " + std::to_string(pc);
}

std::string LoadedProgram::place(uint32_t pc) const {
  std::string at = where(pc);
  if (const size_t slash = at.find_last_of('/'); slash != std::string::npos) at.erase(0, slash + 1);
  return at;
}

}  // namespace uprog::dialect
