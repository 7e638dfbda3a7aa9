// Quality metrics (metrics.h) on hand-computable cases (face labellings and boundary
// curves) and the reader of the ABC ground truth (yaml-cpp). The quality floors on
// fandisk and on the ABC model are in test_evaluation_floors.cpp (the same executable).
#include <boost/test/unit_test.hpp>

#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include "abc_ground_truth.h"
#include "cad_parts.h"
#include "resolution_series.h"
#include "methods.h"
#include "metrics.h"
#include "test_meshes.h"

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace FS = CGAL::Feature_segmentation;
namespace FE = fs_evaluation;

namespace {

typedef FE::Mesh Mesh;

// The square [-1, 1]^2 as a 10 x 10 grid of quads (spacing 0.2), two triangles each.
Mesh square() { return fs_test::to_mesh<Mesh>(fs_test::plane(1., 10)); }

FE::K::Point_3 centroid(const Mesh& m, FE::face_descriptor f)
{
  auto h = halfedge(f, m);
  return CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
}

template <typename Rule>
std::vector<int> face_labels(const Mesh& m, Rule rule)
{
  std::vector<int> l(m.number_of_faces());
  for(auto f : faces(m)) l[f.idx()] = rule(centroid(m, f));
  return l;
}

auto as_map(const std::vector<int>& l)
{
  return boost::make_function_property_map<FE::face_descriptor>([&l](FE::face_descriptor f) { return l[f.idx()]; });
}

// A user line through the grid vertices from (x0, y0) to (x1, y1), axis-aligned.
FS::Feature_line<Mesh> line_through_vertices(const Mesh& m, double x0, double y0, double x1, double y1, double strength)
{
  FS::Feature_line<Mesh> l;
  l.type = FS::Feature_line_type::USER;
  l.strength = strength;
  const int steps = static_cast<int>(std::lround((std::abs(x1 - x0) + std::abs(y1 - y0)) / 0.2));
  for(int k = 0; k <= steps; ++k)
  {
    const double x = x0 + (x1 - x0) * k / steps, y = y0 + (y1 - y0) * k / steps;
    for(auto v : vertices(m))
      if(std::abs(m.point(v).x() - x) < 1e-9 && std::abs(m.point(v).y() - y) < 1e-9)
      {
        FS::Feature_point<Mesh> p;
        p.halfedge = opposite(halfedge(v, m), m); // source(p.halfedge) == v, t = 0
        l.points.push_back(p);
      }
  }
  BOOST_REQUIRE_EQUAL(l.points.size(), static_cast<std::size_t>(steps + 1));
  return l;
}

// The mesh the annotations of the ground-truth tests are for: 4 vertices, 5 faces.
const std::size_t abc_vertices = 4, abc_faces = 5;

// The reader takes a path: `text` in a .yml file of its own in the temporary folder,
// removed with the object. The random name keeps two builds' runs apart.
struct Temporary_yml
{
  std::filesystem::path path;
  explicit Temporary_yml(const std::string& text)
    : path(std::filesystem::temp_directory_path() / ("fs_evaluation_" + std::to_string(std::random_device()()) + ".yml"))
  {
    std::ofstream out(path);
    out << text;
    out.close();
    BOOST_REQUIRE_MESSAGE(out, "cannot write " << path.string());
  }
  ~Temporary_yml()
  {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
  Temporary_yml(const Temporary_yml&) = delete;
  Temporary_yml& operator=(const Temporary_yml&) = delete;
};

// For BOOST_CHECK_EXCEPTION: the message names `path` and says `reason`. Checked inside,
// as a failed predicate alone would not show the message.
auto names_file_and_says(const std::string& path, const std::string& reason)
{
  return [path, reason](const std::runtime_error& e) {
    const std::string what = e.what();
    BOOST_CHECK_MESSAGE(what.find(path) != std::string::npos && what.find(reason) != std::string::npos,
                        "message '" << what << "' should name " << path << " and say '" << reason << "'");
    return true;
  };
}

void check_abc_error(const std::string& text, const std::string& reason)
{
  BOOST_TEST_CONTEXT("annotations: " << text)
  {
    const Temporary_yml yml(text);
    BOOST_CHECK_EXCEPTION(FE::read_abc_ground_truth(yml.path.string(), abc_vertices, abc_faces), std::runtime_error,
                          names_file_and_says(yml.path.string(), reason));
  }
}

} // namespace

BOOST_AUTO_TEST_SUITE(evaluation)

// The boundaries of two meshes of one surface, compared as 3D segments (the resolution
// series' compare_boundaries_across_meshes()), tolerance 0.01: the border of a unit
// square against the same border cut into 1,000 edges (a finer mesh) matches exactly;
// against the border moved by 0.02, nothing; two of its sides against the whole border:
// precision 1, recall 0.505 (the two sides, and on each of the other two the pieces of
// 0.005 whose midpoints, 0.0025 and 0.0075 from a shared corner, lie within 0.01).
BOOST_AUTO_TEST_CASE(boundaries_across_meshes_by_hand)
{
  typedef fs_evaluation::Boundary_segment S;
  typedef FS::internal::Evaluation_point P;
  const P a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  const std::vector<S> square = { S(a, b), S(b, c), S(c, d), S(d, a) };
  std::vector<S> fine, moved;
  for(const S& side : square)
  {
    for(int i = 0; i < 250; ++i)
      fine.emplace_back(side.source() + (side.target() - side.source()) * (i / 250.),
                        side.source() + (side.target() - side.source()) * ((i + 1) / 250.));
    const FS::internal::Evaluation_kernel::Vector_3 up(0, 0, 0.02);
    moved.emplace_back(side.source() + up, side.target() + up);
  }
  const FS::Boundary_scores same = fs_evaluation::compare_boundaries_across_meshes(fine, square, 0.01);
  BOOST_TEST(same.precision == 1.);
  BOOST_TEST(same.recall == 1.);
  BOOST_TEST(same.f_score == 1.);
  const FS::Boundary_scores away = fs_evaluation::compare_boundaries_across_meshes(moved, square, 0.01);
  BOOST_TEST(away.precision == 0.);
  BOOST_TEST(away.recall == 0.);
  const FS::Boundary_scores half =
    fs_evaluation::compare_boundaries_across_meshes({ S(a, b), S(b, c) }, square, 0.01);
  BOOST_TEST(half.precision == 1.);
  BOOST_TEST(half.recall == 0.505, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(rand_index_by_hand)
{
  // 6 pairs; agreements: (0,1) together in both, (0,3), (1,3) apart in both: 3 of 6.
  BOOST_CHECK_CLOSE(FS::rand_index(std::vector<int>{0, 0, 1, 1}, std::vector<int>{0, 0, 0, 1}), 0.5, 1e-12);
  // The ids do not matter, the partition does.
  BOOST_CHECK_CLOSE(FS::rand_index(std::vector<int>{0, 0, 1, 2}, std::vector<int>{7, 7, 3, 5}), 1.0, 1e-12);
  BOOST_CHECK_SMALL(FS::rand_index(std::vector<int>{0, 1, 2, 3}, std::vector<int>{0, 0, 0, 0}), 1e-12);
  // Weighted pairs: (0,1) weight 2 disagree, (0,2) weight 2 agree, (1,2) weight 1 disagree: 2/5.
  BOOST_CHECK_CLOSE(FS::rand_index(std::vector<int>{0, 0, 1}, std::vector<int>{0, 1, 1}, {2., 1., 1.}), 0.4, 1e-12);
}

BOOST_AUTO_TEST_CASE(over_and_under_segmentation_by_hand)
{
  const std::vector<int> ref = {0, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<double> w(8, 1.);
  FS::Partition_scores s = FS::compare_partitions(std::vector<int>{0, 0, 1, 1, 2, 2, 2, 2}, ref, w);
  BOOST_CHECK_EQUAL(s.over_segmentation, 1u); // reference patch 0 in two halves
  BOOST_CHECK_EQUAL(s.under_segmentation, 0u);
  s = FS::compare_partitions(std::vector<int>(8, 0), ref, w);
  BOOST_CHECK_EQUAL(s.over_segmentation, 0u);
  BOOST_CHECK_EQUAL(s.under_segmentation, 1u); // one patch over two reference patches
  BOOST_CHECK_CLOSE(s.rand_index, 12. / 28., 1e-12); // 2 * C(4,2) = 12 of the 28 pairs together in both
  // A piece of 1 face of 4 (25%) is significant at 10%, not at 30%.
  const std::vector<int> sliver = {0, 0, 0, 1, 1, 1, 1, 1};
  BOOST_CHECK_EQUAL(FS::compare_partitions(sliver, ref, w).over_segmentation, 1u);
  BOOST_CHECK_EQUAL(FS::compare_partitions(sliver, ref, w).under_segmentation, 1u);
  BOOST_CHECK_EQUAL(FS::compare_partitions(sliver, ref, w, 0.3).over_segmentation, 0u);
  BOOST_CHECK_EQUAL(FS::compare_partitions(ref, ref, w).over_segmentation + FS::compare_partitions(ref, ref, w).under_segmentation, 0u);
}

BOOST_AUTO_TEST_CASE(boundary_band_share_on_a_grid)
{
  // The square [-1, 1]^2 in cells of 0.2, each cut into two triangles of equal area whose
  // centroids lie 1/3 and 2/3 of the way across the cell (x offsets 0.0667 and 0.1333).
  // With the boundary on x = 0, tolerance 0.1 holds one triangle of each of the 2 x 10
  // cells beside it (20 of the 200 faces), 0.15 both (40), 0.05 none; no boundary, none.
  const Mesh m = square();
  BOOST_CHECK_EQUAL(m.number_of_faces(), 200u);
  const auto truth = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0 ? 0 : 1; });
  BOOST_CHECK_CLOSE(FS::boundary_band_share(m, as_map(truth), 0.1), 0.1, 1e-9);
  BOOST_CHECK_CLOSE(FS::boundary_band_share(m, as_map(truth), 0.15), 0.2, 1e-9);
  BOOST_CHECK_EQUAL(FS::boundary_band_share(m, as_map(truth), 0.05), 0.);
  // Tolerance 2 covers the square: every boundary drawn on it is matched by chance.
  BOOST_CHECK_CLOSE(FS::boundary_band_share(m, as_map(truth), 2.), 1., 1e-9);
  const std::vector<int> one(m.number_of_faces(), 0);
  BOOST_CHECK_EQUAL(FS::boundary_band_share(m, as_map(one), 0.15), 0.);
  BOOST_CHECK_THROW(FS::boundary_band_share(m, as_map(truth), -1.), FS::Invalid_input);
}

BOOST_AUTO_TEST_CASE(mean_scores_of_noise_realisations)
{
  // Two realisations of two methods, the second not run: F 0.5 and 1 average to 0.75,
  // Rand indices 0.25 and 0.5 to 0.375, 3 and 4 patches to 3.5, rounded away from zero to
  // 4; one realisation is itself.
  auto score = [](double f, std::size_t patches, std::size_t small) {
    fs_evaluation::Cad_score s;
    s.boundary.precision = s.boundary.recall = s.boundary.f_score = f;
    s.rand_index = f / 2;
    s.patches = patches;
    s.small_patches = small;
    s.seconds = f;
    return s;
  };
  fs_evaluation::Cad_score off;
  off.ran = false;
  const std::vector<std::vector<fs_evaluation::Cad_score> > runs = {{score(0.5, 3, 0), off}, {score(1., 4, 2), off}};
  const std::vector<fs_evaluation::Cad_score> mean = fs_evaluation::mean_scores(runs);
  BOOST_REQUIRE_EQUAL(mean.size(), 2u);
  BOOST_CHECK_CLOSE(mean[0].boundary.f_score, 0.75, 1e-12);
  BOOST_CHECK_CLOSE(mean[0].boundary.precision, 0.75, 1e-12);
  BOOST_CHECK_CLOSE(mean[0].rand_index, 0.375, 1e-12);
  BOOST_CHECK_CLOSE(mean[0].seconds, 0.75, 1e-12);
  BOOST_CHECK_EQUAL(mean[0].patches, 4u);
  BOOST_CHECK_EQUAL(mean[0].small_patches, 1u);
  BOOST_CHECK(!mean[1].ran);
  const std::vector<fs_evaluation::Cad_score> one = fs_evaluation::mean_scores({runs.front()});
  BOOST_CHECK_EQUAL(one[0].boundary.f_score, 0.5);
  BOOST_CHECK_EQUAL(one[0].rand_index, 0.25);
  BOOST_CHECK_EQUAL(one[0].patches, 3u);
}

BOOST_AUTO_TEST_CASE(cad_table_scores_of_a_cube)
{
  // The unit cube, each side 8 triangles of equal area; sharp edges at 45 degrees find its
  // 6 sides. Against the sides: F 1 and Rand index 1. Against a truth that merges two
  // sides: of the 48 * 47 / 2 = 1128 pairs of triangles (equal weights), the 8 * 8 = 64
  // across the two merged sides disagree, Rand index 1064 / 1128.
  std::vector<int> side;
  const Mesh m = fs_test::to_mesh<Mesh>(fs_test::box(1., 1., 1., 2, side));
  BOOST_REQUIRE_EQUAL(m.number_of_faces(), 48u);
  FE::Cad_options options;
  options.methods = {"sharp45"};
  const std::vector<FE::Cad_score> exact = FE::run_cad_methods(m, side, 6, options);
  BOOST_REQUIRE_EQUAL(exact.size(), FE::cad_methods().size());
  BOOST_CHECK(!exact[0].ran);
  const FE::Cad_score& s = exact[3];
  BOOST_REQUIRE(s.ran);
  BOOST_CHECK_EQUAL(s.patches, 6u);
  BOOST_CHECK_EQUAL(s.small_patches, 0u);
  BOOST_CHECK_CLOSE(s.boundary.f_score, 1., 1e-9);
  BOOST_CHECK_CLOSE(s.rand_index, 1., 1e-9);
  std::vector<int> merged = side;
  for(int& l : merged) l = l == 2 ? 0 : l;
  const std::vector<FE::Cad_score> coarse = FE::run_cad_methods(m, merged, 5, options);
  BOOST_CHECK_EQUAL(coarse[3].patches, 6u);
  BOOST_CHECK_CLOSE(coarse[3].rand_index, 1064. / 1128., 1e-9);
  BOOST_CHECK_LT(coarse[3].boundary.precision, 1.);
}

BOOST_AUTO_TEST_CASE(boundary_precision_recall_on_a_grid)
{
  const Mesh m = square();
  const auto truth = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0 ? 0 : 1; });
  // Same boundary: perfect. The boundary moved by 0.4: matched at 0.5, not at 0.3.
  BOOST_CHECK_CLOSE(FS::compare_boundaries(m, as_map(truth), as_map(truth), 0.01).f_score, 1., 1e-12);
  const auto moved = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0.4 ? 0 : 1; });
  BOOST_CHECK_CLOSE(FS::compare_boundaries(m, as_map(moved), as_map(truth), 0.5).f_score, 1., 1e-12);
  FS::Boundary_scores s = FS::compare_boundaries(m, as_map(moved), as_map(truth), 0.3);
  BOOST_CHECK_EQUAL(s.precision, 0.);
  BOOST_CHECK_EQUAL(s.recall, 0.);
  BOOST_CHECK_EQUAL(s.f_score, 0.);
  BOOST_CHECK_CLOSE(s.boundary_length, 2., 1e-9);
  // Boundary on x = 0 for y < 0, on x = 0.2 for y > 0, joined along y = 0 (length 0.2).
  // Tolerance 0.15: matched are the lower half (1) and the joining edge (midpoint at 0.1):
  // precision 1.2 / 2.2; of the truth, the lower half and the edge (0,0)-(0,0.2)
  // (midpoint 0.1 from the joining edge): recall 1.2 / 2; F = 4/7.
  const auto step = face_labels(m, [](const FE::K::Point_3& c) { return (c.x() < 0 || (c.x() < 0.2 && c.y() > 0)) ? 0 : 1; });
  s = FS::compare_boundaries(m, as_map(step), as_map(truth), 0.15);
  BOOST_CHECK_CLOSE(s.precision, 6. / 11., 1e-9);
  BOOST_CHECK_CLOSE(s.recall, 0.6, 1e-9);
  BOOST_CHECK_CLOSE(s.f_score, 4. / 7., 1e-9);
  // No boundary at all: nothing wrong drawn (precision 1), nothing found (recall 0).
  const std::vector<int> one(m.number_of_faces(), 0);
  s = FS::compare_boundaries(m, as_map(one), as_map(truth), 0.15);
  BOOST_CHECK_EQUAL(s.precision, 1.);
  BOOST_CHECK_EQUAL(s.recall, 0.);
  BOOST_CHECK_THROW(FS::compare_boundaries(m, as_map(one), as_map(truth), -1.), FS::Invalid_input);
  // Area-weighted partition scores on equal-area faces: the face counts.
  BOOST_CHECK_CLOSE(FS::compare_partitions(m, as_map(truth), as_map(truth)).rand_index, 1., 1e-12);
  BOOST_CHECK_EQUAL(FS::compare_partitions(m, as_map(one), as_map(truth)).under_segmentation, 1u);
  BOOST_CHECK_CLOSE(FS::default_boundary_tolerance(m), 0.02 * std::sqrt(2.), 1e-9);
}

