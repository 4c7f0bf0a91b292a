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

// Runs the program again (the same argv, the same process id) with glibc's
// malloc told to advise transparent huge pages for the memory it takes from
// the kernel (GLIBC_TUNABLES=glibc.malloc.hugetlb=1, glibc 2.35 on), when
// the kernel gives them only on advice ("madvise", Debian's and Ubuntu's
// default). Returns when there is nothing to do: another glibc or kernel
// mode, the tunable already set (a user's glibc.malloc.hugetlb=0 opts
// out), or no exec possible. Call it before any thread starts, and only
// where there are images to read: the second start costs about 0.1 s (on
// the 2-core virtual machine: `roofsweep help` 0.12-0.14 s alone,
// `run --help` 0.22-0.24 s restarted), all of a small command's time.
//
// Why: the heap policy above keeps pages once they are in, but the first
// touch of every 4 KB page of an image, a Lab plane or a raster still
// faults. On the 2-core virtual machine the project runs on, faulting was
// a fifth of `match`'s samples (perf). In 2 MB pages, on the bench preset,
// `match` took 3.9-4.2 s instead of 5.0-5.6 s (4 paired runs; reading the
// six images 0.5-0.7 s instead of 1.3-1.5) and `run` 8.5-8.9 s instead of
// 9.3-9.9 s (3 paired runs), with the same output to the byte
// and peak memory within 2 %. The variable can only be set before the
// process starts, hence the exec.
void ReexecWithHugePageHeap(char** argv);

}  // namespace roofsweep
