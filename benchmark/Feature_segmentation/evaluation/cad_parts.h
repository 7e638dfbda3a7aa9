// SPDX-License-Identifier: GPL-3.0-or-later
// The CAD part of the quality evaluation (issue 13), run by evaluate_quality.
//
// The CAD table. The parts of DATA/cad (NAME.obj, a closed triangle mesh meshed from a
// B-rep, and NAME.labels, the B-rep face of every triangle, in the OBJ's face order),
// scored by the boundary F-score at 1% of the bounding-box diagonal (compare_boundaries()
// of metrics.h, on the face patches, against the B-rep faces) and by the Rand index of
// the face patches (rand_index(), faces weighted by area) for:
// - this package at its defaults: creases at 20 degrees, normals filtered before the
//   creases are found (none on a clean mesh), curvature discontinuities, alpha 0.6 (the
//   command line may change alpha, the strength threshold, the filter, the
//   discontinuities and the crest lines: Cad_options);
// - the paper's pipeline (crease_angle 180: crest lines only; fitted on rings alone,
//   neighborhood_radius 0), alpha 0.6 and the default strength threshold;
// - CGAL's sharp_edges_segmentation at 20, 45 and 60 degrees;
// - CGAL's variational shape approximation given the true patch count (seeded);
// each at the noise levels asked (Gaussian, along the vertex normals, standard deviation
// relative to the diagonal, seed 1; by default 0, 0.1% and 0.3%). For every part it
// also gives the share of true boundary length whose dihedral angle is below 20 degrees
// (tangent-continuous: a fillet meeting a plane), which no crease threshold can see. The
// ABC models of DATA/abc (NAME.obj with NAME.yml, e.g. the hex nut) follow the CAD
// parts, outside their mean. Written to OUT/cad_parts.md (the means, then a table per
// noise level) and OUT/cad_parts.csv (a row per part, noise level and method, then the
// means), the markdown printed.
//
// The resolution series is in resolution_series.h; the tables are written by cad_tables.h.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PARTS_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PARTS_H

#include "abc_ground_truth.h"
#include "cad_part_reader.h"
#include "methods.h"
#include "report.h"
#include "scenes.h"

#include "read_input_mesh.h" // the program's reader: the parts are read as a user's files are

#include <unistd.h> // getpid: a temporary file per process
#include <zlib.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fs_evaluation {

/// The settings of the CAD table and of the resolution series: the noise levels, and the
/// parameters of this package's first column (the library's defaults unless the command
/// line changes them). The paper's column shares the filter, the discontinuities and the
/// crest-line switch, but keeps the paper's alpha and strength threshold.
struct Cad_options
{
  std::vector<double> noise = {0., 0.001, 0.003}; ///< standard deviations, fractions of the diagonal
  /// The noise realisations a noisy level is scored on (seeds 1 to noise_seeds): its scores
  /// are their means (patch counts rounded).
  int noise_seeds = 1;
  int crease_filter = FS::default_crease_filter_iterations;
  double alpha = FS::default_alpha;
  double strength_threshold = FS::default_strength_threshold;
  bool tangent = FS::default_tangent_discontinuities;
  bool crest_lines = FS::default_crest_lines_on_clean_tessellations;
  std::set<std::string> methods; ///< the CSV names of cad_methods() to run; empty: all
  /// Whether the method of cad_methods() at `k` runs.
  bool runs(std::size_t k) const;
};

/// The settings of the first column, for the reports.
inline std::string settings_text(const Cad_options& o)
{
  return "alpha " + plain(o.alpha) + ", strength threshold " + plain(o.strength_threshold) + ", crease filter " +
         std::to_string(o.crease_filter) + " rounds, curvature discontinuities " + (o.tangent ? "on" : "off") +
         ", crest lines on clean tessellations " + (o.crest_lines ? "on" : "off");
}

/// The number of distinct labels.
template <typename Label>
std::size_t number_of_distinct(const std::vector<Label>& labels)
{
  return std::set<Label>(labels.begin(), labels.end()).size();
}

/// The share of the true boundary length (edges between faces of different labels) whose
/// dihedral angle is below 20 degrees: tangent-continuous boundaries, which no crease
/// threshold finds.
inline double tangent_continuous_share(const Mesh& mesh, const std::vector<int>& labels)
{
  double low = 0, total = 0;
  for(auto e : edges(mesh))
  {
    if(is_border(e, mesh)) continue;
    const auto h = halfedge(e, mesh);
    const auto f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    if(labels[f.idx()] == labels[g.idx()]) continue;
    const double length = std::sqrt(CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(target(h, mesh))));
    const double c = PMP::compute_face_normal(f, mesh) * PMP::compute_face_normal(g, mesh);
    total += length;
    if(std::acos((std::max)(-1., (std::min)(1., c))) * 180. / CGAL_PI < 20.) low += length;
  }
  return total > 0 ? low / total : 0.;
}

