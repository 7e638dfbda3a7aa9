// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line program of the package: reads a mesh, runs the pipeline stage by
// stage (load -> curvature -> feature lines -> segmentation -> the edits of an edit
// script, if given), each stage and each edit timed, and writes the feature lines
// (CGAL polylines and OBJ), the segmentation (a PLY mesh with a patch id and colour per
// face, and the patch of every vertex and face of the input file) and a JSON summary
// into an output folder. Bad input or bad options give one "error: ..." line on stderr
// and a non-zero exit status.

#include "edit_script.h"
#include "huge_pages.h"
#include "read_input_mesh.h"
#include "read_user_feature_lines.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/Feature_lines.h>
#include <CGAL/Feature_segmentation/Greedy_additive_edge_contraction.h>
#include <CGAL/Feature_segmentation/IO/write_boundaries.h>
#include <CGAL/Feature_segmentation/IO/write_feature_lines.h>
#include <CGAL/Feature_segmentation/IO/write_segmentation.h>
#include <CGAL/Feature_segmentation/Kernighan_lin_with_joins.h>
#include <CGAL/Feature_segmentation/Solver_sequence.h>
#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/input_checks.h>
#include <CGAL/Feature_segmentation/parameters.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/Watershed_distance.h>
#include <CGAL/Feature_segmentation/boundary_curves.h>
#include <CGAL/Feature_segmentation/face_patches.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>

#include <CGAL/property_map.h>

#include <boost/range/counting_range.hpp>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <unistd.h> // getpid: names of temporary output files
#include <exception>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace FS = CGAL::Feature_segmentation;

const char* const program_name = "feature_segmentation";

// smooth_patch_boundaries()'s default number of iterations, for --help and the summary
// (the program passes the option to the library only when it is given).
const int default_smoothing_iterations = 20;

