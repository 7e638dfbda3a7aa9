// SPDX-License-Identifier: GPL-3.0-or-later
// OFF reader of the programs (Geomview's format as CGAL reads it): the keyword
// [ST][C][N][4][n]OFF, the counts, one vertex per line (x y z, then normals, colours or
// texture coordinates, which are skipped), one face per line (n i1 ... in, then an
// optional colour), '#' comments anywhere. The counts are checked against the size of
// the file before anything is allocated.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_OFF_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_OFF_H

#include "mesh_soup.h"

#include <string>
#include <string_view>

namespace fs_app {
namespace internal {

inline void read_off(const std::string& path, const File_content& content, Mesh_soup& soup)
{
  soup.format = "off";
  Text_cursor in(path, content.data(), content.data() + content.size(), '#');
  if(!in.skip_empty_lines())
    throw Input_error(path + ": contains no faces (only comments or blank lines)");

  // The keyword: optional prefixes ST (texture), C (colour), N (normal), 4 (homogeneous
  // coordinates), n (dimension given next), in this order.
  const std::string_view keyword = in.word();
  std::string_view k = keyword;
  const auto strip = [&k](std::string_view prefix) {
    if(k.substr(0, prefix.size()) == prefix)
    {
      k.remove_prefix(prefix.size());
      return true;
    }
    return false;
  };
  strip("ST");
  strip("C");
  strip("N");
  const bool homogeneous = strip("4");
  const bool has_dimension = strip("n");
  if(k != "OFF")
    in.fail("not an OFF file: the first word is " + quoted(keyword) +
            " (expected OFF, COFF, NOFF, STOFF, 4OFF or nOFF)");
  if(has_dimension)
  {
    const std::size_t dimension = in.count("the dimension of nOFF", 1000, true);
    if(dimension != 3)
      in.fail("nOFF with dimension " + std::to_string(dimension) +
              ": only 3-dimensional points can be read");
  }
  Text_cursor look_ahead = in;
  if(look_ahead.word() == "BINARY")
    in.fail("binary OFF is not supported (write the file as text OFF, or as binary PLY)");

  // Counts: each vertex takes at least 6 bytes ("0 0 0\n"), each face at least 7
  // ("3 0 1 2", the last one perhaps without its newline); a header asking for more
  // than the file holds is refused at once.
  const std::size_t limit = max_soup_count;
  const std::size_t nv = in.count("the number of vertices", limit, true);
  const std::size_t nf = in.count("the number of faces", limit, true);
  if(!in.at_line_end())
    in.count("the number of edges", limit); // Geomview's edge count: read, not used
  if(!in.at_line_end())
    in.fail("unexpected " + quoted(in.word()) + " after the counts of the header");
  const std::size_t header_line = in.line();
  in.next_line();
  const double needed = 6.0 * double(nv) + 7.0 * double(nf);
  if(needed > double(in.bytes_left()))
    throw Input_error(path + ":" + std::to_string(header_line) + ": the header announces " +
                      std::to_string(nv) + " vertices and " + std::to_string(nf) +
                      " faces, more than the " + std::to_string(in.bytes_left()) +
                      " remaining bytes can hold (truncated file or wrong counts)");

  soup.points.reserve(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(!in.skip_empty_lines())
      in.fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(nv) +
              " vertices announced (truncated file or wrong counts)");
    const double x = in.coordinate("an x coordinate");
    const double y = in.coordinate("a y coordinate");
    const double z = in.coordinate("a z coordinate");
    if(homogeneous)
    {
      const double w = in.coordinate("a w coordinate");
      if(w == 0)
        in.fail("the homogeneous coordinate of vertex " + std::to_string(i) + " is 0");
      add_point(soup, x / w, y / w, z / w);
    }
    else
      add_point(soup, x, y, z);
    in.next_line();
  }

  soup.begin.reserve(nf + 1);
  soup.face_line.reserve(nf);
  soup.indices.reserve(3 * nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!in.skip_empty_lines())
      in.fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(nf) +
              " faces announced (truncated file or wrong counts)");
    // A face of n vertices takes at least 2n bytes.
    const std::size_t n = in.count("the number of vertices of a face", in.bytes_left() / 2 + 3);
    if(n < 3)
      in.fail("face " + std::to_string(f) + " has " + std::to_string(n) +
              " vertices (at least 3 are needed)");
    for(std::size_t j = 0; j < n; ++j)
    {
      const Text_cursor before = in;
      const long long id = in.index();
      if(id < 0 || static_cast<unsigned long long>(id) >= nv)
      {
        Text_cursor again = before;
        const std::string_view w = again.word();
        if(w.empty())
          in.fail("face " + std::to_string(f) + " announces " + std::to_string(n) +
                  " vertices but lists " + std::to_string(j));
        if(id < 0)
          in.fail("face " + std::to_string(f) + ": " + quoted(w) + " is not a vertex index");
        in.fail("face " + std::to_string(f) + " refers to vertex " + std::string(w) +
                " but the file has " + std::to_string(nv) + " vertices");
      }
      soup.indices.push_back(static_cast<std::uint32_t>(id));
    }
    if(soup.indices.size() > max_soup_count)
      in.fail("too many face indices for one mesh");
    end_face(soup, in.line());
    in.next_line(); // an optional colour follows
  }
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_OFF_H
