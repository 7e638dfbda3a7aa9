// SPDX-License-Identifier: GPL-3.0-or-later
// The segmentation methods the quality evaluation compares, run on one mesh with shared
// precomputation, and their scores with the metrics of metrics.h. Shared by the evaluation program (evaluate_quality) and by the ctest
// floors (test_evaluation_floors), so that both measure the same thing.
//
// Methods (face labels in the mesh's face order):
// - this package's correlation clustering: on the full vertex graph, on the geodesic
//   watershed graph and on the anisotropic watershed graph (the default), at an alpha;
//   as segment_along_features() returns it (faces: the majority of their vertices), or
//   with its boundaries smoothed (smooth_patch_boundaries(); faces: the patch covering
//   most of their area, majority_face_patches(); the curves kept for curve scores);
// - CGAL's Polygon_mesh_processing::sharp_edges_segmentation at a dihedral angle;
// - CGAL's variational shape approximation (approximate_triangle_mesh, L21 metric,
//   hierarchical seeding) with a given number of proxies.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_METHODS_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_METHODS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/edge_weights.h>
#include "metrics.h"
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>

#include <CGAL/Dynamic_property_map.h>
#include <boost/property_map/function_property_map.hpp>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ransac.h"

namespace fs_evaluation {

namespace FS = CGAL::Feature_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Edge_index edge_descriptor;
typedef FS::Principal_curvatures<K> Curvatures;
typedef FS::Feature_lines<Mesh> Lines;
typedef FS::Patch_boundaries<Mesh> Boundaries;

/// The package's default alpha, the parameter every "default" row uses.
constexpr double default_alpha = 0.6;
/// The alphas of the sweep ("best" rows); the paper's useful range is 0.5 to 1.0.
inline std::vector<double> alpha_sweep() { return {0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2}; }
/// The angle CGAL's own example (detect_features_example.cpp) passes to
/// sharp_edges_segmentation: the "default" row of the baseline.
constexpr double default_sharp_angle = 90.;
/// The angles of the sweep of sharp_edges_segmentation, in degrees.
inline std::vector<double> angle_sweep()
{
  std::vector<double> a;
  for(int d = 10; d <= 90; d += 5) a.push_back(d);
  return a;
}

/// The correlation-clustering variants of this package.
enum class Cc_variant { FULL_GRAPH, GEODESIC_WATERSHED, ANISOTROPIC_WATERSHED };

inline std::string name(Cc_variant v)
{
  switch(v)
  {
    case Cc_variant::FULL_GRAPH: return "CC full graph";
    case Cc_variant::GEODESIC_WATERSHED: return "CC geodesic watershed";
    default: return "CC anisotropic watershed";
  }
}

/// One segmentation of a mesh.
struct Segmentation
{
  std::string method;                    ///< e.g. "CC anisotropic watershed"
  std::string setting;                   ///< e.g. "alpha 0.6", "angle 45"
  std::vector<std::size_t> face_patch;   ///< per face index
  std::vector<std::size_t> vertex_patch; ///< per vertex index (from the faces for face-based methods)
  double seconds = 0;
  /// With smoothed boundaries (smooth_cc()): the smoothed curves; else null.
  std::shared_ptr<const Boundaries> curves;
  bool is_smoothed() const { return curves != nullptr; }
};

/// A mesh with what every method shares: curvatures, feature lines (pruned with the
/// default strength threshold and unpruned), the reference weights of the cut cost.
struct Prepared_mesh
{
  const Mesh& mesh;
  typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<Curvatures> >::const_type curvature;
  Lines pruned, unpruned;
  std::vector<double> weight; ///< per edge index: w(e) at default_alpha with the pruned lines
  double tolerance = 0;       ///< default boundary tolerance (1% of the bounding-box diagonal)
  std::vector<double> face_area;

