// Creases (CAD tessellations): the segmentation cut open along edges whose faces bend by
// crease_angle or more (20 degrees, the default; 180 is none). Boxes give exact answers:
// their six faces, whatever the resolution and however thin the box, with every
// triangle on its own side.
#include <boost/test/unit_test.hpp>

#include "crease_meshes.h"

#include <CGAL/Feature_segmentation/internal/faces_from_corners.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <map>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(creases)

BOOST_AUTO_TEST_CASE(cube_at_two_resolutions_is_six_patches)
{
  fs_test::box_is_its_six_sides<SM>(1., 1., 1., 6);
  fs_test::box_is_its_six_sides<SM>(1., 1., 1., 12); // the same shape subdivided: the same patches
  fs_test::box_is_its_six_sides<Poly>(1., 1., 1., 6);
}

// A plate 50 times thinner than wide: its rim triangles are 0.002 x 0.1, far narrower
// than a two-ring fit, which on the uncut mesh spans both big faces.
BOOST_AUTO_TEST_CASE(thin_plate_keeps_its_rim)
{
  fs_test::box_is_its_six_sides<SM>(1., 1., 0.02, 10);
  fs_test::box_is_its_six_sides<Poly>(1., 0.5, 0.01, 8);
}

// A plate with a thin slot, at two resolutions: exactly its ten faces (top, bottom, four
// outer walls, the slot's four walls), every triangle in its own face's patch.
BOOST_AUTO_TEST_CASE(plate_with_a_thin_slot_is_its_ten_faces)
{
  fs_test::slotted_plate_is_its_ten_faces<SM>(1);
  fs_test::slotted_plate_is_its_ten_faces<SM>(2); // the same shape, finer: the same patches
  fs_test::slotted_plate_is_its_ten_faces<Poly>(1);
}

// The elements of `direct` and `euler` that differ: the target, next halfedge and face of
// every halfedge, the halfedge of every vertex and face (by their indices).
template <typename Mesh>
std::size_t halfedge_structure_differences(const Mesh& direct, const Mesh& euler)
{
  namespace I = FS::internal;
  const I::Mesh_indexing<Mesh> a(direct), b(euler);
  BOOST_REQUIRE(a.number_of_vertices() == b.number_of_vertices());
  BOOST_REQUIRE(a.number_of_edges() == b.number_of_edges());
  BOOST_REQUIRE(a.number_of_faces() == b.number_of_faces());
  std::size_t differences = 0;
  auto face_id = [](const I::Mesh_indexing<Mesh>& x, auto h) { return x.face_id(h); };
  auto hb = halfedges(euler).begin();
  for(auto h : halfedges(direct))
  {
    const auto g = *hb++;
    if(a.halfedge_id(h) != b.halfedge_id(g) || a.id(target(h, direct)) != b.id(target(g, euler)) ||
       a.halfedge_id(next(h, direct)) != b.halfedge_id(next(g, euler)) || face_id(a, h) != face_id(b, g))
      ++differences;
  }
  for(std::size_t i = 0; i < a.number_of_vertices(); ++i)
  {
    const auto h = halfedge(a.vertex_at(i), direct), g = halfedge(b.vertex_at(i), euler);
    const bool isolated = h == boost::graph_traits<Mesh>::null_halfedge();
    if(isolated != (g == boost::graph_traits<Mesh>::null_halfedge()) || (!isolated && a.halfedge_id(h) != b.halfedge_id(g)))
      ++differences;
  }
  for(std::size_t f = 0; f < a.number_of_faces(); ++f)
    if(a.halfedge_id(halfedge(a.face_at(f), direct)) != b.halfedge_id(halfedge(b.face_at(f), euler))) ++differences;
  return differences;
}

// The cut copy's faces, added halfedge by halfedge (add_cut_faces), are the mesh that
// Euler::add_face makes face by face from the same sectors, element for element: the
// same targets, next halfedges and faces of every halfedge, the same halfedge of every
// vertex and face. On a closed box (every vertex on a crease) and on a sheet folded by
// 45 degrees (a crease that ends on the border).
template <typename Mesh>
void cut_faces_are_eulers(const Mesh& m)
{
  namespace I = FS::internal;
  const I::Mesh_indexing<Mesh> idx(m);
  I::Crease_cut<Mesh> cut;
  I::compute_crease_cut(idx, get(CGAL::vertex_point, m), 20., 40, true, 0.05, cut);
  BOOST_REQUIRE(cut.is_cut());
  I::Crease_cut<Mesh> again;
  again.is_crease = cut.is_crease;
  const I::Crease_sectors sectors = I::crease_sectors(idx, again);
  BOOST_REQUIRE(again.input_vertex == cut.input_vertex);
  Mesh euler;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> v;
  for(std::size_t i = 0; i < again.input_vertex.size(); ++i) v.push_back(add_vertex(euler));
  for(std::size_t f = 0; f < idx.number_of_faces(); ++f)
  {
    const std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3> t = {
      v[sectors.corner_working[3 * f]], v[sectors.corner_working[3 * f + 1]], v[sectors.corner_working[3 * f + 2]] };
    BOOST_REQUIRE(CGAL::Euler::add_face(t, euler) != boost::graph_traits<Mesh>::null_face());
  }
  BOOST_TEST(halfedge_structure_differences(*cut.mesh, euler) == 0u);
}

