#pragma once

namespace roofsweep {

// Serves allocations up to 32 MB from the heap and keeps up to 512 MB of
// freed heap memory in the process (glibc's mallopt; does nothing
// elsewhere). Call it once, first thing in main.
//
// Why: image planes and rasters of 2048² pixels are 4-48 MB. Above glibc's
// default threshold each one is a fresh mmap whose pages fault in on first
// touch and go back to the kernel on free; on the virtual machines the
// project runs on, that faulting took about 30 % of the edge extraction's
// time and a tenth of `match`'s. Served from the heap and kept there, the pages are
// reused from one image to the next. Programs and benchmarks alike call it,
// so that the benchmarks measure what the program does.
void KeepLargeAllocationsOnHeap();

}  // namespace roofsweep
