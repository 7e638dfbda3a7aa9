// The scale of the features is a length, not a ring count: the same shape tessellated
// finer gives the same patches. CGAL's fandisk against its flat subdivision (each
// triangle into 16, same geometry): with rings alone, the fits on the fine mesh see the
// flat facets of the coarse one and the kinks between them (with its crest lines at the
// full alpha: 7 on the coarse mesh, 36 on the fine one; 26 with the default radius).
// The curvature discontinuities (the tangent lines of fandisk's blends) are a rule on
// flat regions, areas and angles (fandisk has no flat region of one or two triangles at
// a bend), and the gap test of the creases measures lengths inside a ball, so the fine
// mesh has the same creases and discontinuities, each edge split in four, and the same
// patches (data/fandisk.json: the creases and discontinuities bound fandisk's faces,
// and one crest line splits its curved side).
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include "fandisk_reference.h"
#include "test_meshes.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;

fs_test::Soup read_soup(const std::string& file)
{
  std::vector<Epick::Point_3> points;
  std::vector<std::vector<std::size_t> > faces;
  BOOST_REQUIRE(CGAL::IO::read_polygon_soup(file, points, faces));
  fs_test::Soup s;
  for(const auto& p : points) s.points.push_back({ p.x(), p.y(), p.z() });
  s.faces = faces;
  return s;
}

} // namespace

BOOST_AUTO_TEST_SUITE(resolution)

BOOST_AUTO_TEST_CASE(fandisk_and_its_subdivision_give_the_same_patches)
{
  fs_test::Soup coarse_soup = read_soup(std::string(FS_MESH_DIR) + "/fandisk.off");
  fs_test::Soup fine_soup = coarse_soup;
  fs_test::subdivide_flat(fine_soup);
  fs_test::subdivide_flat(fine_soup); // face f of the coarse mesh: faces 16f .. 16f+15
  const SM coarse = fs_test::to_mesh<SM>(coarse_soup), fine = fs_test::to_mesh<SM>(fine_soup);
  BOOST_REQUIRE(num_faces(fine) == 16 * num_faces(coarse));
  FS::Feature_aligned_segmentation<SM> a(coarse), b(fine);
  BOOST_TEST_MESSAGE("fandisk: " << a.number_of_patches() << " patches at " << num_faces(coarse)
                     << " faces, " << b.number_of_patches() << " at " << num_faces(fine));
  BOOST_TEST(a.number_of_patches() == fs_test::fandisk_reference("patches"));
  // each crease edge in four: the gap test measures the lengths of the crease and band
  // edges inside its ball, which flat subdivision keeps. A lone crease edge of the coarse
  // mesh (both ends inside the surface) cuts nothing and is no crease, while its four
  // pieces on the fine mesh form a slit whose middle vertices are cut: fandisk has two.
  BOOST_TEST(b.number_of_crease_edges() ==
             4 * (a.number_of_crease_edges() + fs_test::fandisk_reference("lone_crease_edges")));
  BOOST_TEST(b.number_of_patches() == a.number_of_patches());

  // The partitions agree: the pairs (coarse patch, fine patch) over the coarse faces and
  // their 16 children, weighted by count, are dominated by one fine patch per coarse one.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> pairs;
  std::size_t f = 0;
  for(auto cf : faces(coarse))
  {
    for(std::size_t k = 0; k < 16; ++k)
      ++pairs[{ a.patch(cf), b.patch(SM::Face_index(SM::size_type(16 * f + k))) }];
    ++f;
  }
  std::map<std::size_t, std::size_t> best; // coarse patch -> largest overlap
  for(const auto& p : pairs) best[p.first.first] = std::max(best[p.first.first], p.second);
  std::size_t agree = 0;
  for(const auto& p : best) agree += p.second;
  const double share = double(agree) / double(num_faces(fine));
  BOOST_TEST_MESSAGE("fine faces in the fine patch that best matches their coarse patch: " << share);
  BOOST_TEST(share > 0.95);
}

BOOST_AUTO_TEST_SUITE_END()
