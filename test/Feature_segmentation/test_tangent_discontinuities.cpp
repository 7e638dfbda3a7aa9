// Curvature discontinuities of CAD tessellations (tangent_discontinuities, on by
// default): a floor, a quarter-cylinder fillet and a wall, tangent to each other,
// tessellated as a CAD tessellator does (vertices on the straight rulings). No edge bends
// by 20 degrees, so there is no crease; the two tangent lines are the only edges with a
// plane on one side, and they give exactly the three faces of the part.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "fandisk_reference.h"
#include "test_meshes.h"

#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;

const double pi = 3.14159265358979323846;
const double fillet_radius = 0.3;
const int floor_segments = 4, fillet_segments = 6, wall_segments = 4;

// The profile point i (of floor_segments + fillet_segments + wall_segments + 1) in the
// (x, z) plane: the floor from x = -1 to 0 at z = 0, the fillet of fillet_radius around
// (0, r) in steps of 90 / fillet_segments = 15 degrees (the tangent lines bend by half
// a step, 7.5 degrees), the wall at x = r up to z = r + 1.
std::pair<double, double> profile(int i)
{
  if(i <= floor_segments) return { -1. + double(i) / floor_segments, 0. };
  if(i <= floor_segments + fillet_segments)
  {
    const double t = 0.5 * pi * double(i - floor_segments) / fillet_segments;
    return { fillet_radius * std::sin(t), fillet_radius * (1. - std::cos(t)) };
  }
  return { fillet_radius, fillet_radius + double(i - floor_segments - fillet_segments) / wall_segments };
}

// The profile swept along y over [0, 1] in `rulings` steps.
fs_test::Soup filleted_corner(int rulings)
{
  const int nu = floor_segments + fillet_segments + wall_segments;
  return fs_test::parametric_grid(nu, rulings, false, false, [nu](double u, double v) {
    const auto p = profile(int(std::lround(u * nu)));
    return std::array<double, 3>{ p.first, v, p.second };
  });
}

// 0 on the floor, 1 on the fillet, 2 on the wall, from the face's centroid.
int part_of(const SM& m, SM::Face_index f)
{
  double x = 0, z = 0;
  for(auto v : vertices_around_face(halfedge(f, m), m)) { x += m.point(v).x() / 3; z += m.point(v).z() / 3; }
  if(z < 1e-9) return 0;
  return x > fillet_radius - 1e-9 ? 2 : 1;
}

// Whether edge e lies on one of the two tangent lines (x = 0, z = 0 or x = z = r).
bool on_tangent_line(const SM& m, SM::Edge_index e)
{
  const auto& p = m.point(source(halfedge(e, m), m));
  const auto& q = m.point(target(halfedge(e, m), m));
  auto on = [](const Epick::Point_3& a, double x, double z) { return std::abs(a.x() - x) < 1e-12 && std::abs(a.z() - z) < 1e-12; };
  return (on(p, 0., 0.) && on(q, 0., 0.)) || (on(p, fillet_radius, fillet_radius) && on(q, fillet_radius, fillet_radius));
}

void corner_is_floor_fillet_and_wall(const fs_test::Soup& s, std::size_t tangent_edges)
{
  const SM m = fs_test::to_mesh<SM>(s);
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == tangent_edges);
  for(auto e : edges(m))
  {
    BOOST_TEST(seg.is_crease_edge(e) == on_tangent_line(m, e));
    if(seg.is_crease_edge(e)) BOOST_TEST(seg.weight(e) < 0.); // cutting there pays at the default alpha
  }
  BOOST_TEST(seg.number_of_patches() == 3u);
  std::set<std::pair<std::size_t, int> > pairs;
  for(auto f : faces(m)) pairs.insert({ seg.patch(f), part_of(m, f) });
  BOOST_TEST(pairs.size() == 3u); // each face on its own side of both tangent lines
}

} // namespace

BOOST_AUTO_TEST_SUITE(tangent_discontinuities)

BOOST_AUTO_TEST_CASE(filleted_corner_is_its_three_faces_at_two_resolutions)
{
  corner_is_floor_fillet_and_wall(filleted_corner(4), 2 * 4);
  // the same shape subdivided flat: twice the rulings on each tangent line
  fs_test::Soup fine = filleted_corner(4);
  fs_test::subdivide_flat(fine);
  corner_is_floor_fillet_and_wall(fine, 2 * 8);
}

BOOST_AUTO_TEST_CASE(without_them_the_corner_has_no_crease)
{
  const SM m = fs_test::to_mesh<SM>(filleted_corner(4));
  FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::tangent_discontinuities(false));
  BOOST_TEST(seg.number_of_crease_edges() == 0u);
  BOOST_TEST(&seg.working_mesh() == &m); // nothing to cut
}

// A cylinder's strips all bend alike (1/r): no side is a plane, nothing is marked.
BOOST_AUTO_TEST_CASE(cylinder_has_no_discontinuity)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::cylinder(0.5, 1., 24, 6));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 0u);
}

// On fandisk, a clean tessellation cut open along creases, the crest lines weigh less
// than the creases by default: their alpha_e is alpha - 0.5 (0.1 at the default alpha),
// a crease's is alpha; crest_lines_on_clean_tessellations(true) gives them the full
// alpha (the paper's features). Both find the same crest lines. The figures (crease and
// seam edges, crest lines, patches) are those of data/fandisk.json.
BOOST_AUTO_TEST_CASE(clean_tessellation_crest_lines_weigh_less)
{
  using fs_test::fandisk_reference;
  SM m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m));
  FS::Feature_aligned_segmentation<SM> full(m, FS::parameters::crest_lines_on_clean_tessellations(true)), weak(m);
  BOOST_TEST(fandisk_reference("crease_edges") ==
             fandisk_reference("sharp_crease_edges") + fandisk_reference("seam_edges"));
  BOOST_TEST(full.number_of_crease_edges() == fandisk_reference("crease_edges"));
  BOOST_TEST(weak.number_of_crease_edges() == full.number_of_crease_edges());
  BOOST_TEST(full.feature_lines().lines.size() == fandisk_reference("crest_lines"));
  BOOST_TEST(weak.feature_lines().lines.size() == fandisk_reference("crest_lines"));
  BOOST_TEST(weak.number_of_feature_edges() == full.number_of_feature_edges());
  std::size_t crest_edges = 0, crease_edges = 0;
  for(auto e : edges(m))
  {
    if(weak.is_crease_edge(e))
    {
      ++crease_edges;
      BOOST_TEST(weak.alpha(e) == 0.6, boost::test_tools::tolerance(1e-12));
    }
    else if(weak.is_feature_edge(e))
    {
      ++crest_edges;
      BOOST_TEST(weak.alpha(e) == 0.1, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(full.alpha(e) == 0.6, boost::test_tools::tolerance(1e-12));
    }
  }
  BOOST_TEST(crease_edges == fandisk_reference("crease_edges"));
  BOOST_TEST(crest_edges > 0u);
  BOOST_TEST(crest_edges + crease_edges <= weak.number_of_feature_edges()); // counted on the working mesh
  // a global alpha edit moves the crest lines' alpha_e with it, 0.5 below
  weak.set_alpha(1.5);
  for(auto e : edges(m))
    if(weak.is_feature_edge(e) && !weak.is_crease_edge(e))
      BOOST_TEST(weak.alpha(e) == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(FS::Feature_aligned_segmentation<SM>(m).number_of_patches() == fandisk_reference("patches"));
}

BOOST_AUTO_TEST_SUITE_END()
