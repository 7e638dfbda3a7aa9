// The gap test's search (internal/crease_gap_search): the lengths of the crease and band
// edges in the ball of a candidate. The hierarchy of clusters must give the lengths of
// the search face by face, and both the lengths of a cube's edges inside a ball.
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/internal/crease_cut.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>

#include "crease_meshes.h"
#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef FS::internal::Mesh_indexing<SM> Indexing;

// The raw dihedral angles of m's edges.
std::vector<double> raw_angles(const Indexing& idx, const SM& m)
{
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area;
  FS::internal::face_geometry(idx, get(CGAL::vertex_point, m), normal, area, centroid);
  return FS::internal::dihedral_angles(idx, normal);
}

// The lengths of the hierarchical search and of the search face by face for the
// `candidates`, compared one by one (relative 1e-9: only the order of the sums differs).
void check_hierarchy_against_faces(const SM& m, const std::vector<std::size_t>& candidates, double crease_angle,
                                   std::size_t min_levels)
{
  const Indexing idx(m);
  const std::vector<double> angle = raw_angles(idx, m);
  const auto vpm = get(CGAL::vertex_point, m);
  const FS::internal::Edge_geometry geometry = FS::internal::edge_geometry(idx, vpm);
  const FS::internal::Crease_gap_search<SM> search(idx, geometry, angle, angle, crease_angle);
  BOOST_TEST(search.number_of_levels() >= min_levels);
  const auto faces =
    FS::internal::crease_gap_lengths(idx, geometry, angle, angle, crease_angle, candidates, false, 0);
  const auto clusters =
    FS::internal::crease_gap_lengths(idx, geometry, angle, angle, crease_angle, candidates, false);
  std::size_t mismatches = 0, with_crease = 0, with_band = 0;
  for(std::size_t i = 0; i < candidates.size(); ++i)
  {
    const double tol = 1e-9 * (1 + faces[i].crease + faces[i].band);
    if(std::abs(faces[i].crease - clusters[i].crease) > tol || std::abs(faces[i].band - clusters[i].band) > tol)
      ++mismatches;
    with_crease += faces[i].crease > 0;
    with_band += faces[i].band > 0;
  }
  BOOST_TEST_MESSAGE(candidates.size() << " balls on " << num_faces(m) << " faces, " << search.number_of_levels()
                     << " levels: " << with_crease << " with crease edges, " << with_band << " with band edges");
  BOOST_TEST(mismatches == 0u);
  // the balls hold creases and band edges, so the sums were exercised
  BOOST_TEST(with_crease > 0u);
  BOOST_TEST(with_band > 0u);
}

// CGAL's fandisk subdivided flat once (51,784 faces).
SM fandisk_subdivided_once()
{
  std::vector<Epick::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  BOOST_REQUIRE(CGAL::IO::read_polygon_soup(std::string(FS_MESH_DIR) + "/fandisk.off", points, polygons));
  fs_test::Soup s;
  for(const auto& p : points) s.points.push_back({ p.x(), p.y(), p.z() });
  s.faces = polygons;
  fs_test::subdivide_flat(s);
  return fs_test::to_mesh<SM>(s);
}

// A tube of 20 facets round (they bend by 18 degrees, the band at 20), 4 long, one of
// whose rulings is pushed out to bend by 29 degrees.
SM tube_with_one_ruling_pushed_out()
{
  return fs_test::to_mesh<SM>(fs_test::parametric_grid(20, 4, true, false, [](double u, double v) {
    const double a = 2 * 3.14159265358979323846 * u, r = u < 1e-9 ? 1.03 : 1.;
    return std::array<double, 3>{ r * std::cos(a), r * std::sin(a), 4 * v };
  }));
}

// The crease candidates at 20 degrees (edges bending by that much or more), also marked
// 1 in `is_crease`.
std::vector<std::size_t> crease_candidates(const std::vector<double>& angle, std::vector<char>& is_crease)
{
  std::vector<std::size_t> candidates;
  is_crease.assign(angle.size(), 0);
  for(std::size_t e = 0; e < angle.size(); ++e)
    if(angle[e] >= 20) { candidates.push_back(e); is_crease[e] = 1; }
  return candidates;
}

// What the gap test reads of a mesh (its raw angles, its edge geometry) and its crease
// candidates at 20 degrees (crease_candidates()).
struct Gap_inputs
{
  Indexing idx;
  std::vector<double> angle;
  FS::internal::Edge_geometry geometry;
  std::vector<char> is_crease;
  std::vector<std::size_t> candidates;

