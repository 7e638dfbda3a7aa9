// SPDX-License-Identifier: GPL-3.0-or-later
//
// Timing of the automatic segmentation on real meshes, stage by stage, for the manual's
// performance table: principal curvatures, crest lines, edge weights, the correlation
// clustering solve on the full vertex graph, and the whole one-call segmentation
// (segment_along_features from the bare mesh, on the full vertex graph, and with its
// default options). The stages are the paper's (crest lines only: the one-call check
// runs with crease_angle 180); the last column is the default run, creases included.
// Each stage is called separately through
// the public API, the later stages reusing the earlier ones' output as a user would.
//
// Meshes: CGAL's CAD meshes from FS_MESH_DIR; the paper's models (paper-models/*.off,
// *.obj) from $FEATURE_SEGMENTATION_DATA or --data; and a ~200k-face mesh made here by
// isotropic remeshing with the sharp edges kept (rockerarm if the paper's models are
// there, else fandisk), the size the target (< 2 s for the whole segmentation
// on one core) refers to. Everything runs on one thread.
//
// Usage: bench_segmentation [--data DIR] [--csv bench_segmentation.csv] [--alpha 0.6]
//          [--target-faces 200000] [--repeat 1]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/defaults.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/edge_weights.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_common.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;

namespace FS = CGAL::Feature_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fsys = std::filesystem;

namespace {

using fs_bench::cpu_name;
using fs_bench::csv_text;
using fs_bench::read_mesh;
using fs_bench::fastest;
using fs_bench::refine_to_faces;
using fs_bench::seconds_since;

struct Options
{
  std::string data;
  std::string csv = "bench_segmentation.csv";
  double alpha = CGAL::Feature_segmentation::default_alpha;
  std::size_t target_faces = 200000;
  std::size_t repeat = 1;
};

struct Row
{
  std::string mesh, source;
  std::size_t vertices = 0, faces = 0, feature_edges = 0, patches = 0;
  double curvature = 0, crest = 0, weights = 0, solve = 0, total = 0, cut_cost = 0;
  double default_total = 0; // segment_along_features with every option at its default
  std::size_t default_patches = 0;
  std::string status = "ok";
};




bool parse_options(int argc, char** argv, Options& options)
{
  if(const char* env = std::getenv("FEATURE_SEGMENTATION_DATA"))
    options.data = env;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(i + 1 >= argc)
      return false;
    if(arg == "--data") options.data = argv[++i];
    else if(arg == "--csv") options.csv = argv[++i];
    else if(arg == "--alpha") options.alpha = std::atof(argv[++i]);
    else if(arg == "--target-faces") options.target_faces = std::size_t(std::atol(argv[++i]));
    else if(arg == "--repeat") options.repeat = (std::max)(1L, std::atol(argv[++i]));
    else return false;
  }
  return options.target_faces > 0;
}