/// This package on `mesh` at the settings of `options` or, with `paper`, the paper's
/// pipeline (crease_angle 180: crest lines only, fitted on rings alone; the library's
/// alpha and strength threshold). Face patches only.
inline Segmentation run_package(const Mesh& mesh, const Cad_options& options, bool paper)
{
  const FS::internal::Segmentation_options library;
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  auto fp = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const auto t0 = std::chrono::steady_clock::now();
  FS::segment_along_features(mesh, vp,
                             FS::parameters::crease_angle(paper ? 180. : library.crease_angle)
                               .alpha(paper ? library.alpha : options.alpha)
                               .strength_threshold(paper ? FS::default_strength_threshold : options.strength_threshold)
                               .crease_filter_iterations(options.crease_filter)
                               .tangent_discontinuities(options.tangent)
                               .crest_lines_on_clean_tessellations(options.crest_lines)
                               .neighborhood_radius(paper ? 0. : FS::default_neighborhood_radius)
                               .face_patch_map(fp));
  Segmentation s;
  s.seconds = seconds_since(t0);
  s.method = paper ? "paper's pipeline" : "this package";
  s.setting = paper ? "crease angle 180, radius 0" : settings_text(options);
  s.face_patch.resize(mesh.number_of_faces());
  for(auto f : faces(mesh)) s.face_patch[f.idx()] = get(fp, f);
  return s;
}

/// A method's result on a part: its patch count and boundary scores against the labels.
struct Cad_score
{
  std::size_t patches = 0;
  std::size_t small_patches = 0; ///< patches under 0.1% of the area (small_patch_share)
  FS::Boundary_scores boundary;
  /// FS::rand_index() of the face labels against the true ones, faces weighted by area:
  /// low where patches merge true ones; small patches (confetti) hardly lower it
  double rand_index = 0;
  double seconds = 0;
  bool ran = true; ///< false: the method was not selected (Cad_options::methods)
};

/// The area share under which a patch counts as small in the tables (confetti).
constexpr double small_patch_share = 0.001;

/// The number of patches of `face_patch` whose area (the sum of `area`, one per face) is
/// below `share` of the whole area.
inline std::size_t number_of_small_patches(const std::vector<double>& area, const std::vector<std::size_t>& face_patch,
                                           double share = small_patch_share)
{
  std::map<std::size_t, double> patch_area;
  double total = 0;
  for(std::size_t f = 0; f < face_patch.size(); ++f)
  {
    patch_area[face_patch[f]] += area[f];
    total += area[f];
  }
  std::size_t n = 0;
  for(const auto& pa : patch_area) n += pa.second < share * total ? 1 : 0;
  return n;
}

/// The columns of the CAD table, in the order of run_cad_methods(): (CSV name, header).
inline const std::vector<std::pair<std::string, std::string> >& cad_methods()
{
  static const std::vector<std::pair<std::string, std::string> > methods = {
    {"default", "this package (defaults)"}, {"paper", "paper's pipeline"}, {"sharp20", "sharp edges 20"},
    {"sharp45", "sharp edges 45"},          {"sharp60", "sharp edges 60"}, {"ransac", "Efficient RANSAC"},
    {"vsa", "VSA (true count)"}};
  return methods;
}

inline bool Cad_options::runs(std::size_t k) const { return methods.empty() || methods.count(cad_methods()[k].first) > 0; }