BOOST_AUTO_TEST_CASE(coverage_and_redundancy_on_a_grid)
{
  const Mesh m = square();
  FS::Feature_lines<Mesh> lines;
  lines.lines.push_back(line_through_vertices(m, 0, -1, 0, 1, 20.));    // strong, on x = 0
  lines.lines.push_back(line_through_vertices(m, -1, 0.6, 1, 0.6, 2.)); // weak, on y = 0.6
  const auto on_line = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0 ? 0 : 1; });
  FS::Feature_line_scores s = FS::compare_with_feature_lines(m, as_map(on_line), lines, 0.15);
  BOOST_CHECK_CLOSE(s.coverage, 1., 1e-12);
  BOOST_CHECK_CLOSE(s.strong_length, 2., 1e-9);
  BOOST_CHECK_EQUAL(s.redundant_length, 0.);
  // Boundary on x = 0.4: 0.4 from the strong line (not covered); its two edges whose
  // midpoints are 0.1 from the weak line are supported, the other 8 (1.6) redundant.
  const auto off = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0.4 ? 0 : 1; });
  s = FS::compare_with_feature_lines(m, as_map(off), lines, 0.15);
  BOOST_CHECK_EQUAL(s.coverage, 0.);
  BOOST_CHECK_CLOSE(s.redundant_length, 1.6, 1e-9);
  BOOST_CHECK_CLOSE(s.redundancy_fraction(), 0.8, 1e-9);
  // With the weak line counted as strong (strong length 4): only its two segments whose
  // midpoints are 0.1 from x = 0.4 are covered, 0.4 of 4.
  s = FS::compare_with_feature_lines(m, as_map(off), lines, 0.15, 1.);
  BOOST_CHECK_CLOSE(s.coverage, 0.4 / 4., 1e-9);
}

