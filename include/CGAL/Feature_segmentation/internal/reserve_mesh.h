// SPDX-License-Identifier: GPL-3.0-or-later
// Reserves room for the elements a mesh is about to receive, on the mesh types whose
// graph traits offer CGAL's `reserve()` (Surface_mesh, Polyhedron_3, OpenMesh, ...), so
// that building a mesh element by element does not leave its arrays up to twice the size
// they need; on other FaceGraph models, nothing.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_RESERVE_MESH_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_RESERVE_MESH_H

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

template <typename Mesh, typename = void>
struct Has_reserve : std::false_type {};

template <typename Mesh>
struct Has_reserve<Mesh, std::void_t<decltype(reserve(
                           std::declval<Mesh&>(),
                           std::declval<typename boost::graph_traits<Mesh>::vertices_size_type>(),
                           std::declval<typename boost::graph_traits<Mesh>::edges_size_type>(),
                           std::declval<typename boost::graph_traits<Mesh>::faces_size_type>()))> >
  : std::true_type {};

template <typename Mesh>
void reserve_mesh(Mesh& mesh, std::size_t vertices, std::size_t edges, std::size_t faces)
{
  typedef boost::graph_traits<Mesh> GTr;
  if constexpr(Has_reserve<Mesh>::value)
    reserve(mesh, typename GTr::vertices_size_type(vertices), typename GTr::edges_size_type(edges),
            typename GTr::faces_size_type(faces));
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_RESERVE_MESH_H
