// SPDX-License-Identifier: GPL-3.0-or-later
// The CAD table run (run_cad_table) and written: OUT/cad_parts.md and OUT/cad_parts.csv
// (means per group, then a table per noise level), and the scenes of the worst parts for
// the contact sheet.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_TABLES_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_TABLES_H

#include "cad_parts.h"
#include "report.h"
#include "scenes.h"

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

/// Writes `text` to `path` and prints it.
inline void write_and_print(const std::filesystem::path& path, const std::string& text)
{
  std::ofstream file(path);
  file << text;
  std::cout << "\n" << text << std::flush;
  if(file) std::cout << "evaluate_quality: wrote " << path.string() << " and its .csv" << std::endl;
  else std::cerr << "evaluate_quality: cannot write " << path.string() << std::endl;
}

/// The groups whose means the tables give: (name, sets in it).
inline const std::vector<std::pair<std::string, std::vector<std::string> > >& cad_groups()
{
  static const std::vector<std::pair<std::string, std::vector<std::string> > > groups = {
    {"development (cad + abc-dev)", {"cad", "abc-dev"}}, {"cad", {"cad"}}, {"abc-dev", {"abc-dev"}},
    {"generated", {"generated"}}};
  return groups;
}

/// The mean of `value` (of a Cad_score) of each method at noise level `l` over the parts
/// of `sets`, and the number of those parts.
template <typename Value>
std::pair<std::vector<double>, std::size_t> mean_over_parts(const std::vector<Cad_result>& results,
                                                            const std::vector<std::string>& sets, std::size_t l,
                                                            Value value)
{
  std::vector<double> mean(cad_methods().size(), 0.);
  std::size_t parts = 0;
  for(const Cad_result& r : results)
    if(std::find(sets.begin(), sets.end(), r.set) != sets.end())
    {
      ++parts;
      for(std::size_t k = 0; k < mean.size(); ++k) mean[k] += value(r.scores[l][k]);
    }
  for(double& x : mean) x = parts > 0 ? x / double(parts) : 0.;
  return {mean, parts};
}

/// The mean boundary F of each method at noise level `l` over the parts of `sets`, and
/// the number of those parts.
inline std::pair<std::vector<double>, std::size_t> mean_f(const std::vector<Cad_result>& results,
                                                          const std::vector<std::string>& sets, std::size_t l)
{
  return mean_over_parts(results, sets, l, [](const Cad_score& s) { return s.boundary.f_score; });
}

/// The mean area-weighted Rand index (Cad_score::rand_index) of each method at noise
/// level `l` over the parts of `sets`.
inline std::vector<double> mean_rand_index(const std::vector<Cad_result>& results,
                                           const std::vector<std::string>& sets, std::size_t l)
{
  return mean_over_parts(results, sets, l, [](const Cad_score& s) { return s.rand_index; }).first;
}

