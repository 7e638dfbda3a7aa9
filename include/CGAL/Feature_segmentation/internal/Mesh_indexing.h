// SPDX-License-Identifier: GPL-3.0-or-later
// Contiguous indices for the vertices, edges and faces of any FaceGraph, so that the
// stages keep their scratch data in std::vectors (no std::map keyed by descriptors, no
// property added to the user's mesh). Built once per mesh and shared by the stages.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_INDEXING_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_INDEXING_H

#include <CGAL/Feature_segmentation/internal/mesh_pass_counts.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

template <typename TriangleMesh>
class Mesh_indexing
{
public:
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  typedef typename GTr::edge_descriptor edge_descriptor;
  typedef typename GTr::face_descriptor face_descriptor;

  // Dynamic property maps on a const mesh: CGAL attaches them to the mesh object
  // without changing what it represents, and removes them with this object.
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::const_type VIMap;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<std::size_t> >::const_type HIMap;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t> >::const_type FIMap;

  explicit Mesh_indexing(const TriangleMesh& tm)
    : m_tm(tm),
      m_vimap(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm)),
      m_himap(get(CGAL::dynamic_halfedge_property_t<std::size_t>(), tm)),
      m_fimap(get(CGAL::dynamic_face_property_t<std::size_t>(), tm))
  {
    CGAL_FEATURE_SEGMENTATION_COUNT_PASS(indexings);
    for(vertex_descriptor v : vertices(tm)) { put(m_vimap, v, m_vertices.size()); m_vertices.push_back(v); }
    for(face_descriptor f : faces(tm)) { put(m_fimap, f, m_faces.size()); m_faces.push_back(f); }
    // Edge i owns halfedges 2i and 2i+1 in this numbering (whatever the mesh's own).
    for(edge_descriptor e : edges(tm))
    {
      halfedge_descriptor h = halfedge(e, tm);
      put(m_himap, h, 2 * m_edges.size());
      put(m_himap, opposite(h, tm), 2 * m_edges.size() + 1);
      m_edges.push_back(e);
    }
  }

  const TriangleMesh& mesh() const { return m_tm; }
  std::size_t number_of_vertices() const { return m_vertices.size(); }
  std::size_t number_of_edges() const { return m_edges.size(); }
  std::size_t number_of_faces() const { return m_faces.size(); }

  std::size_t id(vertex_descriptor v) const { return get(m_vimap, v); }
  std::size_t id(face_descriptor f) const { return get(m_fimap, f); }
  std::size_t id(edge_descriptor e) const { return get(m_himap, halfedge(e, m_tm)) / 2; }
  std::size_t halfedge_id(halfedge_descriptor h) const { return get(m_himap, h); }
  std::size_t edge_id(halfedge_descriptor h) const { return get(m_himap, h) / 2; }

  vertex_descriptor vertex_at(std::size_t i) const { return m_vertices[i]; }
  face_descriptor face_at(std::size_t i) const { return m_faces[i]; }
  edge_descriptor edge_at(std::size_t i) const { return m_edges[i]; }
  const std::vector<vertex_descriptor>& vertex_list() const { return m_vertices; }
  const std::vector<face_descriptor>& face_list() const { return m_faces; }
  const std::vector<edge_descriptor>& edge_list() const { return m_edges; }

  /// Face id on the side of `h`, or `npos` on a border halfedge.
  std::size_t face_id(halfedge_descriptor h) const
  {
    face_descriptor f = face(h, m_tm);
    return f == GTr::null_face() ? npos : id(f);
  }

  static constexpr std::size_t npos = std::size_t(-1);

private:
  const TriangleMesh& m_tm;
  VIMap m_vimap;
  HIMap m_himap;
  FIMap m_fimap;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<face_descriptor> m_faces;
  std::vector<edge_descriptor> m_edges;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_INDEXING_H
