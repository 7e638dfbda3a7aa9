// SPDX-License-Identifier: GPL-3.0-or-later
// Wavefront OBJ reader of the programs: `v x y z` (a weight or a colour after the three
// coordinates is skipped), faces `f` whose vertex references are `i`, `i/t`, `i//n` or
// `i/t/n` (1-based, or negative: relative to the last vertex read), polygons of any size.
// Every other statement (`vn`, `vt`, `vp`, `vc`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`,
// `p`, curves, and statements no reader knows) is skipped, as OBJ readers are expected
// to do.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_OBJ_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_OBJ_H

#include "mesh_soup.h"

#include <string>
#include <string_view>

namespace fs_app {
namespace internal {

// The vertex part of a face reference (`i`, `i/t`, `i//n`, `i/t/n`), or `false` when the
// reference has any other form.
inline bool obj_vertex_reference(std::string_view token, long long& index)
{
  const std::size_t slash = token.find('/');
  if(!parse_integer(token.substr(0, slash), index))
    return false;
  if(slash == std::string_view::npos)
    return true;
  // What follows: "t", "/n", "t/n", or "" (a trailing slash, as some exporters write).
  const std::string_view rest = token.substr(slash + 1);
  const std::size_t second = rest.find('/');
  long long unused;
  const std::string_view texture = rest.substr(0, second);
  if(!texture.empty() && !parse_integer(texture, unused))
    return false;
  if(second == std::string_view::npos)
    return true;
  const std::string_view normal = rest.substr(second + 1);
  return normal.empty() || parse_integer(normal, unused);
}

inline void read_obj(const std::string& path, const File_content& content, Mesh_soup& soup)
{
  soup.format = "obj";
  Text_cursor in(path, content.data(), content.data() + content.size(), '#');
  while(in.skip_empty_lines())
  {
    const std::string_view statement = in.word();
    if(statement == "v")
    {
      const double x = in.coordinate("an x coordinate");
      const double y = in.coordinate("a y coordinate");
      const double z = in.coordinate("a z coordinate");
      add_point(soup, x, y, z);
      if(soup.points.size() > max_soup_count)
        in.fail("too many vertices for one mesh");
    }
    else if(statement == "f")
    {
      const std::size_t first = soup.indices.size();
      for(std::string_view token = in.word(); !token.empty(); token = in.word())
      {
        long long id;
        if(!obj_vertex_reference(token, id))
          in.fail("bad vertex reference " + quoted(token) +
                  " in a face (expected i, i/t, i//n or i/t/n)");
        if(id == 0)
          in.fail("vertex references start at 1, found 0 in a face");
        if(id < 0)
        {
          // Relative: -1 is the last vertex read so far.
          if(static_cast<unsigned long long>(-id) > soup.points.size())
            in.fail("the relative reference " + std::string(token) + " goes before the first vertex (" +
                    std::to_string(soup.points.size()) + " vertices read so far)");
          id = static_cast<long long>(soup.points.size()) + id;
        }
        else
        {
          if(static_cast<unsigned long long>(id) > max_soup_count)
            in.fail("vertex reference " + std::string(token) + " is too large");
          id -= 1;
        }
        soup.indices.push_back(static_cast<std::uint32_t>(id));
      }
      const std::size_t n = soup.indices.size() - first;
      if(n < 3)
        in.fail("face " + std::to_string(soup.number_of_faces()) + " has " + std::to_string(n) +
                " vertices (at least 3 are needed)");
      if(soup.indices.size() > max_soup_count)
        in.fail("too many face indices for one mesh");
      end_face(soup, in.line());
    }
    in.next_line();
  }

  // A face may name a vertex defined further down the file; the range is checked once
  // every vertex is known.
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
    for(std::size_t j = soup.begin[f]; j < soup.begin[f + 1]; ++j)
      if(soup.indices[j] >= soup.points.size())
        throw Input_error(path + ":" + std::to_string(soup.face_line[f]) + ": face " +
                          std::to_string(f) + " refers to vertex " +
                          std::to_string(soup.indices[j] + 1ull) + " but the file has " +
                          std::to_string(soup.points.size()) + " vertices");
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_OBJ_H
