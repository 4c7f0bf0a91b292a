#include "algorithms/core/heap_policy.h"

#if defined(__GLIBC__)
#include <gnu/libc-version.h>
#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#endif

namespace roofsweep {

void KeepLargeAllocationsOnHeap() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
#endif
}

void ReexecWithHugePageHeap(char** argv) {
#if defined(__GLIBC__) && defined(__linux__)
  const char* set = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = set ? set : "";
  // Already there: put by the exec below, or by the user (=0 opts out).
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
  // The tunable exists from glibc 2.35 on; older ones would ignore it, and
  // the exec would be for nothing.
  int major = 0, minor = 0;
  if (std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor) != 2 ||
      major * 1000 + minor < 2035)
    return;
  // With "always" every region gets huge pages anyway, with "never" none
  // can; only under "madvise" does malloc's advice make the difference.
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  if (!std::getline(mode, line) || line.find("[madvise]") == std::string::npos) return;
  const std::string value =
      (tunables.empty() ? "" : tunables + ":") + std::string("glibc.malloc.hugetlb=1");
  // The link, not "/proc/self/exe" itself: under valgrind only the link
  // names the program (and valgrind runs it on only with
  // --trace-children=yes; GLIBC_TUNABLES=glibc.malloc.hugetlb=0 keeps it).
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) return;
  exe[n] = '\0';
  if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0) return;
  execv(exe, argv);
  // No exec (no /proc, say): the program runs on as it is, and leaves the
  // environment of what it starts as it found it.
  if (set)
    setenv("GLIBC_TUNABLES", set, 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)argv;
#endif
}

}  // namespace roofsweep
