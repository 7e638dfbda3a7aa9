// SPDX-License-Identifier: GPL-3.0-or-later
// Transparent huge pages for the programs' heap. On a machine whose kernel gives huge
// pages only to memory that asks for them (/sys/kernel/mm/transparent_hugepage/enabled
// is "madvise", Debian's default), every 4 KiB page of a freshly allocated array costs a
// page fault, and on virtual machines a page fault is expensive: reading a 200k-face
// mesh spent more time in page faults than in parsing. glibc asks for huge pages for its
// heap when started with the tunable glibc.malloc.hugetlb=1, and tunables are read only
// at start-up, so the program starts itself again once with the tunable set. Nothing
// else changes: same arguments, same standard streams, same process id (exec).
// Set FEATURE_SEGMENTATION_NO_HUGE_PAGES=1 to keep the default heap.

#ifndef CGAL_FEATURE_SEGMENTATION_DEMO_HUGE_PAGES_H
#define CGAL_FEATURE_SEGMENTATION_DEMO_HUGE_PAGES_H

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace fs_demo {

/// Restarts the program with glibc's huge-page heap if that helps and is not done yet;
/// returns (doing nothing) otherwise, or if the restart fails.
inline void use_huge_page_heap(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  if(std::getenv("FEATURE_SEGMENTATION_NO_HUGE_PAGES") != nullptr)
    return;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if(tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr)
    return; // already set, by us or by the user
  std::ifstream mode_file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string mode;
  std::getline(mode_file, mode);
  if(mode.find("[madvise]") == std::string::npos)
    return; // "always": nothing to ask; "never" or unknown: nothing to gain
  std::string value = "glibc.malloc.hugetlb=1";
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
  (void)argv;
#endif
}

} // namespace fs_demo

#endif // CGAL_FEATURE_SEGMENTATION_DEMO_HUGE_PAGES_H
