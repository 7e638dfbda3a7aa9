// The passes over the mesh, counted (issue 12): one segmentation checks its mesh once
// (check_input_mesh()) and indexes it once (Mesh_indexing), plus one indexing of the
// working mesh when it is cut open along creases; the boundaries, their smoothing and
// the face patches add none. An executable of its own: the debug counter
// (CGAL_FEATURE_SEGMENTATION_COUNT_MESH_PASSES) must be compiled into every use of the
// package's headers in a program.
#define CGAL_FEATURE_SEGMENTATION_COUNT_MESH_PASSES
#define BOOST_TEST_MODULE mesh_passes
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include "test_meshes.h"

#include <map>
#include <vector>

namespace FS = CGAL::Feature_segmentation;
namespace FSI = CGAL::Feature_segmentation::internal;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

void reset() { FSI::mesh_pass_counts() = FSI::Mesh_pass_counts(); }

template <typename Mesh>
void count_passes()
{
  std::vector<int> side;
  const Mesh box = fs_test::to_mesh<Mesh>(fs_test::box(1., 1., 1., 6, side));
  // cut open along its 12 edges: the input checked and indexed, the working mesh indexed
  reset();
  {
    const FS::Feature_aligned_segmentation<Mesh> seg(box);
    BOOST_TEST(seg.number_of_patches() == 6u);
    BOOST_TEST(FSI::mesh_pass_counts().checks == 1u);
    BOOST_TEST(FSI::mesh_pass_counts().indexings == 2u);
    // the boundaries, their smoothing and the face patches reuse the precomputation
    FS::Patch_boundaries<Mesh> b = seg.patch_boundaries();
    FS::smooth_patch_boundaries(b);
    std::map<typename boost::graph_traits<Mesh>::face_descriptor, std::size_t> patch;
    seg.face_patches(b, boost::make_assoc_property_map(patch));
    BOOST_TEST(FSI::mesh_pass_counts().checks == 1u);
    BOOST_TEST(FSI::mesh_pass_counts().indexings == 2u);
  }
  // the paper's pipeline, no cut: the input checked and indexed once
  reset();
  {
    const FS::Feature_aligned_segmentation<Mesh> seg(box, FS::parameters::crease_angle(180.));
    BOOST_TEST(FSI::mesh_pass_counts().checks == 1u);
    BOOST_TEST(FSI::mesh_pass_counts().indexings == 1u);
  }
  // a smooth surface: looked at for creases, none found, nothing cut
  const Mesh sphere = fs_test::to_mesh<Mesh>(fs_test::icosphere(1., 3));
  reset();
  {
    const FS::Feature_aligned_segmentation<Mesh> seg(sphere);
    BOOST_TEST(seg.number_of_crease_edges() == 0u);
    BOOST_TEST(FSI::mesh_pass_counts().checks == 1u);
    BOOST_TEST(FSI::mesh_pass_counts().indexings == 1u);
  }
  // the free function is the class once
  reset();
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> vpatch;
  BOOST_TEST(FS::segment_along_features(box, boost::make_assoc_property_map(vpatch)) == 6u);
  BOOST_TEST(FSI::mesh_pass_counts().checks == 1u);
  BOOST_TEST(FSI::mesh_pass_counts().indexings == 2u);
  // the one-shot curvature function checks and indexes the mesh it is given
  reset();
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor,
           FS::Principal_curvatures<typename CGAL::Kernel_traits<
             typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type>::Kernel> >
    curvature;
  FS::estimate_principal_curvatures(sphere, boost::make_assoc_property_map(curvature));
  BOOST_TEST(FSI::mesh_pass_counts().checks == 1u);
  BOOST_TEST(FSI::mesh_pass_counts().indexings == 1u);
}

} // namespace

BOOST_AUTO_TEST_CASE(one_segmentation_checks_and_indexes_its_mesh_once_surface_mesh) { count_passes<SM>(); }
BOOST_AUTO_TEST_CASE(one_segmentation_checks_and_indexes_its_mesh_once_polyhedron) { count_passes<Poly>(); }
