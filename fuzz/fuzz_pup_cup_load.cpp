// libFuzzer target: CUP bytes into the controller's loader, strictly (as a download gives them)
// and leniently (a hand-written .cup); whatever the loader takes must pass the verifier and run:
// the threads of the AG300 firmware are started on it for 20 ms of virtual time, and the image
// runs on a machine of its own in slices of many lines (the fused copies).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "bytecode/image_view.h"
#include "bytecode/verifier.h"
#include "controller/controller.h"
#include "dialects/pup/cup_loader.h"
#include "dialects/pup/dialect.h"
#include "run_image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace uprog;
  if (size > 1 << 16) return 0;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  pup::CupReadError read_error;
  (void)pup::read_cup(bytes, &read_error);
  pup::CupProgram program = pup::read_cup_text(bytes, "fuzz");
  std::string why;
  const auto loaded = pup::load_cup(program, &why);
  if (!loaded) return 0;
  const std::vector<uint8_t> image = bytecode::encode(loaded->image);
  bytecode::ImageView view;
  if (bytecode::load_image(image.data(), image.size(), view) != bytecode::LoadError::Ok) abort();
  std::vector<uint32_t> scratch(bytecode::verify_scratch_size(view) / 4 + 1);
  if (!bytecode::verify(view, bytecode::VerifyLimits{}, scratch.data(), scratch.size() * 4).ok())
    abort();
  // The image alone, in slices of many lines too, which take the loader's fused copies.
  if (!fuzz::load_and_run(image.data(), image.size()).ok()) abort();
  // Run it: stored through the firmware's own download, every task on a thread of its own.
  controller::ControllerOptions options;
  options.dialect = &pup::dialect();
  controller::Controller drive(options);
  const std::string cup = pup::write_cup(program);
  if (!drive.download(std::vector<uint8_t>(cup.begin(), cup.end())).ok) abort();
  uint32_t thread = 1;
  for (int32_t task = 0; task <= 64 && thread <= 8; ++task) {
    if (loaded->task_routine[static_cast<size_t>(task)] >= 0) {
      (void)drive.send("AProgRun[" + std::to_string(thread++) + "]," + std::to_string(task));
    }
  }
  drive.advance(20'000);
  (void)drive.take_log();
  return 0;
}