// The pipeline, stage by stage, then in one call; fills the timing columns of `row`.
void run(const Mesh& mesh, const Options& options, Row& row)
{
  row.vertices = num_vertices(mesh);
  row.faces = num_faces(mesh);

  auto curvature = get(CGAL::dynamic_vertex_property_t<FS::Principal_curvatures<K> >(), mesh);
  row.curvature = fastest(options.repeat, [&] {
    FS::estimate_principal_curvatures(mesh, curvature, FS::parameters::neighborhood_radius(0.)); // the paper's fit
  });

  FS::Feature_lines<Mesh> lines;
  row.crest = fastest(options.repeat, [&] { lines = FS::detect_crest_lines(mesh, curvature); });

  auto weight = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  row.weights = fastest(options.repeat, [&] {
    row.feature_edges = FS::compute_edge_weights(
      mesh, weight,
      FS::parameters::alpha(options.alpha).principal_curvature_map(curvature).feature_lines(lines));
  });

  // The graph segment_along_features solves: node i = i-th vertex, one edge per mesh edge.
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  std::size_t n = 0;
  for(vertex_descriptor v : vertices(mesh)) put(index, v, n++);
  FS::Correlation_clustering_graph graph(n);
  graph.reserve_edges(num_edges(mesh));
  for(edge_descriptor e : edges(mesh))
    graph.add_edge(get(index, source(e, mesh)), get(index, target(e, mesh)), get(weight, e));

  const FS::Default_correlation_clustering_solver solver;
  std::vector<std::size_t> labels;
  row.solve = fastest(options.repeat, [&] {
    labels.clear();
    row.patches = solver(graph, labels);
  });
  row.cut_cost = FS::cut_cost(graph, labels);

  auto patch = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  std::size_t one_call_patches = 0;
  double one_call_cost = 0;
  row.total = fastest(options.repeat, [&] {
    one_call_patches = FS::segment_along_features(
      mesh, patch,
      FS::parameters::alpha(options.alpha).crease_angle(180.).neighborhood_radius(0.).use_oversegmentation(false).cut_cost_output(&one_call_cost));
  });
  // The stages above must add up to the one-call segmentation; a difference would mean
  // the benchmark times something else than what a user runs.
  if(one_call_patches != row.patches ||
     std::abs(one_call_cost - row.cut_cost) > 1e-9 * (1 + std::abs(row.cut_cost)))
    row.status = "one call differs: " + std::to_string(one_call_patches) + " patches, cost " +
                 std::to_string(one_call_cost);

  // The defaults may solve a smaller graph than the vertex graph (an oversegmentation's).
  row.default_total = fastest(options.repeat, [&] {
    row.default_patches = FS::segment_along_features(mesh, patch, FS::parameters::alpha(options.alpha));
  });
}



std::string format_seconds(double s)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3f", s);
  return buffer;
}

