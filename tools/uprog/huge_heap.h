// Compiling a large program allocates many small nodes; on a virtual machine each first touch
// of a 4 KiB page is an expensive fault. Growing the heap once, advised for transparent huge
// pages, makes those faults one per 2 MiB. A hint only: where it is not available, nothing
// changes.
#pragma once
#include <string>
#include <vector>

namespace uprog::cli {

// Before compiling `sources`: grows the heap for them when they are large (about six times
// their size, measured on bench/peers/gen_large.py's program); nothing for small ones.
void prepare_heap_for_compiling(const std::vector<std::string>& sources);

}  // namespace uprog::cli