  explicit Prepared_mesh(const Mesh& m)
    : mesh(m), curvature(get(CGAL::dynamic_vertex_property_t<Curvatures>(), m))
  {
    // the paper's fit: two rings, no radius (neighborhood_radius 0)
    FS::estimate_principal_curvatures(mesh, curvature, FS::parameters::neighborhood_radius(0.));
    unpruned = FS::detect_crest_lines(mesh, curvature, FS::parameters::strength_threshold(0.));
    pruned = FS::detect_crest_lines(mesh, curvature);
    auto wmap = get(CGAL::dynamic_edge_property_t<double>(), mesh);
    FS::compute_edge_weights(mesh, wmap,
                             FS::parameters::alpha(default_alpha).principal_curvature_map(curvature).feature_lines(pruned));
    weight.resize(mesh.number_of_edges());
    for(auto e : edges(mesh)) weight[e.idx()] = get(wmap, e);
    tolerance = FS::default_boundary_tolerance(mesh);
    face_area.resize(mesh.number_of_faces());
    for(auto f : faces(mesh))
    {
      auto h = halfedge(f, mesh);
      face_area[f.idx()] = std::sqrt(K::Triangle_3(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                                   mesh.point(target(next(h, mesh), mesh))).squared_area());
    }
  }
};

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Vertex labels of a face-based method, for the cut cost.
inline void derive_vertex_patches(const Mesh& mesh, Segmentation& s)
{
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  auto fmap = [&](face_descriptor f) { return s.face_patch[f.idx()]; };
  FS::vertex_patches_from_face_patches(mesh, boost::make_function_property_map<face_descriptor>(fmap), vp);
  s.vertex_patch.resize(mesh.number_of_vertices());
  for(auto v : vertices(mesh)) s.vertex_patch[v.idx()] = get(vp, v);
}

/// This package's segmentation at `alpha`, with the pruned (default) or unpruned lines,
/// as the paper describes it (crease_angle 180: no crease cut).
inline Segmentation run_cc(const Prepared_mesh& pm, Cc_variant variant, double alpha, bool pruned = true)
{
  const Mesh& mesh = pm.mesh;
  auto vpatch = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  auto fpatch = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const auto t0 = std::chrono::steady_clock::now();
  const Lines& lines = pruned ? pm.pruned : pm.unpruned;
  FS::segment_along_features(
    mesh, vpatch,
    FS::parameters::alpha(alpha)
      .crease_angle(180.) // the paper's variants; the crease cut is scored by the CAD table (cad_parts.h)
      .principal_curvature_map(pm.curvature)
      .feature_lines(std::cref(lines))
      .use_oversegmentation(variant != Cc_variant::FULL_GRAPH)
      .watershed_distance(variant == Cc_variant::GEODESIC_WATERSHED ? FS::Watershed_distance::GEODESIC
                                                                    : FS::Watershed_distance::ANISOTROPIC)
      .face_patch_map(fpatch));
  Segmentation s;
  s.seconds = seconds_since(t0);
  s.method = name(variant);
  char buf[64];
  std::snprintf(buf, sizeof(buf), "alpha %.1f%s", alpha, pruned ? "" : ", unpruned lines");
  s.setting = buf;
  s.face_patch.resize(mesh.number_of_faces());
  s.vertex_patch.resize(mesh.number_of_vertices());
  for(auto f : faces(mesh)) s.face_patch[f.idx()] = get(fpatch, f);
  for(auto v : vertices(mesh)) s.vertex_patch[v.idx()] = get(vpatch, v);
  return s;
}

/// `s`, a result of run_cc() on `pm` (with the pruned or unpruned lines, as `pruned`
/// says), with its boundaries smoothed as the package's command-line program does:
/// compute_patch_boundaries() in the metric of the same curvatures and lines, then
/// smooth_patch_boundaries() with its defaults (20 iterations at most). The face patches
/// are those of majority_face_patches() (the patch covering most of a face's area), the
/// vertex patches those after smoothing (a vertex the boundary crossed changes patch), and
/// the curves are kept. `seconds` adds the boundaries' time to the segmentation's.
inline Segmentation smooth_cc(const Prepared_mesh& pm, const Segmentation& s, bool pruned = true)
{
  const Mesh& mesh = pm.mesh;
  auto vpatch = boost::make_function_property_map<vertex_descriptor>(
    [&s](vertex_descriptor v) { return s.vertex_patch[v.idx()]; });
  const auto t0 = std::chrono::steady_clock::now();
  auto boundaries = std::make_shared<Boundaries>(FS::compute_patch_boundaries(
    mesh, vpatch, FS::parameters::principal_curvature_map(pm.curvature)
                    .feature_lines(std::cref(pruned ? pm.pruned : pm.unpruned))));
  FS::smooth_patch_boundaries(*boundaries);
  auto fpatch = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  auto vsmooth = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  FS::majority_face_patches(*boundaries, fpatch);
  boundaries->write_vertex_patches(vsmooth);
  Segmentation r;
  r.seconds = s.seconds + seconds_since(t0);
  r.method = s.method;
  r.setting = s.setting;
  r.face_patch.resize(mesh.number_of_faces());
  r.vertex_patch.resize(mesh.number_of_vertices());
  for(auto f : faces(mesh)) r.face_patch[f.idx()] = get(fpatch, f);
  for(auto v : vertices(mesh)) r.vertex_patch[v.idx()] = get(vsmooth, v);
  r.curves = boundaries;
  return r;
}

/// CGAL's sharp_edges_segmentation: patches are the components of faces separated by
/// edges whose dihedral angle deviates from flat by more than `angle` degrees.
inline Segmentation run_sharp_edges(const Mesh& mesh, double angle)
{
  auto eif = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
  auto pid = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const auto t0 = std::chrono::steady_clock::now();
  PMP::sharp_edges_segmentation(mesh, angle, eif, pid);
  Segmentation s;
  s.seconds = seconds_since(t0);
  s.method = "PMP sharp edges";
  s.setting = "angle " + std::to_string(static_cast<int>(angle));
  s.face_patch.resize(mesh.number_of_faces());
  for(auto f : faces(mesh)) s.face_patch[f.idx()] = get(pid, f);
  derive_vertex_patches(mesh, s);
  return s;
}

/// CGAL's variational shape approximation with `k` proxies (L21 metric, hierarchical
/// seeding, CGAL's default number of iterations). VSA draws its seeds with std::rand,
/// seeded here for a reproducible result.
inline Segmentation run_vsa(const Mesh& mesh, std::size_t k, unsigned seed = 1)
{
  auto proxy = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::srand(seed);
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::Surface_mesh_approximation::approximate_triangle_mesh(
    mesh, CGAL::parameters::max_number_of_proxies(k)
            .seeding_method(CGAL::Surface_mesh_approximation::HIERARCHICAL)
            .face_proxy_map(proxy));
  Segmentation s;
  s.seconds = seconds_since(t0);
  s.method = "VSA";
  s.setting = std::to_string(k) + " proxies";
  s.face_patch.resize(mesh.number_of_faces());
  for(auto f : faces(mesh)) s.face_patch[f.idx()] = get(proxy, f);
  derive_vertex_patches(mesh, s);
  return s;
}

/// CGAL's Efficient RANSAC on the face centroids and normals (efficient_ransac_face_patches()).
inline Segmentation run_efficient_ransac(const Mesh& mesh)
{
  const auto t0 = std::chrono::steady_clock::now();
  Segmentation s;
  s.face_patch = efficient_ransac_face_patches(mesh);
  s.seconds = seconds_since(t0);
  s.method = "Efficient RANSAC";
  s.setting = "planes, cylinders, cones, spheres, tori";
  derive_vertex_patches(mesh, s);
  return s;
}

/// The scores of one segmentation.
struct Scores
{
  std::size_t patches = 0;
  double cut_cost = 0;              ///< Eq. 1 with the reference weights (alpha 0.6, pruned lines)
  FS::Feature_line_scores lines;    ///< against the pruned detected lines
  bool has_ground_truth = false;
  FS::Boundary_scores boundary;     ///< against the ground-truth patches
  FS::Partition_scores partition;   ///< against the ground-truth patches
  double sharp_curve_recall = 0;    ///< share of ground-truth sharp-curve length within the tolerance of a boundary
  bool is_smoothed = false;         ///< curve_lines is set
  FS::Feature_line_scores curve_lines; ///< the smoothed curves themselves against the pruned detected lines
  bool has_curve_scores = false;    ///< smoothed, with a ground truth: curve_boundary is set
  FS::Boundary_scores curve_boundary; ///< the smoothed curves themselves against the ground-truth patches
};

/// Ground-truth sharp curves as feature lines through mesh vertices (a point at t = 0 of
/// an outgoing halfedge), so that compare_with_feature_lines() measures their coverage.
inline Lines curves_as_lines(const Mesh& mesh, const std::vector<std::vector<std::size_t> >& curves,
                             const std::vector<bool>& sharp)
{
  Lines lines;
  for(std::size_t c = 0; c < curves.size(); ++c)
  {
    if(!sharp[c] || curves[c].size() < 2) continue;
    FS::Feature_line<Mesh> l;
    l.type = FS::Feature_line_type::USER;
    l.strength = 1.;
    for(std::size_t v : curves[c])
    {
      FS::Feature_point<Mesh> p;
      p.halfedge = opposite(halfedge(vertex_descriptor(static_cast<Mesh::size_type>(v)), mesh), mesh);
      p.t = 0.;
      l.points.push_back(p);
    }
    lines.lines.push_back(l);
  }
  return lines;
}

/// Scores `s` on `pm`; `ground_truth` (per face, may be empty) and `sharp_curves` when known.
/// Every score but the cut cost (on the vertex patches) is computed on the face patches;
/// for a smoothed segmentation, the coverage and redundancy (curve_lines) and, with a
/// ground truth, the boundary scores (curve_boundary) are computed on the smoothed curves too.
inline Scores score(const Prepared_mesh& pm, const Segmentation& s, const std::vector<int>& ground_truth,
                    const Lines* sharp_curves = nullptr)
{
  const Mesh& mesh = pm.mesh;
  auto fmap = boost::make_function_property_map<face_descriptor>([&](face_descriptor f) { return s.face_patch[f.idx()]; });
  auto vmap = boost::make_function_property_map<vertex_descriptor>([&](vertex_descriptor v) { return s.vertex_patch[v.idx()]; });
  auto wmap = boost::make_function_property_map<edge_descriptor>([&](edge_descriptor e) { return pm.weight[e.idx()]; });
  Scores r;
  r.patches = FS::number_of_patches(mesh, fmap);
  r.cut_cost = FS::cut_cost(mesh, vmap, wmap);
  r.lines = FS::compare_with_feature_lines(mesh, fmap, pm.pruned, pm.tolerance);
  if(s.is_smoothed())
  {
    r.is_smoothed = true;
    r.curve_lines = FS::compare_with_feature_lines(*s.curves, pm.pruned, pm.tolerance);
  }
  if(!ground_truth.empty())
  {
    r.has_ground_truth = true;
    auto gmap = boost::make_function_property_map<face_descriptor>([&](face_descriptor f) { return ground_truth[f.idx()]; });
    r.boundary = FS::compare_boundaries(mesh, fmap, gmap, pm.tolerance);
    r.partition = FS::compare_partitions(s.face_patch, ground_truth, pm.face_area);
    if(sharp_curves != nullptr)
      r.sharp_curve_recall = FS::compare_with_feature_lines(mesh, fmap, *sharp_curves, pm.tolerance, 0.).coverage;
    if(s.is_smoothed())
    {
      r.has_curve_scores = true;
      r.curve_boundary = FS::compare_boundaries(*s.curves, gmap, pm.tolerance);
    }
  }
  return r;
}

/// The selection score of a sweep: the boundary F-score when a ground truth is known,
/// else the harmonic mean of feature-line coverage and of the share of boundary that a
/// feature line supports (1 - redundancy), so that a sweep never looks at a ground truth
/// it does not have.
inline double selection_score(const Scores& s)
{
  if(s.has_ground_truth) return s.boundary.f_score;
  const double a = s.lines.coverage, b = 1. - s.lines.redundancy_fraction();
  return (a + b > 0) ? 2 * a * b / (a + b) : 0.;
}

/// A copy of `mesh` whose vertices moved along their normals by a normal deviate of
/// standard deviation `relative_sigma` times the bounding-box diagonal (seeded:
/// Box-Muller on std::mt19937_64, the same numbers on every platform).
inline Mesh add_normal_noise(const Mesh& mesh, double relative_sigma, std::uint64_t seed)
{
  Mesh noisy = mesh;
  const double sigma = relative_sigma * FS::bounding_box_diagonal(mesh);
  std::vector<K::Vector_3> normals(mesh.number_of_vertices());
  for(auto v : vertices(mesh)) normals[v.idx()] = PMP::compute_vertex_normal(v, mesh);
  std::mt19937_64 rng(seed);
  const double two_pi = 6.283185307179586;
  auto uniform = [&]() { return (static_cast<double>(rng() >> 11) + 0.5) / 9007199254740992.0; }; // (0, 1)
  for(auto v : vertices(noisy))
  {
    const double g = std::sqrt(-2. * std::log(uniform())) * std::cos(two_pi * uniform());
    noisy.point(v) = noisy.point(v) + (sigma * g) * normals[v.idx()];
  }
  return noisy;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_METHODS_H
