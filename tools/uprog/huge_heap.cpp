// See huge_heap.h. Linux and glibc: mallopt keeps the block on the heap and the heap after
// free; madvise(MADV_HUGEPAGE) is honoured when transparent huge pages are in "madvise" or
// "always" mode. Elsewhere the calls are skipped or have no effect.
#include "huge_heap.h"

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#endif

namespace uprog::cli {

namespace {

constexpr size_t kHugePage = size_t{2} << 20;
constexpr size_t kWorthIt = size_t{8} << 20;  // below this the 4 KiB faults cost little
constexpr size_t kHeapPerSourceByte = 6;      // measured on bench/peers/gen_large.py's program

// Grows the heap by `bytes` (from the heap, not a separate mapping), advises it for huge pages,
// and hands it back to malloc for the allocations that follow.
void grow_heap_on_huge_pages(size_t bytes) {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  const int limit = bytes * 2 > INT32_MAX ? INT32_MAX : static_cast<int>(bytes * 2);
  mallopt(M_MMAP_THRESHOLD, limit);
  mallopt(M_TRIM_THRESHOLD, limit);
  void* block = std::malloc(bytes + kHugePage);
  if (block == nullptr) return;
  const uintptr_t start = reinterpret_cast<uintptr_t>(block);
  const uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1);
  const uintptr_t end = (start + bytes + kHugePage) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  std::free(block);
#else
  (void)bytes;
#endif
}

}  // namespace

void prepare_heap_for_compiling(const std::vector<std::string>& sources) {
  size_t total = 0;
  for (const std::string& path : sources) {
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (!error) total += static_cast<size_t>(size);
  }
  if (total * kHeapPerSourceByte >= kWorthIt) grow_heap_on_huge_pages(total * kHeapPerSourceByte);
}

}  // namespace uprog::cli