  explicit Gap_inputs(const SM& m)
    : idx(m), angle(raw_angles(idx, m)), geometry(FS::internal::edge_geometry(idx, get(CGAL::vertex_point, m)))
  {
    candidates = crease_candidates(angle, is_crease);
  }
};

} // namespace

BOOST_AUTO_TEST_SUITE(crease_gap_search)

// A cube of side 4 (mesh edges 0.1): the ball (radius r = 5% of the diagonal, 0.2 sqrt(3))
// around the midpoint of a mesh edge on a cube edge, at distance d < r from a corner,
// holds d + r of that cube edge and sqrt(r^2 - d^2) of each of the two others at the
// corner; farther from the corners, 2r.
BOOST_AUTO_TEST_CASE(cube_edges_inside_a_ball)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::box(4., 4., 4., 40, side));
  const Indexing idx(m);
  const std::vector<double> angle = raw_angles(idx, m);
  const auto vpm = get(CGAL::vertex_point, m);
  const FS::internal::Edge_geometry geometry = FS::internal::edge_geometry(idx, vpm);
  const double r = 0.05 * std::sqrt(48.);
  std::vector<std::size_t> candidates;
  std::vector<double> expected;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    if(angle[e] < 45) continue;
    // an edge along the x axis at y = z = 0
    const auto h = halfedge(idx.edge_at(e), m);
    const auto p = m.point(source(h, m)), q = m.point(target(h, m));
    if(p.y() != 0 || p.z() != 0 || q.y() != 0 || q.z() != 0) continue;
    const double d = (std::min)(0.5 * (p.x() + q.x()), 4 - 0.5 * (p.x() + q.x()));
    candidates.push_back(e);
    expected.push_back(d >= r ? 2 * r : d + r + 2 * std::sqrt(r * r - d * d));
  }
  BOOST_REQUIRE(candidates.size() == 40u);
  for(int levels : { 0, 8 })
  {
    const auto lengths = FS::internal::crease_gap_lengths(idx, geometry, angle, angle, 20., candidates, false, levels);
    for(std::size_t i = 0; i < candidates.size(); ++i)
    {
      BOOST_TEST(lengths[i].crease == expected[i], boost::test_tools::tolerance(1e-9));
      BOOST_TEST(lengths[i].band == 0.);
    }
  }
}

// fandisk subdivided once (51,784 faces): its creases and, in the band below 20 degrees,
// the bends of its blends, at every 50th edge and every crease candidate.
BOOST_AUTO_TEST_CASE(clusters_give_the_lengths_of_the_face_search_on_fandisk)
{
  const SM m = fandisk_subdivided_once();
  const Indexing idx(m);
  const std::vector<double> angle = raw_angles(idx, m);
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    if(angle[e] >= 20 || e % 50 == 0) candidates.push_back(e);
  check_hierarchy_against_faces(m, candidates, 20., 2);
}

