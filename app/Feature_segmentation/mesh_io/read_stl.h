// SPDX-License-Identifier: GPL-3.0-or-later
// STL reader of the programs, binary and ASCII. STL stores each triangle with its own
// three points; points with exactly the same coordinates are merged, numbered in order
// of first appearance (as CGAL's reader numbers them), so that the soup has shared
// vertices. A file is binary when its size is exactly 84 + 50 n bytes for the n of its
// header (some binary files also start with "solid"), ASCII when it starts with "solid".

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_STL_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_STL_H

#include "mesh_soup.h"

#include <cstring>
#include <string>
#include <string_view>

namespace fs_app {
namespace internal {

// STL stores each triangle's own points: a point equal to an earlier one is merged into
// it as it is read, so that points are numbered in order of first appearance.
class Stl_point_merger
{
public:
  Stl_point_merger(Mesh_soup& soup, std::size_t expected_points)
    : m_soup(&soup), m_table(soup.points, expected_points)
  {}

  std::uint32_t index(double x, double y, double z)
  {
    add_point(*m_soup, x, y, z);
    const std::uint32_t last = static_cast<std::uint32_t>(m_soup->points.size() - 1);
    const std::uint32_t first = m_table.first(last);
    if(first != last)
      m_soup->points.pop_back();
    return first;
  }

private:
  Mesh_soup* m_soup;
  Position_table m_table;
};

inline std::uint32_t little_endian_32(const char* b)
{
  return std::uint32_t(static_cast<unsigned char>(b[0])) |
         std::uint32_t(static_cast<unsigned char>(b[1])) << 8 |
         std::uint32_t(static_cast<unsigned char>(b[2])) << 16 |
         std::uint32_t(static_cast<unsigned char>(b[3])) << 24;
}

inline void read_binary_stl(const std::string& path, const File_content& content, Mesh_soup& soup)
{
  const std::size_t n = little_endian_32(content.data() + 80);
  soup.begin.reserve(n + 1);
  soup.indices.reserve(3 * n);
  soup.points.reserve(n / 2 + 3);
  Stl_point_merger merger(soup, n / 2 + 3);
  const char* record = content.data() + 84;
  for(std::size_t t = 0; t < n; ++t, record += 50)
  {
    for(int k = 0; k < 3; ++k) // after the normal: three points of three floats
    {
      float c[3];
      for(int d = 0; d < 3; ++d)
      {
        const std::uint32_t b = little_endian_32(record + 12 + 12 * k + 4 * d);
        std::memcpy(&c[d], &b, sizeof(float));
        if(!std::isfinite(c[d]))
          throw Input_error(path + ": triangle " + std::to_string(t + 1) +
                            " has a NaN or infinite coordinate");
      }
      soup.indices.push_back(merger.index(c[0], c[1], c[2]));
    }
    end_face(soup, 0);
  }
}

inline void read_ascii_stl(const std::string& path, const File_content& content, Mesh_soup& soup)
{
  Text_cursor in(path, content.data(), content.data() + content.size(), '\0');
  Stl_point_merger merger(soup, content.size() / 200 + 3);
  const auto expect = [&in](std::string_view keyword, const char* context) {
    const std::string_view w = in.word_across_lines();
    if(w != keyword)
      in.fail("expected '" + std::string(keyword) + "' " + context + ", found " +
              (w.empty() ? std::string("the end of the file") : quoted(w)));
  };
  std::size_t solids = 0;
  for(std::string_view w = in.word_across_lines(); !w.empty(); w = in.word_across_lines())
  {
    if(w != "solid")
      in.fail("expected 'solid', found " + quoted(w));
    ++solids;
    in.next_line(); // the solid's name
    for(;;)
    {
      const std::string_view facet = in.word_across_lines();
      if(facet == "endsolid")
      {
        in.next_line();
        break;
      }
      if(facet != "facet")
        in.fail("expected 'facet' or 'endsolid', found " +
                (facet.empty() ? std::string("the end of the file") : quoted(facet)));
      expect("normal", "after 'facet'");
      for(int d = 0; d < 3; ++d)
        in.coordinate("a normal coordinate");
      expect("outer", "before a facet's points");
      expect("loop", "after 'outer'");
      const std::size_t line = in.line();
      std::size_t n = 0;
      for(std::string_view v = in.word_across_lines(); v != "endloop"; v = in.word_across_lines())
      {
        if(v != "vertex")
          in.fail("expected 'vertex' or 'endloop', found " +
                  (v.empty() ? std::string("the end of the file") : quoted(v)));
        const double x = in.coordinate("an x coordinate");
        const double y = in.coordinate("a y coordinate");
        const double z = in.coordinate("a z coordinate");
        soup.indices.push_back(merger.index(x, y, z));
        ++n;
      }
      if(n < 3)
        in.fail("a facet with " + std::to_string(n) + " vertices (at least 3 are needed)");
      if(soup.indices.size() > max_soup_count)
        in.fail("too many facets for one mesh");
      end_face(soup, line);
      expect("endfacet", "after 'endloop'");
    }
  }
  if(solids == 0)
    throw Input_error(path + ": contains no faces (no 'solid' in the file)");
}

inline void read_stl(const std::string& path, const File_content& content, Mesh_soup& soup)
{
  soup.format = "stl";
  if(content.size() >= 84)
  {
    const std::size_t n = little_endian_32(content.data() + 80);
    if(84 + 50 * static_cast<unsigned long long>(n) == content.size())
      return read_binary_stl(path, content, soup);
  }
  std::size_t first = 0;
  while(first < content.size() && (is_blank(content.data()[first]) || content.data()[first] == '\n'))
    ++first;
  if(content.view().substr(first, 5) == "solid")
    return read_ascii_stl(path, content, soup);
  if(content.size() < 84)
    throw Input_error(path + ": not an STL file (" + std::to_string(content.size()) +
                      " bytes: too short for a binary STL header, and no 'solid' keyword)");
  const unsigned long long n = little_endian_32(content.data() + 80);
  throw Input_error(path + ": not a valid binary STL file: its header announces " +
                    std::to_string(n) + " triangles, which take " + std::to_string(84 + 50 * n) +
                    " bytes, but the file has " + std::to_string(content.size()) +
                    " (truncated file or wrong count)");
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_STL_H
