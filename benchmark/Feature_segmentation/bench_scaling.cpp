// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the whole program scales with the mesh and the threads. It makes the series
// itself: CGAL's fandisk (12,946 faces) and its flat subdivisions (each triangle into four
// by its edge midpoints, the geometry unchanged) up to --levels (4: 3.3M faces), and, when
// the development data is there (--data DIR or $FEATURE_SEGMENTATION_DATA), the CAD parts
// 142473 subdivided 4 times (4,864,512 faces, about 5M) and 42811 subdivided 5 times
// (11,145,216 faces: at most 60 s and 8 GB at all cores). Each mesh is written as OFF and
// segmented by the program `feature_segmentation` at its defaults, in a process of its own,
// at 1 thread and at all cores, --repeat times, the fastest run kept: wall time and peak
// resident memory of the process (wait4), seconds and peak resident memory of every stage
// and the seconds of the parts of the segmentation (summary.json). Then the growth
// exponent of every stage over the fandisk series (least squares of log seconds against
// log faces, stages of 5 ms and more) against that of n log n over the same sizes; the
// cost of every step of the series (4 times the faces), and at the largest mesh of the
// series up to a million faces (828k) each stage against the mesh 4 times smaller (at most
// 4.4 times, for the wall time and the curvature) and all cores against one thread (at
// most 0.65 with two cores); and, on the 207k mesh, the program against CGAL's
// read_polygon_mesh() and sharp_edges_segmentation() at 20 degrees in this process (the
// CSV's cgal_sharp_edges_s).
// Writes a table, a CSV and an SVG plot (seconds per stage against faces, log-log).
//
// Usage: bench_scaling [--data DIR] [--levels 4] [--repeat 3] [--program PATH] [--work DIR]
//          [--csv scaling.csv] [--md scaling.md] [--svg scaling.svg]

#include "bench_common.h"
#include "svg_plot.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

