// Creases (CAD tessellations): the segmentation cut open along edges whose faces bend by
// crease_angle or more (20 degrees, the default; 180 is none). Boxes give exact answers: their six faces, whatever the
// resolution and however thin the box, with every triangle on its own side.
#include <boost/test/unit_test.hpp>
#include <boost/property_map/property_map.hpp>

#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/internal/crease_cut.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_meshes.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Surface_mesh<Epick::Point_3> SM;
typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double> > Poly;

// Whether the face patches are exactly the sides of a box (or any solid with
// `number_of_sides` faces): as many patches as sides, and two faces share a patch if and
// only if they share a side.
template <typename Mesh, typename PatchOf>
bool patches_are_sides(const Mesh& m, PatchOf patch_of, const std::vector<int>& side, std::size_t number_of_sides)
{
  std::set<std::pair<std::size_t, int> > pairs;
  std::set<std::size_t> patches;
  std::size_t i = 0;
  for(auto f : faces(m))
  {
    pairs.insert({ patch_of(f), side[i++] });
    patches.insert(patch_of(f));
  }
  return pairs.size() == number_of_sides && patches.size() == number_of_sides;
}

template <typename Mesh>
bool patches_are_sides(const Mesh& m, const FS::Feature_aligned_segmentation<Mesh>& seg,
                       const std::vector<int>& side, std::size_t number_of_sides = 6)
{
  return patches_are_sides(m, [&](auto f) { return seg.patch(f); }, side, number_of_sides);
}

template <typename Mesh>
void box_is_its_six_sides(double a, double b, double c, int n)
{
  std::vector<int> side;
  const Mesh m = fs_test::to_mesh<Mesh>(fs_test::box(a, b, c, n, side));
  FS::Feature_aligned_segmentation<Mesh> seg(m, FS::parameters::crease_angle(20.));
  // the 12 box edges, n mesh edges each; the flat diagonals bend by 0 degrees
  BOOST_TEST(seg.number_of_crease_edges() == std::size_t(12 * n));
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(patches_are_sides(m, seg, side));
  // the working mesh: the box cut open along its 12 edges, the 8 corners in 3 copies
  // and the other box-edge vertices in 2
  const std::size_t nv = num_vertices(m);
  BOOST_TEST(num_vertices(seg.working_mesh()) == nv + 8 * 2 + 12 * (n - 1));
  BOOST_TEST(num_faces(seg.working_mesh()) == num_faces(m));
  std::size_t creases = 0;
  for(auto e : edges(m))
    if(seg.is_crease_edge(e))
    {
      ++creases;
      // cutting along a 90 degree crease is rewarded at the default alpha
      BOOST_TEST(seg.weight(e) < 0.);
      BOOST_TEST(seg.alpha(e) == 0.6);
    }
  BOOST_TEST(creases == std::size_t(12 * n));
}

