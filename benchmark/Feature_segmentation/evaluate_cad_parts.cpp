// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality on CAD parts (issue 13): the parts of DATA/cad (NAME.obj, a closed triangle
// mesh meshed from a B-rep, and NAME.labels, the B-rep face of every triangle), scored
// by the boundary F-score at 1% of the bounding-box diagonal (compare_boundaries() of
// evaluation.h, on the face patches) for:
// - this package at its defaults: creases at 20 degrees, normals filtered before the
//   creases are found (crease_filter_iterations, 40; none on a clean mesh), alpha 0.6;
// - the paper's pipeline (crease_angle 180: crest lines only), alpha 0.6;
// - CGAL's sharp_edges_segmentation at 20, 45 and 60 degrees;
// each at the noise levels asked (Gaussian, along the normals, relative to the diagonal;
// seeded). For every part it also prints the share of true boundary length whose
// dihedral angle is below 20 degrees (tangent-continuous), which no feature-line method
// can see. The ABC models of DATA/abc (NAME.obj with NAME.yml, e.g. the hex nut) follow
// the CAD parts, outside their mean.
//
// Usage: evaluate_cad_parts [--data DIR] [--out FILE.csv] [--noise X,Y,...] [--crease-filter N]
//                           [--alpha A] [--strength-threshold S] [--no-tangent] [--no-crest-lines]
//   N: rounds of normal filtering before the creases are found (default: the library's, 40)
//   --no-tangent: without the curvature discontinuities (tangent_discontinuities(false))
//   --no-crest-lines: no crest lines on the clean parts (crest_lines_on_clean_tessellations(false))
//   DIR (default $FEATURE_SEGMENTATION_DATA) holds cad/; without it the program says so
//   and exits with status 0 (nothing to evaluate).

#include "evaluation/abc_ground_truth.h"
#include "evaluation/methods.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace fs_evaluation;
namespace fsys = std::filesystem;

namespace {

struct Part
{
  std::string name;
  Mesh mesh;
  std::vector<int> labels;
};

// An ABC model (NAME.obj with NAME.yml): its labels are the ground-truth surfaces.
bool read_abc_part(const fsys::path& obj, Part& part)
{
  std::string error;
  if(!read_mesh_in_file_order(obj.string(), part.mesh, error)) return false;
  const Abc_ground_truth truth = read_abc_ground_truth(fsys::path(obj).replace_extension(".yml").string(),
                                                       part.mesh.number_of_vertices(), part.mesh.number_of_faces());
  part.labels = truth.face_patch;
  part.name = "abc_" + obj.stem().string();
  return std::find(part.labels.begin(), part.labels.end(), -1) == part.labels.end();
}

bool read_part(const fsys::path& obj, Part& part)
{
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_OBJ(obj.string(), points, polygons)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, part.mesh); // keeps the face order
  std::ifstream in(fsys::path(obj).replace_extension(".labels"));
  int x;
  while(in >> x) part.labels.push_back(x);
  part.name = obj.stem().string();
  return part.labels.size() == part.mesh.number_of_faces();
}

double tangent_continuous_share(const Mesh& mesh, const std::vector<int>& labels)
{
  double low = 0, total = 0;
  for(auto e : edges(mesh))
  {
    if(is_border(e, mesh)) continue;
    const auto h = halfedge(e, mesh);
    const auto f = face(h, mesh), g = face(opposite(h, mesh), mesh);
    if(labels[f.idx()] == labels[g.idx()]) continue;
    const double len = std::sqrt(CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(target(h, mesh))));
    const double c = PMP::compute_face_normal(f, mesh) * PMP::compute_face_normal(g, mesh);
    total += len;
    if(std::acos((std::max)(-1., (std::min)(1., c))) * 180. / 3.14159265358979323846 < 20.) low += len;
  }
  return total > 0 ? low / total : 0.;
}

