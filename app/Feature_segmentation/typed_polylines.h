// SPDX-License-Identifier: GPL-3.0-or-later
// The polylines of the program's outputs, each with its type: the features the
// segmentation used (crest lines as ridges and valleys, the user's lines, and the creases
// of a CAD tessellation, chained from its crease edges, split into creases found by their
// dihedral angle and seams found as curvature discontinuities), and the boundaries
// between patches (the smoothed curves inside faces, and the creases between two
// different patches, exactly on the mesh's edges). Written in CGAL's polylines format
// with the types in a companion file, and as OBJ with one object per type.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_TYPED_POLYLINES_H
#define CGAL_FEATURE_SEGMENTATION_APP_TYPED_POLYLINES_H

#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/IO/write_feature_lines.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace fs_app {

/// A polyline with its type ("crease", "seam", "seam_line", "ridge", "valley", "user",
/// "smoothed").
struct Typed_polyline
{
  std::string type;
  std::vector<std::array<double, 3> > points;
  bool is_closed = false; ///< the last point joins the first (not repeated in `points`)
};

/// The types in the order the OBJ file lists its objects.
inline const std::vector<std::string>& polyline_types()
{
  static const std::vector<std::string> types = {"crease", "seam", "seam_line", "ridge",
                                                 "valley", "user", "smoothed"};
  return types;
}

/// The marked edges of `mesh` (a `Surface_mesh`) chained into polylines of vertices: a
/// chain runs through the vertices with two marked edges and ends at the others; what is
/// left are closed loops. Deterministic: chains start at the vertices in their index
/// order. The edges are marked by TBB's threads (`is_marked` is called from several
/// threads at once), the rest looks at the marked edges and their ends only.
template <typename Mesh, typename IsMarked>
std::vector<std::pair<std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>, bool> >
edge_chains(const Mesh& mesh, IsMarked is_marked)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename Mesh::Edge_index Edge_index;
  const std::size_t ne = mesh.number_of_edges() + mesh.number_of_removed_edges();
  std::vector<char> marked(ne, 0);
  CGAL::Feature_segmentation::internal::for_each_range(ne, true, 16384, [&](std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
    {
      const Edge_index e(static_cast<typename Edge_index::size_type>(i));
      marked[i] = !mesh.is_removed(e) && is_marked(e);
    }
  });
  std::vector<std::size_t> marked_edges, ends;
  for(std::size_t i = 0; i < ne; ++i)
    if(marked[i]) marked_edges.push_back(i);
  std::vector<int> degree(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), 0);
  for(std::size_t i : marked_edges)
  {
    const halfedge_descriptor h = halfedge(Edge_index(static_cast<typename Edge_index::size_type>(i)), mesh);
    for(vertex_descriptor v : { source(h, mesh), target(h, mesh) })
      if(degree[v.idx()]++ == 0) ends.push_back(v.idx());
  }
  std::sort(ends.begin(), ends.end());
  std::vector<char> used(ne, 0);
  auto next_out = [&](vertex_descriptor v) {
    for(halfedge_descriptor h : CGAL::halfedges_around_source(v, mesh))
    {
      const std::size_t e = edge(h, mesh).idx();
      if(marked[e] && !used[e]) return h;
    }
    return boost::graph_traits<Mesh>::null_halfedge();
  };
  std::vector<std::pair<std::vector<vertex_descriptor>, bool> > chains;
  auto walk = [&](halfedge_descriptor h) {
    std::vector<vertex_descriptor> chain(1, source(h, mesh));
    const vertex_descriptor start = source(h, mesh);
    bool closed = false;
    while(h != boost::graph_traits<Mesh>::null_halfedge())
    {
      used[edge(h, mesh).idx()] = 1;
      const vertex_descriptor w = target(h, mesh);
      if(w == start) { closed = true; break; }
      chain.push_back(w);
      if(degree[w.idx()] != 2) break;
      h = next_out(w);
    }
    chains.emplace_back(std::move(chain), closed);
  };
  for(std::size_t i : ends)
  {
    const vertex_descriptor v(static_cast<typename vertex_descriptor::size_type>(i));
    if(degree[i] != 2)
      for(halfedge_descriptor h = next_out(v); h != boost::graph_traits<Mesh>::null_halfedge(); h = next_out(v))
        walk(h);
  }
  for(std::size_t i : marked_edges) // loops: every vertex of two marked edges
    if(!used[i]) walk(halfedge(Edge_index(static_cast<typename Edge_index::size_type>(i)), mesh));
  return chains;
}

/// Appends to `out` the chains of the marked edges of `mesh` as polylines of `type`.
template <typename Mesh, typename IsMarked>
void append_edge_chains(const Mesh& mesh, IsMarked is_marked, const std::string& type,
                        std::vector<Typed_polyline>& out)
{
  for(const auto& chain : edge_chains(mesh, is_marked))
  {
    Typed_polyline p;
    p.type = type;
    p.is_closed = chain.second;
    for(auto v : chain.first)
    {
      const auto& q = mesh.point(v);
      p.points.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
    }
    out.push_back(std::move(p));
  }
}