void print_row(const Row& r)
{
  char line[512];
  if(r.status != "ok" && r.faces == 0)
  {
    std::snprintf(line, sizeof(line), "%-24s %-9s %s\n", r.mesh.c_str(), r.source.c_str(), r.status.c_str());
    std::cout << line << std::flush;
    return;
  }
  std::snprintf(line, sizeof(line), "%-24s %-9s %8zu %8zu %7zu %7s %7s %7s %7s %7s %7zu %10.4g %7s %7zu  %s\n",
                r.mesh.c_str(), r.source.c_str(), r.vertices, r.faces, r.feature_edges,
                format_seconds(r.curvature).c_str(), format_seconds(r.crest).c_str(),
                format_seconds(r.weights).c_str(), format_seconds(r.solve).c_str(),
                format_seconds(r.total).c_str(), r.patches, r.cut_cost,
                format_seconds(r.default_total).c_str(), r.default_patches, r.status.c_str());
  std::cout << line << std::flush;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  if(!parse_options(argc, argv, options))
  {
    std::cerr << "usage: " << argv[0]
              << " [--data DIR] [--csv FILE] [--alpha A] [--target-faces N] [--repeat R]\n";
    return 1;
  }

  const std::string cpu = cpu_name();
  const unsigned cores = std::thread::hardware_concurrency();
  std::cout << "Machine: " << cpu << ", " << cores << " cores (the benchmark uses one thread)\n"
            << "alpha = " << options.alpha << ", other parameters at their defaults; times in seconds,"
            << " fastest of " << options.repeat << " run(s).\n"
            << "curv = principal curvatures, crest = crest lines, weights = edge weights from both,"
            << " solve = Default_correlation_clustering_solver on the full vertex graph,\n"
            << "total = segment_along_features from the bare mesh on the full vertex graph (all stages in one call);\n"
            << "patches, cut cost: of that solve; dflt, d.patch: segment_along_features with its default options.\n\n";

  std::vector<std::pair<std::string, std::string> > inputs; // (path, source)
  for(const char* name : {"fandisk", "anchor_dense", "blade", "rotor", "pinion", "couplingdown"})
    inputs.emplace_back(std::string(FS_MESH_DIR) + "/" + name + ".off", "cgal");

  std::string data_note;
  const fsys::path models = fsys::path(options.data) / "paper-models";
  std::string large_base = std::string(FS_MESH_DIR) + "/fandisk.off";
  std::error_code ec;
  if(options.data.empty() || !fsys::is_directory(models, ec))
  {
    data_note = options.data.empty()
      ? "paper models skipped: no data folder (set FEATURE_SEGMENTATION_DATA or --data)"
      : "paper models skipped: " + models.string() + " not found";
    std::cerr << "bench_segmentation: " << data_note << std::endl;
  }
  else
  {
    std::vector<std::string> found;
    for(const auto& entry : fsys::directory_iterator(models, ec))
    {
      const std::string ext = entry.path().extension().string();
      if(entry.is_regular_file() && (ext == ".off" || ext == ".obj"))
        found.push_back(entry.path().string());
    }
    std::sort(found.begin(), found.end());
    for(const std::string& path : found)
    {
      inputs.emplace_back(path, "paper");
      if(fsys::path(path).stem() == "rockerarm_tri")
        large_base = path;
    }
  }

  char header[512];
  std::snprintf(header, sizeof(header), "%-24s %-9s %8s %8s %7s %7s %7s %7s %7s %7s %7s %10s %7s %7s  %s\n",
                "mesh", "source", "vertices", "faces", "feat.e", "curv", "crest", "weights",
                "solve", "total", "patches", "cut cost", "dflt", "d.patch", "status");
  std::cout << header;
  if(!data_note.empty())
    std::cout << "(" << data_note << ")\n";

  std::vector<Row> rows;
  auto measure = [&](const std::string& name, const std::string& source, const Mesh& mesh) {
    Row row;
    row.mesh = name;
    row.source = source;
    try
    {
      run(mesh, options, row);
    }
    catch(const std::exception& e)
    {
      row.status = std::string("error: ") + e.what();
    }
    print_row(row);
    rows.push_back(row);
  };

  for(const auto& input : inputs)
  {
    Mesh mesh;
    std::string error;
    const std::string name = fsys::path(input.first).filename().string();
    if(!read_mesh(input.first, mesh, error))
    {
      Row row;
      row.mesh = name;
      row.source = input.second;
      row.status = "skipped: " + error + " (" + input.first + ")";
      print_row(row);
      rows.push_back(row);
      continue;
    }
    measure(name, input.second, mesh);
  }

  {
    Mesh mesh;
    std::string error;
    const std::string base = fsys::path(large_base).stem().string();
    if(!read_mesh(large_base, mesh, error))
      std::cerr << "bench_segmentation: cannot read " << large_base << " (" << error
                << "): no large mesh" << std::endl;
    else
    {
      const auto start = std::chrono::steady_clock::now();
      refine_to_faces(mesh, options.target_faces);
      std::cerr << "bench_segmentation: remeshed " << base << " to " << num_faces(mesh) << " faces in "
                << format_seconds(seconds_since(start)) << " s" << std::endl;
      measure(base + "_remeshed", "generated", mesh);
    }
  }

  std::ofstream csv(options.csv);
  if(!csv)
  {
    std::cerr << "bench_segmentation: cannot write " << options.csv << std::endl;
    return 1;
  }
  csv << "mesh,source,vertices,faces,feature_edges,curvature_s,crest_lines_s,weights_s,solve_s,"
         "total_s,patches,cut_cost,default_total_s,default_patches,alpha,cpu,cores,status\n";
  csv.precision(6);
  for(const Row& r : rows)
    csv << csv_text(r.mesh) << ',' << r.source << ',' << r.vertices << ',' << r.faces << ','
        << r.feature_edges << ',' << r.curvature << ',' << r.crest << ',' << r.weights << ','
        << r.solve << ',' << r.total << ',' << r.patches << ',' << r.cut_cost << ','
        << r.default_total << ',' << r.default_patches << ','
        << options.alpha << ',' << csv_text(cpu) << ',' << cores << ',' << csv_text(r.status) << '\n';
  csv.close();
  fs_bench::write_provenance(options.csv, argc, argv);
  std::cout << "\nCSV written to " << options.csv << std::endl;
  return 0;
}
