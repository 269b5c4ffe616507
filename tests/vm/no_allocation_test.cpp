// The freestanding rule: once an image is loaded, running it allocates nothing. This test
// replaces the global allocator with a counting one and runs programs of every kind.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>

#include "vm_fixture.h"

namespace {
std::atomic<long> g_allocations{0};
}

// The replacements pair malloc with free themselves; g++ cannot see that through new/delete.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow form too (std::stable_sort's buffer takes it): its memory comes back through the
// delete below, so it must come from malloc as well.
void* operator new(size_t size, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size ? size : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }

namespace uprog::test {
namespace {

TEST(NoAllocation, RunningEveryCaseAllocatesNothing) {
  namespace fs = std::filesystem;
  int programs = 0;
  for (const auto& e : fs::directory_iterator(fs::path(UPROG_SOURCE_DIR) / "tests/vm/cases")) {
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    auto p = std::make_unique<LoadedProgram>();
    ASSERT_TRUE(p->load(text.str())) << e.path();
    const int main_routine = p->image.find_routine("main");
    ASSERT_GE(main_routine, 0);
    const long before = g_allocations.load();
    p->machine.start(0, static_cast<uint32_t>(main_routine));
    p->run_to_end();
    p->machine.set_breakpoint(0);
    p->machine.start(0, static_cast<uint32_t>(main_routine));
    p->machine.run_slice(0, vm::Budget::unlimited());
    p->machine.resume(0);
    p->run_to_end();
    EXPECT_EQ(g_allocations.load(), before) << e.path();
    ++programs;
  }
  EXPECT_GT(programs, 10);
}

}  // namespace
}  // namespace uprog::test
