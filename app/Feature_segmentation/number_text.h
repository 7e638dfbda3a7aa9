// SPDX-License-Identifier: GPL-3.0-or-later
// The shortest text that reads back as a double (0.85, not 0.84999999999999998): the
// numbers of edit scripts, of the replay options and of the batch table.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_NUMBER_TEXT_H
#define CGAL_FEATURE_SEGMENTATION_APP_NUMBER_TEXT_H

#include <charconv>
#include <string>

namespace fs_app {

inline std::string number_text(double x)
{
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_NUMBER_TEXT_H
