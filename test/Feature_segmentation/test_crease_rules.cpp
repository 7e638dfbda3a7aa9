// The rules of the crease cut: when normals are filtered and how far (and the filters'
// range Gaussian), the crease angle's checks, long thin parts, the weight of crest
// lines on CAD parts, and faces that the creases isolate. Exact answers on boxes and rods
// whose faces are known.
#include <boost/test/unit_test.hpp>

#include "crease_meshes.h"
#include "crease_test_geometry.h"

#include <CGAL/boost/graph/Euler_operations.h>

#include <array>

BOOST_AUTO_TEST_SUITE(crease_rules)

namespace {

// The raw face normals of a mesh, what the normal filter reads, and their roughness.
struct Normal_field
{
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area;
  std::vector<std::uint32_t> begin, ring;
  double roughness = 0;

  explicit Normal_field(const SM& m)
  {
    const FS::internal::Mesh_indexing<SM> idx(m);
    FS::internal::face_geometry(idx, get(CGAL::vertex_point, m), normal, area, centroid);
    FS::internal::vertex_adjacent_faces(idx, begin, ring);
    roughness = FS::internal::normal_roughness(normal, begin, ring);
  }
};

} // namespace

BOOST_AUTO_TEST_CASE(face_rings_are_the_faces_sharing_a_vertex)
{
  // against a search over all pairs of faces, in increasing order, on a closed box and
  // on a disc with a border (the box without its top); and the same normals and angles
  // by two threads as by one
  std::vector<int> side;
  SM box = fs_test::to_mesh<SM>(fs_test::box(1., 2., 0.5, 4, side));
  SM open = box;
  for(auto f : faces(box))
    if(side[f.idx()] == 5) CGAL::Euler::remove_face(halfedge(f, open), open); // the same indices in the copy
  open.collect_garbage();
  BOOST_TEST(!CGAL::is_closed(open));
  for(const SM* m : { &box, &open })
  {
    const FS::internal::Mesh_indexing<SM> idx(*m);
    std::vector<std::uint32_t> begin, ring;
    FS::internal::vertex_adjacent_faces(idx, begin, ring);
    const std::size_t nf = idx.number_of_faces();
    BOOST_TEST_REQUIRE(begin.size() == nf + 1);
    std::vector<std::set<std::size_t> > corners(nf);
    for(std::size_t f = 0; f < nf; ++f)
      for(auto v : CGAL::vertices_around_face(halfedge(idx.face_at(f), *m), *m)) corners[f].insert(idx.id(v));
    std::size_t wrong = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      std::vector<std::uint32_t> expected;
      for(std::size_t g = 0; g < nf; ++g)
        if(std::any_of(corners[g].begin(), corners[g].end(), [&](std::size_t v) { return corners[f].count(v) > 0; }))
          expected.push_back(std::uint32_t(g));
      if(!std::equal(expected.begin(), expected.end(), ring.begin() + begin[f], ring.begin() + begin[f + 1]) ||
         expected.size() != begin[f + 1] - begin[f])
        ++wrong;
    }
    BOOST_TEST(wrong == 0u);
    std::vector<Eigen::Vector3d> n1, c1, n2, c2;
    std::vector<double> a1, a2;
    FS::internal::face_geometry(idx, get(CGAL::vertex_point, *m), n1, a1, c1, false);
    FS::internal::face_geometry(idx, get(CGAL::vertex_point, *m), n2, a2, c2, true);
    BOOST_TEST((n1 == n2 && a1 == a2 && c1 == c2));
    BOOST_TEST((FS::internal::dihedral_angles(idx, n1, false) == FS::internal::dihedral_angles(idx, n1, true)));
  }
}

BOOST_AUTO_TEST_CASE(clean_box_is_not_filtered)
{
  // every face of a clean box has a neighbour with its own normal: the roughness is 0,
  // no round of filtering runs, and the creases are those of the raw angles
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::box(1., 2., 0.1, 5, side));
  FS::Feature_aligned_segmentation<SM> raw(m, FS::parameters::crease_angle(20.).crease_filter_iterations(0));
  FS::Feature_aligned_segmentation<SM> filtered(m, FS::parameters::crease_angle(20.));
  BOOST_TEST(raw.number_of_crease_edges() == 60u);
  BOOST_TEST(filtered.number_of_crease_edges() == 60u);
  for(auto e : edges(m)) BOOST_TEST(raw.is_crease_edge(e) == filtered.is_crease_edge(e));
}