// The searches of keep_creases_with_gap() end once their verdict is sure (upper bounds on
// the lengths within each ball, Gap_edge_hierarchy); the verdicts must be those of the whole searches: on
// fandisk subdivided once (its creases pass) and on a coarse tube of 20 facets round,
// which bend by 18 degrees (the band), but for one line pushed out to bend by 29 (its
// candidates fail).
BOOST_AUTO_TEST_CASE(searches_end_once_their_verdict_is_sure)
{
  const SM fandisk = fandisk_subdivided_once();
  const SM tube = tube_with_one_ruling_pushed_out();
  std::size_t total_kept = 0, total_dropped = 0, total_early = 0;
  for(const SM* m : { &fandisk, &tube })
  {
    const Gap_inputs in(*m);
    const auto vpm = get(CGAL::vertex_point, *m);
    std::vector<char> is_crease = in.is_crease;
    const auto full =
      FS::internal::crease_gap_lengths(in.idx, in.geometry, in.angle, in.angle, 20., in.candidates, false);
    const auto bound = FS::internal::crease_gap_length_bounds(in.geometry, in.angle, in.angle, 20., in.candidates);
    // by TBB's threads: the same sums, bit for bit
    const auto threaded =
      FS::internal::crease_gap_length_bounds(in.geometry, in.angle, in.angle, 20., in.candidates, true, true);
    std::size_t same = 0;
    for(std::size_t i = 0; i < bound.size(); ++i)
      same += threaded[i].crease == bound[i].crease && threaded[i].band == bound[i].band;
    BOOST_TEST(same == bound.size());
    std::size_t below_bound = 0, early = 0;
    for(std::size_t i = 0; i < in.candidates.size(); ++i)
    {
      const double tol = 1e-9 * (1 + bound[i].crease + bound[i].band);
      below_bound += full[i].crease <= bound[i].crease + tol && full[i].band <= bound[i].band + tol;
    }
    BOOST_TEST(below_bound == in.candidates.size());
    // and above the clipped lengths of every crease and band edge in the ball, reached
    // or not (brute force over the edges)
    const double r = FS::internal::crease_gap_ball_radius(in.geometry.points, in.geometry.ends);
    std::size_t above_all = 0;
    for(std::size_t i = 0; i < in.candidates.size(); ++i)
    {
      const auto& ends = in.geometry.ends;
      const auto& p = in.geometry.points;
      const std::size_t c = in.candidates[i];
      const Eigen::Vector3d mid = 0.5 * (p[ends[c][0]] + p[ends[c][1]]);
      const Eigen::Vector3d t = (p[ends[c][1]] - p[ends[c][0]]).normalized();
      FS::internal::Gap_lengths all;
      for(std::size_t e = 0; e < ends.size(); ++e)
      {
        const double l = FS::internal::length_in_ball(p[ends[e][0]], p[ends[e][1]], mid, r);
        if(in.angle[e] >= 20.) all.crease += l;
        else if(FS::internal::is_crease_gap_band_edge(in.angle[e], in.angle[e], 20.))
          all.band += l * FS::internal::band_weight(p[ends[e][1]] - p[ends[e][0]], t);
      }
      const double tol = 1e-9 * (1 + all.crease + all.band);
      above_all += all.crease <= bound[i].crease + tol && all.band <= bound[i].band + tol;
    }
    BOOST_TEST(above_all == in.candidates.size());
    // the searches that end early find less than the whole search
    const auto partial = FS::internal::crease_gap_lengths(in.idx, in.geometry, in.angle, in.angle, 20., in.candidates,
                                                          false, 8, true,
                                                          [&](std::size_t i) {
      const FS::internal::Gap_lengths b = bound[i];
      return [b](const FS::internal::Gap_lengths& l) {
        return l.band > 0.5 * b.crease * (1 + 1e-9) || b.band * (1 + 1e-9) < 0.5 * l.crease;
      };
    });
    for(std::size_t i = 0; i < in.candidates.size(); ++i)
      early += partial[i].crease + partial[i].band < full[i].crease + full[i].band;
    FS::internal::keep_creases_with_gap(in.idx, vpm, in.angle, in.angle, 0., 20., is_crease, false);
    std::size_t wrong = 0;
    for(std::size_t i = 0; i < in.candidates.size(); ++i)
    {
      const bool drop = full[i].band > FS::internal::Crease_gap::ratio * full[i].crease;
      wrong += (is_crease[in.candidates[i]] != 0) == drop;
      (drop ? total_dropped : total_kept) += 1;
    }
    BOOST_TEST(wrong == 0u);
    total_early += early;
  }
  BOOST_TEST(total_kept > 0u);
  BOOST_TEST(total_dropped > 0u);
  BOOST_TEST(total_early > 0u);
}

