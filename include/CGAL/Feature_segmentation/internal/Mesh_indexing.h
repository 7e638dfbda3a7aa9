// SPDX-License-Identifier: GPL-3.0-or-later
// Contiguous indices for the vertices, edges and faces of any FaceGraph, so that the
// stages keep their scratch data in std::vectors (no std::map keyed by descriptors, no
// property added to the user's mesh). Built once per mesh and shared by the stages.
// On a Surface_mesh without removed elements the ids are the mesh's own indices, so
// nothing is stored (for the halfedges too: edge i owns halfedges 2i and 2i+1 there).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_INDEXING_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_INDEXING_H

#include <CGAL/Feature_segmentation/internal/mesh_pass_counts.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/range/adaptor/transformed.hpp>
#include <boost/range/counting_range.hpp>

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>

#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

template <typename T> struct Is_surface_mesh : std::false_type {};
template <typename P> struct Is_surface_mesh<CGAL::Surface_mesh<P> > : std::true_type {};

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

  explicit Mesh_indexing(const TriangleMesh& tm) : m_tm(tm)
  {
    CGAL_FEATURE_SEGMENTATION_COUNT_PASS(indexings);
    if constexpr(Is_surface_mesh<TriangleMesh>::value)
      if(!tm.has_garbage())
      {
        m_identity = true;
        m_nv = tm.number_of_vertices();
        m_ne = tm.number_of_edges();
        m_nf = tm.number_of_faces();
        return;
      }
    m_vertices.emplace(Numbering<vertex_descriptor, VIMap>{get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm), {}});
    m_edges.emplace(Numbering<edge_descriptor, HIMap>{get(CGAL::dynamic_halfedge_property_t<std::size_t>(), tm), {}});
    m_faces.emplace(Numbering<face_descriptor, FIMap>{get(CGAL::dynamic_face_property_t<std::size_t>(), tm), {}});
    for(vertex_descriptor v : vertices(tm)) m_vertices->add(v, v);
    for(face_descriptor f : faces(tm)) m_faces->add(f, f);
    // Edge i owns halfedges 2i and 2i+1 in this numbering (whatever the mesh's own).
    for(edge_descriptor e : edges(tm))
    {
      const halfedge_descriptor h = halfedge(e, tm);
      put(m_edges->ids, opposite(h, tm), 2 * m_edges->list.size() + 1);
      m_edges->add(e, h, 2);
    }
    m_nv = m_vertices->list.size();
    m_ne = m_edges->list.size();
    m_nf = m_faces->list.size();
  }

  const TriangleMesh& mesh() const { return m_tm; }
  std::size_t number_of_vertices() const { return m_nv; }
  std::size_t number_of_edges() const { return m_ne; }
  std::size_t number_of_faces() const { return m_nf; }

  std::size_t id(vertex_descriptor v) const { return index_of(v, m_vertices); }
  std::size_t id(face_descriptor f) const { return index_of(f, m_faces); }
  std::size_t halfedge_id(halfedge_descriptor h) const { return index_of(h, m_edges); }
  std::size_t id(edge_descriptor e) const { return halfedge_id(halfedge(e, m_tm)) / 2; }
  std::size_t edge_id(halfedge_descriptor h) const { return halfedge_id(h) / 2; }

  vertex_descriptor vertex_at(std::size_t i) const { return element_at(i, m_vertices); }
  face_descriptor face_at(std::size_t i) const { return element_at(i, m_faces); }
  edge_descriptor edge_at(std::size_t i) const { return element_at(i, m_edges); }
  // The elements in id order.
  auto vertex_list() const { return make_range(m_nv, [this](std::size_t i) { return vertex_at(i); }); }
  auto face_list() const { return make_range(m_nf, [this](std::size_t i) { return face_at(i); }); }
  auto edge_list() const { return make_range(m_ne, [this](std::size_t i) { return edge_at(i); }); }

  /// Face id on the side of `h`, or `npos` on a border halfedge.
  std::size_t face_id(halfedge_descriptor h) const
  {
    face_descriptor f = face(h, m_tm);
    return f == GTr::null_face() ? npos : id(f);
  }

  static constexpr std::size_t npos = std::size_t(-1);

private:
  // The numbering of one kind of element on a mesh that is not numbered already: the
  // ids (of the elements, or of the halfedges for the edges) and the elements in id order.
  template <typename Element, typename Ids>
  struct Numbering
  {
    Ids ids;
    std::vector<Element> list;
    // Appends `e`, whose id is `stride` times its place; `key` carries the id.
    template <typename Key>
    void add(Element e, Key key, std::size_t stride = 1)
    {
      put(ids, key, stride * list.size());
      list.push_back(e);
    }
  };

  // The id of `x`: its own index on a Surface_mesh without removed elements, else the
  // numbering's.
  template <typename Descriptor, typename N>
  std::size_t index_of(Descriptor x, const std::optional<N>& numbering) const
  {
    if constexpr(Is_surface_mesh<TriangleMesh>::value)
      if(m_identity) return std::size_t(x.idx());
    return get(numbering->ids, x);
  }
  // The element of id `i`: the same index on a Surface_mesh without removed elements,
  // else the numbering's entry.
  template <typename Descriptor, typename Ids>
  Descriptor element_at(std::size_t i, const std::optional<Numbering<Descriptor, Ids> >& numbering) const
  {
    if constexpr(Is_surface_mesh<TriangleMesh>::value)
      if(m_identity) return Descriptor(typename TriangleMesh::size_type(i));
    return numbering->list[i];
  }

  template <typename At>
  static auto make_range(std::size_t n, At at)
  {
    return boost::adaptors::transform(boost::counting_range(std::size_t(0), n), at);
  }

  const TriangleMesh& m_tm;
  bool m_identity = false;
  std::size_t m_nv = 0, m_ne = 0, m_nf = 0;
  std::optional<Numbering<vertex_descriptor, VIMap> > m_vertices;
  std::optional<Numbering<edge_descriptor, HIMap> > m_edges; // ids of the halfedges
  std::optional<Numbering<face_descriptor, FIMap> > m_faces;
};

// Per face f of the mesh of `idx` (a triangle mesh), its three edges and the faces across
// them in the order of halfedges_around_face: edge[3 f + k] and across[3 f + k] (`none`
// across a border), as ids of type Id.
template <typename TriangleMesh, typename Id>
void face_edges_and_neighbours(const Mesh_indexing<TriangleMesh>& idx, Id none, std::vector<Id>& edge,
                               std::vector<Id>& across)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces();
  edge.assign(3 * nf, none);
  across.assign(3 * nf, none);
  for(std::size_t f = 0; f < nf; ++f)
  {
    int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
    {
      if(k == 3) break;
      const std::size_t g = idx.face_id(opposite(h, tm));
      edge[3 * f + k] = Id(idx.edge_id(h));
      across[3 * f + k] = g == idx.npos ? none : Id(g);
      ++k;
    }
  }
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_MESH_INDEXING_H