/// Runs the methods of cad_methods() that `options` selects on `mesh` (a part, maybe
/// noisy) and scores them against `labels` at 1% of `mesh`'s diagonal; the others get a
/// score of zero (Cad_score::ran false).
inline std::vector<Cad_score> run_cad_methods(const Mesh& mesh, const std::vector<int>& labels,
                                              std::size_t true_patches, const Cad_options& options)
{
  const std::function<Segmentation()> method[] = {
    [&] { return run_package(mesh, options, false); }, [&] { return run_package(mesh, options, true); },
    [&] { return run_sharp_edges(mesh, 20.); },        [&] { return run_sharp_edges(mesh, 45.); },
    [&] { return run_sharp_edges(mesh, 60.); },        [&] { return run_efficient_ransac(mesh); },
    [&] { return run_vsa(mesh, true_patches); }};
  auto truth =
    boost::make_function_property_map<face_descriptor>([&labels](face_descriptor f) { return labels[f.idx()]; });
  std::vector<double> area;
  area.reserve(mesh.number_of_faces());
  for(auto f : faces(mesh)) area.push_back(PMP::face_area(f, mesh));
  std::vector<Cad_score> scores;
  for(std::size_t k = 0; k < cad_methods().size(); ++k)
  {
    if(!options.runs(k))
    {
      scores.emplace_back();
      scores.back().ran = false;
      continue;
    }
    const Segmentation s = method[k]();
    auto patches = boost::make_function_property_map<face_descriptor>(
      [&s](face_descriptor f) { return s.face_patch[f.idx()]; });
    Cad_score r;
    r.patches = number_of_distinct(s.face_patch);
    r.small_patches = number_of_small_patches(area, s.face_patch);
    r.boundary = FS::compare_boundaries(mesh, patches, truth, FS::default_boundary_tolerance(mesh));
    r.rand_index = FS::rand_index(s.face_patch, labels, area);
    r.seconds = s.seconds;
    scores.push_back(r);
  }
  return scores;
}

/// The means of the scores of one or more runs of the same methods (noise realisations):
/// boundary scores, Rand indices and seconds averaged, patch counts averaged and rounded
/// (one run: its own scores).
inline std::vector<Cad_score> mean_scores(const std::vector<std::vector<Cad_score> >& runs)
{
  std::vector<Cad_score> mean = runs.front();
  const double n = double(runs.size());
  for(std::size_t k = 0; k < mean.size(); ++k)
  {
    if(!mean[k].ran) continue;
    double patches = 0, small = 0, rand = 0;
    FS::Boundary_scores b;
    b.precision = b.recall = b.f_score = 0.;
    double seconds = 0;
    for(const auto& run : runs)
    {
      const Cad_score& s = run[k];
      patches += double(s.patches);
      small += double(s.small_patches);
      rand += s.rand_index / n;
      b.precision += s.boundary.precision / n;
      b.recall += s.boundary.recall / n;
      b.f_score += s.boundary.f_score / n;
      b.boundary_length += s.boundary.boundary_length / n;
      b.reference_length += s.boundary.reference_length / n;
      seconds += s.seconds / n;
    }
    mean[k].patches = std::size_t(std::lround(patches / n));
    mean[k].small_patches = std::size_t(std::lround(small / n));
    mean[k].boundary = b;
    mean[k].rand_index = rand;
    mean[k].seconds = seconds;
  }
  return mean;
}

/// The results on one part.
struct Cad_result
{
  std::string name;
  std::string set; ///< part_set(): "cad" and "abc-dev" make the development set, "abc" follows it
  std::size_t faces = 0, true_patches = 0;
  double tangent_share = 0;
  double band_share = 0; ///< FS::boundary_band_share() of the true patches at 1% of the diagonal
  std::vector<std::vector<Cad_score> > scores; ///< [noise level][method]
  std::filesystem::path path;                   ///< the part's file, read again for its scene
  Part_format format = Part_format::OBJ_LABELS;
};

/// Reads a part (read_cad_part()) and runs the methods at every noise level.
inline bool evaluate_cad_part(const std::filesystem::path& path, Part_format format, const Cad_options& options,
                              Cad_result& result, std::string& error)
{
  Cad_part part;
  if(!read_cad_part(path, format, part, error)) return false;
  result.name = part.name;
  result.path = path;
  result.format = format;
  result.set = part_set(format);
  result.faces = part.mesh.number_of_faces();
  result.true_patches = number_of_distinct(part.labels);
  result.tangent_share = tangent_continuous_share(part.mesh, part.labels);
  result.band_share = FS::boundary_band_share(
    part.mesh, boost::make_function_property_map<face_descriptor>([&part](face_descriptor f) { return part.labels[f.idx()]; }),
    FS::default_boundary_tolerance(part.mesh));
  std::cerr << "evaluate_quality: CAD part " << part.name << " (" << result.faces << " faces)" << std::endl;
  for(double sigma : options.noise)
  {
    if(!(sigma > 0))
    {
      result.scores.push_back(run_cad_methods(part.mesh, part.labels, result.true_patches, options));
      continue;
    }
    // seeds 1 to noise_seeds at every level (results/cad_parts.csv: seed 1 alone)
    std::vector<std::vector<Cad_score> > runs;
    for(int seed = 1; seed <= options.noise_seeds; ++seed)
      runs.push_back(
        run_cad_methods(add_normal_noise(part.mesh, sigma, std::uint64_t(seed)), part.labels, result.true_patches, options));
    result.scores.push_back(mean_scores(runs));
  }
  return true;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_PARTS_H