// The plate [0,1]x[0,0.6]x[0,0.2] pierced by a slot [0.45,0.46]x[0.1,0.5], each grid cell
// refined `refine` times in x and y (and the walls in as many layers): the slot is 0.01
// wide, narrower than the curvature fit's radius (1% of the diagonal, 0.0118), and its
// walls face each other across it.
template <typename Mesh>
void slotted_plate_is_its_ten_faces(int refine)
{
  auto breakpoints = [&](std::vector<double> v) {
    std::vector<double> r;
    for(std::size_t i = 0; i + 1 < v.size(); ++i)
      for(int k = 0; k < refine; ++k) r.push_back(v[i] + (v[i + 1] - v[i]) * k / refine);
    r.push_back(v.back());
    return r;
  };
  const std::vector<double> xs = breakpoints({0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.46, 0.5, 0.6, 0.7, 0.8, 0.9, 1.});
  const std::vector<double> ys = breakpoints({0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
  std::vector<int> side;
  const Mesh m = fs_test::to_mesh<Mesh>(
    fs_test::slotted_plate(xs, ys, 5 * refine, 6 * refine, 1 * refine, 5 * refine, 0.2, 2 * refine, side));
  BOOST_REQUIRE(CGAL::is_closed(m));
  FS::Feature_aligned_segmentation<Mesh> seg(m); // the defaults
  BOOST_TEST(seg.number_of_patches() == 10u);
  BOOST_TEST(patches_are_sides(m, seg, side, 10));
  // the face rule of the final boundaries: every boundary is a crease, a border of the
  // working mesh, so the smoothing has nothing to move and every face keeps its side
  FS::Patch_boundaries<Mesh> b = seg.patch_boundaries();
  BOOST_TEST(b.curves().empty());
  FS::smooth_patch_boundaries(b);
  std::map<typename boost::graph_traits<Mesh>::face_descriptor, std::size_t> patch;
  seg.face_patches(b, boost::make_assoc_property_map(patch));
  BOOST_TEST(patches_are_sides(m, [&](auto f) { return patch.at(f); }, side, 10));
}

// The unit cube with its corner (1,1,1) cut off by the plane 2x + y + z = 3.8: one
// triangle, A = (0.9,1,1), B = (1,0.8,1), C = (1,1,0.8), the pentagons fanned into
// triangles. `side[f]`: 0..5 for x=0, x=1, y=0, y=1, z=0, z=1, and 6 for the triangle.
// The triangle's normal (2,1,1)/sqrt(6) bends by 35.3 degrees from the side x=1 and by
// 65.9 from y=1 and z=1: three creases around one face.
fs_test::Soup cube_with_a_cut_corner(std::vector<int>& side)
{
  typedef std::array<double, 3> P;
  const std::vector<std::pair<std::vector<P>, P> > polygons = { // the polygon, its outward normal
    {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {-1, 0, 0}},
    {{{1, 0, 0}, {1, 1, 0}, {1, 1, 0.8}, {1, 0.8, 1}, {1, 0, 1}}, {1, 0, 0}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {0, -1, 0}},
    {{{0, 1, 0}, {1, 1, 0}, {1, 1, 0.8}, {0.9, 1, 1}, {0, 1, 1}}, {0, 1, 0}},
    {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, -1}},
    {{{0, 0, 1}, {1, 0, 1}, {1, 0.8, 1}, {0.9, 1, 1}, {0, 1, 1}}, {0, 0, 1}},
    {{{0.9, 1, 1}, {1, 0.8, 1}, {1, 1, 0.8}}, {2, 1, 1}}};
  fs_test::Soup s;
  std::map<P, std::size_t> id;
  auto point = [&](const P& p) {
    auto it = id.find(p);
    if(it != id.end()) return it->second;
    s.points.push_back(p);
    return id[p] = s.points.size() - 1;
  };
  side.clear();
  for(std::size_t k = 0; k < polygons.size(); ++k)
  {
    std::vector<P> q = polygons[k].first;
    const P& a = q[0]; const P& b = q[1]; const P& c = q[2];
    const P u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const P n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const P& out = polygons[k].second;
    if(n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) std::reverse(q.begin(), q.end());
    for(std::size_t i = 1; i + 1 < q.size(); ++i) // convex: a fan
    {
      s.faces.push_back({point(q[0]), point(q[i]), point(q[i + 1])});
      side.push_back(int(k));
    }
  }
  return s;
}

// The box of box() with noise along the normals: every vertex inside a side (not on a
// box edge) moves along its side's normal by a deterministic pseudo-random amount,
// uniform in [-amplitude, amplitude].
fs_test::Soup noisy_box(double amplitude, int n, std::vector<int>& side)
{
  fs_test::Soup s = fs_test::box(1., 1., 1., n, side);
  unsigned long long state = 12345;
  for(auto& p : s.points)
  {
    int on_faces = 0, axis = 0;
    for(int k = 0; k < 3; ++k)
      if(p[k] == 0. || p[k] == 1.) { ++on_faces; axis = k; }
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = double(state >> 11) / double(1ULL << 53); // [0, 1)
    if(on_faces == 1) p[axis] += (p[axis] == 0. ? -1. : 1.) * amplitude * (2 * u - 1);
  }
  return s;
}

} // namespace

BOOST_AUTO_TEST_SUITE(creases)

