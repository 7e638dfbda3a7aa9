// SPDX-License-Identifier: GPL-3.0-or-later
//
// Boundary smoothing on real meshes, for the manual and issue 5's closing note: the
// patch boundaries of the default segmentation, their length in the anisotropic metric
// (the smoothing's energy) and in the Euclidean metric before and after smoothing, the
// number of iterations and vertex moves, and the time of the smoothing alone (and of
// computing the boundaries, which includes curvatures, feature lines and metric).
//
// Meshes: CGAL's fandisk from FS_MESH_DIR; the paper's rockerarm
// (paper-models/rockerarm_tri.off) from $FEATURE_SEGMENTATION_DATA or --data. Everything
// runs on one thread.
//
// Usage: bench_smoothing [--data DIR] [--csv bench_smoothing.csv] [--alpha 0.6]
//          [--iterations 20] [--repeat 3]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/defaults.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/segment_along_features.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace FS = CGAL::Feature_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fsys = std::filesystem;

namespace {

struct Options
{
  std::string data;
  std::string csv = "bench_smoothing.csv";
  double alpha = CGAL::Feature_segmentation::default_alpha;
  int iterations = 20;
  int repeat = 3;
};

struct Row
{
  std::string mesh, status = "ok";
  std::size_t faces = 0, patches = 0, curves = 0, junctions = 0, iterations = 0, moves = 0, refined_faces = 0;
  double aniso_before = 0, aniso_after = 0, eucl_before = 0, eucl_after = 0;
  double boundaries_s = 0, smoothing_s = 0, refine_s = 0;
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string cpu_name()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while(std::getline(cpuinfo, line))
    if(line.compare(0, 10, "model name") == 0)
    {
      const std::size_t colon = line.find(':');
      if(colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
    }
  return "unknown";
}

bool parse_options(int argc, char** argv, Options& o)
{
  if(const char* env = std::getenv("FEATURE_SEGMENTATION_DATA")) o.data = env;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(i + 1 >= argc) return false;
    if(arg == "--data") o.data = argv[++i];
    else if(arg == "--csv") o.csv = argv[++i];
    else if(arg == "--alpha") o.alpha = std::atof(argv[++i]);
    else if(arg == "--iterations") o.iterations = std::atoi(argv[++i]);
    else if(arg == "--repeat") o.repeat = (std::max)(1, std::atoi(argv[++i]));
    else return false;
  }
  return o.iterations >= 0;
}

void run(const Mesh& mesh, const Options& o, Row& row)
{
  row.faces = num_faces(mesh);
  auto patch = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  row.patches = FS::segment_along_features(mesh, patch, FS::parameters::alpha(o.alpha));
  // the smoothing changes the boundaries: time it on fresh copies, keep the fastest run
  row.boundaries_s = row.smoothing_s = 1e300;
  for(int r = 0; r < o.repeat; ++r)
  {
    auto start = std::chrono::steady_clock::now();
    FS::Patch_boundaries<Mesh> b = FS::compute_patch_boundaries(mesh, patch);
    row.boundaries_s = (std::min)(row.boundaries_s, seconds_since(start));
    row.curves = b.curves().size();
    row.junctions = b.number_of_junctions();
    start = std::chrono::steady_clock::now();
    const FS::Boundary_smoothing_report rep =
      FS::smooth_patch_boundaries(b, FS::parameters::smoothing_iterations(o.iterations));
    row.smoothing_s = (std::min)(row.smoothing_s, seconds_since(start));
    row.aniso_before = rep.energy.front();
    row.aniso_after = rep.energy.back();
    row.eucl_before = rep.length.front();
    row.eucl_after = rep.length.back();
    row.iterations = rep.number_of_iterations;
    row.moves = rep.number_of_vertex_moves;
    Mesh refined;
    auto fp = refined.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
    start = std::chrono::steady_clock::now();
    FS::refine_mesh_along_boundaries(b, refined, fp);
    const double t = seconds_since(start);
    row.refine_s = r == 0 ? t : (std::min)(row.refine_s, t);
    row.refined_faces = num_faces(refined);
  }
}

void print_row(const Row& r)
{
  char line[512];
  if(r.faces == 0)
  {
    std::snprintf(line, sizeof(line), "%-18s %s\n", r.mesh.c_str(), r.status.c_str());
    std::cout << line;
    return;
  }
  std::snprintf(line, sizeof(line),
                "%-18s %7zu %4zu %5zu %4zu | %9.4f %9.4f %6.1f%% | %9.4f %9.4f %6.1f%% | %4zu %6zu | %7.3f %7.3f %7.3f %8zu  %s\n",
                r.mesh.c_str(), r.faces, r.patches, r.curves, r.junctions, r.aniso_before, r.aniso_after,
                100 * (r.aniso_after / r.aniso_before - 1), r.eucl_before, r.eucl_after,
                100 * (r.eucl_after / r.eucl_before - 1), r.iterations, r.moves, r.boundaries_s, r.smoothing_s,
                r.refine_s, r.refined_faces, r.status.c_str());
  std::cout << line << std::flush;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  if(!parse_options(argc, argv, o))
  {
    std::cerr << "usage: " << argv[0] << " [--data DIR] [--csv FILE] [--alpha A] [--iterations N] [--repeat R]\n";
    return 1;
  }
  const std::string cpu = cpu_name();
  std::cout << "Machine: " << cpu << ", " << std::thread::hardware_concurrency()
            << " cores (one thread used). Boundaries of segment_along_features (alpha = " << o.alpha
            << ", defaults otherwise), smoothed with at most " << o.iterations
            << " iterations, tolerance 1e-4; times in seconds, fastest of " << o.repeat << ".\n"
            << "aniso = length in the anisotropic metric (the energy), eucl = Euclidean length;"
            << " bound = compute_patch_boundaries (curvature, crest lines, metric), smooth = "
            << "smooth_patch_boundaries, refine = refine_mesh_along_boundaries.\n\n";

  std::vector<std::pair<std::string, std::string> > inputs = { { "fandisk", std::string(FS_MESH_DIR) + "/fandisk.off" } };
  if(o.data.empty())
    std::cout << "(rockerarm skipped: no data folder; set FEATURE_SEGMENTATION_DATA or --data)\n";
  else
    inputs.emplace_back("rockerarm", (fsys::path(o.data) / "paper-models" / "rockerarm_tri.off").string());

  char header[512];
  std::snprintf(header, sizeof(header),
                "%-18s %7s %4s %5s %4s | %9s %9s %7s | %9s %9s %7s | %4s %6s | %7s %7s %7s %8s  %s\n", "mesh", "faces",
                "pat", "curv", "junc", "aniso0", "aniso1", "change", "eucl0", "eucl1", "change", "it", "moves",
                "bound", "smooth", "refine", "refined", "status");
  std::cout << header;
  std::vector<Row> rows;
  for(const auto& in : inputs)
  {
    Row row;
    row.mesh = in.first;
    Mesh mesh;
    std::error_code ec;
    if(!fsys::exists(in.second, ec)) row.status = "skipped: " + in.second + " not found";
    else if(!PMP::IO::read_polygon_mesh(in.second, mesh) || !CGAL::is_triangle_mesh(mesh))
      row.status = "skipped: cannot read a triangle mesh from " + in.second;
    else
    {
      try { run(mesh, o, row); }
      catch(const std::exception& e) { row.status = std::string("error: ") + e.what(); row.faces = 0; }
    }
    print_row(row);
    rows.push_back(row);
  }
  std::ofstream csv(o.csv);
  if(!csv)
  {
    std::cerr << "bench_smoothing: cannot write " << o.csv << std::endl;
    return 1;
  }
  csv << "mesh,faces,patches,curves,junctions,anisotropic_before,anisotropic_after,euclidean_before,"
         "euclidean_after,iterations,vertex_moves,boundaries_s,smoothing_s,refine_s,refined_faces,alpha,cpu,status\n";
  for(const Row& r : rows)
    csv << r.mesh << ',' << r.faces << ',' << r.patches << ',' << r.curves << ',' << r.junctions << ','
        << r.aniso_before << ',' << r.aniso_after << ',' << r.eucl_before << ',' << r.eucl_after << ','
        << r.iterations << ',' << r.moves << ',' << r.boundaries_s << ',' << r.smoothing_s << ',' << r.refine_s << ','
        << r.refined_faces << ',' << o.alpha << ",\"" << cpu << "\",\"" << r.status << "\"\n";
  return 0;
}
