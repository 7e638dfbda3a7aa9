// SPDX-License-Identifier: GPL-3.0-or-later
// The resolution series. Fandisk at its 13k faces and flat-subdivided (each triangle into
// four by its edge midpoints, CGAL's PTQ with the linear mask: the geometry unchanged)
// once, twice and three times (52k, 207k, 828k faces), segmented by this package at the
// settings of the CAD table's first column: the patch count of each, and the boundary
// precision, recall and F-score of each result against the coarse result's boundaries.
// The meshes differ, so the boundaries are compared as 3D segments
// (compare_boundaries_across_meshes()). Written to OUT/resolution.md and
// OUT/resolution.csv, the markdown printed.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_RESOLUTION_SERIES_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_RESOLUTION_SERIES_H

#include "cad_tables.h"

#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace fs_evaluation {

typedef FS::internal::Evaluation_segment Boundary_segment;

/// The patch boundary of a face labelling of `mesh` as 3D segments: the edges between two
/// faces of different patches (border edges are not boundaries).
inline std::vector<Boundary_segment> boundary_segments(const Mesh& mesh, const std::vector<std::size_t>& face_patch)
{
  auto patches = boost::make_function_property_map<face_descriptor>(
    [&face_patch](face_descriptor f) { return face_patch[f.idx()]; });
  return FS::internal::patch_boundary_segments(mesh, patches, get(CGAL::vertex_point, mesh));
}

/// Boundary precision, recall and F-score of the segments `boundary` against the segments
/// `reference`, which may lie on different meshes of one surface (one part at two
/// resolutions), where compare_boundaries() of metrics.h compares two labellings of one
/// mesh edge by edge. Both boundaries are first cut into pieces no longer than half the
/// tolerance, so that the points sampled, the pieces' midpoints (each weighing its
/// piece's length), are as dense along a coarse edge as along a fine one. A piece is
/// matched when its midpoint lies within `tolerance` of the other boundary; precision is
/// the matched share of `boundary`'s length, recall that of `reference`'s.
inline FS::Boundary_scores compare_boundaries_across_meshes(const std::vector<Boundary_segment>& boundary,
                                                            const std::vector<Boundary_segment>& reference,
                                                            double tolerance)
{
  const auto pieces = [tolerance](const std::vector<Boundary_segment>& segments) {
    std::vector<Boundary_segment> result;
    for(const Boundary_segment& s : segments)
    {
      const double length = std::sqrt(s.squared_length());
      const std::size_t n =
        tolerance > 0 ? (std::max)(std::size_t(1), std::size_t(std::ceil(length / (0.5 * tolerance)))) : 1;
      const auto step = (s.target() - s.source()) / double(n);
      for(std::size_t i = 0; i < n; ++i)
        result.emplace_back(s.source() + double(i) * step, s.source() + double(i + 1) * step);
    }
    return result;
  };
  return FS::internal::compare_boundary_segments(pieces(boundary), pieces(reference), tolerance);
}

/// Subdivides `mesh` flat once: every triangle into four by its edge midpoints (CGAL's PTQ
/// with the linear mask), the geometry unchanged.
inline void subdivide_flat(Mesh& mesh)
{
  CGAL::Subdivision_method_3::PTQ(mesh, CGAL::Linear_mask_3<Mesh>(&mesh, get(CGAL::vertex_point, mesh)),
                                  CGAL::parameters::number_of_iterations(1));
}

/// Fandisk's resolution series: the mesh of `fandisk` and its `levels` flat subdivisions,
/// each segmented by run_package() at `options`, scored against the coarse result; writes
/// OUT/resolution.md and OUT/resolution.csv and prints the markdown. Returns false,
/// having said why, when the mesh cannot be read.
inline bool run_resolution_series(const std::string& fandisk, const std::string& out, const Cad_options& options,
                                  const std::string& machine, int levels = 3)
{
  Mesh mesh;
  if(!PMP::IO::read_polygon_mesh(fandisk, mesh) || is_empty(mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cout << "evaluate_quality: " << fandisk << " is not a readable triangle mesh: resolution series skipped"
              << std::endl;
    return false;
  }
  const double tolerance = FS::default_boundary_tolerance(mesh); // the geometry, hence the diagonal, stays
  std::vector<Boundary_segment> coarse;
  Text_table md, csv;
  md.header = {"subdivisions", "faces", "patches", "boundary P", "boundary R", "boundary F", "seconds"};
  csv.header = {"subdivisions", "faces", "patches", "precision", "recall", "f", "seconds"};
  for(int level = 0; level <= levels; ++level)
  {
    if(level > 0) subdivide_flat(mesh);
    std::cerr << "evaluate_quality: fandisk subdivided " << level << " times (" << mesh.number_of_faces() << " faces)"
              << std::endl;
    const Segmentation s = run_package(mesh, options, false);
    const std::vector<Boundary_segment> boundary = boundary_segments(mesh, s.face_patch);
    if(level == 0) coarse = boundary;
    const FS::Boundary_scores b = compare_boundaries_across_meshes(boundary, coarse, tolerance);
    const std::string faces = std::to_string(mesh.number_of_faces());
    const std::string patches = std::to_string(number_of_distinct(s.face_patch));
    md.rows.push_back({std::to_string(level) + (level == 0 ? " (reference)" : ""), faces, patches, fmt(b.precision),
                       fmt(b.recall), "**" + fmt(b.f_score) + "**", fmt(s.seconds, 2)});
    csv.rows.push_back({std::to_string(level), faces, patches, fmt(b.precision, 6), fmt(b.recall, 6),
                        fmt(b.f_score, 6), fmt(s.seconds, 3)});
  }
  std::ofstream csv_file(std::filesystem::path(out) / "resolution.csv");
  csv.write_csv(csv_file);
  std::ostringstream text;
  text << "# Resolution series (fandisk)\n\nMachine: " << machine << ". Produced by `evaluate_quality` "
       << "(evaluation/resolution_series.h): " << fandisk << " and its flat subdivisions (each triangle into four by its "
       << "edge midpoints, CGAL's PTQ with Linear_mask_3: the geometry unchanged), segmented by this package with "
       << settings_text(options) << ". Boundary precision, recall and F-score of each result against the boundary "
       << "of the coarse result, tolerance 1% of the diagonal, the two boundaries compared as 3D segments cut in "
       << "pieces of at most half the tolerance (compare_boundaries_across_meshes()).\n\n";
  md.write_markdown(text);
  write_and_print(std::filesystem::path(out) / "resolution.md", text.str());
  return true;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_RESOLUTION_SERIES_H