// A wrong command line: reported with exit status 2, as getopt-style programs do.
class Usage_error : public std::runtime_error
{
public:
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

struct Options
{
  std::string input = std::string(FS_MESH_DIR) + "/fandisk.off";
  std::string output_dir = "feature_segmentation_output";
  int rings = 2;
  double radius = FS::default_neighborhood_radius;
  std::optional<double> strength_threshold; // unset: the library's default
  bool ridges = true;
  bool valleys = true;
  std::string feature_edges_file;           // empty: none
  // The library's defaults for alpha and gamma (segment_along_features()).
  double alpha = 0.6;
  double gamma = 0.05;
  double crease_angle = CGAL::Feature_segmentation::internal::Segmentation_options().crease_angle;
  // most rounds of normal filtering before creases: the library's default
  int crease_filter = CGAL::Feature_segmentation::internal::Segmentation_options().crease_filter_iterations;
  std::string solver = "gaec+klj";
  bool full_graph = false;
  std::string watershed = "anisotropic";
  std::string edits_file;                   // empty: no edits
  std::optional<int> smoothing_iterations;  // unset: the library's default
  bool quiet = false;
  bool help = false;
};

void print_usage(std::ostream& os)
{
  os << "Usage: " << program_name << " [MESH] [--output-dir DIR] [options]\n"
     << "\n"
     << "Detects the feature lines (ridges and valleys) of a triangle mesh and writes\n"
     << "  DIR/feature_lines.polylines.txt  CGAL polylines, one feature line per line of text\n"
     << "  DIR/feature_lines.obj            the same lines as OBJ line elements\n"
     << "and segments it into patches bounded by them (correlation clustering), writing\n"
     << "  DIR/segmentation.ply             the mesh (triangulated, repaired) with a patch_id\n"
     << "                                   and a red, green, blue colour per face\n"
     << "  DIR/face_patches.txt             the patch of every face of MESH, one per line\n"
     << "  DIR/vertex_patches.txt           the patch of every vertex of MESH, one per line\n"
     << "  DIR/boundaries.polylines.txt     the boundaries between the patches, smoothed:\n"
     << "                                   CGAL polylines, one curve per line of text\n"
     << "  DIR/segmentation_refined.ply     the mesh refined along the smoothed boundaries,\n"
     << "                                   every face in one patch (patch_id and colour)\n"
     << "  DIR/summary.json                 mesh and feature counts, patches, cut cost,\n"
     << "                                   oversegments, seconds per stage, and for each\n"
     << "                                   edit of --edits its patches, cut cost, seconds;\n"
     << "                                   boundary curves and lengths before and after\n"
     << "                                   the smoothing\n"
     << "\n"
     << "MESH is an .off, .obj, .ply or .stl file (default: " << FS_MESH_DIR << "/fandisk.off).\n"
     << "Quads and polygons are triangulated, duplicate points and faces removed, with a\n"
     << "notice on stderr.\n"
     << "\n"
     << "Patch files follow the input file's order: line i is the patch of its i-th vertex\n"
     << "(or face). Patches are numbered from 0. A face has the patch of the majority of\n"
     << "its three vertices (the smallest of the three when all differ); a quad or polygon\n"
     << "that was triangulated has the patch of its first triangle. A duplicate vertex\n"
     << "(same position as an earlier one) or duplicate face (same vertices as an earlier\n"
     << "one) has the patch of that earlier one; a pinched (non-manifold) vertex, split\n"
     << "into copies to repair it, has the patch of the copy in the first face (in file\n"
     << "order) that uses it; a vertex that no face uses has -1. For STL, the vertices are\n"
     << "the distinct points in order of first appearance.\n"
     << "\n"
     << "The boundaries are the curves between the patches of the vertices (through the\n"
     << "triangles whose vertices lie in different patches), smoothed in the metric of the\n"
     << "edge weights so that they settle on the features and straighten elsewhere; the\n"
     << "smoothing may move a vertex next to a boundary to the neighbouring patch, which\n"
     << "segmentation_refined.ply shows (its vertices are the mesh's, then the new ones).\n"
     << "The patch files and segmentation.ply keep the clustering's patches.\n"
     << "\n"
     << "Options:\n"
     << "  --output-dir DIR          output folder, created if needed\n"
     << "                            (default: ./feature_segmentation_output)\n"
     << "  --rings N                 curvature neighbourhood in rings, integer >= 1 (default: 2)\n"
     << "  --radius X                and beyond the rings, the vertices within X times the\n"
     << "                            bounding box diagonal (normals within 30 degrees);\n"
     << "                            0 <= X <= 1, 0: rings only (default: "
     << FS::default_neighborhood_radius << ")\n"
     << "  --strength-threshold X    drop feature lines weaker than X, X >= 0\n"
     << "                            (default: " << FS::default_strength_threshold << ")\n"
     << "  --no-ridges               do not detect ridges\n"
     << "  --no-valleys              do not detect valleys\n"
     << "  --feature-edges FILE      add user feature lines: a CGAL polylines file whose\n"
     << "                            points are mesh vertices and segments mesh edges\n"
     << "  --alpha X                 weight of the feature lines, any finite number; larger\n"
     << "                            gives more patches, useful range 0.5 to 1 (default: 0.6)\n"
     << "  --gamma X                 anisotropy of the metric, X >= 0 (default: 0.05)\n"
     << "  --crease-angle D          edges whose faces bend by D degrees or more are creases:\n"
     << "                            the mesh is cut open along them and their sides tied by\n"
     << "                            crease weights (a gap test keeps strong bends of smooth\n"
     << "                            surfaces out); 180 or more: none (with --radius 0,\n"
     << "                            the paper's method)\n"
     << "                            (default: "
     << CGAL::Feature_segmentation::internal::Segmentation_options().crease_angle << ")\n"
     << "  --crease-filter N         rounds of bilateral filtering of the face normals\n"
     << "                            before the creases are found; none on clean meshes;\n"
     << "                            0: raw dihedral angles (default: "
     << CGAL::Feature_segmentation::internal::Segmentation_options().crease_filter_iterations << ")\n"
     << "  --solver NAME             correlation clustering solver: gaec+klj (greedy additive\n"
     << "                            edge contraction, then Kernighan-Lin with joins),\n"
     << "                            gaec, or klj (from singletons) (default: gaec+klj)\n"
     << "  --full-graph              cluster the full vertex graph, not the reduced graph G'\n"
     << "                            of the watershed oversegmentation (slower)\n"
     << "  --watershed NAME          distance of the watershed oversegmentation: anisotropic\n"
     << "                            (the paper's) or geodesic (default: anisotropic)\n"
     << "  --edits FILE              apply the edit script FILE (below) after the automatic\n"
     << "                            segmentation; the patch outputs are the edited result\n"
     << "  --smoothing-iterations N  iterations of the boundary smoothing, integer >= 0; 0\n"
     << "                            writes the boundaries unsmoothed (default: "
     << default_smoothing_iterations << ")\n"
     << "  --quiet                   no progress or notice lines on stderr (by default every\n"
     << "                            stage prints 'progress: STAGE ...' when it starts and\n"
     << "                            'progress: STAGE done in X s' when it ends)\n"
     << "  --help                    print this help and exit\n"
     << "\n"
     << "Edit scripts (--edits FILE): one edit per line, applied in order; '#' starts a\n"
     << "comment, blank lines are ignored. Numbers are decimal, finite.\n"
     << "  alpha A                   global refine/coarsen: set alpha to A (the alpha_e of\n"
     << "                            every feature edge moves by A - alpha)\n"
     << "  refine REGION D           local refine: add D to alpha_e on the feature edges\n"
     << "                            of REGION, re-solve the patches it touches\n"
     << "  coarsen REGION D          local coarsen: subtract D from those alpha_e\n"
     << "  scale REGION F            multiply those alpha_e by F >= 0\n"
     << "  merge REGION              merge the patches that REGION touches (kept by later\n"
     << "                            solves)\n"
     << "  sketch [alpha A] X Y Z X Y Z ...\n"
     << "                            a sketched feature line through two points or more,\n"
     << "                            each moved to the nearest point of the surface; the\n"
     << "                            edges it crosses get alpha_e >= A > 1 (default: 2)\n"
     << "  undo                      take back the last edit not yet undone\n"
     << "REGION is 'ball X Y Z R' (the faces whose centroid lies within R > 0 of X Y Z) or\n"
     << "'faces I J ...' (faces of MESH numbered from 0 in file order, as in\n"
     << "face_patches.txt; a triangulated polygon stands for all its triangles). A region\n"
     << "without faces, or a merge inside one patch, changes nothing. A mistake in the\n"
     << "script gives 'error: FILE:LINE: reason' and exit status 1 before the\n"
     << "segmentation runs or anything is written. summary.json lists every edit\n"
     << "(\"edits\"): its line, verb, the patches and cut cost after it, and its seconds\n"
     << "(the library's re-weighting and re-solve; finding the region's faces or locating\n"
     << "the sketch's points apart, as prepare_seconds).\n";
}

// Strict number parsing: the whole argument must be the number ("1.5x", "", "abc",
// "nan" and out-of-range values are refused).
int parse_int(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  long value = 0;
  try
  {
    value = std::stol(text, &used, 10);
  }
  catch(const std::exception&)
  {
    throw Usage_error(option + " expects an integer (got '" + text + "')");
  }
  if(used != text.size() || std::isspace(static_cast<unsigned char>(text[0])))
    throw Usage_error(option + " expects an integer (got '" + text + "')");
  if(value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw Usage_error(option + " is out of range (got '" + text + "')");
  return static_cast<int>(value);
}

double parse_double(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double value = 0;
  try
  {
    value = std::stod(text, &used);
  }
  catch(const std::exception&)
  {
    throw Usage_error(option + " expects a number (got '" + text + "')");
  }
  if(used != text.size() || std::isspace(static_cast<unsigned char>(text[0])))
    throw Usage_error(option + " expects a number (got '" + text + "')");
  if(!std::isfinite(value))
    throw Usage_error(option + " expects a finite number (got '" + text + "')");
  return value;
}

Options parse_command_line(int argc, char** argv)
{
  Options options;
  bool has_input = false;
  bool has_watershed = false;
  for(int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    std::string value;
    bool has_inline_value = false;
    if(arg.rfind("--", 0) == 0)
    {
      const std::size_t eq = arg.find('=');
      if(eq != std::string::npos)
      {
        value = arg.substr(eq + 1);
        arg = arg.substr(0, eq);
        has_inline_value = true;
      }
    }
    auto take_value = [&]() -> std::string {
      if(has_inline_value)
        return value;
      // "--rings --quiet" is a forgotten value, not a folder or number named "--quiet".
      if(i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0)
        throw Usage_error(arg + " expects a value");
      return argv[++i];
    };
    auto refuse_value = [&]() {
      if(has_inline_value)
        throw Usage_error(arg + " takes no value");
    };

    if(arg == "--help" || arg == "-h") { refuse_value(); options.help = true; }
    else if(arg == "--quiet") { refuse_value(); options.quiet = true; }
    else if(arg == "--no-ridges") { refuse_value(); options.ridges = false; }
    else if(arg == "--no-valleys") { refuse_value(); options.valleys = false; }
    else if(arg == "--output-dir")
    {
      options.output_dir = take_value();
      if(options.output_dir.empty())
        throw Usage_error("--output-dir expects a non-empty folder name");
    }
    else if(arg == "--rings")
    {
      options.rings = parse_int(arg, take_value());
      if(options.rings < 1)
        throw Usage_error("--rings must be an integer >= 1 (got " +
                          std::to_string(options.rings) + ")");
    }
    else if(arg == "--radius")
    {
      const std::string text = take_value();
      options.radius = parse_double(arg, text);
      if(!(options.radius >= 0) || !(options.radius <= 1))
        throw Usage_error("--radius must be a number in [0, 1] (got " + text + ")");
    }
    else if(arg == "--strength-threshold")
    {
      const std::string text = take_value();
      const double x = parse_double(arg, text);
      if(x < 0)
        throw Usage_error("--strength-threshold must be >= 0 (got '" + text + "')");
      options.strength_threshold = x;
    }
    else if(arg == "--feature-edges")
    {
      options.feature_edges_file = take_value();
      if(options.feature_edges_file.empty())
        throw Usage_error("--feature-edges expects a file name");
    }
    else if(arg == "--alpha")
      options.alpha = parse_double(arg, take_value());
    else if(arg == "--gamma")
    {
      const std::string text = take_value();
      options.gamma = parse_double(arg, text);
      if(options.gamma < 0)
        throw Usage_error("--gamma must be >= 0 (got '" + text + "')");
    }
    else if(arg == "--crease-angle")
    {
      const std::string text = take_value();
      options.crease_angle = parse_double(arg, text);
      if(!(options.crease_angle > 0))
        throw Usage_error("--crease-angle must be > 0 degrees (got '" + text + "')");
    }
    else if(arg == "--crease-filter")
    {
      const std::string text = take_value();
      options.crease_filter = parse_int(arg, text);
      if(options.crease_filter < 0 || options.crease_filter > 1000)
        throw Usage_error("--crease-filter must be an integer in 0 .. 1000 (got '" + text + "')");
    }
    else if(arg == "--solver")
    {
      options.solver = take_value();
      if(options.solver != "gaec+klj" && options.solver != "gaec" && options.solver != "klj")
        throw Usage_error("--solver must be gaec+klj, gaec or klj (got '" + options.solver + "')");
    }
    else if(arg == "--full-graph") { refuse_value(); options.full_graph = true; }
    else if(arg == "--smoothing-iterations")
    {
      const int n = parse_int(arg, take_value());
      if(n < 0)
        throw Usage_error("--smoothing-iterations must be an integer >= 0 (got " + std::to_string(n) + ")");
      options.smoothing_iterations = n;
    }
    else if(arg == "--watershed")
    {
      options.watershed = take_value();
      has_watershed = true;
      if(options.watershed != "anisotropic" && options.watershed != "geodesic")
        throw Usage_error("--watershed must be anisotropic or geodesic (got '" + options.watershed + "')");
    }
    else if(arg == "--edits")
    {
      options.edits_file = take_value();
      if(options.edits_file.empty())
        throw Usage_error("--edits expects a file name");
    }
    else if(arg.size() > 1 && arg[0] == '-')
      throw Usage_error("unknown option '" + arg + "' (see --help)");
    else
    {
      if(has_input)
        throw Usage_error("more than one input mesh ('" + options.input + "' and '" + arg + "')");
      options.input = arg;
      has_input = true;
    }
  }
  if(!options.ridges && !options.valleys && !options.quiet && !options.help)
    std::cerr << "notice: --no-ridges and --no-valleys: no crest lines will be detected\n";
  if(options.full_graph && has_watershed && !options.quiet && !options.help)
    std::cerr << "notice: --full-graph: no oversegmentation, --watershed has no effect\n";
  return options;
}

// Wall-clock seconds of each stage, in the order the stages ran.
class Stage_timer
{
public:
  explicit Stage_timer(bool quiet) : m_quiet(quiet) {}

  template <typename F>
  auto run(const std::string& name, F&& f)
  {
    if(!m_quiet)
      std::cerr << "progress: " << name << " ..." << std::endl;
    const auto start = std::chrono::steady_clock::now();
    auto finish = [&]() {
      const std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
      m_seconds.emplace_back(name, d.count());
      if(!m_quiet)
        std::cerr << "progress: " << name << " done in " << std::fixed << std::setprecision(3)
                  << d.count() << " s" << std::defaultfloat << std::endl;
    };
    if constexpr(std::is_void_v<decltype(f())>)
    {
      f();
      finish();
    }
    else
    {
      auto result = f();
      finish();
      return result;
    }
  }

  const std::vector<std::pair<std::string, double> >& seconds() const { return m_seconds; }

private:
  bool m_quiet;
  std::vector<std::pair<std::string, double> > m_seconds;
};

std::string json_string(const std::string& s)
{
  std::ostringstream os;
  os << '"';
  for(unsigned char c : s)
  {
    switch(c)
    {
      case '"': os << "\\\""; break;
      case '\\': os << "\\\\"; break;
      case '\n': os << "\\n"; break;
      case '\t': os << "\\t"; break;
      case '\r': os << "\\r"; break;
      default:
        if(c < 0x20)
          os << "\\u" << std::hex << std::setw(4) << std::setfill('0') << int(c) << std::dec;
        else
          os << c;
    }
  }
  os << '"';
  return os.str();
}

// `digits` significant digits; by default the fewest that read back as `x` (0.6, not
// 0.59999999999999998), which is as deterministic as a fixed count.
std::string json_number(double x, int digits = 0)
{
  std::ostringstream os;
  if(digits > 0)
  {
    os << std::setprecision(digits) << x;
    return os.str();
  }
  for(int d = 1;; ++d)
  {
    os.str(std::string());
    os << std::setprecision(d) << x;
    if(d >= std::numeric_limits<double>::max_digits10 ||
       std::strtod(os.str().c_str(), nullptr) == x)
      return os.str();
  }
}

// The solver chosen with --solver, timed on its own: the segmentation stage also builds
// the graph and its weights, and the summary reports both times.
class Timed_solver
{
public:
  Timed_solver(const std::string& name, double& seconds) : m_name(name), m_seconds(&seconds) {}

  std::size_t operator()(const FS::Correlation_clustering_graph& g,
                         std::vector<std::size_t>& labels) const
  {
    const auto start = std::chrono::steady_clock::now();
    std::size_t n = 0;
    if(m_name == "gaec")
      n = FS::Greedy_additive_edge_contraction()(g, labels);
    else if(m_name == "klj")
    {
      labels.clear(); // from singletons
      n = FS::Kernighan_lin_with_joins()(g, labels);
    }
    else
      n = FS::Default_correlation_clustering_solver()(g, labels);
    const std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
    *m_seconds = d.count();
    return n;
  }

private:
  std::string m_name;
  double* m_seconds; // the solver is copied by the segmentation: the time lives with the caller
};

struct Results
{
  fs_demo::Read_report read_report;
  std::size_t number_of_vertices = 0;
  std::size_t number_of_edges = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_feature_edges = 0;
  std::size_t number_of_crease_edges = 0;
  std::size_t number_of_ridges = 0;
  std::size_t number_of_valleys = 0;
  std::size_t number_of_user_lines = 0;
  std::size_t number_of_lines = 0;
  std::size_t number_of_patches = 0;       // after the edits
  double cut_cost = 0;                     // after the edits
  std::size_t number_of_automatic_patches = 0; // before the edits
  double automatic_cut_cost = 0;           // before the edits
  std::size_t number_of_oversegments = 0;
  double solver_seconds = 0;               // of the automatic segmentation
  std::vector<fs_demo::Edit_record> edits;
  // The boundaries and their smoothing.
  std::size_t number_of_curves = 0;
  std::size_t number_of_junctions = 0;
  std::size_t smoothing_iterations_run = 0;
  std::size_t smoothing_vertex_moves = 0;
  double length_before = 0, length_after = 0;
  double anisotropic_length_before = 0, anisotropic_length_after = 0;
  double smoothing_seconds = 0;
  std::size_t number_of_refined_vertices = 0;
  std::size_t number_of_refined_faces = 0;
  std::size_t number_of_split_faces = 0;
};

void write_summary(std::ostream& os, const Options& options, const Results& r,
                   const std::vector<std::pair<std::string, double> >& seconds)
{
  const double threshold = options.strength_threshold ? *options.strength_threshold
                                                      : FS::default_strength_threshold;
  os << "{\n"
     << "  \"program\": \"" << program_name << "\",\n"
     << "  \"input\": " << json_string(options.input) << ",\n"
     << "  \"options\": {\n"
     << "    \"rings\": " << options.rings << ",\n"
     << "    \"radius\": " << json_number(options.radius) << ",\n"
     << "    \"strength_threshold\": " << json_number(threshold) << ",\n"
     << "    \"ridges\": " << (options.ridges ? "true" : "false") << ",\n"
     << "    \"valleys\": " << (options.valleys ? "true" : "false") << ",\n"
     << "    \"feature_edges_file\": "
     << (options.feature_edges_file.empty() ? std::string("null")
                                            : json_string(options.feature_edges_file)) << ",\n"
     << "    \"alpha\": " << json_number(options.alpha) << ",\n"
     << "    \"gamma\": " << json_number(options.gamma) << ",\n"
     << "    \"crease_angle\": " << json_number(options.crease_angle) << ",\n"
     << "    \"crease_filter\": " << options.crease_filter << ",\n"
     << "    \"full_graph\": " << (options.full_graph ? "true" : "false") << ",\n"
     << "    \"watershed\": " << json_string(options.watershed) << ",\n"
     << "    \"edits_file\": "
     << (options.edits_file.empty() ? std::string("null") : json_string(options.edits_file)) << ",\n"
     << "    \"smoothing_iterations\": "
     << (options.smoothing_iterations ? *options.smoothing_iterations : default_smoothing_iterations) << ",\n"
     << "    \"solver\": " << json_string(options.solver) << "\n"
     << "  },\n"
     << "  \"input_file\": {\n"
     << "    \"format\": " << json_string(r.read_report.format) << ",\n"
     << "    \"vertices\": " << r.read_report.number_of_file_points << ",\n"
     << "    \"faces\": " << r.read_report.number_of_file_faces << ",\n"
     << "    \"removed_vertices\": " << r.read_report.number_of_merged_points << ",\n"
     << "    \"removed_faces\": " << r.read_report.number_of_removed_faces << ",\n"
     << "    \"duplicated_vertices\": " << r.read_report.number_of_duplicated_points << ",\n"
     << "    \"triangulated_faces\": " << r.read_report.number_of_triangulated_faces << "\n"
     << "  },\n"
     << "  \"mesh\": {\n"
     << "    \"vertices\": " << r.number_of_vertices << ",\n"
     << "    \"edges\": " << r.number_of_edges << ",\n"
     << "    \"faces\": " << r.number_of_faces << ",\n"
     << "    \"border_edges\": " << r.read_report.number_of_border_edges << "\n"
     << "  },\n"
     << "  \"feature_lines\": {\n"
     << "    \"total\": " << r.number_of_lines << ",\n"
     << "    \"ridges\": " << r.number_of_ridges << ",\n"
     << "    \"valleys\": " << r.number_of_valleys << ",\n"
     << "    \"user\": " << r.number_of_user_lines << "\n"
     << "  },\n"
     << "  \"feature_edges\": " << r.number_of_feature_edges << ",\n"
     << "  \"crease_edges\": " << r.number_of_crease_edges << ",\n"
     << "  \"segmentation\": {\n"
     << "    \"patches\": " << r.number_of_patches << ",\n"
     << "    \"cut_cost\": " << json_number(r.cut_cost) << ",\n"
     << "    \"automatic_patches\": " << r.number_of_automatic_patches << ",\n"
     << "    \"automatic_cut_cost\": " << json_number(r.automatic_cut_cost) << ",\n"
     << "    \"oversegments\": " << r.number_of_oversegments << ",\n"
     << "    \"solver_seconds\": " << json_number(r.solver_seconds, 6) << "\n"
     << "  },\n";
  // One edit per line, so that a line-based tool reads them.
  os << "  \"edits\": [";
  for(std::size_t i = 0; i < r.edits.size(); ++i)
  {
    const fs_demo::Edit_record& e = r.edits[i];
    os << (i == 0 ? "\n" : ",\n") << "    {\"line\": " << e.line << ", \"verb\": " << json_string(e.verb)
       << ", \"patches\": " << e.patches << ", \"cut_cost\": " << json_number(e.cut_cost);
    if(e.verb == "undo")
      os << ", \"undone_line\": " << e.undone_line;
    else if(e.verb == "sketch")
      os << ", \"points\": " << e.points;
    else if(e.verb != "alpha")
      os << ", \"faces\": " << e.faces;
    os << ", \"seconds\": " << json_number(e.seconds, 6)
       << ", \"solver_seconds\": " << json_number(e.solver_seconds, 6)
       << ", \"prepare_seconds\": " << json_number(e.prepare_seconds, 6) << "}";
  }
  os << (r.edits.empty() ? "],\n" : "\n  ],\n")
     << "  \"boundaries\": {\n"
     << "    \"curves\": " << r.number_of_curves << ",\n"
     << "    \"junctions\": " << r.number_of_junctions << ",\n"
     << "    \"length_before\": " << json_number(r.length_before) << ",\n"
     << "    \"length_after\": " << json_number(r.length_after) << ",\n"
     << "    \"anisotropic_length_before\": " << json_number(r.anisotropic_length_before) << ",\n"
     << "    \"anisotropic_length_after\": " << json_number(r.anisotropic_length_after) << ",\n"
     << "    \"smoothing_iterations\": " << r.smoothing_iterations_run << ",\n"
     << "    \"vertex_moves\": " << r.smoothing_vertex_moves << ",\n"
     << "    \"smoothing_seconds\": " << json_number(r.smoothing_seconds, 6) << ",\n"
     << "    \"refined_vertices\": " << r.number_of_refined_vertices << ",\n"
     << "    \"refined_faces\": " << r.number_of_refined_faces << ",\n"
     << "    \"split_faces\": " << r.number_of_split_faces << "\n"
     << "  },\n"
     << "  \"seconds\": {\n";
  double total = 0;
  for(const auto& s : seconds)
  {
    os << "    " << json_string(s.first) << ": " << json_number(s.second, 6) << ",\n";
    total += s.second;
  }
  os << "    \"total\": " << json_number(total, 6) << "\n"
     << "  }\n"
     << "}\n";
}

// Writes a file through `write`, atomically: into a temporary file next to it, renamed
// over `path` once complete, so that an interrupted run never leaves a half-written file
// under the final name. Fails with a clear message when it cannot.
template <typename Write>
void write_file(const std::filesystem::path& path, Write&& write)
{
  std::filesystem::path temporary = path;
  temporary += ".partial-" + std::to_string(static_cast<long long>(::getpid()));
  try
  {
    std::ofstream out(temporary);
    if(!out)
      throw std::runtime_error(path.string() + ": cannot be opened for writing");
    write(out);
    out.close();
    if(!out)
      throw std::runtime_error(path.string() + ": write failed (disk full?)");
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if(ec)
      throw std::runtime_error(path.string() + ": cannot be written (" + ec.message() + ")");
  }
  catch(...)
  {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

int run(const Options& options)
{
  namespace sfs = std::filesystem;
  Stage_timer timer(options.quiet);
  Results results;

  // Fail on an unusable output folder before spending time on the mesh.
  std::error_code ec;
  sfs::create_directories(options.output_dir, ec);
  if(ec || !sfs::is_directory(options.output_dir))
    throw std::runtime_error(options.output_dir + ": cannot create the output folder" +
                             (ec ? " (" + ec.message() + ")" : std::string()));

  // A mistake in the edit script is found before the mesh is read; face indices are
  // checked against the file as soon as it is read.
  fs_demo::Edit_script script;
  if(!options.edits_file.empty())
    script = fs_demo::read_edit_script(options.edits_file);

  Mesh mesh;
  fs_demo::Input_correspondence<Mesh> correspondence;
  results.read_report = timer.run("load", [&]() {
    return fs_demo::read_input_mesh(options.input, mesh, correspondence);
  });
  if(!options.quiet)
    for(const std::string& notice : results.read_report.notices)
      std::cerr << "notice: " << options.input << ": " << notice << '\n';
  fs_demo::check_face_indices(script, results.read_report.number_of_file_faces);
  results.number_of_vertices = num_vertices(mesh);
  results.number_of_edges = num_edges(mesh);
  results.number_of_faces = num_faces(mesh);
  if(!options.quiet)
    std::cerr << "mesh: " << results.number_of_vertices << " vertices, "
              << results.number_of_faces << " faces" << std::endl;

  // The segmentation class detects the curvature and the crest lines itself, on the
  // mesh cut open along its creases (working_mesh()), where the fits see one side of a
  // crease at a time. User feature lines (--feature-edges) are located on the input mesh
  // and added to the lines detected there, as before creases existed.
  typedef FS::Feature_aligned_segmentation<Mesh> Segmentation;
  double last_solver_seconds = 0; // written by the solver at each solve
  std::optional<Segmentation> segmentation;
  const auto common = FS::parameters::alpha(options.alpha)
                        .gamma(options.gamma)
                        .crease_angle(options.crease_angle)
                        .crease_filter_iterations(options.crease_filter)
                        .neighborhood_rings(options.rings)
                        .neighborhood_radius(options.radius)
                        .strength_threshold(options.strength_threshold ? *options.strength_threshold
                                                                       : FS::default_strength_threshold)
                        .detect_ridges(options.ridges)
                        .detect_valleys(options.valleys)
                        .solver(Timed_solver(options.solver, last_solver_seconds))
                        .use_oversegmentation(!options.full_graph)
                        .watershed_distance(options.watershed == "geodesic" ? FS::Watershed_distance::GEODESIC
                                                                            : FS::Watershed_distance::ANISOTROPIC);
  if(!options.feature_edges_file.empty())
  {
    auto curvature_map =
      mesh.add_property_map<Mesh::Vertex_index, FS::Principal_curvatures<K> >("v:fs_principal_curvatures").first;
    timer.run("curvature", [&]() {
      FS::estimate_principal_curvatures(mesh, curvature_map, FS::parameters::neighborhood_rings(options.rings).neighborhood_radius(options.radius));
    });
    FS::Feature_lines<Mesh> lines = timer.run("feature_lines", [&]() {
      FS::Feature_lines<Mesh> detected;
      if(options.ridges || options.valleys)
        detected = FS::detect_crest_lines(
          mesh, curvature_map,
          FS::parameters::strength_threshold(options.strength_threshold ? *options.strength_threshold
                                                                        : FS::default_strength_threshold)
            .detect_ridges(options.ridges)
            .detect_valleys(options.valleys));
      results.number_of_user_lines = fs_demo::read_user_feature_lines(options.feature_edges_file, mesh, detected);
      return detected;
    });
    timer.run("segmentation", [&]() {
      segmentation.emplace(mesh, common.principal_curvature_map(curvature_map).feature_lines(std::cref(lines)));
    });
  }
  else
    timer.run("segmentation", [&]() { segmentation.emplace(mesh, common); });
  const FS::Feature_lines<Mesh>& lines = segmentation->feature_lines();
  const Mesh& working_mesh = segmentation->working_mesh();
  results.number_of_ridges = lines.number_of_lines(FS::Feature_line_type::RIDGE);
  results.number_of_valleys = lines.number_of_lines(FS::Feature_line_type::VALLEY);
  results.number_of_lines = lines.lines.size();
  results.number_of_feature_edges = segmentation->number_of_feature_edges();
  results.number_of_crease_edges = segmentation->number_of_crease_edges();
  if(!options.quiet)
    std::cerr << "feature lines: " << results.number_of_ridges << " ridges, "
              << results.number_of_valleys << " valleys, " << results.number_of_user_lines
              << " user; " << results.number_of_crease_edges << " crease edges; "
              << results.number_of_feature_edges << " feature edges" << std::endl;
  results.solver_seconds = last_solver_seconds;
  results.number_of_automatic_patches = results.number_of_patches = segmentation->number_of_patches();
  results.automatic_cut_cost = results.cut_cost = segmentation->cut_cost();
  results.number_of_oversegments = segmentation->number_of_oversegments();
  if(!options.quiet)
    std::cerr << "segmentation: " << results.number_of_patches << " patches, cut cost "
              << results.cut_cost << ", " << results.number_of_oversegments << " oversegments"
              << " (solver " << options.solver << ": " << std::fixed << std::setprecision(3)
              << results.solver_seconds << " s)" << std::defaultfloat << std::endl;

  if(!script.edits.empty())
  {
    fs_demo::Edit_runner<Mesh, K> runner(mesh, correspondence, *segmentation, last_solver_seconds);
    timer.run("edits", [&]() {
      for(const fs_demo::Script_edit& e : script.edits)
      {
        results.edits.push_back(runner.apply(script, e));
        const fs_demo::Edit_record& r = results.edits.back();
        if(!options.quiet)
          std::cerr << "edit " << options.edits_file << ":" << r.line << ": " << r.verb << ": "
                    << r.patches << " patches, cut cost " << r.cut_cost << " (" << std::fixed
                    << std::setprecision(3) << r.seconds << " s)" << std::defaultfloat << std::endl;
      }
    });
    results.number_of_patches = segmentation->number_of_patches();
    results.cut_cost = segmentation->cut_cost();
  }
  auto vertex_patch = mesh.add_property_map<Mesh::Vertex_index, long>("v:fs_patch", -1).first;
  auto face_patch = mesh.add_property_map<Mesh::Face_index, long>("f:fs_patch", -1).first;
  segmentation->vertex_patches(vertex_patch);
  segmentation->face_patches(face_patch);

  // The patch of every point and face of the input file, in file order (-1: a point no
  // face uses).
  std::vector<long> file_vertex_patch, file_face_patch;
  for(Mesh::Vertex_index v : correspondence.vertex_of_file_point)
    file_vertex_patch.push_back(v == Mesh::null_vertex() ? -1L : get(vertex_patch, v));
  for(Mesh::Face_index f : correspondence.face_of_file_face)
    file_face_patch.push_back(get(face_patch, f));

  // The boundaries of the final patches, in the metric of the weights, from the
  // segmentation's own precomputation (which knows the sketches' feature points).
  FS::Patch_boundaries<Mesh> boundaries =
    timer.run("boundaries", [&]() { return segmentation->patch_boundaries(); });
  results.number_of_curves = boundaries.curves().size();
  results.number_of_junctions = boundaries.number_of_junctions();
  results.length_before = boundaries.length();
  results.anisotropic_length_before = boundaries.anisotropic_length();
  const FS::Boundary_smoothing_report smoothing = timer.run("smoothing", [&]() {
    return options.smoothing_iterations
             ? FS::smooth_patch_boundaries(
                 boundaries, FS::parameters::smoothing_iterations(*options.smoothing_iterations))
             : FS::smooth_patch_boundaries(boundaries);
  });
  results.smoothing_seconds = timer.seconds().back().second;
  results.smoothing_iterations_run = smoothing.number_of_iterations;
  results.smoothing_vertex_moves = smoothing.number_of_vertex_moves;
  results.length_after = boundaries.length();
  results.anisotropic_length_after = boundaries.anisotropic_length();
  if(!options.quiet)
    std::cerr << "boundaries: " << results.number_of_curves << " curves, length "
              << results.length_before << " -> " << results.length_after << " ("
              << results.smoothing_iterations_run << " smoothing iterations)" << std::endl;

  Mesh refined;
  auto refined_patch = refined.add_property_map<Mesh::Face_index, long>("f:fs_patch", -1).first;
  results.number_of_split_faces = timer.run("refinement", [&]() {
    return FS::refine_mesh_along_boundaries(boundaries, refined, refined_patch);
  });
  results.number_of_refined_vertices = num_vertices(refined);
  results.number_of_refined_faces = num_faces(refined);

  const sfs::path dir(options.output_dir);
  // summary.json marks a complete set of outputs: a previous run's goes first, and the
  // new one is written last.
  sfs::remove(dir / "summary.json", ec);
  timer.run("write", [&]() {
    write_file(dir / "feature_lines.polylines.txt",
               [&](std::ostream& os) { FS::write_polylines(os, working_mesh, lines); });
    write_file(dir / "feature_lines.obj",
               [&](std::ostream& os) { FS::write_OBJ_lines(os, working_mesh, lines); });
    write_file(dir / "segmentation.ply",
               [&](std::ostream& os) { FS::write_PLY_segmentation(os, mesh, face_patch); });
    write_file(dir / "boundaries.polylines.txt",
               [&](std::ostream& os) { FS::write_boundary_polylines(os, boundaries); });
    write_file(dir / "segmentation_refined.ply",
               [&](std::ostream& os) { FS::write_PLY_segmentation(os, refined, refined_patch); });
    write_file(dir / "face_patches.txt", [&](std::ostream& os) {
      FS::write_patch_ids(os, boost::counting_range(std::size_t(0), file_face_patch.size()),
                          CGAL::make_property_map(file_face_patch));
    });
    write_file(dir / "vertex_patches.txt", [&](std::ostream& os) {
      FS::write_patch_ids(os, boost::counting_range(std::size_t(0), file_vertex_patch.size()),
                          CGAL::make_property_map(file_vertex_patch));
    });
  });
  // Written last, so that it holds the time of every stage.
  write_file(dir / "summary.json",
             [&](std::ostream& os) { write_summary(os, options, results, timer.seconds()); });

  if(!options.quiet)
    std::cerr << "outputs written to " << options.output_dir << "/" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  fs_demo::use_huge_page_heap(argv);
  Options options;
  try
  {
    options = parse_command_line(argc, argv);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
  if(options.help)
  {
    print_usage(std::cout);
    return EXIT_SUCCESS;
  }
  try
  {
    return run(options);
  }
  catch(const fs_demo::Input_error& e)
  {
    std::cerr << "error: " << e.what() << '\n';
  }
  catch(const fs_demo::Edit_script_error& e)
  {
    std::cerr << "error: " << e.what() << '\n';
  }
  catch(const FS::Invalid_input& e)
  {
    std::cerr << "error: " << options.input << ": " << e.what() << '\n';
  }
  catch(const std::bad_alloc&)
  {
    std::cerr << "error: " << options.input << ": out of memory\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
  }
  return EXIT_FAILURE;
}