/// Writes OUT/cad_parts.md and OUT/cad_parts.csv, and prints the markdown.
inline void write_cad_tables(const std::string& out, const Cad_options& options, const std::vector<Cad_result>& results,
                             const std::string& machine)
{
  const auto& methods = cad_methods();
  const std::size_t levels = options.noise.size();

  Text_table csv;
  csv.header = {"set", "part", "faces", "true_patches", "tangent_share", "band_share", "noise", "method",
                "patches", "small_patches", "precision", "recall", "f", "rand_index", "seconds"};
  for(const Cad_result& r : results)
    for(std::size_t l = 0; l < levels; ++l)
      for(std::size_t k = 0; k < methods.size(); ++k)
      {
        if(!options.runs(k)) continue;
        const Cad_score& s = r.scores[l][k];
        csv.rows.push_back({r.set, r.name, std::to_string(r.faces), std::to_string(r.true_patches),
                            fmt(r.tangent_share, 6), fmt(r.band_share, 6), plain(options.noise[l]), methods[k].first,
                            std::to_string(s.patches), std::to_string(s.small_patches), fmt(s.boundary.precision, 6),
                            fmt(s.boundary.recall, 6), fmt(s.boundary.f_score, 6), fmt(s.rand_index, 6),
                            fmt(s.seconds, 3)});
      }
  for(const auto& group : cad_groups())
    for(std::size_t l = 0; l < levels; ++l)
    {
      const auto m = mean_f(results, group.second, l);
      if(m.second == 0) continue;
      const std::vector<double> rand = mean_rand_index(results, group.second, l);
      for(std::size_t k = 0; k < methods.size(); ++k)
        if(options.runs(k))
          csv.rows.push_back({"mean " + group.first, "", "", "", "", "", plain(options.noise[l]), methods[k].first, "", "",
                            "", "", fmt(m.first[k], 6), fmt(rand[k], 6), ""});
    }
  std::ofstream csv_file(std::filesystem::path(out) / "cad_parts.csv");
  csv.write_csv(csv_file);

  std::ostringstream md;
  md << "# CAD parts\n\nMachine: " << machine << ". Produced by `evaluate_quality` (evaluation/cad_tables.h). "
     << "Boundary F-score at 1% of the bounding-box diagonal against the true patches (the B-rep faces; the ABC "
        "surfaces), on the face patches, the patch count in parentheses and, after a slash, the number of patches "
        "under 0.1% of the area; the means also give the Rand index of the face patches against the true ones, faces "
        "weighted by area (low where patches merge true ones). Sets: \"cad\", Fusion 360 parts meshed by gmsh; "
        "\"abc-dev\", native ABC meshes "
        "(read by the program's reader, which separates the faces of non-manifold edges); \"abc\", the ABC models "
        "with a YAML ground truth, outside the means. \"this package (defaults)\": segment_along_features() with "
     << settings_text(options)
     << "; \"paper's pipeline\": crease_angle 180 (crest lines only), neighborhood_radius 0, alpha 0.6; \"sharp "
        "edges N\": CGAL's sharp_edges_segmentation at N degrees; \"Efficient RANSAC\": CGAL's shape detection "
        "(planes, cylinders, cones, spheres, tori) on the face centroids and normals, a patch per connected set of "
        "faces of one shape (evaluation/ransac.h); \"VSA (true count)\": CGAL's variational shape "
        "approximation with the true patch count (L21, hierarchical seeding, seeded). \"tang.\": the share of the "
        "true boundary length whose dihedral angle is below 20 degrees (tangent-continuous), on the clean mesh. "
        "\"band\": the share of the area within the tolerance of a true boundary (FS::boundary_band_share()), about "
        "the precision of a boundary drawn anywhere: where it is near 1, many small patches score a high F. "
        "Noise: every vertex moved along its normal by a normal deviate of the given standard deviation ("
     << (options.noise_seeds == 1 ? std::string("seed 1") :
                                    "the means over seeds 1 to " + std::to_string(options.noise_seeds) +
                                      ", patch counts rounded")
     << ").\n";
  for(const auto& group : cad_groups())
  {
    if(mean_f(results, group.second, 0).second == 0) continue;
    md << "\n## Mean boundary F: " << group.first << ", " << mean_f(results, group.second, 0).second
       << " parts\n\n";
    Text_table means;
    means.header = {"noise (of the diagonal)"};
    for(std::size_t k = 0; k < methods.size(); ++k)
      if(options.runs(k)) means.header.push_back(methods[k].second);
    Text_table rand = means;
    for(std::size_t l = 0; l < levels; ++l)
    {
      means.rows.push_back({plain(100 * options.noise[l]) + "%"});
      rand.rows.push_back(means.rows.back());
      const std::vector<double> f = mean_f(results, group.second, l).first;
      const std::vector<double> ri = mean_rand_index(results, group.second, l);
      for(std::size_t k = 0; k < methods.size(); ++k)
        if(options.runs(k))
        {
          means.rows.back().push_back(fmt(f[k]));
          rand.rows.back().push_back(fmt(ri[k]));
        }
    }
    means.write_markdown(md);
    md << "\nMean Rand index (faces weighted by area):\n\n";
    rand.write_markdown(md);
  }
  for(std::size_t l = 0; l < levels; ++l)
  {
    md << "\n## Noise " << plain(100 * options.noise[l]) << "% of the diagonal\n\n";
    Text_table t;
    t.header = {"set", "part", "faces", "true patches", "tang.", "band"};
    for(std::size_t k = 0; k < methods.size(); ++k)
      if(options.runs(k)) t.header.push_back(methods[k].second);
    for(const Cad_result& r : results)
    {
      t.rows.push_back({r.set, r.name, std::to_string(r.faces), std::to_string(r.true_patches), fmt(r.tangent_share),
                        fmt(r.band_share)});
      for(const Cad_score& s : r.scores[l])
        if(s.ran)
          t.rows.back().push_back(fmt(s.boundary.f_score) + " (" + std::to_string(s.patches) + "/" +
                                  std::to_string(s.small_patches) + ")");
    }
    for(const auto& group : cad_groups())
    {
      const auto m = mean_f(results, group.second, l);
      if(m.second == 0) continue;
      t.rows.push_back({"", "mean " + group.first + " (" + std::to_string(m.second) + ")", "", "", "", ""});
      for(std::size_t k = 0; k < methods.size(); ++k)
        if(options.runs(k)) t.rows.back().push_back("**" + fmt(m.first[k]) + "**");
    }
    t.write_markdown(md);
  }
  write_and_print(std::filesystem::path(out) / "cad_parts.md", md.str());
}