// The hierarchy of the bounds: a ball holding the whole mesh gets the whole lengths (the
// root's sums, exact); a ball of radius 0.01 at the centre of a cube of side 4 (mesh
// edges 0.1), 2 from every face, meets no leaf and gets nothing; a ball of radius 0.2
// around the midpoint of a cube edge's middle mesh edge gets at least its clipped length
// along the edge (0.4) and at most that plus the edges of the leaves near its sphere,
// all on the cube's edges within one leaf's reach (8 mesh edges, 0.8) of the ball.
BOOST_AUTO_TEST_CASE(hierarchy_sums_inside_and_bounds_across)
{
  std::vector<int> side;
  const SM cube = fs_test::to_mesh<SM>(fs_test::box(4., 4., 4., 40, side));
  const Gap_inputs in(cube);
  const FS::internal::Gap_edge_hierarchy h(in.geometry, in.angle, in.angle, 20.);
  std::vector<std::uint32_t> stack;
  const Eigen::Vector3d t = Eigen::Vector3d::UnitX();
  // the cube's 12 edges of length 4 are its creases; nothing is in the band
  const FS::internal::Gap_lengths whole = h.lengths(Eigen::Vector3d(2, 2, 2), 100., t, true, stack);
  BOOST_TEST(whole.crease == 48., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(whole.band == 0.);
  const FS::internal::Gap_lengths none = h.lengths(Eigen::Vector3d(2, 2, 2), 0.01, t, true, stack);
  BOOST_TEST(none.crease == 0.);
  const FS::internal::Gap_lengths across = h.lengths(Eigen::Vector3d(2.05, 0, 0), 0.2, t, true, stack);
  BOOST_TEST(across.crease >= 0.4 - 1e-12);
  BOOST_TEST(across.crease <= 0.4 + 2 * 0.8 + 1e-12);
}

// A zero-length edge, which the face search does not cross: a grid folded by 30 degrees
// (creases) along u = 0.5 and by 16 degrees (the band) along v = 0.7, one of whose
// interior vertices is moved onto its neighbour.
BOOST_AUTO_TEST_CASE(a_zero_length_edge_is_never_crossed_whole)
{
  fs_test::Soup s = fs_test::parametric_grid(60, 60, false, false, [](double u, double v) {
    const double pi = 3.14159265358979323846;
    const double t = std::tan(15. * pi / 180.), t2 = std::tan(16. * pi / 180.);
    return std::array<double, 3>{ u, v, -t * std::abs(u - 0.5) - t2 * (std::max)(0., v - 0.7) };
  });
  // vertex (i, j) = (20, 30) onto (21, 30): the edge between them has length zero
  const std::size_t a = 30 * 61 + 20, b = a + 1;
  s.points[a] = s.points[b];
  const SM m = fs_test::to_mesh<SM>(s);
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < num_edges(m); ++e) candidates.push_back(e);
  check_hierarchy_against_faces(m, candidates, 20., 1);
}

// Only the candidates near a band edge are searched: on a grid folded by 30 degrees along
// u = 0.5 (the creases) and by 16 degrees along v = 0.7 (band edges, 16 >= 0.75 * 20),
// the crease edges within a ball's radius of the band line are, and no other crease
// edge's ball holds any band length; a cube has no band edge, so none is searched.
BOOST_AUTO_TEST_CASE(only_candidates_near_band_edges_are_searched)
{
  const SM m = fs_test::to_mesh<SM>(fs_test::parametric_grid(60, 60, false, false, [](double u, double v) {
    const double pi = 3.14159265358979323846;
    const double t = std::tan(15. * pi / 180.), t2 = std::tan(16. * pi / 180.);
    return std::array<double, 3>{ u, v, -t * std::abs(u - 0.5) - t2 * (std::max)(0., v - 0.7) };
  }));
  const Indexing idx(m);
  const std::vector<double> angle = raw_angles(idx, m);
  const auto vpm = get(CGAL::vertex_point, m);
  const FS::internal::Edge_geometry geometry = FS::internal::edge_geometry(idx, vpm);
  std::vector<std::size_t> candidates;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    if(angle[e] >= 20) candidates.push_back(e);
  BOOST_REQUIRE(candidates.size() == 60u); // the crease line u = 0.5, 60 grid edges
  const std::vector<std::size_t> near =
    FS::internal::candidates_near_band_edges(geometry, angle, angle, 20., candidates);
  const auto lengths = FS::internal::crease_gap_lengths(idx, geometry, angle, angle, 20., candidates, false);
  const double r = FS::internal::Crease_gap_search<SM>(idx, geometry, angle, angle, 20.).radius();
  std::size_t with_band = 0;
  for(std::size_t i = 0; i < candidates.size(); ++i)
  {
    const bool searched = std::find(near.begin(), near.end(), candidates[i]) != near.end();
    with_band += lengths[i].band > 0;
    if(!searched) BOOST_TEST(lengths[i].band == 0.);
    // below the band line (v < 0.7, where the surface is z = -t |u - 0.5|), the nearest
    // band point of a crease edge's midpoint is the folds' crossing (0.5, 0.7, 0): it is
    // searched exactly when 0.7 - v is less than the ball's radius (up to the 1e-6)
    const auto h = halfedge(idx.edge_at(candidates[i]), m);
    const double v = 0.5 * (m.point(source(h, m)).y() + m.point(target(h, m)).y());
    if(v < 0.7)
    {
      if(0.7 - v < r * (1 - 1e-6)) BOOST_TEST(searched);
      if(0.7 - v > r * (1 + 1e-5)) BOOST_TEST(!searched);
    }
  }
  BOOST_TEST(with_band > 0u);
  BOOST_TEST(near.size() < candidates.size());

  std::vector<int> side;
  const SM cube = fs_test::to_mesh<SM>(fs_test::box(4., 4., 4., 10, side));
  const Indexing cidx(cube);
  const std::vector<double> cangle = raw_angles(cidx, cube);
  std::vector<std::size_t> ccandidates;
  for(std::size_t e = 0; e < cidx.number_of_edges(); ++e)
    if(cangle[e] >= 20) ccandidates.push_back(e);
  BOOST_TEST(ccandidates.size() == 120u); // 12 cube edges of 10 mesh edges
  const FS::internal::Edge_geometry cgeometry = FS::internal::edge_geometry(cidx, get(CGAL::vertex_point, cube));
  BOOST_TEST(FS::internal::candidates_near_band_edges(cgeometry, cangle, cangle, 20., ccandidates).empty());
}

