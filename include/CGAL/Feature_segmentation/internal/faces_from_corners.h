// SPDX-License-Identifier: GPL-3.0-or-later
// Adding a mesh's faces from their corners and the twin links between them, in time
// linear in the mesh, and its precondition (one fan of faces per vertex): used by the crease cut's copy (crease_cut.h) and by the programs'
// readers (app/.../soup_topology.h).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_FACES_FROM_CORNERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_FACES_FROM_CORNERS_H

#include <CGAL/Feature_segmentation/internal/parallel_for.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// Whether every vertex has a single fan of faces (the precondition of
// add_faces_from_corners()): turning around vertex v from corner to corner across its
// edges visits every corner at v. The corners at v (leaving it) are corner_at(k) for k
// from corner_begin(v) to corner_begin(v + 1) - 1; next_corner(c) and previous_corner(c)
// are the corners after and before c in its face; twin_of(c) as in
// add_faces_from_corners(). A walk starts from a corner whose previous corner has no
// twin (the edge into v is on the border), if any, so that it covers an open fan whole.
// The vertices in chunks by TBB's threads if `parallel`.
template <typename CornerBegin, typename CornerAt, typename NextCorner, typename PreviousCorner, typename TwinOf>
bool every_vertex_has_one_fan(std::size_t nv, const CornerBegin& corner_begin, const CornerAt& corner_at,
                              const NextCorner& next_corner, const PreviousCorner& previous_corner,
                              const TwinOf& twin_of, std::size_t none, bool parallel)
{
  const std::size_t chunk = 16384;
  std::vector<char> pinched((nv + chunk - 1) / chunk, 0);
  for_each_range(pinched.size(), parallel, 1, [&](std::size_t first_chunk, std::size_t last_chunk) {
    for(std::size_t ch = first_chunk; ch < last_chunk; ++ch)
      for(std::size_t v = ch * chunk; v < (std::min)(nv, (ch + 1) * chunk) && !pinched[ch]; ++v)
      {
        const std::size_t first = std::size_t(corner_begin(v)), last = std::size_t(corner_begin(v + 1));
        if(last - first < 2) continue;
        std::size_t start = std::size_t(corner_at(first));
        for(std::size_t k = first; k < last; ++k)
          if(std::size_t(twin_of(previous_corner(std::size_t(corner_at(k))))) == none)
          {
            start = std::size_t(corner_at(k));
            break;
          }
        std::size_t visited = 1;
        for(std::size_t c = start;;)
        {
          // across the edge from v to the next vertex, to the twin's face, whose corner
          // at v follows the twin
          const std::size_t t = std::size_t(twin_of(c));
          if(t == none) break;
          c = std::size_t(next_corner(t));
          if(c == start) break;
          if(++visited > last - first) break;
        }
        if(visited != last - first) pinched[ch] = 1;
      }
  });
  return std::find(pinched.begin(), pinched.end(), 1) == pinched.end();
}

// Adds `nf` faces to `mesh`, which holds the vertices `vertex` and nothing else, halfedge
// by halfedge, as CGAL::Euler::add_face would add them one by one in face order: the same
// edges in the same order and directions, the same next halfedges, the same halfedge of
// every face (the one into its first corner) and of every vertex (the border halfedge
// into it if it has one, else the halfedge into it of its last face). Face f has the
// corners first_corner(f) to first_corner(f + 1) - 1; the halfedge of corner c runs from
// vertex[vertex_of(c)] to the vertex of the next corner of its face; twin_of(c) is the
// corner whose halfedge is its opposite, or `none` on a border. `face` receives the faces.
// Preconditions (which the callers check first): twins are mutual and join the same two
// vertices the other way, and every vertex has a single fan of faces.
template <typename Mesh, typename FirstCorner, typename VertexOf, typename TwinOf>
void add_faces_from_corners(Mesh& mesh,
                            const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& vertex,
                            std::size_t nf, const FirstCorner& first_corner, const VertexOf& vertex_of,
                            const TwinOf& twin_of, std::size_t none,
                            std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& face)
{
  typedef boost::graph_traits<Mesh> GTr;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  const std::size_t nc = nf > 0 ? std::size_t(first_corner(nf)) : 0;
  std::vector<halfedge_descriptor> halfedge_of(nc, GTr::null_halfedge());
  face.resize(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t first = std::size_t(first_corner(f)), last = std::size_t(first_corner(f + 1));
    const auto fd = add_face(mesh);
    face[f] = fd;
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t t = std::size_t(twin_of(c));
      halfedge_descriptor h;
      if(t != none && halfedge_of[t] != GTr::null_halfedge())
        h = opposite(halfedge_of[t], mesh);
      else
      {
        h = halfedge(add_edge(mesh), mesh);
        const std::size_t n = c + 1 == last ? first : c + 1;
        set_target(h, vertex[std::size_t(vertex_of(n))], mesh);
        set_target(opposite(h, mesh), vertex[std::size_t(vertex_of(c))], mesh);
        set_face(opposite(h, mesh), GTr::null_face(), mesh);
      }
      halfedge_of[c] = h;
      set_face(h, fd, mesh);
    }
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t n = c + 1 == last ? first : c + 1;
      set_next(halfedge_of[c], halfedge_of[n], mesh);
      set_halfedge(vertex[std::size_t(vertex_of(n))], halfedge_of[c], mesh);
    }
    set_halfedge(fd, halfedge_of[last - 1], mesh);
  }
  // The border: corner c (a -> b) without a twin has the border halfedge b -> a as its
  // opposite, which runs into a, is a's halfedge, and goes on with the border halfedge
  // leaving a (one per vertex, with one fan each).
  std::vector<halfedge_descriptor> border_from(vertex.size(), GTr::null_halfedge());
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t first = std::size_t(first_corner(f)), last = std::size_t(first_corner(f + 1));
    for(std::size_t c = first; c < last; ++c)
      if(std::size_t(twin_of(c)) == none)
        border_from[std::size_t(vertex_of(c + 1 == last ? first : c + 1))] = opposite(halfedge_of[c], mesh);
  }
  for(std::size_t c = 0; c < nc; ++c)
    if(std::size_t(twin_of(c)) == none)
    {
      const halfedge_descriptor border = opposite(halfedge_of[c], mesh);
      const std::size_t a = std::size_t(vertex_of(c));
      set_next(border, border_from[a], mesh);
      set_halfedge(vertex[a], border, mesh);
    }
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_FACES_FROM_CORNERS_H