BOOST_AUTO_TEST_CASE(boundary_curves_on_a_grid)
{
  // Vertices with x < 0 in patch 0: the curve crosses the column of triangles between
  // x = -0.2 and x = 0, from the border at y = -1 to the border at y = 1.
  const Mesh m = square();
  auto vlabel = boost::make_function_property_map<FE::vertex_descriptor>(
    [&](FE::vertex_descriptor v) { return m.point(v).x() < -1e-9 ? 0 : 1; });
  FS::Patch_boundaries<Mesh> b = FS::compute_patch_boundaries(m, vlabel);
  BOOST_REQUIRE_EQUAL(b.curves().size(), 1u);
  const auto truth = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0 ? 0 : 1; });
  const auto far = face_labels(m, [](const FE::K::Point_3& c) { return c.x() < 0.6 ? 0 : 1; });
  // Every point of the curve is within 0.2 of x = 0 and at least 0.6 from x = 0.6.
  FS::Boundary_scores s = FS::compare_boundaries(b, as_map(truth), 0.25);
  BOOST_CHECK_EQUAL(s.f_score, 1.);
  BOOST_CHECK_CLOSE(s.boundary_length, b.curves()[0].length(), 1e-9);
  BOOST_CHECK_CLOSE(s.reference_length, 2., 1e-9);
  BOOST_CHECK_GT(s.boundary_length, 2.); // a zigzag through the triangles' centroids
  s = FS::compare_boundaries(b, as_map(far), 0.25);
  BOOST_CHECK_EQUAL(s.precision, 0.);
  BOOST_CHECK_EQUAL(s.recall, 0.);
  BOOST_CHECK_THROW(FS::compare_boundaries(b, as_map(truth), -1.), FS::Invalid_input);
  FS::Feature_lines<Mesh> lines;
  lines.lines.push_back(line_through_vertices(m, 0, -1, 0, 1, 20.));
  FS::Feature_line_scores c = FS::compare_with_feature_lines(b, lines, 0.25);
  BOOST_CHECK_EQUAL(c.coverage, 1.);
  BOOST_CHECK_EQUAL(c.redundant_length, 0.);
  lines.lines[0] = line_through_vertices(m, 0.6, -1, 0.6, 1, 20.);
  c = FS::compare_with_feature_lines(b, lines, 0.25);
  BOOST_CHECK_EQUAL(c.coverage, 0.);
  BOOST_CHECK_CLOSE(c.redundancy_fraction(), 1., 1e-9);
  // Smoothed on flat ground, the curve becomes straight: the segment from border to border.
  FS::smooth_patch_boundaries(b);
  s = FS::compare_boundaries(b, as_map(truth), 0.25);
  BOOST_TEST_MESSAGE("grid curve: length " << s.boundary_length << " after smoothing");
  BOOST_CHECK_CLOSE(s.boundary_length, 2., 0.5);
  BOOST_CHECK_EQUAL(s.f_score, 1.);
}

