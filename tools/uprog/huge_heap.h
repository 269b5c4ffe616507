// Compiling a large program allocates many small nodes; on a virtual machine each first touch
// of a 4 KiB page is an expensive fault. Growing the heap once, advised for transparent huge
// pages, makes those faults one per 2 MiB. A hint only: where it is not available, nothing
// changes.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace uprog::cli {

// Grows the heap by about `bytes` (from the heap, not a separate mapping), advises it for huge
// pages, and hands it back to malloc for the allocations that follow.
void grow_heap_on_huge_pages(size_t bytes);

// Before compiling `sources`: grows the heap for them when they are large (about six times
// their size, measured on bench/peers/gen_large.py's program); nothing for small ones.
void prepare_heap_for_compiling(const std::vector<std::string>& sources);

}  // namespace uprog::cli