/// Writes OUT/scenes/worst_K_NAME.scene (render_scenes' input; scripts/run_evaluation.sh
/// lays them out in OUT/contact_sheets/cad_worst_five.png) for the `count` parts of the
/// development and generated sets whose boundary F at the defaults, clean, is lowest:
/// their ground truth, this package at `options`, sharp edges at 20 degrees and Efficient
/// RANSAC, each method's patches coloured like the true patches they overlap most.
inline void write_worst_part_scenes(const std::string& out, const Cad_options& options,
                                    const std::vector<Cad_result>& results, std::size_t count = 5)
{
  const auto clean = std::find(options.noise.begin(), options.noise.end(), 0.);
  if(clean == options.noise.end()) return; // no clean run to rank the parts by
  if(!options.runs(0)) return;             // nor the package's scores
  const std::size_t l = std::size_t(clean - options.noise.begin());
  std::vector<const Cad_result*> parts;
  for(const Cad_result& r : results)
    if(r.set == "cad" || r.set == "abc-dev" || r.set == "generated") parts.push_back(&r);
  std::stable_sort(parts.begin(), parts.end(), [l](const Cad_result* a, const Cad_result* b) {
    return a->scores[l][0].boundary.f_score < b->scores[l][0].boundary.f_score;
  });
  if(parts.size() > count) parts.resize(count);
  const std::filesystem::path folder = std::filesystem::path(out) / "scenes";
  std::filesystem::create_directories(folder);
  for(std::size_t k = 0; k < parts.size(); ++k)
  {
    Cad_part part;
    std::string error;
    if(!read_cad_part(parts[k]->path, parts[k]->format, part, error))
    {
      std::cerr << "evaluate_quality: " << parts[k]->path.string() << ": " << error << std::endl;
      continue;
    }
    const std::vector<std::size_t> truth(part.labels.begin(), part.labels.end());
    std::vector<double> area(part.mesh.number_of_faces());
    for(auto f : faces(part.mesh)) area[f.idx()] = PMP::face_area(f, part.mesh);
    Scene_writer scene((folder / ("worst_" + std::to_string(k + 1) + "_" + part.name + ".scene")).string(),
                       part.mesh);
    const auto label = [](const std::string& method, const Segmentation& s, const Cad_score* score) {
      std::ostringstream text;
      text << method << ": " << number_of_distinct(s.face_patch) << " patches";
      if(score) text << ", F " << std::fixed << std::setprecision(3) << score->boundary.f_score;
      return text.str();
    };
    scene.tile_with_patches("ground truth: " + std::to_string(parts[k]->true_patches) + " patches", truth);
    const Cad_score* scores = parts[k]->scores[l].data(); // cad_methods(): 0 default, 2 sharp20, 5 ransac
    const std::pair<std::size_t, Segmentation> runs[] = {{0, run_package(part.mesh, options, false)},
                                                         {2, run_sharp_edges(part.mesh, 20.)},
                                                         {5, run_efficient_ransac(part.mesh)}};
    for(const auto& run : runs)
      scene.tile_with_patches(label(cad_methods()[run.first].second, run.second,
                                    scores[run.first].ran ? &scores[run.first] : nullptr),
                              match_to_reference(run.second.face_patch, truth, area));
    if(!scene.good()) std::cerr << "evaluate_quality: cannot write the scene of " << part.name << std::endl;
  }
}