// The filter with a stop measures the roughness inside its rounds (one pass over the
// pairs); the result must be that of running exactly the rounds after which the
// roughness, measured on its own, first falls to the stop.
BOOST_AUTO_TEST_CASE(filter_stops_after_the_round_that_makes_the_normals_smooth)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_box(0.004, 16, side));
  const Normal_field field(m);
  const auto& [normal, centroid, area, begin, ring, r0] = field;
  const double stop = 0.1 * r0;
  // the rounds needed, one at a time, measured by normal_roughness
  int rounds = 0;
  std::vector<Eigen::Vector3d> n = normal;
  while(FS::internal::normal_roughness(n, begin, ring) > stop && rounds < 40)
  {
    n = FS::internal::filter_face_normals(n, 1., area, centroid, begin, ring, 1, 0.3, 0.);
    ++rounds;
  }
  BOOST_TEST_MESSAGE("noisy box: roughness " << r0 << ", down to a tenth after " << rounds << " rounds");
  BOOST_TEST(rounds >= 2);
  BOOST_TEST(rounds < 40);
  const auto stopped = FS::internal::filter_face_normals(normal, r0, area, centroid, begin, ring, 40, 0.3, stop);
  const auto exact = FS::internal::filter_face_normals(normal, r0, area, centroid, begin, ring, rounds, 0.3, 0.);
  const auto fewer = FS::internal::filter_face_normals(normal, r0, area, centroid, begin, ring, rounds - 1, 0.3, 0.);
  BOOST_TEST((stopped == exact));
  BOOST_TEST((stopped != fewer));
}

// The range Gaussian of both normal filters: read from its table within 4e-6 of the
// exponential over the differences of unit normals (|n_f - n_g|^2 in [0, 4]), the
// exponential itself beyond (the gradient filter's carried normals), 1 at 0.
BOOST_AUTO_TEST_CASE(range_gaussian_matches_the_exponential)
{
  const double sigma_r = 0.3, inv = 1. / (2 * sigma_r * sigma_r);
  const FS::internal::Range_gaussian range(sigma_r);
  BOOST_TEST(range(0.) == 1.);
  double worst = 0.;
  for(int k = 0; k <= 40000; ++k)
  {
    const double d2 = 4. * k / 40000. + (k % 7) * 1e-6;
    worst = (std::max)(worst, std::abs(range(d2) / std::exp(-d2 * inv) - 1.));
  }
  BOOST_TEST(worst < 4e-6);
  BOOST_TEST(worst > 0.); // a table, not the exponential
  for(double d2 : {4., 4.5, 9.})
    BOOST_TEST(range(d2) == std::exp(-d2 * inv));
}

BOOST_AUTO_TEST_CASE(bad_crease_angle_is_refused)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::box(1., 1., 1., 2, side));
  BOOST_CHECK_THROW(FS::Feature_aligned_segmentation<SM>(m, FS::parameters::crease_angle(0.)), FS::Invalid_input);
  BOOST_CHECK_THROW(FS::Feature_aligned_segmentation<SM>(m, FS::parameters::crease_angle(-5.)), FS::Invalid_input);
  BOOST_CHECK_THROW(FS::Feature_aligned_segmentation<SM>(m, FS::parameters::crease_angle(std::nan(""))),
                    FS::Invalid_input);
  BOOST_CHECK_THROW(FS::Feature_aligned_segmentation<SM>(m, FS::parameters::crease_angle(20.).crease_filter_iterations(-1)),
                    FS::Invalid_input);
  BOOST_CHECK_THROW(FS::Feature_aligned_segmentation<SM>(m, FS::parameters::crease_angle(20.).crease_filter_iterations(1001)),
                    FS::Invalid_input);
}


// A rod forty times longer than its radius (length 40, radius 1), 20 facets round it
// (18 degrees between neighbours, in the gap test's band) and flat ends. The ball of the
// gap test (5% of the diagonal, about the rod's width) around an end's 90-degree crease
// holds more band length along the side than crease length round the end; a bend of 85
// degrees or more on a clean tessellation is a crease whatever its ball holds, so the
// rod is its side and its two ends.
BOOST_AUTO_TEST_CASE(the_ends_of_a_long_rod_are_creases)
{
  const int around = 20;
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::closed_rod([](double, double) { return 1.; }, 40., around, 80, side));
  BOOST_REQUIRE(CGAL::is_closed(m) && CGAL::is_triangle_mesh(m));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == std::size_t(2 * around)); // the two end rings only
  BOOST_TEST(seg.number_of_patches() == 3u);
  BOOST_TEST(fs_test::patches_are_sides(m, seg, side, 3));
}