BOOST_AUTO_TEST_CASE(cube_at_two_resolutions_is_six_patches)
{
  box_is_its_six_sides<SM>(1., 1., 1., 6);
  box_is_its_six_sides<SM>(1., 1., 1., 12); // the same shape subdivided: the same patches
  box_is_its_six_sides<Poly>(1., 1., 1., 6);
}

// A plate 50 times thinner than wide: its rim triangles are 0.002 x 0.1, far narrower
// than a two-ring fit, which on the uncut mesh spans both big faces.
BOOST_AUTO_TEST_CASE(thin_plate_keeps_its_rim)
{
  box_is_its_six_sides<SM>(1., 1., 0.02, 10);
  box_is_its_six_sides<Poly>(1., 0.5, 0.01, 8);
}

// A plate with a thin slot, at two resolutions: exactly its ten faces (top, bottom, four
// outer walls, the slot's four walls), every triangle in its own face's patch.
BOOST_AUTO_TEST_CASE(plate_with_a_thin_slot_is_its_ten_faces)
{
  slotted_plate_is_its_ten_faces<SM>(1);
  slotted_plate_is_its_ten_faces<SM>(2); // the same shape, finer: the same patches
  slotted_plate_is_its_ten_faces<Poly>(1);
}

BOOST_AUTO_TEST_CASE(crease_ties_follow_alpha_edits)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::box(1., 1., 1., 6, side));
  FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::crease_angle(20.));
  BOOST_TEST(seg.number_of_patches() == 6u);
  // alpha -1: every weight (ties included) is Similarity + Award > 0: no cut pays
  BOOST_TEST(seg.set_alpha(-1.) == 1u);
  BOOST_TEST(seg.cut_cost() == 0.);
  BOOST_TEST(seg.undo());
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(patches_are_sides(m, seg, side));
  // merging two sides by a stroke over a face of each: 5 patches
  std::vector<SM::Face_index> stroke = { *faces(m).begin(), *std::prev(faces(m).end()) };
  BOOST_TEST(seg.merge_patches(stroke) == 5u);
}

// The feature-edge count, after construction and after a sketch, is the number of input
// edges that is_feature_edge() reports: each crease once (not once per tie).
BOOST_AUTO_TEST_CASE(feature_edge_count_counts_creases_once)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::box(1., 1., 1., 6, side));
  FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::crease_angle(20.));
  auto counted = [&]() {
    std::size_t n = 0;
    for(auto e : edges(m)) if(seg.is_feature_edge(e)) ++n;
    return n;
  };
  BOOST_TEST(seg.number_of_feature_edges() == 72u); // flat sides: creases only
  BOOST_TEST(counted() == 72u);
  // a sketch across the top side (side 5), from the centroid of its first face to that
  // of its last
  std::vector<SM::Face_index> top;
  std::size_t i = 0;
  for(auto f : faces(m)) if(side[i++] == 5) top.push_back(f);
  auto centroid = [&](SM::Face_index f) {
    auto h = halfedge(f, m);
    return CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
  };
  seg.add_sketch({ { top.front(), centroid(top.front()) }, { top.back(), centroid(top.back()) } });
  BOOST_TEST(seg.number_of_feature_edges() > 72u);
  BOOST_TEST(seg.number_of_feature_edges() == counted());
}

BOOST_AUTO_TEST_CASE(crease_angle_180_is_the_papers_pipeline)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::box(1., 1., 1., 6, side));
  FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::crease_angle(180.));
  BOOST_TEST(seg.number_of_crease_edges() == 0u);
  BOOST_TEST(&seg.working_mesh() == &m);
  // the default (20 degrees): the 12 box edges of 6 mesh edges each, on a cut copy
  FS::Feature_aligned_segmentation<SM> by_default(m);
  BOOST_TEST(by_default.number_of_crease_edges() == 72u);
  BOOST_TEST(&by_default.working_mesh() != &m);
  BOOST_TEST(by_default.number_of_patches() == 6u);
  // a 90 degree crease below the threshold counts as none
  FS::Feature_aligned_segmentation<SM> seg95(m, FS::parameters::crease_angle(95.));
  BOOST_TEST(seg95.number_of_crease_edges() == 0u);
  FS::Feature_aligned_segmentation<SM> seg85(m, FS::parameters::crease_angle(85.));
  BOOST_TEST(seg85.number_of_crease_edges() == 72u);
}