/// Appends the feature lines `lines` of `mesh` (ridges, valleys, the user's lines).
template <typename Mesh>
void append_feature_lines(const Mesh& mesh, const CGAL::Feature_segmentation::Feature_lines<Mesh>& lines,
                          std::vector<Typed_polyline>& out)
{
  namespace FS = CGAL::Feature_segmentation;
  for(const FS::Feature_line<Mesh>& line : lines.lines)
  {
    Typed_polyline p;
    p.type = FS::internal::feature_line_type_name(line.type);
    p.is_closed = line.is_closed;
    for(const FS::Feature_point<Mesh>& fp : line.points)
    {
      const auto q = fp.point(mesh, get(CGAL::vertex_point, mesh));
      p.points.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
    }
    out.push_back(std::move(p));
  }
}

// Every feature that a segmentation `seg` of `mesh` uses, typed: the crease edges chained
// into "crease" lines, the curvature discontinuities into "seam" lines, then its feature
// lines (crest lines, seam lines through the faces, the user's lines and sketches:
// append_feature_lines) on its working mesh.
template <typename Mesh, typename Segmentation>
std::vector<Typed_polyline> typed_feature_lines(const Mesh& mesh, const Segmentation& seg)
{
  std::vector<Typed_polyline> features;
  append_edge_chains(
    mesh, [&](typename Mesh::Edge_index e) { return seg.is_crease_edge(e) && !seg.is_curvature_discontinuity_edge(e); },
    "crease", features);
  append_edge_chains(
    mesh, [&](typename Mesh::Edge_index e) { return seg.is_curvature_discontinuity_edge(e); }, "seam", features);
  append_feature_lines(seg.working_mesh(), seg.feature_lines(), features);
  return features;
}

// Every boundary between two patches of `seg`, typed: the curves of `boundaries`
// ("smoothed", inside faces), then the crease edges between two faces of different
// patches of `face_patch` chained into "crease" lines, on the mesh's edges.
template <typename Mesh, typename Segmentation, typename Boundaries, typename FacePatchMap>
std::vector<Typed_polyline> typed_boundary_lines(const Mesh& mesh, const Segmentation& seg,
                                                 const Boundaries& boundaries, FacePatchMap face_patch)
{
  std::vector<Typed_polyline> lines;
  for(const auto& c : boundaries.curves())
  {
    Typed_polyline p;
    p.type = "smoothed";
    p.is_closed = c.is_closed();
    for(const auto& q : c.points) p.points.push_back({q.point[0], q.point[1], q.point[2]});
    lines.push_back(std::move(p));
  }
  append_edge_chains(
    mesh,
    [&](typename Mesh::Edge_index e) {
      const auto h = halfedge(e, mesh);
      return seg.is_crease_edge(e) && !is_border_edge(h, mesh) &&
             get(face_patch, face(h, mesh)) != get(face_patch, face(opposite(h, mesh), mesh));
    },
    "crease", lines);
  return lines;
}

/// The number of polylines of `type`.
inline std::size_t number_of_polylines(const std::vector<Typed_polyline>& lines, const std::string& type)
{
  std::size_t n = 0;
  for(const Typed_polyline& l : lines) n += l.type == type;
  return n;
}

/// CGAL's polylines format: a line per polyline, its number of points then their
/// coordinates; a closed polyline repeats its first point.
inline void write_typed_polylines(std::ostream& os, const std::vector<Typed_polyline>& lines)
{
  namespace FSI = CGAL::Feature_segmentation::internal;
  for(const Typed_polyline& l : lines)
  {
    os << l.points.size() + (l.is_closed && !l.points.empty() ? 1 : 0);
    for(const auto& p : l.points)
    {
      for(double x : p) { os << ' '; FSI::write_double(os, x); }
    }
    if(l.is_closed && !l.points.empty())
      for(double x : l.points.front()) { os << ' '; FSI::write_double(os, x); }
    os << '\n';
  }
}

/// The companion of write_typed_polylines(): the type of each polyline, a line each.
inline void write_polyline_types(std::ostream& os, const std::vector<Typed_polyline>& lines)
{
  for(const Typed_polyline& l : lines) os << l.type << '\n';
}

/// OBJ line elements, one object per type (`o crease`, `o ridge`, ...), so that a
/// viewer can show or hide each kind.
inline void write_typed_OBJ_lines(std::ostream& os, const std::vector<Typed_polyline>& lines)
{
  namespace FSI = CGAL::Feature_segmentation::internal;
  os << "# " << lines.size() << " polylines, one object per type\n";
  std::size_t next_index = 1; // OBJ indices start at 1 and run over the whole file
  for(const std::string& type : polyline_types())
  {
    if(number_of_polylines(lines, type) == 0) continue;
    os << "o " << type << '\n';
    for(const Typed_polyline& l : lines)
    {
      if(l.type != type || l.points.size() < 2) continue;
      for(const auto& p : l.points)
      {
        os << 'v';
        for(double x : p) { os << ' '; FSI::write_double(os, x); }
        os << '\n';
      }
      os << 'l';
      for(std::size_t k = 0; k < l.points.size(); ++k) os << ' ' << next_index + k;
      if(l.is_closed) os << ' ' << next_index;
      os << '\n';
      next_index += l.points.size();
    }
  }
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_TYPED_POLYLINES_H