// The same rod with light noise: every vertex of the side moved along its radius by up
// to +-0.01 (add_noise_along()), the ends left planar. Its roughness (0.012) is above a
// clean tessellation's and below a noisy mesh's, so its bends are tested on the raw
// angles, where the side's 18-degree bends and the noise around them fill the band
// round the ends; a bend of 85 degrees or more is a crease on every mesh, so the two end
// rings stay creases (without that rule on rough meshes, no crease is left at all).
BOOST_AUTO_TEST_CASE(the_ends_of_a_lightly_noisy_long_rod_are_creases)
{
  const int around = 20;
  std::vector<int> side;
  fs_test::Soup s = fs_test::closed_rod([](double, double) { return 1.; }, 40., around, 80, side);
  std::vector<std::array<double, 3> > radial;
  for(const auto& p : s.points)
  {
    const double r = std::hypot(p[0], p[1]);
    radial.push_back(r > 0 ? std::array<double, 3>{ p[0] / r, p[1] / r, 0. } : std::array<double, 3>{ 0., 0., 0. });
  }
  fs_test::add_noise_along(s, radial, 0.01);
  const SM m = fs_test::to_mesh<SM>(s);
  const FS::internal::Mesh_indexing<SM> idx(m);
  const fs_test::Detected_creases detected = fs_test::detect_creases_at_defaults(idx);
  BOOST_TEST(!detected.clean);
  const fs_test::Face_geometry g = fs_test::face_geometry_of(idx);
  const double roughness = FS::internal::normal_roughness(g.normal, g.begin, g.ring);
  BOOST_TEST_MESSAGE("roughness " << roughness);
  BOOST_TEST(roughness > FS::internal::crease_filter_roughness);
  BOOST_TEST(roughness < FS::internal::Crease_gap::raw_roughness);
  std::size_t ring = 0, other = 0;
  for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
  {
    if(!detected.is_crease[e]) continue;
    const auto h = halfedge(idx.edge_at(e), m);
    const int a = side[idx.face_id(h)], b = side[idx.face_id(opposite(h, m))];
    (a != b ? ring : other) += 1;
  }
  BOOST_TEST(ring == std::size_t(2 * around)); // both end rings whole
  BOOST_TEST(other == 0u);
}