BOOST_AUTO_TEST_CASE(noisy_box_creases_come_from_filtered_normals)
{
  // noise of 1.5% of the side on a 12 x 12 grid (cells of 8.3%): raw neighbouring
  // normals differ by up to about 20 degrees, so on the raw dihedral angles there are
  // creases inside the sides (96 here, and only 45 of the 144 box-edge pieces pass the
  // gap test in the noisy band around them); the filtered normals keep exactly the 12
  // box edges, 12 mesh edges each, and the patches are the six sides
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(noisy_box(0.015, 12, side));
  // creases off the box edges: an edge on a box edge has both ends on two common
  // box faces (two coordinates both 0 or 1 on both ends)
  auto creases_inside_sides = [&m](const FS::Feature_aligned_segmentation<SM>& seg) {
    std::size_t inside = 0;
    for(auto e : edges(m))
    {
      if(!seg.is_crease_edge(e)) continue;
      const auto& p = m.point(source(halfedge(e, m), m));
      const auto& q = m.point(target(halfedge(e, m), m));
      int shared = 0;
      for(int k = 0; k < 3; ++k)
        if((p[k] == 0. || p[k] == 1.) && p[k] == q[k]) ++shared;
      if(shared < 2) ++inside;
    }
    return inside;
  };
  FS::Feature_aligned_segmentation<SM> raw(m, FS::parameters::crease_angle(20.).crease_filter_iterations(0));
  BOOST_TEST(raw.number_of_crease_edges() != 12u * 12u);
  BOOST_TEST(creases_inside_sides(raw) > 0u);
  FS::Feature_aligned_segmentation<SM> filtered(m, FS::parameters::crease_angle(20.));
  BOOST_TEST(filtered.number_of_crease_edges() == 12u * 12u);
  BOOST_TEST(creases_inside_sides(filtered) == 0u);
  BOOST_TEST(filtered.number_of_patches() == 6u);
  BOOST_TEST(patches_are_sides(m, filtered, side));
}

BOOST_AUTO_TEST_CASE(strong_noise_needs_every_filter_round)
{
  // noise of 3% of the side on a 16 x 16 grid (cells of 6.25%): neighbouring normals
  // differ by up to about 50 degrees. After 5 rounds of the filter the median face is
  // smooth but the most tilted faces, which the range Gaussian protects, still make
  // creases inside the sides; the default rounds (all of them run once the mesh is
  // found noisy) leave exactly the 12 box edges of 16 mesh edges and the six sides.
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(noisy_box(0.03, 16, side));
  FS::Feature_aligned_segmentation<SM> few(m, FS::parameters::crease_filter_iterations(5));
  BOOST_TEST(few.number_of_crease_edges() > 12u * 16u);
  BOOST_TEST(few.number_of_patches() > 6u);
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 12u * 16u);
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(patches_are_sides(m, seg, side));
}

