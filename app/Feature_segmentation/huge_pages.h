// SPDX-License-Identifier: GPL-3.0-or-later
// The programs' heap: glibc's tunables, which are read only at start-up, so the program
// starts itself again once with them set (same arguments, same standard streams, same
// process id: exec).
// - Transparent huge pages. On a machine whose kernel gives huge pages only to memory
//   that asks for them (/sys/kernel/mm/transparent_hugepage/enabled is "madvise",
//   Debian's default), every 4 KiB page of a freshly allocated array costs a page fault,
//   and on virtual machines a page fault is expensive: reading a 200k-face mesh spent
//   more time in page faults than in parsing. glibc asks for huge pages for its heap
//   with glibc.malloc.hugetlb=1.
// - For the one-shot commands (not `edit`, which serves the editor for as long as it
//   runs), the heap keeps what is freed for the next stage instead of returning it to
//   the system: no mmap for large blocks (glibc.malloc.mmap_max=0; blocks over 32 MiB
//   were always mapped afresh), no trimming, one arena (so that the main thread reuses
//   what TBB's threads freed). A stage's arrays then reuse the previous stage's memory
//   instead of being faulted in and zeroed again: fandisk at 3.3M faces on 2 threads,
//   boundaries 0.7-0.8 s -> 0.44 s, the whole run 14.4-15.8 s -> 13.7 s, peak 2.15 ->
//   2.18 GB (AMD EPYC, 2 cores).
// Set FEATURE_SEGMENTATION_NO_HUGE_PAGES=1 to keep glibc's default heap.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_HUGE_PAGES_H
#define CGAL_FEATURE_SEGMENTATION_APP_HUGE_PAGES_H

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace fs_app {

/// Restarts the program with the heap's tunables if they help and are not set yet;
/// returns (doing nothing) otherwise, or if the restart fails.
inline void use_huge_page_heap(int argc, char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("FEATURE_SEGMENTATION_NO_HUGE_PAGES") != nullptr)
    return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if(tunables != nullptr && (std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr ||
                             std::strstr(tunables, "glibc.malloc.mmap_max") != nullptr))
    return; // already set, by us or by the user
  std::string value;
  std::ifstream mode_file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(mode_file, mode);
  // "always": nothing to ask; "never" or unknown: nothing to gain
  if(mode.find("[madvise]") != std::string::npos)
    value = "glibc.malloc.hugetlb=1";
  const bool serves = argc > 1 && std::strcmp(argv[1], "edit") == 0;
  if(!serves)
    value += std::string(value.empty() ? "" : ":") +
             "glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=4294967295:glibc.malloc.arena_max=1";
  if(value.empty())
    return;
  if(tunables != nullptr && *tunables != '\0')
    value = std::string(tunables) + ":" + value;
  if(setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0)
    return;
  execv("/proc/self/exe", argv);
  // exec failed (no /proc, say): go on with the default heap
  if(tunables != nullptr)
    setenv("GLIBC_TUNABLES", tunables, 1);
  else
    unsetenv("GLIBC_TUNABLES");
#else
  (void)argc;
  (void)argv;
#endif
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_HUGE_PAGES_H
