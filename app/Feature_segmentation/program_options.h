// SPDX-License-Identifier: GPL-3.0-or-later
// The options of the program `feature_segmentation`: one struct, read once from the
// command line by Boost.Program_options (subcommands `segment`, the default, `edit` and
// `batch`), and the --help text.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_OPTIONS_H
#define CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_OPTIONS_H

#include "number_text.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Feature_segmentation/crest_lines.h>
#include <CGAL/Feature_segmentation/principal_curvatures.h>
#include <CGAL/Feature_segmentation/smooth_boundaries.h>
#include <CGAL/Feature_segmentation/internal/Segmentation_data.h>

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>
#include <boost/program_options/positional_options.hpp>
#include <boost/program_options/value_semantic.hpp>
#include <boost/program_options/variables_map.hpp>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
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

// A wrong command line: reported with exit status 2, as getopt-style programs do.
class Usage_error : public std::runtime_error
{
public:
  explicit Usage_error(const std::string& what) : std::runtime_error(what) {}
};

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


inline void require(bool ok, const std::string& message) { if(!ok) throw Usage_error(message); }

// Strict number parsing: the whole argument must be the number ("1.5x", "", " 1", "abc",
// "nan" and out-of-range values are refused).
inline int parse_int(const std::string& option, const std::string& text)
{
  std::size_t used = 0; // stays 0 if stol throws
  long value = 0;
  try { value = std::stol(text, &used, 10); } catch(const std::exception&) {}
  require(used != 0 && used == text.size() && !std::isspace(static_cast<unsigned char>(text[0])),
          option + " expects an integer (got '" + text + "')");
  require(value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max(),
          option + " is out of range (got '" + text + "')");
  return static_cast<int>(value);
}

inline double parse_double(const std::string& option, const std::string& text)
{
  std::size_t used = 0; // stays 0 if stod throws
  double value = 0;
  try { value = std::stod(text, &used); } catch(const std::exception&) {}
  require(used != 0 && used == text.size() && !std::isspace(static_cast<unsigned char>(text[0])),
          option + " expects a number (got '" + text + "')");
  require(std::isfinite(value), option + " expects a finite number (got '" + text + "')");
  return value;
}

namespace po = boost::program_options;

// An option's value as Boost hands it over: `apply` runs at every occurrence, in
// command-line order (po::store), so the first wrong value is the one reported, a
// repeated option's last value wins, and the checks and messages stay ours (Boost's
// typed values refuse a repeated option and word their own errors).
class Option_value : public po::value_semantic
{
public:
  Option_value(unsigned tokens, std::function<void(const std::string&)> apply)
    : m_tokens(tokens), m_apply(std::move(apply))
  {}
  std::string name() const override { return m_tokens == 0 ? "" : "arg"; }
  unsigned min_tokens() const override { return m_tokens; }
  unsigned max_tokens() const override { return m_tokens; }
  bool is_composing() const override { return false; }
  bool is_required() const override { return false; }
  void parse(boost::any& value_store, const std::vector<std::string>& tokens, bool /*utf8*/) const override
  {
    m_apply(tokens.empty() ? std::string() : tokens.front());
    value_store = true; // so that the variables_map tells which options were given
  }
  bool apply_default(boost::any&) const override { return false; }
  void notify(const boost::any&) const override {}

private:
  unsigned m_tokens;
  std::function<void(const std::string&)> m_apply;
};

inline Option_value* flag_option(std::function<void()> f) { return new Option_value(0, [f](const std::string&) { f(); }); }
inline Option_value* value_option(std::function<void(const std::string&)> f) { return new Option_value(1, std::move(f)); }

// A value that may be anything but empty.
inline Option_value* text_option(std::string& field, const std::string& if_empty)
{
  return value_option([&field, if_empty](const std::string& t) { require(!t.empty(), if_empty); field = t; });
}

// Two tokens read as before, not as Boost would: "--solver=" is an empty value, which the
// option's own check names ("--solver must be ...", "--rings expects an integer (got
// '')"), and "--" an unknown option, not the end of the options.
inline std::vector<po::option> parse_as_before(std::vector<std::string>& args)
{
  const std::string token = args.front();
  const std::size_t equals = token.find('=');
  if(token.rfind("--", 0) != 0 || (token != "--" && equals != token.size() - 1))
    return {};
  po::option option(equals == std::string::npos || equals == 2 ? "--" : token.substr(2, equals - 2),
                    std::vector<std::string>(1));
  option.original_tokens.push_back(token);
  args.erase(args.begin());
  return {option};
}

// The options of one subcommand are refused by the others, not ignored.
inline void check_scope(const std::string& flag, Command command)
{
  if(command != Command::EDIT && (flag == "--port" || flag == "--host" || flag == "--web-root" || flag == "--no-token"))
    throw Usage_error(flag + " is an option of 'edit' (" + program_name + " edit MESH " + flag + " ...)");
  if(command != Command::BATCH && flag == "--jobs")
    throw Usage_error("--jobs is an option of 'batch' (" + std::string(program_name) + " batch INPUTS --jobs N)");
  if(command != Command::BATCH && flag == "--force")
    throw Usage_error("--force is an option of 'batch'");
}