BOOST_AUTO_TEST_CASE(smooth_bends_are_not_creases)
{
  // open prisms of height 1, each side a column of 4 quads split in two:
  // - 12 sides, 30 degrees between neighbours, nothing bending less: the 12 x 4 side
  //   edges are all creases (a CAD prism);
  // - 18 sides alternating 22 and 18 degrees, as a coarse smooth surface bends: each
  //   22-degree edge (a candidate at 20) has as much 18-degree edge beside it, in the
  //   band [15, 20) under the threshold, above half its length: none is a crease.
  for(int variant = 0; variant < 2; ++variant)
  {
    fs_test::Soup s;
    std::vector<double> turn;
    if(variant == 0) turn.assign(12, 30.);
    else for(int i = 0; i < 18; ++i) turn.push_back(i % 2 ? 18. : 22.);
    // sides of length 0.35 whose directions turn by turn[i] at vertex i: the polygon
    // closes (the turns add up to 360 degrees in a repeating pattern) and the side
    // edge at vertex i bends by turn[i]
    const int columns = int(turn.size()), rows = 4;
    std::vector<std::array<double, 2> > corner(columns);
    double direction = 0, x = 0, y = 0;
    for(int i = 0; i < columns; ++i)
    {
      corner[i] = { x, y };
      x += 0.35 * std::cos(direction);
      y += 0.35 * std::sin(direction);
      direction += turn[(i + 1) % columns] * 3.14159265358979323846 / 180.;
    }
    for(int j = 0; j <= rows; ++j)
      for(int i = 0; i < columns; ++i)
        s.points.push_back({ corner[i][0], corner[i][1], double(j) / rows });
    for(int j = 0; j < rows; ++j)
      for(int i = 0; i < columns; ++i)
      {
        const std::size_t p = j * columns + i, q = j * columns + (i + 1) % columns;
        s.faces.push_back({ p, q, q + columns });
        s.faces.push_back({ p, q + columns, p + columns });
      }
    const SM m = fs_test::to_mesh<SM>(s);
    FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::crease_angle(20.));
    if(variant == 0) BOOST_TEST(seg.number_of_crease_edges() == 12u * 4u);
    else BOOST_TEST(seg.number_of_crease_edges() == 0u);
  }
}

#ifdef CGAL_LINKED_WITH_TBB
// The crease detection on TBB's threads (concurrency_tag Parallel_tag): the normal
// filter's rounds and the gap test's candidates, each face and candidate computed alone,
// give exactly the sequential creases and patches at 1, 2 and 8 threads, on a noisy box
// (3,072 faces: every filter round runs, in blocks of 1,024 faces; the candidates of
// its 192 creases are tested in blocks of 64).
BOOST_AUTO_TEST_CASE(parallel_creases_equal_the_sequential_ones_at_any_thread_count)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(noisy_box(0.03, 16, side));
  auto creases = [&](auto tag) {
    FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::concurrency_tag(tag));
    std::vector<std::size_t> out;
    for(auto e : edges(m))
      if(seg.is_crease_edge(e)) out.push_back(std::size_t(e.idx()));
    for(auto f : faces(m)) out.push_back(seg.patch(f));
    return out;
  };
  const std::vector<std::size_t> sequential = creases(CGAL::Sequential_tag());
  for(int threads : {1, 2, 8})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    BOOST_TEST(creases(CGAL::Parallel_tag()) == sequential, threads << " threads");
  }
}
#endif

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
  const SM m = fs_test::to_mesh<SM>(noisy_box(0.004, 16, side));
  FS::internal::Mesh_indexing<SM> idx(m);
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area;
  FS::internal::face_geometry(idx, get(CGAL::vertex_point, m), normal, area, centroid);
  std::vector<std::uint32_t> begin, ring;
  FS::internal::vertex_adjacent_faces(idx, begin, ring);
  const double r0 = FS::internal::normal_roughness(normal, begin, ring);
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
// A closed rod along z, of the given length, whose cross-section at height z has radius
// radius(a, z) at the angle a: `around` x `along` quadrilaterals on its side (planar
// when the radius is a product of a function of a and one of z: each of two coplanar
// triangles, a clean tessellation), a fan on each end; side: 0 on the side, 1 and 2 on
// the ends.
template <typename Radius>
fs_test::Soup closed_rod(Radius radius, double length, int around, int along, std::vector<int>& side)
{
  fs_test::Soup s;
  for(int j = 0; j <= along; ++j)
    for(int i = 0; i < around; ++i)
    {
      const double a = 2 * M_PI * i / around, z = length * j / along, r = radius(a, z);
      s.points.push_back({r * std::cos(a), r * std::sin(a), z});
    }
  const std::size_t bottom = s.points.size(), top = bottom + 1;
  s.points.push_back({0., 0., 0.});
  s.points.push_back({0., 0., length});
  const auto at = [&](int i, int j) { return std::size_t(j * around + (i % around)); };
  side.clear();
  for(int j = 0; j < along; ++j)
    for(int i = 0; i < around; ++i)
    {
      s.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      side.insert(side.end(), {0, 0});
    }
  for(int i = 0; i < around; ++i)
  {
    s.faces.push_back({bottom, at(i + 1, 0), at(i, 0)});
    s.faces.push_back({top, at(i, along), at(i + 1, along)});
    side.insert(side.end(), {1, 2});
  }
  return s;
}