BOOST_AUTO_TEST_CASE(cut_cost_and_vertex_patches_by_hand)
{
  // One quad (-1,-1), (1,-1), (-1,1), (1,1) split along the diagonal v0-v3.
  const Mesh m = fs_test::to_mesh<Mesh>(fs_test::plane(1., 1));
  BOOST_REQUIRE_EQUAL(m.number_of_faces(), 2u);
  auto vlabel = boost::make_function_property_map<FE::vertex_descriptor>([&](FE::vertex_descriptor v) { return m.point(v).x() < 0 ? 0 : 1; });
  auto length = boost::make_function_property_map<FE::edge_descriptor>([&](FE::edge_descriptor e) {
    return std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  });
  // Cut: the two horizontal sides (2 each) and the diagonal (2 sqrt 2).
  BOOST_CHECK_CLOSE(FS::cut_cost(m, vlabel, length), 4. + 2. * std::sqrt(2.), 1e-9);
  // Faces labelled 5 (the one with v1) and 7 (the one with v2): v1 -> 5, v2 -> 7, and
  // v0, v3 (in both faces: a tie) -> the smaller, 5.
  std::vector<int> fl(2);
  for(auto f : faces(m))
  {
    bool has_v1 = false;
    for(auto v : vertices_around_face(halfedge(f, m), m)) has_v1 |= (m.point(v).x() > 0 && m.point(v).y() < 0);
    fl[f.idx()] = has_v1 ? 5 : 7;
  }
  auto vp = get(CGAL::dynamic_vertex_property_t<int>(), m);
  FS::vertex_patches_from_face_patches(m, as_map(fl), vp);
  for(auto v : vertices(m))
    BOOST_CHECK_EQUAL(get(vp, v), (m.point(v).x() < 0 && m.point(v).y() > 0) ? 7 : 5);
  BOOST_CHECK_EQUAL(FS::number_of_patches(m, as_map(fl)), 2u);
}