// A first argument that is a word (letters, '-' and '_' inside, no '.', no '/') and no
// existing file: a misspelt subcommand, not a mesh (a mesh file has an extension).
inline bool looks_like_a_subcommand(const std::string& word)
{
  if(word.empty() || !std::isalpha(static_cast<unsigned char>(word.front()))) return false;
  for(char c : word)
    if(!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') return false;
  std::error_code ec;
  return !std::filesystem::exists(word, ec);
}

inline Options parse_command_line(int argc, char** argv)
{
  Options o;
  int first = 1;
  if(argc > 1 && std::string(argv[1]) == "edit") { o.command = Command::EDIT; first = 2; }
  else if(argc > 1 && std::string(argv[1]) == "batch") { o.command = Command::BATCH; first = 2; }
  else if(argc > 1 && std::string(argv[1]) == "segment") first = 2;
  else if(argc > 1 && looks_like_a_subcommand(argv[1]))
    throw Usage_error("unknown subcommand '" + std::string(argv[1]) +
                      "' (the subcommands are segment, edit and batch; a mesh is a file name with its extension)");
  const bool batch = o.command == Command::BATCH;
  bool has_input = false;
  typedef const std::string& Text;

  po::options_description described;
  described.add_options()
    ("help,h", flag_option([&] { o.help = true; }))
    ("help-all", flag_option([&] { o.help = o.help_all = true; }))
    ("quiet", flag_option([&] { o.quiet = true; }))
    ("no-ridges", flag_option([&] { o.ridges = false; }))
    ("no-valleys", flag_option([&] { o.valleys = false; }))
    ("full-graph", flag_option([&] { o.full_graph = true; }))
    ("crest-lines-on-clean-tessellations", flag_option([&] { o.crest_lines_on_clean_tessellations = true; }))
    ("no-tangent-discontinuities", flag_option([&] { o.tangent_discontinuities = false; }))
    ("force", flag_option([&] { o.force = true; }))
    ("no-token", flag_option([&] { o.no_token = true; }))
    ("output-dir", text_option(o.output_dir, "--output-dir expects a non-empty folder name"))
    ("rings", value_option([&](Text t) {
       o.rings = parse_int("--rings", t);
       require(o.rings >= 1, "--rings must be an integer >= 1 (got " + std::to_string(o.rings) + ")"); }))
    ("radius", value_option([&](Text t) {
       o.radius = parse_double("--radius", t);
       require(o.radius >= 0 && o.radius <= 1, "--radius must be a number in [0, 1] (got " + t + ")"); }))
    ("strength-threshold", value_option([&](Text t) {
       o.strength_threshold = parse_double("--strength-threshold", t);
       require(*o.strength_threshold >= 0, "--strength-threshold must be >= 0 (got '" + t + "')"); }))
    ("feature-edges", text_option(o.feature_edges_file, "--feature-edges expects a file name"))
    ("alpha", value_option([&](Text t) { o.alpha = parse_double("--alpha", t); }))
    ("gamma", value_option([&](Text t) {
       o.gamma = parse_double("--gamma", t);
       require(o.gamma >= 0, "--gamma must be >= 0 (got '" + t + "')"); }))
    ("crease-angle", value_option([&](Text t) {
       o.crease_angle = parse_double("--crease-angle", t);
       require(o.crease_angle > 0, "--crease-angle must be > 0 degrees (got '" + t + "')"); }))
    ("crease-filter", value_option([&](Text t) {
       o.crease_filter = parse_int("--crease-filter", t);
       require(o.crease_filter >= 0 && o.crease_filter <= 1000,
               "--crease-filter must be an integer in 0 .. 1000 (got '" + t + "')"); }))
    ("solver", value_option([&](Text t) {
       require(t == "gaec+klj" || t == "gaec" || t == "klj", "--solver must be gaec+klj, gaec or klj (got '" + t + "')");
       o.solver = t; }))
    ("watershed", value_option([&](Text t) {
       require(t == "anisotropic" || t == "geodesic", "--watershed must be anisotropic or geodesic (got '" + t + "')");
       o.watershed = t; }))
    ("edits", text_option(o.edits_file, "--edits expects a file name"))
    ("undo-memory", value_option([&](Text t) {
       const int mib = parse_int("--undo-memory", t);
       require(mib >= 0 && mib <= 1 << 20, "--undo-memory must be an integer of MiB in 0 .. 1048576 (got " + t + ")");
       o.undo_memory_mib = std::size_t(mib); }))
    ("smoothing-iterations", value_option([&](Text t) {
       const int n = parse_int("--smoothing-iterations", t);
       require(n >= 0, "--smoothing-iterations must be an integer >= 0 (got " + std::to_string(n) + ")");
       o.smoothing_iterations = n; }))
    ("port", value_option([&](Text t) {
       o.port = parse_int("--port", t);
       require(o.port >= 0 && o.port <= 65535, "--port must be an integer in 0 .. 65535 (got " + t + ")"); }))
    ("host", text_option(o.host, "--host expects a non-empty value"))
    ("web-root", text_option(o.web_root, "--web-root expects a non-empty value"))
    ("threads", value_option([&](Text t) {
       o.threads = parse_int("--threads", t);
       require(o.threads >= 0 && o.threads <= 1024, "--threads must be an integer in 0 .. 1024 (got " + t + ")"); }))
    ("jobs", value_option([&](Text t) {
       o.jobs = parse_int("--jobs", t);
       require(o.jobs >= 1 && o.jobs <= 1024, "--jobs must be an integer in 1 .. 1024 (got " + t + ")"); }))
    ("input", value_option([&](Text t) { // the positional arguments: the mesh, or batch's inputs
       require(batch || !has_input, "more than one input mesh ('" + o.input + "' and '" + t + "')");
       if(batch) o.inputs.push_back(t);
       else o.input = t;
       has_input = true; }));
  po::positional_options_description positional;
  positional.add("input", -1);
  // --opt=value and --opt value, -h; exact names only (no prefixes of them)
  namespace style = po::command_line_style;
  const int command_line_style = style::allow_long | style::long_allow_adjacent | style::long_allow_next |
                                 style::allow_short | style::allow_dash_for_short | style::short_allow_next;
  po::variables_map given;
  try
  {
    const po::parsed_options parsed = po::command_line_parser(std::vector<std::string>(argv + first, argv + argc))
                                        .options(described)
                                        .positional(positional)
                                        .style(command_line_style)
                                        .extra_style_parser(&parse_as_before)
                                        .allow_unregistered()
                                        .run();
    for(const po::option& option : parsed.options)
    {
      if(option.position_key >= 0)
        continue;
      // Unknown options are let through (allow_unregistered) to be named as typed: '-x',
      // '--x' of '--x=1'; "input" is the positional arguments' name, not an option.
      const std::string& typed = option.original_tokens.front();
      if(option.unregistered || option.string_key == "input")
        throw Usage_error("unknown option '" + typed.substr(0, typed.rfind("--", 0) == 0 ? typed.find('=') : typed.npos) +
                          "' (see --help)");
      const std::string flag = "--" + option.string_key;
      check_scope(flag, o.command);
      // "--rings --quiet" is a forgotten value, not a folder or number named "--quiet"
      // (Boost takes it for the value unless it is -h).
      require(option.original_tokens.size() == 1 || option.value.front().rfind("--", 0) != 0, flag + " expects a value");
    }
    po::store(parsed, given);
  }
  catch(const po::invalid_syntax& e)
  {
    const std::string flag = e.get_option_name();
    if(e.kind() == po::invalid_syntax::missing_parameter)
      check_scope(flag, o.command);
    require(e.kind() != po::invalid_syntax::missing_parameter, flag + " expects a value");
    require(e.kind() != po::invalid_syntax::extra_parameter, flag + " takes no value");
    throw Usage_error(e.what());
  }
  catch(const po::error& e)
  {
    throw Usage_error(e.what());
  }
  if(batch && !o.help)
  {
    require(!o.inputs.empty(), "batch: no input (give meshes, folders of meshes or list files)");
    require(given.count("output-dir"), "batch: --output-dir DIR is required (one folder per mesh goes into it)");
    require(o.edits_file.empty(), "batch: --edits is an option of one mesh, not of a batch");
  }
  if(!o.ridges && !o.valleys && !o.quiet && !o.help)
    std::cerr << "notice: --no-ridges and --no-valleys: no crest lines will be detected\n";
  if(o.full_graph && given.count("watershed") && !o.quiet && !o.help)
    std::cerr << "notice: --full-graph: no oversegmentation, --watershed has no effect\n";
  return o;
}

/// The options that decide the segmentation, as command-line flags (" --alpha 0.6 ..."),
/// every one explicit, numbers in the shortest form that reads back exactly: what a
/// replay of an editor session (`--edits edits.txt`) must be given.
inline std::string segmentation_options_text(const Options& o)
{
  const auto number = number_text;
  std::string t = " --rings " + std::to_string(o.rings) + " --radius " + number(o.radius) +
                  " --strength-threshold " +
                  number(o.strength_threshold ? *o.strength_threshold : FS::default_strength_threshold) +
                  " --alpha " + number(o.alpha) + " --gamma " + number(o.gamma) + " --crease-angle " +
                  number(o.crease_angle) + " --crease-filter " + std::to_string(o.crease_filter) + " --solver " +
                  o.solver + " --watershed " + o.watershed;
  if(o.full_graph) t += " --full-graph";
  if(!o.ridges) t += " --no-ridges";
  if(!o.valleys) t += " --no-valleys";
  if(o.crest_lines_on_clean_tessellations) t += " --crest-lines-on-clean-tessellations";
  if(!o.tangent_discontinuities) t += " --no-tangent-discontinuities";
  if(!o.feature_edges_file.empty()) t += " --feature-edges " + o.feature_edges_file;
  if(o.smoothing_iterations) t += " --smoothing-iterations " + std::to_string(*o.smoothing_iterations);
  return t;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_OPTIONS_H