// --crease-filter, --alpha, --strength-threshold; the library's defaults otherwise
// (alpha and the threshold apply to the package at creases, not to the paper's column)
int crease_filter = FS::internal::Segmentation_options().crease_filter_iterations;
double alpha = FS::internal::Segmentation_options().alpha;
double strength_threshold = FS::default_strength_threshold;
bool tangent = FS::internal::Segmentation_options().tangent_discontinuities;
bool crest_lines = FS::internal::Segmentation_options().crest_lines_on_clean_tessellations;

Segmentation run_package(const Mesh& mesh, double crease_angle)
{
  auto vp = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  auto fp = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const auto t0 = std::chrono::steady_clock::now();
  const bool paper = crease_angle >= 180.;
  FS::segment_along_features(mesh, vp, FS::parameters::crease_angle(crease_angle)
                                                   .alpha(paper ? FS::internal::Segmentation_options().alpha : alpha)
                                                   .strength_threshold(paper ? FS::default_strength_threshold
                                                                             : strength_threshold)
                                                   .crease_filter_iterations(crease_filter)
                                                   .tangent_discontinuities(tangent)
                                                   .crest_lines_on_clean_tessellations(crest_lines)
                                                   // the paper's pipeline also fits on rings alone
                                                   .neighborhood_radius(paper ? 0. : FS::default_neighborhood_radius)
                                                   .face_patch_map(fp));
  Segmentation s;
  s.seconds = seconds_since(t0);
  s.face_patch.resize(mesh.number_of_faces());
  s.vertex_patch.resize(mesh.number_of_vertices());
  for(auto f : faces(mesh)) s.face_patch[f.idx()] = get(fp, f);
  for(auto v : vertices(mesh)) s.vertex_patch[v.idx()] = get(vp, v);
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = std::getenv("FEATURE_SEGMENTATION_DATA") ? std::getenv("FEATURE_SEGMENTATION_DATA") : "";
  std::string out = "cad_parts.csv";
  std::vector<double> noise = { 0. };
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--data" && i + 1 < argc) data = argv[++i];
    else if(a == "--out" && i + 1 < argc) out = argv[++i];
    else if(a == "--crease-filter" && i + 1 < argc)
    {
      char* end = nullptr;
      const long n = std::strtol(argv[++i], &end, 10);
      if(end == argv[i] || *end != '\0' || n < 0 || n > 1000)
      {
        std::cerr << "evaluate_cad_parts: --crease-filter takes an integer in 0 .. 1000 (got '" << argv[i] << "')\n";
        return 2;
      }
      crease_filter = int(n);
    }
    else if((a == "--alpha" || a == "--strength-threshold") && i + 1 < argc)
    {
      char* end = nullptr;
      const double x = std::strtod(argv[++i], &end);
      if(end == argv[i] || *end != '\0' || !std::isfinite(x) || (a != "--alpha" && x < 0))
      {
        std::cerr << "evaluate_cad_parts: " << a << " takes a finite number" << (a == "--alpha" ? "" : " >= 0")
                  << " (got '" << argv[i] << "')\n";
        return 2;
      }
      (a == "--alpha" ? alpha : strength_threshold) = x;
    }
    else if(a == "--no-tangent") tangent = false;
    else if(a == "--no-crest-lines") crest_lines = false;
    else if(a == "--noise" && i + 1 < argc)
    {
      noise.clear();
      std::stringstream ss(argv[++i]);
      std::string x;
      while(std::getline(ss, x, ',')) noise.push_back(std::stod(x));
    }
    else { std::cerr << "usage: evaluate_cad_parts [--data DIR] [--out FILE.csv] [--noise X,Y,...] [--crease-filter N]\n"
                 "                          [--alpha A] [--strength-threshold S] [--no-tangent] [--no-crest-lines]\n"; return 2; }
  }
  const fsys::path dir = fsys::path(data) / "cad";
  if(data.empty() || !fsys::is_directory(dir))
  {
    std::cout << "evaluate_cad_parts: no CAD parts (" << (data.empty() ? "FEATURE_SEGMENTATION_DATA unset" : dir.string() + " absent")
              << "); nothing evaluated\n";
    return 0;
  }
  std::vector<fsys::path> objs;
  for(const auto& e : fsys::directory_iterator(dir))
    if(e.path().extension() == ".obj") objs.push_back(e.path());
  std::sort(objs.begin(), objs.end());
  // the ABC models (DATA/abc) follow, outside the CAD mean
  const std::vector<fsys::path> abc = ground_truth_models(fsys::path(data) / "abc");
  const std::size_t number_of_cad_parts = objs.size();
  objs.insert(objs.end(), abc.begin(), abc.end());

  std::ofstream csv(out);
  csv << "part,faces,true_patches,tangent_share,noise,method,patches,precision,recall,f,seconds\n";
  for(double sigma : noise)
  {
    std::printf("\nnoise %.2f%% of the diagonal; boundary F (patches)\n", 100 * sigma);
    std::printf("%-20s %6s %5s %6s | %-13s %-13s | %6s %6s %6s\n", "part", "faces", "true", "tang.",
                "creases20", "paper", "sharp20", "sharp45", "sharp60");
    double sum[5] = { 0, 0, 0, 0, 0 };
    int n = 0;
    for(std::size_t i = 0; i < objs.size(); ++i)
    {
      const fsys::path& obj = objs[i];
      if(i == number_of_cad_parts && n > 0)
        std::printf("%-20s %6s %5s %6s | %5.3f         %5.3f         | %6.3f %6.3f %6.3f\n", "mean (CAD parts)", "", "",
                    "", sum[0] / n, sum[1] / n, sum[2] / n, sum[3] / n, sum[4] / n);
      Part part;
      if(!(i < number_of_cad_parts ? read_part(obj, part) : read_abc_part(obj, part))) { std::printf("%s: cannot read the mesh or its labels\n", obj.string().c_str()); continue; }
      const Mesh mesh = sigma > 0 ? add_normal_noise(part.mesh, sigma, 1) : part.mesh;
      const Prepared_mesh pm(mesh);
      const int true_patches = *std::max_element(part.labels.begin(), part.labels.end()) + 1;
      const double tangent = tangent_continuous_share(part.mesh, part.labels);
      std::vector<std::pair<std::string, Segmentation> > runs;
      runs.emplace_back("creases20", run_package(mesh, 20.));
      runs.emplace_back("paper", run_package(mesh, 180.));
      for(double a : { 20., 45., 60. })
        runs.emplace_back("sharp" + std::to_string(int(a)), run_sharp_edges(mesh, a));
      double f[5];
      std::size_t np[5];
      for(std::size_t k = 0; k < runs.size(); ++k)
      {
        const Scores s = score(pm, runs[k].second, part.labels);
        f[k] = s.boundary.f_score;
        np[k] = s.patches;
        if(i < number_of_cad_parts) sum[k] += f[k];
        csv << part.name << ',' << mesh.number_of_faces() << ',' << true_patches << ',' << tangent << ','
            << sigma << ',' << runs[k].first << ',' << s.patches << ',' << s.boundary.precision << ','
            << s.boundary.recall << ',' << f[k] << ',' << runs[k].second.seconds << '\n';
      }
      if(i < number_of_cad_parts) ++n;
      std::printf("%-20.20s %6zu %5d %6.3f | %5.3f (%4zu)  %5.3f (%4zu)  | %6.3f %6.3f %6.3f\n", part.name.c_str(),
                  std::size_t(mesh.number_of_faces()), true_patches, tangent, f[0], np[0], f[1], np[1], f[2], f[3], f[4]);
    }
    if(n > 0 && number_of_cad_parts == objs.size())
      std::printf("%-20s %6s %5s %6s | %5.3f         %5.3f         | %6.3f %6.3f %6.3f\n", "mean (CAD parts)", "", "",
                  "", sum[0] / n, sum[1] / n, sum[2] / n, sum[3] / n, sum[4] / n);
  }
  std::cout << "\nwritten: " << out << std::endl;
  return 0;
}