// The same annotations in flow and in block style (the latter as PyYAML writes the ABC
// files, with a "---", comments and quoted scalars added) read alike: faces 1 and 0 in a
// plane, face 3 in a surface without type, faces 2 and 4 in none; of the curves, the one
// without vertices is left out.
BOOST_AUTO_TEST_CASE(abc_ground_truth_flow_and_block)
{
  const std::string flow =
    "{curves: [{sharp: true, vert_indices: [0, 1,\n   2]}, {type: Circle}, {sharp: false, vert_indices: [2, 3]}],\n"
    " surfaces: [{face_indices: [1, 0], type: Plane}, {face_indices: [3]}]}\n";
  const std::string block =
    "---\n"
    "# a comment\n"
    "curves:\n"
    "- sharp: True\n"
    "  vert_indices:\n"
    "  - 0\n"
    "  - 1\n"
    "  - 2\n"
    "- type: Circle # no vert_indices\n"
    "- sharp: 'false'\n"
    "  vert_indices: [2, 3]\n"
    "surfaces:\n"
    "  - type: \"Plane\"\n"
    "    face_indices:\n"
    "      - 1\n"
    "      - 0\n"
    "  - face_indices: [3]\n";
  const std::vector<int> face_patch = {0, 0, -1, 1, -1};
  const std::vector<std::string> patch_type = {"Plane", "?"};
  const std::vector<std::size_t> curve0 = {0, 1, 2}, curve1 = {2, 3};
  const std::pair<const char*, std::string> variants[] = {{"flow", flow}, {"block", block}};
  for(const auto& variant : variants)
  {
    BOOST_TEST_CONTEXT(variant.first << " style")
    {
      const Temporary_yml yml(variant.second);
      const FE::Abc_ground_truth gt = FE::read_abc_ground_truth(yml.path.string(), abc_vertices, abc_faces);
      BOOST_CHECK_EQUAL_COLLECTIONS(gt.face_patch.begin(), gt.face_patch.end(), face_patch.begin(), face_patch.end());
      BOOST_CHECK_EQUAL_COLLECTIONS(gt.patch_type.begin(), gt.patch_type.end(), patch_type.begin(), patch_type.end());
      BOOST_REQUIRE_EQUAL(gt.curves.size(), 2u);
      BOOST_CHECK_EQUAL_COLLECTIONS(gt.curves[0].begin(), gt.curves[0].end(), curve0.begin(), curve0.end());
      BOOST_CHECK_EQUAL_COLLECTIONS(gt.curves[1].begin(), gt.curves[1].end(), curve1.begin(), curve1.end());
      BOOST_CHECK(gt.curve_is_sharp == std::vector<bool>({true, false}));
    }
  }
}