// every_vertex_has_one_fan() on faces given by their corners (`first`, `corner_vertex`,
// `twin` as add_faces_from_corners() takes them) over `nv` vertices.
bool corners_have_one_fan_each(std::size_t nv, const std::vector<std::size_t>& first,
                               const std::vector<std::size_t>& corner_vertex, const std::vector<std::size_t>& twin)
{
  std::vector<std::size_t> face_of(corner_vertex.size()), begin(nv + 1, 0), at(corner_vertex.size());
  for(std::size_t f = 0; f + 1 < first.size(); ++f)
    for(std::size_t c = first[f]; c < first[f + 1]; ++c) face_of[c] = f;
  for(std::size_t v : corner_vertex) ++begin[v + 1];
  for(std::size_t v = 0; v < nv; ++v) begin[v + 1] += begin[v];
  std::vector<std::size_t> fill(begin.begin(), begin.end() - 1);
  for(std::size_t c = 0; c < corner_vertex.size(); ++c) at[fill[corner_vertex[c]]++] = c;
  const auto next = [&](std::size_t c) { return c + 1 == first[face_of[c] + 1] ? first[face_of[c]] : c + 1; };
  const auto previous = [&](std::size_t c) { return c == first[face_of[c]] ? first[face_of[c] + 1] - 1 : c - 1; };
  return FS::internal::every_vertex_has_one_fan(nv, [&](std::size_t v) { return begin[v]; },
                                                [&](std::size_t k) { return at[k]; }, next, previous,
                                                [&](std::size_t c) { return twin[c]; }, std::size_t(-1), false);
}

// add_faces_from_corners() on polygons with a border: a 4 x 3 grid of vertices (unit
// cells), its six cells quads but for the first, split into two triangles, gives the
// mesh Euler::add_face makes face by face, element for element (7 faces, 12 vertices,
// 18 edges: 17 of the grid and the first cell's diagonal).
template <typename Mesh>
void corner_faces_are_eulers()
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const auto id = [](int i, int j) { return std::size_t(j * 4 + i); };
  std::vector<std::vector<std::size_t> > polygons = { { id(0, 0), id(1, 0), id(1, 1) }, { id(0, 0), id(1, 1), id(0, 1) } };
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 3; ++i)
      if(i + j > 0) polygons.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
  std::vector<std::size_t> first(1, 0), corner_vertex;
  for(const auto& p : polygons)
  {
    corner_vertex.insert(corner_vertex.end(), p.begin(), p.end());
    first.push_back(corner_vertex.size());
  }
  // corner c runs from its vertex to the next corner's; its twin runs the other way
  const std::size_t none = std::size_t(-1);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> corner_of;
  for(std::size_t f = 0; f + 1 < first.size(); ++f)
    for(std::size_t c = first[f]; c < first[f + 1]; ++c)
      corner_of[{ corner_vertex[c], corner_vertex[c + 1 == first[f + 1] ? first[f] : c + 1] }] = c;
  std::vector<std::size_t> twin(corner_vertex.size(), none);
  for(const auto& [ends, c] : corner_of)
  {
    const auto o = corner_of.find({ ends.second, ends.first });
    if(o != corner_of.end()) twin[c] = o->second;
  }
  auto points = [](Mesh& m) {
    std::vector<vertex_descriptor> v;
    for(int j = 0; j < 3; ++j)
      for(int i = 0; i < 4; ++i)
      {
        v.push_back(add_vertex(m));
        put(get(CGAL::vertex_point, m), v.back(), typename boost::property_traits<
            typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type(double(i), double(j), 0.));
      }
    return v;
  };
  Mesh direct, euler;
  const std::vector<vertex_descriptor> dv = points(direct), ev = points(euler);
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> faces;
  FS::internal::add_faces_from_corners(direct, dv, polygons.size(), [&](std::size_t f) { return first[f]; },
                                       [&](std::size_t c) { return corner_vertex[c]; },
                                       [&](std::size_t c) { return twin[c]; }, none, faces);
  for(const auto& p : polygons)
  {
    std::vector<vertex_descriptor> fv;
    for(std::size_t v : p) fv.push_back(ev[v]);
    BOOST_REQUIRE(CGAL::Euler::add_face(fv, euler) != boost::graph_traits<Mesh>::null_face());
  }
  BOOST_TEST(CGAL::is_valid_polygon_mesh(direct));
  BOOST_TEST(faces.size() == 7u);
  BOOST_TEST(num_edges(direct) == 18u);
  BOOST_TEST(halfedge_structure_differences(direct, euler) == 0u);
  BOOST_TEST(corners_have_one_fan_each(12, first, corner_vertex, twin));
}