// A clean tessellation whose creases cut it into its faces is a CAD part: its crest lines
// weigh alpha - 0.5. One whose creases leave a piece of 90% of the surface or more, with
// no large planar region (no plane, no ruled strip), is a smooth model with a few creases
// (a remeshed or subdivided one): its crest lines are its features and keep the full
// alpha. A rod whose cross-section has four lobes and whose girth swells and shrinks
// along it (by 10%, every 10 units): its side carries the lobes' four ridges and four
// valleys along its length, each of its quadrilaterals is planar but no two of them
// share a plane; its ends are creases. (A plain rod, ruled, is a CAD part whatever its
// length: the_ends_of_a_long_rod_are_creases.)
BOOST_AUTO_TEST_CASE(crest_lines_weigh_less_on_a_cad_part_only)
{
  const auto lobes = [](double a, double z) {
    return (1. + 0.2 * std::cos(4 * a)) * (1. + 0.1 * std::sin(2 * M_PI * z / 10.));
  };
  std::vector<int> side;
  struct Result { std::size_t patches; double least_crest_alpha, most_crest_alpha; };
  const auto run = [&](double length, bool full_alpha) {
    const SM m = fs_test::to_mesh<SM>(fs_test::closed_rod(lobes, length, 96, int(4 * length), side));
    FS::Feature_aligned_segmentation<SM> seg(
      m, FS::parameters::crest_lines_on_clean_tessellations(full_alpha));
    BOOST_TEST(seg.number_of_crease_edges() == 192u); // the two end rings (the side bends by 14 degrees at most)
    Result r{seg.number_of_patches(), 1e300, -1e300};
    for(auto e : edges(m))
      if(seg.is_feature_edge(e) && !seg.is_crease_edge(e))
      {
        r.least_crest_alpha = (std::min)(r.least_crest_alpha, seg.alpha(e));
        r.most_crest_alpha = (std::max)(r.most_crest_alpha, seg.alpha(e));
      }
    BOOST_TEST(r.least_crest_alpha <= r.most_crest_alpha); // it has crest lines
    return r;
  };
  // short: the side is 68% of the surface (the ends' areas 1.02 pi = 3.20 and 3.84 at
  // heights 0 and 2, the side's perimeter 7.20 swelling by up to 9.5% over the length 2):
  // the creases cut it into its faces, its crest lines weigh 0.6 - 0.5
  const Result short_default = run(2., false), short_full = run(2., true);
  BOOST_TEST(short_default.least_crest_alpha == 0.1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(short_default.most_crest_alpha == 0.1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(short_full.least_crest_alpha == 0.6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(short_default.patches == 3u); // the side and the two ends
  // long (the side 99% of the surface, no two quadrilaterals in one plane): a smooth rod,
  // its crest lines at the full alpha either way, and they bound patches of its side
  const Result long_default = run(100., false), long_full = run(100., true);
  BOOST_TEST(long_default.least_crest_alpha == 0.6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(long_default.most_crest_alpha == 0.6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(long_default.patches > 3u);
  BOOST_TEST(long_default.patches == long_full.patches);
}

namespace {

// A rod of radius 1 and the given length (48 facets round, 4 rings per unit of length),
// every vertex inside its side moved radially by a seeded uniform amount of up to 3% of
// the radius (the end rings stay, so the ends keep their 90-degree creases).
SM noisy_rod(double length, std::vector<int>& side)
{
  fs_test::Soup s = fs_test::closed_rod([](double, double) { return 1.; }, length, 48, int(4 * length), side);
  unsigned long long state = 2024;
  for(std::size_t v = 0; v + 2 < s.points.size(); ++v) // not the two centres of the ends
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = double(state >> 11) / double(1ULL << 53); // [0, 1)
    if(!(s.points[v][2] > 0. && s.points[v][2] < length)) continue;
    const double f = 1. + 0.03 * (2 * u - 1);
    s.points[v][0] *= f;
    s.points[v][1] *= f;
  }
  return fs_test::to_mesh<SM>(s);
}

// The least and the most alpha_e of the crest-line edges (feature edges that are no
// creases) of `seg`; the least is above the most if there are none.
std::pair<double, double> crest_alphas(const SM& m, const FS::Feature_aligned_segmentation<SM>& seg)
{
  double least = 1e300, most = -1e300;
  for(auto e : edges(m))
    if(seg.is_feature_edge(e) && !seg.is_crease_edge(e))
    {
      least = (std::min)(least, seg.alpha(e));
      most = (std::max)(most, seg.alpha(e));
    }
  return { least, most };
}

// The crease edges of `seg` between a face of side `label` and a face of another side.
std::size_t creases_around(const SM& m, const FS::Feature_aligned_segmentation<SM>& seg,
                           const std::vector<int>& side, int label)
{
  std::size_t n = 0;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m);
    if(is_border_edge(h, m)) continue;
    const int a = side[face(h, m).idx()], b = side[face(opposite(h, m), m).idx()];
    if((a == label) != (b == label) && seg.is_crease_edge(e)) ++n;
  }
  return n;
}

} // namespace

// A noisy tessellation is not clean, and has no exactly planar region to tell a CAD part
// by; its creases, found on the filtered normals, still cut it into its faces. The noisy
// rod of length 4 (noise of 0.6% of the diagonal): its creases are the two end rings,
// which cut it into the side (80% of the area: 8 pi against pi for each end) and the two
// ends; its crest lines, which the noise strews along the side, weigh 0.6 - 0.5 (0.6
// with crest_lines_on_clean_tessellations(true)). Either way the side is one patch.
BOOST_AUTO_TEST_CASE(crest_lines_weigh_less_on_a_noisy_cad_part)
{
  std::vector<int> side;
  const SM m = noisy_rod(4., side);
  for(bool full_alpha : {false, true})
  {
    FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::crest_lines_on_clean_tessellations(full_alpha));
    BOOST_TEST(seg.number_of_crease_edges() == 96u);
    const auto [least, most] = crest_alphas(m, seg);
    BOOST_TEST(least <= most); // it has crest lines
    BOOST_TEST(least == (full_alpha ? 0.6 : 0.1), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(most == (full_alpha ? 0.6 : 0.1), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(seg.number_of_patches() == 3u);
    BOOST_TEST(fs_test::patches_are_sides(m, seg, side, 3));
  }
}

// On a noisy mesh the crest lines weigh less even where the creases cut nothing apart:
// the noisy rod of length 40 (its side 97.6% of the area: 80 pi against pi for each end)
// is noisy (raw roughness above Crease_gap::raw_roughness), so its crest lines along the
// side weigh 0.6 - 0.5 and the side is one patch.
BOOST_AUTO_TEST_CASE(crest_lines_weigh_less_on_a_noisy_mesh_its_creases_do_not_cut)
{
  std::vector<int> side;
  const SM m = noisy_rod(40., side);
  BOOST_TEST_REQUIRE(Normal_field(m).roughness > FS::internal::Crease_gap::raw_roughness);
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 96u);
  const auto [least, most] = crest_alphas(m, seg);
  BOOST_TEST(least <= most); // it has crest lines
  BOOST_TEST(least == 0.1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(most == 0.1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(seg.number_of_patches() == 3u);
  BOOST_TEST(fs_test::patches_are_sides(m, seg, side, 3));
}

// A face cut out alone by its three creases is no patch of its own: it joins the side it
// bends least from (x=1, 35.3 degrees), and the part is the cube's six sides.
BOOST_AUTO_TEST_CASE(a_face_isolated_by_creases_joins_its_flattest_neighbour)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::cube_with_a_cut_corner(side));
  BOOST_REQUIRE(CGAL::is_closed(m) && CGAL::is_triangle_mesh(m));
  FS::Feature_aligned_segmentation<SM> seg(m);
  std::vector<int> joined = side;
  for(int& k : joined) if(k == 6) k = 1;
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(fs_test::patches_are_sides(m, seg, joined, 6));
  // the two creases of 65.9 degrees stay, the one of 35.3 is cleared
  BOOST_TEST(creases_around(m, seg, side, 6) == 2u);
}

// Two faces cut out together by their creases (a chamfer quad of two triangles) are no
// patch of their own either: they join the side they bend least from (y=1, 26.6
// degrees), and the part is the cube's six sides, which are quads of two triangles too
// but bend by 90 degrees from every neighbour. No face of the development data's ground
// truth has fewer than three triangles.
BOOST_AUTO_TEST_CASE(two_faces_isolated_by_creases_join_their_flattest_neighbour)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::cube_with_a_chamfered_edge(side));
  BOOST_REQUIRE(CGAL::is_closed(m) && CGAL::is_triangle_mesh(m));
  BOOST_REQUIRE(std::count(side.begin(), side.end(), 6) == 2);
  FS::Feature_aligned_segmentation<SM> seg(m);
  std::vector<int> joined = side;
  for(int& k : joined) if(k == 6) k = 3;
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(fs_test::patches_are_sides(m, seg, joined, 6));
  // the chamfer keeps its creases of 63.4 and 90 degrees (to x=1: 1 edge; to z=0 and
  // z=1: 1 edge each); the one of 26.6 to y=1 is cleared
  BOOST_TEST(creases_around(m, seg, side, 6) == 3u);
}

