// SPDX-License-Identifier: GPL-3.0-or-later
// Reading of user feature lines for the package's programs: a file in CGAL's polylines
// format ("n x1 y1 z1 ... xn yn zn" per line) whose segments are edges of the mesh, as
// written by Mesh_3's feature-edge tools or by hand. Each polyline point is snapped to
// the mesh vertex at the same position (within a tolerance relative to the mesh size),
// each segment must then be a mesh edge, and each polyline becomes a feature line of
// type USER whose points sit on mesh vertices. Errors are `Input_error`s naming the line.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_READ_USER_FEATURE_LINES_H
#define CGAL_FEATURE_SEGMENTATION_APP_READ_USER_FEATURE_LINES_H

#include "read_input_mesh.h"

#include <CGAL/Feature_segmentation/Feature_lines.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs_app {

template <typename Mesh>
std::size_t read_user_feature_lines(std::istream& in, const std::string& path, const Mesh& mesh,
                                    CGAL::Feature_segmentation::Feature_lines<Mesh>& lines);

/// Reads the polylines of `path` and appends them to `lines` as USER lines; returns the
/// number of lines added. Throws `Input_error` on an unreadable file, a malformed line, a
/// point that is not a mesh vertex or a segment that is not a mesh edge.
template <typename Mesh>
std::size_t read_user_feature_lines(const std::string& path, const Mesh& mesh,
                                    CGAL::Feature_segmentation::Feature_lines<Mesh>& lines)
{
  internal::check_readable_file(path);
  std::ifstream in(path);
  return read_user_feature_lines(in, path, mesh, lines);
}

/// Reads the polylines of `in` (the content of the file `path`, which names it in
/// messages) and appends them to `lines`, as the overload above.
template <typename Mesh>
std::size_t read_user_feature_lines(std::istream& in, const std::string& path, const Mesh& mesh,
                                    CGAL::Feature_segmentation::Feature_lines<Mesh>& lines)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef CGAL::Search_traits_adapter<vertex_descriptor, VPM, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Neighbor_search;
  typedef typename Neighbor_search::Tree Tree;
  typedef typename Neighbor_search::Distance Distance;

  const VPM vpm = get(CGAL::vertex_point, mesh);
  Tree tree(vertices(mesh).begin(), vertices(mesh).end(), typename Tree::Splitter(),
            Traits(vpm));
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                    CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  // Points written with a few digits still match; distinct vertices of any sane mesh
  // are much farther apart than this.
  const double tolerance = 1e-6 * diagonal;

  std::size_t added = 0;
  std::string text;
  std::size_t line_number = 0;
  while(std::getline(in, text))
  {
    ++line_number;
    const std::string where = path + ": line " + std::to_string(line_number);
    std::istringstream ls(text);
    long long n = 0;
    if(!(ls >> n))
    {
      std::string word;
      std::istringstream blank(text);
      if(!(blank >> word))
        continue; // an empty line
      throw Input_error(where + ": expected the number of points");
    }
    if(n < 2)
      throw Input_error(where + ": a polyline needs at least 2 points (got " +
                        std::to_string(n) + ")");
    std::vector<vertex_descriptor> chain;
    for(long long i = 0; i < n; ++i)
    {
      double x, y, z;
      if(!(ls >> x >> y >> z))
        throw Input_error(where + ": expected " + std::to_string(n) + " points of 3 coordinates");
      if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        throw Input_error(where + ": point " + std::to_string(i + 1) +
                          " has a NaN or infinite coordinate");
      const Point query(x, y, z);
      Neighbor_search search(tree, query, 1, 0, true, Distance(vpm));
      if(search.begin() == search.end() ||
         std::sqrt(search.begin()->second) > tolerance)
        throw Input_error(where + ": point " + std::to_string(i + 1) + " (" + std::to_string(x) +
                          " " + std::to_string(y) + " " + std::to_string(z) +
                          ") is not a vertex of the mesh");
      chain.push_back(search.begin()->first);
    }
    std::string rest;
    if(ls >> rest)
      throw Input_error(where + ": unexpected text after " + std::to_string(n) + " points");

    CGAL::Feature_segmentation::Feature_line<Mesh> line;
    line.type = CGAL::Feature_segmentation::Feature_line_type::USER;
    line.is_closed = chain.size() > 2 && chain.front() == chain.back();
    if(line.is_closed)
      chain.pop_back();
    const std::size_t number_of_segments = line.is_closed ? chain.size() : chain.size() - 1;
    for(std::size_t i = 0; i < number_of_segments; ++i)
    {
      const vertex_descriptor a = chain[i], b = chain[(i + 1) % chain.size()];
      const std::pair<halfedge_descriptor, bool> h = halfedge(a, b, mesh);
      if(!h.second)
        throw Input_error(where + ": segment " + std::to_string(i + 1) +
                          " is not an edge of the mesh");
      // A point at a vertex: the source of the halfedge leaving it along the line.
      line.points.push_back({h.first, 0.});
      line.length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, a), get(vpm, b))));
    }
    if(!line.is_closed)
    {
      const std::pair<halfedge_descriptor, bool> h = halfedge(chain[chain.size() - 2], chain.back(), mesh);
      line.points.push_back({h.first, 1.});
    }
    lines.lines.push_back(line);
    ++added;
  }
  return added;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_READ_USER_FEATURE_LINES_H
