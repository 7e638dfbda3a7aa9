// SPDX-License-Identifier: GPL-3.0-or-later
// The peak resident memory of the program (Linux: VmHWM of /proc/self/status) and its
// reset (writing 5 to /proc/self/clear_refs), so that each stage reports its own peak.
// Elsewhere, or where /proc refuses, the peak is unknown (-1) and nothing is reset.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_PEAK_MEMORY_H
#define CGAL_FEATURE_SEGMENTATION_APP_PEAK_MEMORY_H

#include <fstream>
#include <sstream>
#include <string>

namespace fs_app {

// The peak resident memory since the start or the last reset, in MiB; -1 if unknown.
inline double peak_resident_mib()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, 6, "VmHWM:") == 0)
    {
      std::istringstream in(line.substr(6));
      double kib = -1;
      in >> kib;
      return kib >= 0 ? kib / 1024 : -1;
    }
  return -1;
}

// Starts a new peak at the current resident memory (no effect where unsupported).
inline void reset_peak_resident()
{
  std::ofstream clear("/proc/self/clear_refs");
  if(clear) clear << "5";
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_PEAK_MEMORY_H
