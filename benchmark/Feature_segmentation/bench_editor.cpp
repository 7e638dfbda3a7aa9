// The interactive editor's answer times (issue: every edit but a sketch within 50 ms of
// server time on rockerarm, 41k faces, and within 100 ms at 200k faces). For each mesh
// the editor's session (editor_api.h, what `feature_segmentation edit` serves) is built
// at the defaults, then every kind of edit is sent as the page sends it, as JSON, N times
// (--repeat, default 15): the time of the edit request (parse, region, library edit,
// new state) and of the triangles' patches as runs, which the page gets with the edit
// (labels?format=runs); median and maximum.
// Meshes: fandisk (12,946 faces, from CGAL's data), fandisk subdivided flat twice
// (207,136 faces, made here), and rockerarm (41k faces) from the paper's models in
// --data DIR or $FEATURE_SEGMENTATION_DATA (skipped, with a message, when absent).
// The library's edits alone (set_alpha, add_to_alpha, merge_patches) are timed on
// fandisk, x16 and x64 (828k faces): they should not grow with the mesh (issue: nothing
// proportional to the mesh on the edit path; set_alpha at 207k median <= 5 ms).
//
// Usage: bench_editor [--data DIR] [--repeat N] [--out FILE]
#include "bench_common.h"

#include "editor_api.h"

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using fs_bench::seconds_since;

struct Row
{
  std::string mesh, op;
  std::size_t faces = 0, patches = 0;
  double edit_median = 0, edit_max = 0, labels_median = 0;
  double solve_median = -1; // library edits: the weights of G', the solve, the patch ids
};

