// main() of the Google Benchmark programs: the heap policy of the roofsweep
// program first (see heap_policy.h), so that a benchmark measures the
// library as the program runs it.
#include <benchmark/benchmark.h>

#include "algorithms/core/heap_policy.h"

int main(int argc, char** argv) {
  roofsweep::ReexecWithHugePageHeap(argv);
  roofsweep::KeepLargeAllocationsOnHeap();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