namespace {

namespace fs = std::filesystem;
using fs_bench::Soup_point;
using fs_bench::Soup_triangle;

const std::vector<std::string> stages = { "load", "segmentation", "boundaries", "smoothing", "refinement", "write" };
// the parts of the stage "segmentation" that summary.json times (stage_seconds)
const std::vector<std::string> sub_stages = { "creases", "curvature", "feature_lines", "weight_terms", "oversegmentation" };

struct Run
{
  std::string mesh;
  std::size_t faces = 0;
  bool series = false; // part of the fandisk series (for the exponents)
  unsigned threads = 1;
  double wall = 0, peak_mib = 0;
  double cgal_sharp_edges = -1; // CGAL's read and sharp_edges_segmentation, on the 207k mesh
  std::size_t patches = 0;
  std::map<std::string, double> seconds, stage_peak_mib;
};

void write_off(const fs::path& path, const std::vector<Soup_point>& points, const std::vector<Soup_triangle>& triangles)
{
  std::ofstream out(path);
  out << "OFF\n" << points.size() << ' ' << triangles.size() << " 0\n" << std::setprecision(17);
  for(const Soup_point& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const Soup_triangle& t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  if(!out) throw std::runtime_error("cannot write " + path.string());
}

void read_soup(const std::string& path, std::vector<Soup_point>& points, std::vector<Soup_triangle>& triangles)
{
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> p;
  std::vector<std::vector<std::size_t> > f;
  if(!CGAL::IO::read_polygon_soup(path, p, f)) throw std::runtime_error("cannot read " + path);
  points.clear();
  for(const auto& q : p) points.push_back({ { q.x(), q.y(), q.z() } });
  triangles.clear();
  for(const auto& face : f)
    for(std::size_t k = 1; k + 1 < face.size(); ++k) // fan (the meshes used are triangles)
      triangles.push_back({ { std::uint32_t(face[0]), std::uint32_t(face[k]), std::uint32_t(face[k + 1]) } });
}

// Runs the program on `mesh` in a child process; fills the wall time, the process's peak
// resident memory and what summary.json reports.
void run_program(const std::string& program, const fs::path& mesh, const fs::path& out_dir, Run& r)
{
  const std::string threads = std::to_string(r.threads);
  std::vector<std::string> args = { program, mesh.string(), "--output-dir", out_dir.string(), "--quiet",
                                    "--threads", threads };
  std::vector<char*> argv;
  for(std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  // posix_spawn, not fork: a forked child would count this process's pages in its peak
  pid_t pid = 0;
  if(posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot run " + program);
  int status = 0;
  struct rusage usage;
  if(wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(program + " failed on " + mesh.string());
  r.wall = fs_bench::seconds_since(start);
  r.peak_mib = double(usage.ru_maxrss) / 1024; // kilobytes on Linux
  std::ifstream in(out_dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  r.patches = summary["segmentation"]["patches"].get<std::size_t>();
  for(const std::string& s : sub_stages) r.seconds[s] = summary["segmentation"]["stage_seconds"][s].get<double>();
  for(const std::string& s : stages)
  {
    if(summary["seconds"].contains(s)) r.seconds[s] = summary["seconds"][s].get<double>();
    if(summary["peak_memory_mib"].contains(s)) r.stage_peak_mib[s] = summary["peak_memory_mib"][s].get<double>();
  }
  // the process's peak: the largest of its stages' (each read in the program itself); the
  // rusage figure, used where /proc gave none, can include pages of this process, which
  // the child shares until it executes the program
  double stages_peak = -1;
  for(const auto& p : r.stage_peak_mib) stages_peak = (std::max)(stages_peak, p.second);
  if(stages_peak > 0) r.peak_mib = stages_peak;
}

// The fastest of `repeat` runs (by wall time): the timings of a shared machine vary from
// run to run, and the least of them is the one least disturbed.
void best_run(const std::string& program, const fs::path& mesh, const fs::path& out_dir, int repeat, Run& r)
{
  for(int i = 0; i < repeat; ++i)
  {
    Run trial = r;
    run_program(program, mesh, out_dir, trial);
    if(i == 0 || trial.wall < r.wall) r = trial;
  }
}

// CGAL's simple alternative on the same file, in this process: reading it with CGAL's
// reader into a Surface_mesh, then Polygon_mesh_processing::sharp_edges_segmentation at
// 20 degrees; the seconds of the fastest of `repeat` runs.
double cgal_sharp_edges_seconds(const fs::path& mesh_path, int repeat)
{
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  double best = -1;
  for(int i = 0; i < repeat; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(mesh_path.string(), mesh)) throw std::runtime_error("CGAL cannot read " + mesh_path.string());
    auto eif = get(CGAL::dynamic_edge_property_t<bool>(), mesh);
    auto pid = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
    CGAL::Polygon_mesh_processing::sharp_edges_segmentation(mesh, 20., eif, pid);
    const double t = fs_bench::seconds_since(start);
    if(best < 0 || t < best) best = t;
  }
  return best;
}

// Least-squares slope of log y against log x over the points with y >= min_y.
double growth_exponent(const std::vector<double>& x, const std::vector<double>& y, double min_y)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    if(!(y[i] >= min_y)) continue;
    const double a = std::log(x[i]), b = std::log(y[i]);
    sx += a; sy += b; sxx += a * a; sxy += a * b;
    ++n;
  }
  if(n < 3) return std::nan("");
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

std::string fixed(double x, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

} // namespace

int main(int argc, char** argv)
{
  namespace po = boost::program_options;
  std::string data, program = FS_PROGRAM_PATH, work = "bench_scaling_work", csv_path = "scaling.csv",
                    md_path = "scaling.md", svg_path = "scaling.svg";
  int levels = 4, repeat = 3;
  po::options_description options("bench_scaling options");
  options.add_options()("help", "this text")("data", po::value(&data), "the development data (default: $FEATURE_SEGMENTATION_DATA)")
    ("levels", po::value(&levels), "subdivisions of fandisk, 0 .. 5 (default 4: 3.3M faces)")
    ("repeat", po::value(&repeat), "runs of each mesh and thread count, the fastest kept (default 3)")
    ("program", po::value(&program), "the program feature_segmentation (default: the one built with this benchmark)")
    ("work", po::value(&work), "a folder for the meshes and outputs (default: bench_scaling_work)")
    ("csv", po::value(&csv_path), "the CSV (default scaling.csv)")("md", po::value(&md_path), "the Markdown table")
    ("svg", po::value(&svg_path), "the plot");
  try
  {
    po::variables_map vm;
    po::store(po::parse_command_line(argc, argv, options), vm);
    po::notify(vm);
    if(vm.count("help")) { std::cout << options; return 0; }
    if(levels < 0 || levels > 5) throw std::runtime_error("--levels must be in 0 .. 5");
    if(repeat < 1 || repeat > 100) throw std::runtime_error("--repeat must be in 1 .. 100");
    if(data.empty() && std::getenv("FEATURE_SEGMENTATION_DATA")) data = std::getenv("FEATURE_SEGMENTATION_DATA");

    fs::create_directories(work);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    std::vector<unsigned> thread_counts = { 1u };
    if(cores > 1) thread_counts.push_back(cores);

    struct Mesh_file { std::string name; fs::path path; std::size_t faces; bool series; };
    std::vector<Mesh_file> meshes;
    std::vector<Soup_point> points;
    std::vector<Soup_triangle> triangles;
    read_soup(std::string(FS_MESH_DIR) + "/fandisk.off", points, triangles);
    for(int level = 0; level <= levels; ++level)
    {
      if(level > 0) fs_bench::subdivide(points, triangles);
      const fs::path path = fs::path(work) / ("fandisk_" + std::to_string(level) + ".off");
      write_off(path, points, triangles);
      meshes.push_back({ "fandisk x" + std::to_string(1 << (2 * level)), path, triangles.size(), true });
    }
    // CAD parts of the development data, subdivided flat: about 5M faces, and over 10M
    const struct { const char* part; int levels; const char* name; const char* file; } large_parts[] = {
      { "142473_f37f7cba_0", 4, "CAD 142473 x256", "142473_x256.off" },
      { "42811_d1f01a68_2", 5, "CAD 42811 x1024", "42811_x1024.off" } };
    for(const auto& part : large_parts)
    {
      const fs::path large = fs::path(data) / "cad" / (std::string(part.part) + ".obj");
      if(data.empty() || !fs::exists(large))
      {
        std::cout << "bench_scaling: " << large.string() << " not found (--data or FEATURE_SEGMENTATION_DATA): no "
                  << part.name << '\n';
        continue;
      }
      read_soup(large.string(), points, triangles);
      for(int level = 0; level < part.levels; ++level) fs_bench::subdivide(points, triangles);
      const fs::path path = fs::path(work) / part.file;
      write_off(path, points, triangles);
      meshes.push_back({ part.name, path, triangles.size(), false });
    }
    points.clear(); points.shrink_to_fit();
    triangles.clear(); triangles.shrink_to_fit();

    std::vector<Run> runs;
    std::cout << "bench_scaling on " << fs_bench::cpu_name() << ", " << cores << " cores; the program at its defaults, "
              << "the fastest of " << repeat << " runs\n\n"
              << std::left << std::setw(18) << "mesh" << std::right << std::setw(10) << "faces" << std::setw(5) << "thr"
              << std::setw(9) << "wall s" << std::setw(9) << "peak MB";
    for(const std::string& s : stages) std::cout << std::setw(13) << s;
    std::cout << std::setw(9) << "patches" << '\n';
    for(const Mesh_file& m : meshes)
      for(unsigned t : thread_counts)
      {
        Run r;
        r.mesh = m.name; r.faces = m.faces; r.series = m.series; r.threads = t;
        best_run(program, m.path, fs::path(work) / "out", repeat, r);
        std::cout << std::left << std::setw(18) << r.mesh << std::right << std::setw(10) << r.faces << std::setw(5)
                  << t << std::setw(9) << fixed(r.wall, 2) << std::setw(9) << fixed(r.peak_mib * 1.048576, 0);
        for(const std::string& s : stages)
          std::cout << std::setw(13) << (fixed(r.seconds[s], 2) + "/" + fixed(r.stage_peak_mib[s] * 1.048576, 0));
        std::cout << std::setw(9) << r.patches << '\n';
        runs.push_back(r);
      }
    std::cout << "(a stage: seconds / peak resident MB during it)\n\n";
    // CGAL's sharp_edges_segmentation on the fandisk mesh of 207,136 faces (x16)
    const std::size_t compared_faces = 207136;
    double cgal_seconds = -1;
    for(const Mesh_file& m : meshes)
      if(m.series && m.faces == compared_faces)
      {
        cgal_seconds = cgal_sharp_edges_seconds(m.path, repeat);
        for(Run& r : runs) if(r.series && r.faces == compared_faces) r.cgal_sharp_edges = cgal_seconds;
      }

    // growth exponents over the fandisk series
    std::vector<double> sizes;
    for(const Mesh_file& m : meshes) if(m.series) sizes.push_back(double(m.faces));
    std::vector<double> nlogn;
    for(double n : sizes) nlogn.push_back(n * std::log(n));
    const double limit = growth_exponent(sizes, nlogn, 0) + 0.1; // n log n, and room for timing noise
    std::ostringstream md;
    md << "Scaling of the program `feature_segmentation` at its defaults (`bench_scaling`, " << fs_bench::cpu_name()
       << ", " << cores << " cores): fandisk and its flat subdivisions";
    for(const Mesh_file& m : meshes)
      if(!m.series) md << ", " << m.name << " (the CAD part subdivided flat)";
    md << "; the fastest of " << repeat << " runs of each. Seconds / peak resident MB of each stage; wall and peak of the "
          "whole process.\n\n| mesh | faces | threads | wall s | peak MB |";
    for(const std::string& s : stages) md << ' ' << s << " |";
    md << " patches |\n|---|---:|---:|---:|---:|";
    for(std::size_t i = 0; i < stages.size(); ++i) md << "---:|";
    md << "---:|\n";
    for(const Run& r : runs)
    {
      md << "| " << r.mesh << " | " << r.faces << " | " << r.threads << " | " << fixed(r.wall, 2) << " | "
         << fixed(r.peak_mib * 1.048576, 0) << " |";
      for(const std::string& s : stages)
        md << ' ' << fixed(r.seconds.at(s), 2) << " / " << fixed(r.stage_peak_mib.count(s) ? r.stage_peak_mib.at(s) * 1.048576 : r.peak_mib * 1.048576, 0) << " |";
      md << ' ' << r.patches << " |\n";
    }
    md << "\nGrowth exponents over the fandisk series (slope of log seconds against log faces, stages of 5 ms and more; "
       << "n log n over these sizes: " << fixed(limit - 0.1, 2) << "):\n\n| stage |";
    for(unsigned t : thread_counts) md << ' ' << t << " thread" << (t > 1 ? "s" : "") << " |";
    md << "\n|---|";
    for(std::size_t i = 0; i < thread_counts.size(); ++i) md << "---:|";
    md << '\n';
    bool all_pass = true;
    std::vector<std::string> rows = stages;
    rows.insert(rows.begin() + 2, sub_stages.begin(), sub_stages.end()); // after "segmentation", its parts
    rows.push_back("wall");
    auto is_sub_stage = [](const std::string& s) { return std::find(sub_stages.begin(), sub_stages.end(), s) != sub_stages.end(); };
    auto row_name = [&](const std::string& s) { return is_sub_stage(s) ? "- " + s : s; };
    for(const std::string& s : rows)
    {
      md << "| " << row_name(s) << " |";
      for(unsigned t : thread_counts)
      {
        std::vector<double> y;
        for(const Run& r : runs)
          if(r.series && r.threads == t) y.push_back(s == "wall" ? r.wall : r.seconds.at(s));
        const double e = growth_exponent(sizes, y, 0.005);
        if(std::isfinite(e) && e > limit) all_pass = false;
        md << ' ' << (std::isfinite(e) ? fixed(e, 2) : std::string("-")) << " |";
      }
      md << '\n';
    }
    md << '\n' << (all_pass ? "PASS" : "MISS") << "  every stage grows no faster than n log n (exponent at most "
       << fixed(limit, 2) << ", n log n's plus 0.1 for timing noise)\n";

    // The cost of 4 times the faces: every step of the series; then, at the largest mesh of
    // the series of at most a million faces (fandisk x64, 828k), each stage against the
    // mesh 4 times smaller, and all cores against one thread.
    auto series_run = [&](std::size_t faces, unsigned t) -> const Run* {
      for(const Run& r : runs) if(r.series && r.faces == faces && r.threads == t) return &r;
      return nullptr;
    };
    auto seconds_of = [](const Run& r, const std::string& s) { return s == "wall" ? r.wall : r.seconds.at(s); };
    auto ratio_of = [&](const Run& a, const Run& b, const std::string& s) {
      return seconds_of(b, s) / (std::max)(1e-9, seconds_of(a, s));
    };
    if(sizes.size() >= 2)
    {
      md << "\nCost of 4 times the faces, one thread (linear: 4.0):\n\n| faces | 4 times | wall | curvature |\n"
            "|---:|---:|---:|---:|\n";
      std::size_t big = std::size_t(sizes[1]);
      for(std::size_t i = 1; i < sizes.size(); ++i)
      {
        const Run* a = series_run(std::size_t(sizes[i - 1]), 1);
        const Run* b = series_run(std::size_t(sizes[i]), 1);
        md << "| " << a->faces << " | " << b->faces << " | " << fixed(ratio_of(*a, *b, "wall"), 2) << " | "
           << fixed(ratio_of(*a, *b, "curvature"), 2) << " |\n";
        if(sizes[i] <= 1e6) big = std::size_t(sizes[i]);
      }
      const Run* b = series_run(big, 1);
      const Run* a = series_run(big / 4, 1);
      md << "\nAt " << big << " faces against " << a->faces << ", one thread:\n\n| stage | " << a->faces << " | " << big
         << " | ratio |\n|---|---:|---:|---:|\n";
      for(const std::string& s : rows)
        md << "| " << row_name(s) << " | " << fixed(seconds_of(*a, s), 3) << " | " << fixed(seconds_of(*b, s), 3) << " | "
           << fixed(ratio_of(*a, *b, s), 2) << " |\n";
      for(const std::string& s : { std::string("wall"), std::string("curvature") })
        md << '\n' << (ratio_of(*a, *b, s) <= 4.4 ? "PASS" : "MISS") << "  " << s << ": " << fixed(ratio_of(*a, *b, s), 2)
           << " times the seconds for 4 times the faces (at most 4.4)";
      md << '\n';
      if(thread_counts.size() > 1)
      {
        const unsigned n = thread_counts.back();
        const Run* one = series_run(big, 1);
        const Run* all = series_run(big, n);
        md << "\nThreads at " << big << " faces: seconds with " << n << " threads / seconds with 1 (perfect: "
           << fixed(1. / n, 2) << "):\n\n| stage | 1 thread | " << n << " threads | ratio |\n|---|---:|---:|---:|\n";
        for(const std::string& s : rows)
          md << "| " << row_name(s) << " | " << fixed(seconds_of(*one, s), 3) << " | " << fixed(seconds_of(*all, s), 3) << " | "
             << fixed(ratio_of(*one, *all, s), 2) << " |\n";
        md << '\n' << (ratio_of(*one, *all, "wall") <= 0.65 ? "PASS" : "MISS") << "  wall time with " << n << " threads: "
           << fixed(ratio_of(*one, *all, "wall"), 2) << " of one thread's (at most 0.65)\n";
      }
    }
    if(cgal_seconds > 0)
    {
      md << "\nAgainst CGAL at " << compared_faces << " faces: CGAL's read_polygon_mesh() and sharp_edges_segmentation() "
            "at 20 degrees (in this process) take " << fixed(cgal_seconds, 3) << " s; the program (a process of its own):\n\n"
            "| threads | seconds | of CGAL's |\n|---:|---:|---:|\n";
      double at_default = -1;
      for(unsigned t : thread_counts)
      {
        const Run* r = series_run(compared_faces, t);
        md << "| " << t << " | " << fixed(r->wall, 3) << " | " << fixed(r->wall / cgal_seconds, 2) << " |\n";
        at_default = r->wall / cgal_seconds; // the program's default: all cores
      }
      md << '\n' << (at_default <= 0.35 ? "PASS" : "MISS") << "  the program at its defaults: " << fixed(at_default, 2)
         << " of CGAL's time (at most 0.35)\n";
    }
    // the largest part of over 10M faces, at all cores (the program's default)
    for(const Mesh_file& m : meshes)
    {
      if(m.series || m.faces < 10000000) continue;
      for(const Run& r : runs)
        if(r.mesh == m.name && r.threads == thread_counts.back())
        {
          const double gb = r.peak_mib * 1.048576 / 1000.;
          md << '\n' << (r.wall <= 60 && gb <= 8 ? "PASS" : "MISS") << "  " << m.name << ", " << r.faces << " faces, "
             << r.threads << " threads: " << fixed(r.wall, 1) << " s and " << fixed(gb, 2)
             << " GB peak (at most 60 s and 8 GB)\n";
        }
    }
    std::cout << md.str();

    std::ofstream csv(csv_path);
    csv << "mesh,faces,threads,wall_s,peak_mb";
    for(const std::string& s : stages) csv << ',' << s << "_s," << s << "_peak_mb";
    for(const std::string& s : sub_stages) csv << ',' << s << "_s";
    csv << ",patches,cgal_sharp_edges_s\n";
    for(const Run& r : runs)
    {
      csv << fs_bench::csv_text(r.mesh) << ',' << r.faces << ',' << r.threads << ',' << r.wall << ','
          << r.peak_mib * 1.048576;
      for(const std::string& s : stages)
        csv << ',' << r.seconds.at(s) << ',' << (r.stage_peak_mib.count(s) ? std::to_string(r.stage_peak_mib.at(s) * 1.048576) : "");
      for(const std::string& s : sub_stages) csv << ',' << r.seconds.at(s);
      csv << ',' << r.patches << ',';
      if(r.cgal_sharp_edges >= 0) csv << r.cgal_sharp_edges;
      csv << '\n';
    }
    std::ofstream(md_path) << md.str();

    // the plot: seconds per stage against faces, log-log, one panel per thread count
    std::vector<double> x;
    for(double n : sizes) x.push_back(std::log10(n));
    const std::vector<std::string> colours = { "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#000000" };
    std::vector<fs_bench::Panel> panels;
    for(unsigned t : thread_counts)
    {
      fs_bench::Panel p;
      p.title = "fandisk series, " + std::to_string(t) + " thread" + (t > 1 ? "s" : "");
      p.x_label = "log10 faces";
      p.y_label = "seconds";
      p.allow_log = true;
      std::vector<std::string> plotted = stages; // the stages of the program and its wall time
      plotted.push_back("wall");
      for(std::size_t k = 0; k < plotted.size(); ++k)
      {
        fs_bench::Series series{ plotted[k], colours[k % colours.size()], k + 1 == plotted.size() ? "6,3" : "", {} };
        for(const Run& r : runs)
          if(r.series && r.threads == t)
            series.y.push_back((std::max)(1e-3, seconds_of(r, plotted[k])));
        p.series.push_back(series);
      }
      panels.push_back(p);
    }
    std::ofstream svg(svg_path);
    fs_bench::svg_figure(svg, x, panels, "bench_scaling: seconds per stage of feature_segmentation at its defaults (floor 1 ms), " +
                                          fs_bench::cpu_name());
    fs_bench::write_provenance(csv_path, argc, argv);
    std::cout << "\nWritten: " << csv_path << ", " << md_path << ", " << svg_path << '\n';
  }
  catch(const std::exception& e)
  {
    std::cerr << "bench_scaling: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
