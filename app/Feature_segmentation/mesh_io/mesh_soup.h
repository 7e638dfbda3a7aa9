// SPDX-License-Identifier: GPL-3.0-or-later
// The polygon soup that the programs' file readers produce (Mesh_soup), with the file
// buffer they read from (file_content.h) and the text cursor they share (text_cursor.h),
// both included here. A reader is given the whole file in memory, checks every count of
// a header against the bytes that are really there before it allocates, and stops at the
// first problem with one `Input_error` naming the file and the line
// ("<file>:<line>: <reason>"), so that a malformed file costs bounded time and memory.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_MESH_SOUP_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_MESH_SOUP_H

#include "file_content.h"
#include "text_cursor.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace fs_app {

/// A polygon soup exactly as in the file: points and faces in file order. Face `f` uses
/// the points `indices[begin[f]] ... indices[begin[f + 1] - 1]`. Every index is below
/// `points.size()` and every coordinate is finite (the readers check both).
struct Mesh_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::uint32_t> begin{0};   ///< one more entry than there are faces
  std::vector<std::uint32_t> indices;
  std::vector<std::uint32_t> face_line;  ///< line of each face in a text file, else empty
  std::string format;                    ///< "off", "obj", "ply" or "stl"

  std::size_t number_of_faces() const { return begin.size() - 1; }
  std::size_t face_size(std::size_t f) const { return begin[f + 1] - begin[f]; }
  const std::uint32_t* face(std::size_t f) const { return indices.data() + begin[f]; }
};

namespace internal {

// Element counts are stored in 32 bits: a file with more than 4 billion points or
// indices would need tens of gigabytes, far beyond what the pipeline handles anyway.
constexpr std::size_t max_soup_count = std::numeric_limits<std::uint32_t>::max() - 1;

/// Exact merging of points at the same position, over the points of a soup: an open
/// addressing table of point indices (no allocation per point), keyed by the bits of
/// the coordinates with -0 taken as 0. Coordinates are finite. Used by the STL reader
/// (points merged as they are read) and by the repairs (points of any file).
class Position_table
{
public:
  explicit Position_table(const std::vector<std::array<double, 3> >& points,
                          std::size_t expected = 0)
    : m_points(&points)
  {
    std::size_t size = 16;
    while(size < 2 * expected)
      size *= 2;
    m_slots.assign(size, empty);
  }

  /// The first point, among those given to this function so far, at the position of
  /// point `i`; `i` itself (now recorded) if there is none.
  std::uint32_t first(std::uint32_t i)
  {
    if(2 * (m_used + 1) > m_slots.size())
      grow();
    const std::array<double, 3>& p = (*m_points)[i];
    for(std::size_t slot = hash(p) & (m_slots.size() - 1);; slot = (slot + 1) & (m_slots.size() - 1))
    {
      const std::uint32_t j = m_slots[slot];
      if(j == empty)
      {
        m_slots[slot] = i;
        ++m_used;
        return i;
      }
      const std::array<double, 3>& q = (*m_points)[j];
      if(p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
        return j;
    }
  }

private:
  static constexpr std::uint32_t empty = std::uint32_t(-1);

  static std::uint64_t hash(const std::array<double, 3>& p)
  {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for(double v : p)
    {
      if(v == 0)
        v = 0; // -0 and 0 are one position
      std::uint64_t b;
      std::memcpy(&b, &v, sizeof b);
      h = (h ^ b) * 0xbf58476d1ce4e5b9ull;
      h ^= h >> 29;
    }
    return h;
  }

  void grow()
  {
    std::vector<std::uint32_t> old(2 * m_slots.size(), empty);
    old.swap(m_slots);
    for(const std::uint32_t j : old)
      if(j != empty)
        for(std::size_t slot = hash((*m_points)[j]) & (m_slots.size() - 1);;
            slot = (slot + 1) & (m_slots.size() - 1))
          if(m_slots[slot] == empty)
          {
            m_slots[slot] = j;
            break;
          }
  }

  const std::vector<std::array<double, 3> >* m_points;
  std::vector<std::uint32_t> m_slots;
  std::size_t m_used = 0;
};

/// Appends the point (x, y, z) to `soup`.
inline void add_point(Mesh_soup& soup, double x, double y, double z)
{
  soup.points.push_back({{x, y, z}});
}

/// Closes the face whose indices were appended since the last call.
inline void end_face(Mesh_soup& soup, std::size_t line)
{
  soup.begin.push_back(static_cast<std::uint32_t>(soup.indices.size()));
  if(line != 0)
    soup.face_line.push_back(static_cast<std::uint32_t>(line));
}

/// The name of face `f` in messages: "face 12", with its line in a text file.
inline std::string face_name(const Mesh_soup& soup, std::size_t f)
{
  std::string name = "face " + std::to_string(f);
  if(f < soup.face_line.size())
    name += " (line " + std::to_string(soup.face_line[f]) + ")";
  return name;
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_MESH_SOUP_H