std::string three_decimals(double x)
{
  std::ostringstream o;
  o << std::fixed << std::setprecision(3) << x;
  return o.str();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// Writes fandisk subdivided flat `levels` times as OFF.
std::string subdivided_fandisk(int levels)
{
  CGAL::Surface_mesh<fs_app::K::Point_3> m;
  std::string error;
  if(!fs_bench::read_mesh(std::string(FS_MESH_DIR) + "/fandisk.off", m, error))
    throw std::runtime_error("fandisk.off: " + error);
  std::vector<fs_bench::Soup_point> points;
  std::vector<fs_bench::Soup_triangle> triangles;
  for(auto v : m.vertices()) points.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  for(auto f : m.faces())
  {
    fs_bench::Soup_triangle t;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = std::uint32_t(v);
    triangles.push_back(t);
  }
  for(int i = 0; i < levels; ++i) fs_bench::subdivide(points, triangles);
  const std::string path =
    (std::filesystem::temp_directory_path() / ("bench_editor_fandisk_" + std::to_string(levels) + ".off")).string();
  std::ofstream out(path);
  out << std::setprecision(17) << "OFF\n" << points.size() << ' ' << triangles.size() << " 0\n";
  for(const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const auto& t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return path;
}

void bench(const std::string& name, const std::string& path, int repeat, std::vector<Row>& rows)
{
  fs_app::Options options;
  options.input = path;
  options.quiet = true;
  const auto start = std::chrono::steady_clock::now();
  fs_app::Editor_session session(options);
  std::cerr << name << ": session ready in " << seconds_since(start) << " s" << std::endl;
  const std::size_t n = session.number_of_triangles();
  const nlohmann::json mesh = nlohmann::json::parse(session.mesh());
  const std::vector<double> xyz = mesh["vertices"].get<std::vector<double> >();
  const std::vector<std::size_t> tri = mesh["triangles"].get<std::vector<std::size_t> >();
  const double diagonal = mesh["diagonal"].get<double>();
  // a region: the triangles within 5% of the diagonal of the centroid of triangle n/3
  auto centroid = [&](std::size_t f, int k) {
    return (xyz[3 * tri[3 * f] + k] + xyz[3 * tri[3 * f + 1] + k] + xyz[3 * tri[3 * f + 2] + k]) / 3;
  };
  std::vector<std::size_t> region;
  for(std::size_t f = 0; f < n; ++f)
  {
    double d2 = 0;
    for(int k = 0; k < 3; ++k) d2 += CGAL::square(centroid(f, k) - centroid(n / 3, k));
    if(d2 <= CGAL::square(0.05 * diagonal)) region.push_back(f);
  }

  auto measure = [&](const std::string& op, auto make_request, auto after) {
    std::vector<double> edit, labels;
    std::size_t patches = 0;
    for(int r = 0; r < repeat; ++r)
    {
      const nlohmann::json request = make_request(r);
      auto t0 = std::chrono::steady_clock::now();
      const nlohmann::json state = session.edit(request);
      edit.push_back(seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      const std::string l = session.labels_runs();
      labels.push_back(seconds_since(t0));
      patches = state["patches"].get<std::size_t>();
      after(r);
    }
    rows.push_back({name, op, n, patches, 1000 * median(edit), 1000 * *std::max_element(edit.begin(), edit.end()),
                    1000 * median(labels)});
  };
  auto nothing = [](int) {};
  auto undo = [&](int) { session.edit({{"op", "undo"}}); };
  measure("alpha", [](int r) { return nlohmann::json{{"op", "alpha"}, {"value", r % 2 ? 0.6 : 0.9}}; }, nothing);
  measure("refine", [&](int) { return nlohmann::json{{"op", "refine"}, {"faces", region}, {"amount", 0.3}}; }, undo);
  measure("coarsen", [&](int) { return nlohmann::json{{"op", "coarsen"}, {"faces", region}, {"amount", 0.3}}; },
          undo);
  measure("merge",
          [&](int) {
            // two triangles of different patches: the first, and the first of another patch
            const nlohmann::json l = nlohmann::json::parse(session.labels());
            const auto& fp = l["face_patches"];
            std::size_t other = 0;
            while(other < n && fp[other] == fp[0]) ++other;
            return nlohmann::json{{"op", "merge"}, {"faces", {0, other}}};
          },
          undo);
  session.edit({{"op", "alpha"}, {"value", 0.9}});
  measure("undo", [](int) { return nlohmann::json{{"op", "undo"}}; },
          [&](int) { session.edit({{"op", "redo"}}); });
  measure("redo",
          [&](int) {
            session.edit({{"op", "undo"}}); // untimed: something to redo
            return nlohmann::json{{"op", "redo"}};
          },
          nothing);
  // a sketch across the region, through three of its triangles
  measure("sketch",
          [&](int) {
            nlohmann::json points = nlohmann::json::array();
            for(std::size_t i : {std::size_t(0), region.size() / 2, region.size() - 1})
              points.push_back({centroid(region[i], 0), centroid(region[i], 1), centroid(region[i], 2)});
            return nlohmann::json{{"op", "sketch"}, {"points", points}};
          },
          undo);
}

// The library's own edits, without the editor: Feature_aligned_segmentation at its
// defaults; `repeat` times each: set_alpha() between 0.6 and 0.9, add_to_alpha() of
// +0.3 on the faces within 5% of the diagonal of the centroid of face F/3 (then undo),
// merge_patches() of the first face and the first face of another patch (then undo),
// add_sketch() through the centroids of the region's first, middle and last faces (then
// undo). The construction's time goes to the standard error.
// "solve" is the part of the edit that builds the weights of G', solves and numbers
// the patches (stage_times: graph + solve + labels); "labels" the time of
// vertex_patches() after it, what a caller who asks for every vertex's patch pays.
void bench_library(const std::string& name, const std::string& path, int repeat, std::vector<Row>& rows)
{
  typedef CGAL::Surface_mesh<fs_app::K::Point_3> Mesh;
  Mesh m;
  std::string error;
  if(!fs_bench::read_mesh(path, m, error)) throw std::runtime_error(path + ": " + error);
  const auto start = std::chrono::steady_clock::now();
  CGAL::Feature_segmentation::Feature_aligned_segmentation<Mesh> seg(m);
  std::cerr << name << ": Feature_aligned_segmentation built in " << seconds_since(start) << " s" << std::endl;
  auto patch_map = m.add_property_map<Mesh::Vertex_index, std::size_t>("v:bench_patch").first;
  auto centroid = [&](Mesh::Face_index f) {
    const auto h = m.halfedge(f);
    return CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
  };
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(m);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const auto center = centroid(Mesh::Face_index(Mesh::size_type(num_faces(m) / 3)));
  std::vector<Mesh::Face_index> region;
  for(auto f : m.faces())
    if(CGAL::squared_distance(centroid(f), center) <= CGAL::square(0.05 * diagonal)) region.push_back(f);
  // `solves`: whether the edit runs the solver (a merge does not: no "solve" then)
  auto measure = [&](const std::string& op, auto edit_once, auto after, bool solves) {
    std::vector<double> edit, labels, solve;
    std::size_t patches = 0;
    for(int r = 0; r < repeat; ++r)
    {
      const std::size_t recorded = seg.number_of_recorded_edits();
      auto t0 = std::chrono::steady_clock::now();
      patches = edit_once(r);
      edit.push_back(seconds_since(t0));
      const auto& st = seg.stage_times();
      solve.push_back(st.graph + st.solve + st.labels);
      t0 = std::chrono::steady_clock::now();
      seg.vertex_patches(patch_map);
      labels.push_back(seconds_since(t0));
      after(seg.number_of_recorded_edits() > recorded);
    }
    rows.push_back({name, op + " (library)", num_faces(m), patches, 1000 * median(edit),
                    1000 * *std::max_element(edit.begin(), edit.end()), 1000 * median(labels),
                    solves ? 1000 * median(solve) : -1});
  };
  auto nothing = [](bool) {};
  auto undo = [&](bool recorded) { if(recorded) seg.undo(); }; // an edit that changed nothing records no state
  measure("set_alpha", [&](int r) { return seg.set_alpha(r % 2 ? 0.6 : 0.9); }, nothing, true);
  measure("add_to_alpha", [&](int) { return seg.add_to_alpha(region, 0.3); }, undo, true);
  Mesh::Face_index other = *m.faces().begin();
  for(auto f : m.faces())
    if(seg.patch(f) != seg.patch(*m.faces().begin())) { other = f; break; }
  const std::vector<Mesh::Face_index> stroke = { *m.faces().begin(), other };
  measure("merge_patches", [&](int) { return seg.merge_patches(stroke); }, undo, false);
  typedef CGAL::Feature_segmentation::Feature_aligned_segmentation<Mesh>::Sketch_point Sketch_point;
  std::vector<Sketch_point> sketch;
  for(std::size_t i : {std::size_t(0), region.size() / 2, region.size() - 1})
    sketch.push_back({region[i], centroid(region[i])});
  measure("add_sketch", [&](int) { return seg.add_sketch(sketch); }, undo, true);
  std::cerr << name << ": library edits measured (" << seg.number_of_oversegments() << " oversegments)" << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
  std::string data = std::getenv("FEATURE_SEGMENTATION_DATA") ? std::getenv("FEATURE_SEGMENTATION_DATA") : "";
  std::string out = "bench_editor.csv";
  int repeat = 15;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--data" && i + 1 < argc) data = argv[++i];
    else if(a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if(a == "--out" && i + 1 < argc) out = argv[++i];
    else
    {
      std::cerr << "usage: bench_editor [--data DIR] [--repeat N] [--out FILE]\n";
      return 2;
    }
  }
  std::vector<Row> rows;
  try
  {
    bench("fandisk", std::string(FS_MESH_DIR) + "/fandisk.off", repeat, rows);
    const std::string rockerarm = data + "/paper-models/rockerarm_tri.off";
    if(!data.empty() && std::filesystem::exists(rockerarm))
      bench("rockerarm", rockerarm, repeat, rows);
    else
      std::cerr << "rockerarm skipped: " << (data.empty() ? "no --data DIR and no $FEATURE_SEGMENTATION_DATA"
                                                          : rockerarm + " is absent") << std::endl;
    const std::string big = subdivided_fandisk(2);
    bench("fandisk x16", big, repeat, rows);
    // the library's edits at three sizes of one shape (G' is alike at every size), and
    // on rockerarm (a G' of thousands of nodes)
    bench_library("fandisk", std::string(FS_MESH_DIR) + "/fandisk.off", repeat, rows);
    if(!data.empty() && std::filesystem::exists(rockerarm)) bench_library("rockerarm", rockerarm, repeat, rows);
    bench_library("fandisk x16", big, repeat, rows);
    std::filesystem::remove(big);
    const std::string bigger = subdivided_fandisk(3);
    bench_library("fandisk x64", bigger, repeat, rows);
    std::filesystem::remove(bigger);
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  std::cout << "Editor answer times, " << fs_bench::cpu_name() << ", one thread, median of " << repeat
            << " (ms; edit = the POST /api/edit handler's work, labels = the triangles' patches as runs, which the"
            << " page gets with the edit;"
            << " (library): the Feature_aligned_segmentation edit, of which solve = weights of G' + solve + patch"
            << " ids, labels = vertex_patches())\n\n"
            << "| mesh | faces | edit | patches | edit median | edit max | of which solve | labels median |\n"
            << "|---|---:|---|---:|---:|---:|---:|---:|\n";
  std::ofstream csv(out);
  csv << "mesh,faces,edit,patches,edit_ms_median,edit_ms_max,solve_ms_median,labels_ms_median\n";
  for(const Row& r : rows)
  {
    std::cout << "| " << r.mesh << " | " << r.faces << " | " << r.op << " | " << r.patches << " | " << std::fixed
              << std::setprecision(3) << r.edit_median << " | " << r.edit_max << " | "
              << (r.solve_median < 0 ? std::string("-") : three_decimals(r.solve_median)) << " | "
              << r.labels_median << " |\n"
              << std::defaultfloat;
    csv << fs_bench::csv_text(r.mesh) << ',' << r.faces << ',' << r.op << ',' << r.patches << ',' << r.edit_median
        << ',' << r.edit_max << ',' << (r.solve_median < 0 ? std::string() : std::to_string(r.solve_median)) << ','
        << r.labels_median << '\n';
  }
  csv.close();
  fs_bench::write_provenance(out, argc, argv);
  std::cout << "\nCSV: " << out << '\n';
  return 0;
}