// Malformed or inconsistent annotations, and a missing file, throw std::runtime_error
// naming the file and what is wrong.
BOOST_AUTO_TEST_CASE(abc_ground_truth_errors)
{
  check_abc_error("surfaces: [{face_indices: [0], type: Plane}\n", "end of sequence flow not found"); // unclosed '['
  check_abc_error("surfaces: [{face_indices: [0, 5]}]\n", "bad face index '5'"); // faces 0 to 4
  check_abc_error("surfaces: [{face_indices: [-1]}]\n", "bad face index '-1'");
  check_abc_error("surfaces: [{face_indices: [1.5]}]\n", "bad face index '1.5'");
  check_abc_error("surfaces: [{face_indices: [0x1]}]\n", "bad face index '0x1'"); // indices are decimal
  check_abc_error("surfaces: [{face_indices: [[1]]}]\n", "bad face index ''");
  check_abc_error("surfaces: [{face_indices: [0]}, {face_indices: [2, 0]}]\n", "face 0 in two surfaces");
  check_abc_error("surfaces: [{type: Plane}]\n", "a surface without 'face_indices'");
  check_abc_error("surfaces: [{face_indices: 1}]\n", "a surface without 'face_indices'");
  check_abc_error("curves: []\n", "no 'surfaces' sequence");
  check_abc_error("surfaces: {face_indices: [0]}\n", "no 'surfaces' sequence");
  check_abc_error("", "no 'surfaces' sequence");
  check_abc_error("surfaces: []\ncurves: [{vert_indices: [0, 4]}]\n", "bad vertex index '4'"); // vertices 0 to 3
  std::string missing;
  {
    const Temporary_yml yml("");
    missing = yml.path.string();
  } // removed here
  BOOST_CHECK_EXCEPTION(FE::read_abc_ground_truth(missing, abc_vertices, abc_faces), std::runtime_error,
                        names_file_and_says(missing, "cannot read"));
}

BOOST_AUTO_TEST_SUITE_END()
