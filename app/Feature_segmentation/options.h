// SPDX-License-Identifier: GPL-3.0-or-later
// The options of the program `feature_segmentation` and of the Python module: one struct,
// its subcommands and its error. option_table.h says how each field is named, checked
// and set; program_options.h reads them from a command line.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_OPTIONS_H
#define CGAL_FEATURE_SEGMENTATION_APP_OPTIONS_H

#include "number_text.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/internal/Segmentation_data.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs_app {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace FS = CGAL::Feature_segmentation;

inline const char* const program_name = "feature_segmentation";

// for --help and the summary (the program passes the option only when it is given)
inline const int default_smoothing_iterations = FS::default_smoothing_iterations;

// A wrong option: the program reports it with exit status 2, as getopt-style programs do;
// the Python module raises ValueError.
class Usage_error : public std::runtime_error { public: using std::runtime_error::runtime_error; };

// The subcommand: `segment` (the default) writes the outputs; `edit` serves the editor;
// `batch` segments many meshes.
enum class Command { SEGMENT, EDIT, BATCH };

struct Options
{
  Command command = Command::SEGMENT;
  // edit: the address and port the editor's server listens on (0: a free port), and the
  // folder of its web page (empty: the one built next to the program).
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string web_root;
  bool no_token = false; ///< edit: serve the API without the session token (scripted local use)
  // batch: the meshes, folders of meshes and list files given; the meshes segmented at
  // once; whether meshes with complete outputs are done again.
  std::vector<std::string> inputs;
  int jobs = 1;
  // threads of the parallel stages (0: all cores)
  int threads = 0;
  bool force = false;
  std::string input = std::string(FS_MESH_DIR) + "/fandisk.off";
  std::string output_dir = "feature_segmentation_output";
  int rings = 2;
  double radius = FS::default_neighborhood_radius;
  std::optional<double> strength_threshold; // unset: the library's default
  bool ridges = true;
  bool valleys = true;
  std::string feature_edges_file;           // empty: none
  // The library's defaults (defaults.h)
  double alpha = CGAL::Feature_segmentation::default_alpha;
  double gamma = CGAL::Feature_segmentation::default_gamma;
  double crease_angle = CGAL::Feature_segmentation::default_crease_angle;
  // most rounds of normal filtering before creases
  int crease_filter = CGAL::Feature_segmentation::default_crease_filter_iterations;
  // clean tessellations of CAD parts: crest lines at the full alpha, and cuts along
  // curvature discontinuities
  bool crest_lines_on_clean_tessellations = CGAL::Feature_segmentation::default_crest_lines_on_clean_tessellations;
  bool tangent_discontinuities = CGAL::Feature_segmentation::default_tangent_discontinuities;
  std::string solver = "gaec+klj";
  bool full_graph = false;
  std::string watershed = "anisotropic";
  std::string edits_file;                   // empty: no edits
  // the memory the editing history may keep, MiB (Feature_aligned_segmentation's default)
  std::size_t undo_memory_mib = std::size_t(256);
  std::optional<int> smoothing_iterations;  // unset: the library's default
  bool quiet = false;
  bool help = false;     ///< --help: the short usage
  bool help_all = false; ///< --help-all: every option in full, the outputs, the edit scripts
};

/// Throws Usage_error(message) unless `ok`.
inline void require(bool ok, const std::string& message) { if(!ok) throw Usage_error(message); }

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_OPTIONS_H