BOOST_AUTO_TEST_CASE(the_ends_of_a_long_rod_are_creases)
{
  const int around = 20;
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(closed_rod([](double, double) { return 1.; }, 40., around, 80, side));
  BOOST_REQUIRE(CGAL::is_closed(m) && CGAL::is_triangle_mesh(m));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == std::size_t(2 * around)); // the two end rings only
  BOOST_TEST(seg.number_of_patches() == 3u);
  BOOST_TEST(patches_are_sides(m, seg, side, 3));
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
    const SM m = fs_test::to_mesh<SM>(closed_rod(lobes, length, 96, int(4 * length), side));
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

// A noisy tessellation is not clean, and has no exactly planar region to tell a CAD part
// by; its creases, found on the filtered normals, still cut it into its faces. A rod of
// length 4 and radius 1 (48 facets round, 16 rings along), every vertex inside its side
// moved radially by a seeded uniform amount of up to 3% of the radius (0.6% of the
// diagonal; the end rings stay, so the ends keep their 90-degree creases): its creases
// are the two end rings, which cut it into the side (80% of the area: 8 pi against pi
// for each end) and the two ends, so it is a CAD part and its crest lines, which the
// noise strews along the side, weigh 0.6 - 0.5 (0.6 with
// crest_lines_on_clean_tessellations(true)). Either way the side is one patch.
BOOST_AUTO_TEST_CASE(crest_lines_weigh_less_on_a_noisy_cad_part)
{
  std::vector<int> side;
  fs_test::Soup s = closed_rod([](double, double) { return 1.; }, 4., 48, 16, side);
  unsigned long long state = 2024;
  for(std::size_t v = 0; v + 2 < s.points.size(); ++v) // not the two centres of the ends
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = double(state >> 11) / double(1ULL << 53); // [0, 1)
    if(!(s.points[v][2] > 0. && s.points[v][2] < 4.)) continue;
    const double f = 1. + 0.03 * (2 * u - 1);
    s.points[v][0] *= f;
    s.points[v][1] *= f;
  }
  const SM m = fs_test::to_mesh<SM>(s);
  for(bool full_alpha : {false, true})
  {
    FS::Feature_aligned_segmentation<SM> seg(m, FS::parameters::crest_lines_on_clean_tessellations(full_alpha));
    BOOST_TEST(seg.number_of_crease_edges() == 96u);
    double least = 1e300, most = -1e300;
    for(auto e : edges(m))
      if(seg.is_feature_edge(e) && !seg.is_crease_edge(e))
      {
        least = (std::min)(least, seg.alpha(e));
        most = (std::max)(most, seg.alpha(e));
      }
    BOOST_TEST(least <= most); // it has crest lines
    BOOST_TEST(least == (full_alpha ? 0.6 : 0.1), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(most == (full_alpha ? 0.6 : 0.1), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(seg.number_of_patches() == 3u);
    BOOST_TEST(patches_are_sides(m, seg, side, 3));
  }
}

// A face cut out alone by its three creases is no patch of its own: it joins the side it
// bends least from (x=1, 35.3 degrees), and the part is the cube's six sides.
BOOST_AUTO_TEST_CASE(a_face_isolated_by_creases_joins_its_flattest_neighbour)
{
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(cube_with_a_cut_corner(side));
  BOOST_REQUIRE(CGAL::is_closed(m) && CGAL::is_triangle_mesh(m));
  FS::Feature_aligned_segmentation<SM> seg(m);
  std::vector<int> joined = side;
  for(int& k : joined) if(k == 6) k = 1;
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(patches_are_sides(m, seg, joined, 6));
  // the two creases of 65.9 degrees stay, the one of 35.3 is cleared
  std::size_t triangle_creases = 0;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m);
    const bool on_triangle = side[face(h, m).idx()] == 6 || side[face(opposite(h, m), m).idx()] == 6;
    if(on_triangle && seg.is_crease_edge(e)) ++triangle_creases;
  }
  BOOST_TEST(triangle_creases == 2u);
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
