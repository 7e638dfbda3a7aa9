// SPDX-License-Identifier: GPL-3.0-or-later
// Text files of many similar lines (a PLY file's vertices and faces, one patch id per
// line) made by TBB's threads: the lines are formatted in chunks, several chunks at once,
// and written in their order, so that the file is the same byte for byte at any thread
// count. The numbers are made by std::to_chars: integers exactly, doubles as the
// shortest text that reads back as the same double.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_ORDERED_TEXT_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_ORDERED_TEXT_H

#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

inline void append_integer(std::string& out, long long x, char after)
{
  char text[24];
  char* end = std::to_chars(text, text + sizeof(text) - 1, x).ptr;
  *end++ = after;
  out.append(text, std::size_t(end - text));
}

inline void append_double(std::string& out, double x, char after)
{
  char text[40];
  char* end = std::to_chars(text, text + sizeof(text) - 1, x).ptr;
  *end++ = after;
  out.append(text, std::size_t(end - text));
}

// Writes the lines of the items 0 .. n-1 to `os` in this order; format(i, text) appends
// the text of item i to `text`. The items are formatted in chunks of `chunk` items, up
// to `chunks_at_once` chunks at a time by TBB's threads (so that only their text is held
// at once), each chunk's text written as soon as its batch is done; on the calling
// thread alone if not `parallel` (a format that is not safe to call from several
// threads at once).
template <typename Format>
void write_ordered_text(std::ostream& os, std::size_t n, const Format& format, bool parallel = true,
                        std::size_t chunk = 16384, std::size_t chunks_at_once = 32)
{
  chunk = (std::max)(chunk, std::size_t(1));
  const std::size_t number_of_chunks = (n + chunk - 1) / chunk;
  std::vector<std::string> text((std::min)(number_of_chunks, chunks_at_once));
  for(std::size_t first = 0; first < number_of_chunks; first += text.size())
  {
    const std::size_t batch = (std::min)(text.size(), number_of_chunks - first);
    for_each_range(batch, parallel && batch > 1, 1, [&](std::size_t b0, std::size_t b1) {
      for(std::size_t b = b0; b < b1; ++b)
      {
        std::string& t = text[b];
        t.clear();
        const std::size_t begin = (first + b) * chunk, end = (std::min)(n, begin + chunk);
        for(std::size_t i = begin; i < end; ++i) format(i, t);
      }
    });
    for(std::size_t b = 0; b < batch; ++b) os.write(text[b].data(), std::streamsize(text[b].size()));
  }
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_ORDERED_TEXT_H