BOOST_AUTO_TEST_CASE(corner_faces_are_those_of_euler_add_face)
{
  corner_faces_are_eulers<SM>();
  corner_faces_are_eulers<Poly>();
}

// Two triangles that share one vertex (a bow tie) pinch it: two fans there; with a third
// triangle joining them along an edge each, one fan again.
BOOST_AUTO_TEST_CASE(a_vertex_of_two_fans_is_found)
{
  const std::size_t none = std::size_t(-1);
  // vertex 0 is shared; triangles (0 1 2) and (0 3 4)
  BOOST_TEST(!corners_have_one_fan_each(5, { 0, 3, 6 }, { 0, 1, 2, 0, 3, 4 }, std::vector<std::size_t>(6, none)));
  // with (0 2 3) after them: corner 2 (2 -> 0) twins corner 6 (0 -> 2), corner 3 (0 -> 3)
  // twins corner 8 (3 -> 0)
  std::vector<std::size_t> twin(9, none);
  twin[2] = 6; twin[6] = 2;
  twin[3] = 8; twin[8] = 3;
  BOOST_TEST(corners_have_one_fan_each(5, { 0, 3, 6, 9 }, { 0, 1, 2, 0, 3, 4, 0, 2, 3 }, twin));
}

fs_test::Soup folded_sheet()
{
  fs_test::Soup s = fs_test::plane(1., 12);
  for(auto& p : s.points)
    if(p[0] > 0.5) p[2] = p[0] - 0.5;
  return s;
}

BOOST_AUTO_TEST_CASE(cut_faces_are_those_of_euler_add_face)
{
  std::vector<int> side;
  cut_faces_are_eulers(fs_test::to_mesh<SM>(fs_test::noisy_box(0., 6, side)));
  cut_faces_are_eulers(fs_test::to_mesh<Poly>(fs_test::noisy_box(0., 6, side)));
  cut_faces_are_eulers(fs_test::to_mesh<SM>(folded_sheet()));
  cut_faces_are_eulers(fs_test::to_mesh<Poly>(folded_sheet()));
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
  BOOST_TEST(fs_test::patches_are_sides(m, seg, side));
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
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_box(0.015, 12, side));
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
  BOOST_TEST(fs_test::patches_are_sides(m, filtered, side));
}

BOOST_AUTO_TEST_CASE(strong_noise_needs_every_filter_round)
{
  // noise of 3% of the side on a 16 x 16 grid (cells of 6.25%): neighbouring normals
  // differ by up to about 50 degrees. After 5 rounds of the filter the median face is
  // smooth but the most tilted faces, which the range Gaussian protects, still make
  // creases inside the sides; the default rounds (all of them run once the mesh is
  // found noisy) leave exactly the 12 box edges of 16 mesh edges and the six sides.
  std::vector<int> side;
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_box(0.03, 16, side));
  // (the filter alone: without the tangent-continuous boundaries, whose revolution seams
  // also clear the noise inside a fitted piece)
  FS::Feature_aligned_segmentation<SM> few(
    m, FS::parameters::crease_filter_iterations(5).tangent_discontinuities(false));
  BOOST_TEST(few.number_of_crease_edges() > 12u * 16u);
  // With them, a noisy side is one straight piece of a profile about an axis near its
  // normal, so every crease that 5 rounds leave inside it is noise and is unmarked
  // (revolution_seams.h): the box edges are left, and the sides are the patches.
  FS::Feature_aligned_segmentation<SM> cleared(m, FS::parameters::crease_filter_iterations(5));
  BOOST_TEST(cleared.number_of_crease_edges() == 12u * 16u);
  BOOST_TEST(cleared.number_of_patches() == 6u);
  BOOST_TEST(fs_test::patches_are_sides(m, cleared, side));
  FS::Feature_aligned_segmentation<SM> seg(m);
  BOOST_TEST(seg.number_of_crease_edges() == 12u * 16u);
  BOOST_TEST(seg.number_of_patches() == 6u);
  BOOST_TEST(fs_test::patches_are_sides(m, seg, side));
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
  const SM m = fs_test::to_mesh<SM>(fs_test::noisy_box(0.03, 16, side));
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

BOOST_AUTO_TEST_SUITE_END()
