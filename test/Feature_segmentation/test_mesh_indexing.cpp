// The contiguous ids of the stages (internal/Mesh_indexing.h): on a Surface_mesh without
// removed elements they are the mesh's own indices (no maps); on one with removed
// elements, and on a Polyhedron_3, they are numbered in iteration order. Either way:
// ids 0 .. n-1, element_at(id(x)) == x, edge i owns halfedges 2i and 2i+1. And the
// 32-bit ids the stages copy into arrays (internal/compact_index.h).
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/compact_index.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <cstddef>
#include <cstdint>
#include <set>
#include <stdexcept>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<Epick> Poly_epick;

// The invariants every indexing keeps, on a mesh of nv vertices, ne edges, nf faces.
template <typename Mesh>
void check_indexing(const Mesh& m, std::size_t nv, std::size_t ne, std::size_t nf)
{
  const FS::internal::Mesh_indexing<Mesh> idx(m);
  BOOST_TEST(idx.number_of_vertices() == nv);
  BOOST_TEST(idx.number_of_edges() == ne);
  BOOST_TEST(idx.number_of_faces() == nf);
  std::set<std::size_t> vids, fids, eids;
  for(auto v : vertices(m))
  {
    vids.insert(idx.id(v));
    BOOST_TEST((idx.vertex_at(idx.id(v)) == v));
  }
  for(auto f : faces(m))
  {
    fids.insert(idx.id(f));
    BOOST_TEST((idx.face_at(idx.id(f)) == f));
  }
  for(auto e : edges(m))
  {
    const std::size_t i = idx.id(e);
    eids.insert(i);
    BOOST_TEST((idx.edge_at(i) == e));
    BOOST_TEST(idx.halfedge_id(halfedge(e, m)) == 2 * i);
    BOOST_TEST(idx.halfedge_id(opposite(halfedge(e, m), m)) == 2 * i + 1);
  }
  BOOST_TEST(vids.size() == nv);
  BOOST_TEST(fids.size() == nf);
  BOOST_TEST(eids.size() == ne);
  BOOST_TEST((vids.empty() || *vids.rbegin() == nv - 1));
  BOOST_TEST((fids.empty() || *fids.rbegin() == nf - 1));
  BOOST_TEST((eids.empty() || *eids.rbegin() == ne - 1));
  // the lists in id order
  std::size_t k = 0;
  for(auto v : idx.vertex_list()) BOOST_TEST((idx.id(v) == k++));
  k = 0;
  for(auto f : idx.face_list()) BOOST_TEST((idx.id(f) == k++));
  k = 0;
  for(auto e : idx.edge_list()) BOOST_TEST((idx.id(e) == k++));
}

} // namespace

BOOST_AUTO_TEST_SUITE(mesh_indexing)

// A 4 x 4 grid: 25 vertices, 56 edges, 32 faces. On the Surface_mesh the ids are its
// own indices.
BOOST_AUTO_TEST_CASE(surface_mesh_uses_its_own_indices)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  check_indexing(m, 25, 56, 32);
  const FS::internal::Mesh_indexing<SM> idx(m);
  for(auto v : m.vertices()) BOOST_TEST(idx.id(v) == std::size_t(v.idx()));
  for(auto f : m.faces()) BOOST_TEST(idx.id(f) == std::size_t(f.idx()));
  for(auto e : m.edges()) BOOST_TEST(idx.id(e) == std::size_t(e.idx()));
}

// The grid with one corner face removed (garbage not collected): 32 - 1 faces; the
// corner vertex of that face alone goes with it when it has no other face (a corner of
// the grid has one or two faces; the test counts what the mesh keeps).
BOOST_AUTO_TEST_CASE(surface_mesh_with_removed_elements)
{
  SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  CGAL::Euler::remove_face(halfedge(*m.faces().begin(), m), m);
  BOOST_REQUIRE(m.has_garbage());
  check_indexing(m, m.number_of_vertices(), m.number_of_edges(), m.number_of_faces());
  BOOST_TEST(m.number_of_faces() == 31u);
}

BOOST_AUTO_TEST_CASE(polyhedron)
{
  const SM sm = fs_test::to_mesh<SM>(fs_test::plane(1., 4));
  Poly_epick p;
  CGAL::copy_face_graph(sm, p);
  check_indexing(p, 25, 56, 32);
}

// 32-bit ids: values and "none" (a border's missing face) read back; sizes from 2^32 - 1
// on are refused.
BOOST_AUTO_TEST_CASE(compact_index)
{
  const FS::internal::Compact_index a(std::size_t(123456789)), none(std::size_t(-1)), zero;
  BOOST_TEST(std::size_t(a) == 123456789u);
  BOOST_TEST(std::size_t(none) == std::size_t(-1));
  BOOST_TEST(std::size_t(zero) == 0u);
  BOOST_TEST(std::size_t(FS::internal::Compact_index(std::size_t(UINT32_MAX) - 1)) == std::size_t(UINT32_MAX) - 1);
  BOOST_CHECK_NO_THROW(FS::internal::check_compact_index_range(std::size_t(UINT32_MAX) - 1));
  BOOST_CHECK_THROW(FS::internal::check_compact_index_range(std::size_t(UINT32_MAX)), std::length_error);
}

BOOST_AUTO_TEST_SUITE_END()