// On a rough mesh a piece of up to crease_noisy_piece_max_faces (15) faces cut out by
// creases joins the neighbour it bends least from, whatever the bend (noise cuts such
// pieces out far more often than a part's faces do); on a clean one only pieces of one
// or two faces do. A 6 x 6 grid of a square with the creases around a block of 2 x 2
// cells (8 faces, 8 creases, all 90 degrees but the first edge's 70), 2 x 3 cells (12
// faces, 10 creases) and 2 x 4 cells (16 faces, 12 creases, which stays).
BOOST_AUTO_TEST_CASE(pieces_of_up_to_fifteen_faces_join_on_a_rough_mesh)
{
  BOOST_REQUIRE(FS::internal::crease_noisy_piece_max_faces == 15u);
  const SM m = fs_test::to_mesh<SM>(fs_test::plane(1., 6));
  const FS::internal::Mesh_indexing<SM> idx(m);
  const std::array<double, 2> blocks[] = { { -1. / 3, 1. / 3 }, { -1. / 3, 2. / 3 }, { -2. / 3, 2. / 3 } };
  const std::size_t expected_creases[] = { 8, 10, 12 };
  for(std::size_t b = 0; b < 3; ++b)
  {
    const double bottom = blocks[b][0], top = blocks[b][1];
    auto inside = [&](std::size_t f) {
      double x = 0, y = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(idx.face_at(f), m), m))
      {
        x += m.point(v).x() / 3;
        y += m.point(v).y() / 3;
      }
      return std::abs(x) < 1. / 3 && y > bottom && y < top;
    };
    std::vector<char> is_crease(idx.number_of_edges(), 0);
    std::vector<double> angle(idx.number_of_edges(), 0.);
    std::size_t first = idx.npos, creases = 0;
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      const auto h = halfedge(idx.edge_at(e), m);
      const std::size_t f = idx.face_id(h), g = idx.face_id(opposite(h, m));
      if(f == idx.npos || g == idx.npos || inside(f) == inside(g)) continue;
      is_crease[e] = 1;
      angle[e] = first == idx.npos ? 70. : 90.;
      if(first == idx.npos) first = e;
      ++creases;
    }
    BOOST_REQUIRE(creases == expected_creases[b]);
    std::vector<char> clean = is_crease;
    BOOST_TEST(FS::internal::join_isolated_crease_faces(idx, angle, clean) == 0u);
    std::vector<char> rough = is_crease;
    const std::size_t cleared = FS::internal::join_isolated_crease_faces(
      idx, angle, rough, FS::internal::crease_noisy_piece_max_faces, 180.);
    if(b < 2)
    {
      BOOST_TEST(cleared == 1u);
      BOOST_TEST(rough[first] == 0);
      BOOST_TEST(std::size_t(std::count(rough.begin(), rough.end(), 1)) == creases - 1);
    }
    else
      BOOST_TEST(cleared == 0u);
  }
}