// The band weighs by direction (band_weight): a band edge counts its length in the ball
// times the squared cosine of its angle with the candidate.
// - A rod of radius 1 and length 40, 20 facets round (its rulings bend by 18 degrees, in
//   the band) and flat ends: the rulings run across the ends' 90-degree ring edges
//   (cosine 0), so the band of every ring edge's ball is 0 though its rulings' length
//   there exceeds half the ring's: the 40 ring edges pass the test, with no exception for
//   strong bends (keep_from 360). Counted whole (by_direction false, as on a smooth
//   model), the rulings make the ring edges fail.
// - A tube of 20 facets with one ruling pushed out to bend by 29 degrees: its candidates
//   run along the band rulings (cosine 1), which count whole, and it fails the test.
BOOST_AUTO_TEST_CASE(band_edges_weigh_by_the_squared_cosine_of_their_angle)
{
  std::vector<int> side;
  const SM rod = fs_test::to_mesh<SM>(fs_test::closed_rod([](double, double) { return 1.; }, 40., 20, 80, side));
  const SM tube = tube_with_one_ruling_pushed_out();
  for(const SM* m : { &rod, &tube })
  {
    const Gap_inputs in(*m);
    const auto vpm = get(CGAL::vertex_point, *m);
    std::vector<char> is_crease = in.is_crease;
    BOOST_REQUIRE(in.candidates.size() == (m == &rod ? 40u : 4u));
    const double r = FS::internal::Crease_gap_search<SM>(in.idx, in.geometry, in.angle, in.angle, 20.).radius();
    for(int levels : { 0, 8 })
    {
      const auto lengths =
        FS::internal::crease_gap_lengths(in.idx, in.geometry, in.angle, in.angle, 20., in.candidates, false, levels);
      for(std::size_t i = 0; i < in.candidates.size(); ++i)
      {
        // every band edge in the ball, unweighted (the ball's surface is connected here)
        const auto& ends = in.geometry.ends[in.candidates[i]];
        const Eigen::Vector3d c = 0.5 * (in.geometry.points[ends[0]] + in.geometry.points[ends[1]]);
        double band = 0;
        for(std::size_t e = 0; e < in.idx.number_of_edges(); ++e)
          if(FS::internal::is_crease_gap_band_edge(in.angle[e], in.angle[e], 20.))
            band += FS::internal::length_in_ball(in.geometry.points[in.geometry.ends[e][0]],
                                                 in.geometry.points[in.geometry.ends[e][1]], c, r);
        BOOST_TEST(band > FS::internal::Crease_gap::ratio * lengths[i].crease);
        if(m == &rod)
          BOOST_TEST(lengths[i].band <= 1e-12 * band);
        else
          BOOST_TEST(lengths[i].band == band, boost::test_tools::tolerance(1e-9));
      }
    }
    std::vector<char> whole = is_crease; // the band counted whole (by_direction false)
    FS::internal::keep_creases_with_gap(in.idx, vpm, in.angle, in.angle, 0., 20., is_crease, false);
    const std::size_t kept = std::size_t(std::count(is_crease.begin(), is_crease.end(), char(1)));
    BOOST_TEST(kept == (m == &rod ? 40u : 0u));
    FS::internal::keep_creases_with_gap(in.idx, vpm, in.angle, in.angle, 0., 20., whole, false, 360., false);
    BOOST_TEST(std::count(whole.begin(), whole.end(), char(1)) == 0); // the rod's ends too fail
  }
}

BOOST_AUTO_TEST_SUITE_END()