/// The CAD table: evaluates the parts of DATA/cad (NAME.obj), DATA/abc-dev (NAME.obj.gz),
/// DATA/abc (NAME.obj with NAME.yml) and `generated` (NAME.obj, the gmsh parts made by
/// the build), each with its ground truth, at every noise level of `options`;
/// `only_parts`, if not empty, keeps the parts named in it. Writes OUT/cad_parts.md and
/// OUT/cad_parts.csv and prints the markdown. Without any of these folders, says so on
/// the standard output and returns false (nothing written).
inline bool run_cad_table(const std::string& data, const std::string& out, const Cad_options& options,
                          const std::string& machine, const std::set<std::string>& only_parts = {},
                          const std::string& generated = {})
{
  namespace fsys = std::filesystem;
  std::error_code ec;
  const fsys::path cad = fsys::path(data) / "cad", abc_dev = fsys::path(data) / "abc-dev";
  const bool has_data = !data.empty() && (fsys::is_directory(cad, ec) || fsys::is_directory(abc_dev, ec));
  if(!has_data)
    std::cout << "evaluate_quality: no development parts ("
              << (data.empty() ? "no data folder: set FEATURE_SEGMENTATION_DATA or --data"
                               : cad.string() + " and " + abc_dev.string() + " absent")
              << ")" << std::endl;
  const bool has_generated = !generated.empty() && fsys::is_directory(generated, ec);
  if(!has_generated)
    std::cout << "evaluate_quality: no generated parts ("
              << (generated.empty() ? "no folder given: --generated DIR" : generated + " absent: build the target generated_parts")
              << ")" << std::endl;
  if(!has_data && !has_generated)
  {
    std::cout << "evaluate_quality: CAD table skipped" << std::endl;
    return false;
  }
  const auto files = [&ec](const fsys::path& folder, const std::string& ending) {
    std::vector<fsys::path> result;
    if(fsys::is_directory(folder, ec))
      for(const auto& e : fsys::directory_iterator(folder, ec))
      {
        const std::string name = e.path().filename().string();
        if(name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
          result.push_back(e.path());
      }
    std::sort(result.begin(), result.end());
    return result;
  };
  std::vector<std::pair<fsys::path, Part_format> > inputs;
  for(const fsys::path& p : files(cad, ".obj")) inputs.emplace_back(p, Part_format::OBJ_LABELS);
  for(const fsys::path& p : files(abc_dev, ".obj.gz")) inputs.emplace_back(p, Part_format::GZIPPED_OBJ_LABELS);
  if(has_data)
    for(const fsys::path& p : ground_truth_models(fsys::path(data) / "abc")) inputs.emplace_back(p, Part_format::ABC_YML);
  if(has_generated)
    for(const fsys::path& p : files(generated, ".obj")) inputs.emplace_back(p, Part_format::GENERATED_OBJ_LABELS);
  std::vector<Cad_result> results;
  for(const auto& input : inputs)
  {
    std::string stem = input.first.filename().string();
    stem = stem.substr(0, stem.find('.'));
    if(input.second == Part_format::ABC_YML) stem = "abc_" + stem;
    if(!only_parts.empty() && only_parts.count(stem) == 0) continue;
    Cad_result r;
    std::string error;
    bool ok = false;
    try
    {
      ok = evaluate_cad_part(input.first, input.second, options, r, error);
    }
    catch(const std::exception& e)
    {
      error = e.what();
    }
    if(ok) results.push_back(r);
    else std::cout << "evaluate_quality: " << input.first.string() << " skipped: " << error << std::endl;
  }
  write_cad_tables(out, options, results, machine);
  write_worst_part_scenes(out, options, results);
  return true;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_CAD_TABLES_H