// The rounds of filtering a noisy mesh gets: 40 * (roughness / 0.15)^3 rounded up, at
// least 5 and at most the given number.
BOOST_AUTO_TEST_CASE(noisy_meshes_get_rounds_growing_with_the_cube_of_their_roughness)
{
  using FS::internal::noisy_filter_rounds;
  BOOST_TEST(noisy_filter_rounds(0.15, 40) == 40);  // the full roughness
  BOOST_TEST(noisy_filter_rounds(0.3, 40) == 40);   // capped
  BOOST_TEST(noisy_filter_rounds(0.12, 40) == 21);  // 40 * 0.512 = 20.48
  BOOST_TEST(noisy_filter_rounds(0.1, 40) == 12);   // 40 * 8 / 27 = 11.85
  BOOST_TEST(noisy_filter_rounds(0.075, 40) == 5);  // 40 / 8
  BOOST_TEST(noisy_filter_rounds(0.035, 40) == 5);  // the least
  BOOST_TEST(noisy_filter_rounds(0.1, 3) == 3);     // the user's fewer rounds
  BOOST_TEST(noisy_filter_rounds(1e300, 40) == 40); // no overflow
}

// A face at a border, cut out by the creases of the edges it shares (here its only one),
// joins its flattest neighbour too: a 4 x 4 grid of a square with a triangle folded up
// by 60 degrees along one edge of its border is one patch, and that edge no crease.
BOOST_AUTO_TEST_CASE(a_border_face_isolated_by_creases_joins_its_flattest_neighbour)
{
  const int n = 4;
  fs_test::Soup s = fs_test::plane(1., n);
  // the top border runs from (i, n) to (i + 1, n), points n (n + 1) + i, at y = 1
  const std::size_t p = std::size_t(n * (n + 1) + 1), q = p + 1;
  const double x = 0.5 * (s.points[p][0] + s.points[q][0]);
  s.points.push_back({x, 1. + 0.25 * std::cos(M_PI / 3), 0.25 * std::sin(M_PI / 3)});
  s.faces.push_back({p, q, s.points.size() - 1});
  const SM m = fs_test::to_mesh<SM>(s);
  BOOST_REQUIRE(CGAL::is_triangle_mesh(m) && num_faces(m) == std::size_t(2 * n * n + 1));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 0u);
  BOOST_TEST(seg.number_of_patches() == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
