// SPDX-License-Identifier: GPL-3.0-or-later
// The one table of the program's options: for every option its keyword, kind, scope, the
// line of --help, and how a value is checked and stored in Options. The command-line
// parser (program_options.h) registers its flags from it and --help lists them
// (program_usage.h), the Python module maps its keyword arguments through it, the replay
// line of edits.txt and the options of summary.json are written from it, and the Dask
// runner builds its command line from it: a name, a check or a message is written once.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_OPTION_TABLE_H
#define CGAL_FEATURE_SEGMENTATION_APP_OPTION_TABLE_H

#include "options.h"

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace fs_app {

/// What an option holds: a switch (a bool: `--full-graph`, or `--no-ridges` for a switch
/// that is on by default), an integer, a number or a text.
enum class Option_kind { SWITCH, INTEGER, NUMBER, TEXT };

/// A value on its way into Options, converted by the front end (command line or Python)
/// to the option's kind.
struct Option_input
{
  std::string name; ///< how the option is named in messages: "--crease-angle" or "crease_angle"
  std::string got;  ///< the value as the user wrote it, for messages
  bool on = false;
  long long integer = 0;
  double number = 0;
  std::string text;
};

/// One option.
struct Option_entry
{
  std::string keyword;                   ///< "crease_angle": the Python keyword
  Option_kind kind = Option_kind::TEXT;
  bool negated = false;                  ///< a switch on by default: its flag is --no-KEYWORD
  bool segmentation = false;             ///< decides the segmentation: a Python keyword, in the replay line
  std::optional<Command> only;           ///< the one subcommand that takes it, if any
  std::string metavar;                   ///< --help: "X", "N", "FILE", ...
  std::string help;                      ///< --help: one line
  /// Checks `in` and stores it; throws Usage_error with the message the user sees.
  std::function<void(Options&, const Option_input&)> set;
  /// The value as text (a switch: "true" or "false"; "" for an unset value): the replay
  /// line's value and the Python module's default.
  std::function<std::string(const Options&)> value;
  /// The default as --help shows it, where `value(Options())` is empty (a library default
  /// the program passes only when given).
  std::string shown_default = {};

  /// The value in effect: `value(o)`, or the library default it leaves unset.
  std::string effective_value(const Options& o) const
  {
    const std::string v = value(o);
    return v.empty() ? shown_default : v;
  }

  /// "--crease-angle", "--no-ridges"
  std::string flag() const
  {
    std::string f = "--" + std::string(negated ? "no-" : "") + keyword;
    for(char& c : f)
      if(c == '_') c = '-';
    return f;
  }
};

namespace internal {

inline std::function<std::string(const Options&)> number_value(double Options::*field)
{
  return [field](const Options& o) { return fs_app::number_text(o.*field); };
}
inline std::function<std::string(const Options&)> integer_value(int Options::*field)
{
  return [field](const Options& o) { return std::to_string(o.*field); };
}
inline std::function<std::string(const Options&)> text_value(std::string Options::*field)
{
  return [field](const Options& o) { return o.*field; };
}
inline std::function<std::string(const Options&)> switch_value(bool Options::*field)
{
  return [field](const Options& o) { return std::string(o.*field ? "true" : "false"); };
}
inline std::function<void(Options&, const Option_input&)> set_switch(bool Options::*field)
{
  return [field](Options& o, const Option_input& in) { o.*field = in.on; };
}
// A text that may be anything but empty.
inline std::function<void(Options&, const Option_input&)> set_text(std::string Options::*field,
                                                                    const std::string& expects)
{
  return [field, expects](Options& o, const Option_input& in) {
    require(!in.text.empty(), in.name + " expects " + expects);
    o.*field = in.text;
  };
}
// An integer in [low, high], or >= low.
inline std::function<void(Options&, const Option_input&)>
set_integer(int Options::*field, int low, std::optional<int> high = std::nullopt)
{
  return [field, low, high](Options& o, const Option_input& in) {
    if(high)
      require(in.integer >= low && in.integer <= *high, in.name + " must be an integer in " + std::to_string(low) +
                                                          " .. " + std::to_string(*high) + " (got " + in.got + ")");
    else
      require(in.integer >= low,
              in.name + " must be an integer >= " + std::to_string(low) + " (got " + std::to_string(in.integer) + ")");
    o.*field = int(in.integer);
  };
}

} // namespace internal

/// The options, in the order of the replay line (the segmentation's options first).
inline const std::vector<Option_entry>& option_table()
{
  using namespace internal;
  typedef Option_kind Kind;
  typedef const Option_input& In;
  static const std::vector<Option_entry> table = [] {
    std::vector<Option_entry> t;
    const auto add = [&t](Option_entry e) { t.push_back(std::move(e)); };
    // The segmentation's options (Python keywords; the replay line of edits.txt).
    add({"rings", Kind::INTEGER, false, true, {}, "N", "curvature fit over N rings",
         set_integer(&Options::rings, 1), integer_value(&Options::rings)});
    add({"radius", Kind::NUMBER, false, true, {}, "X", "... and X times the diagonal",
         [](Options& o, In in) {
           require(in.number >= 0 && in.number <= 1, in.name + " must be a number in [0, 1] (got " + in.got + ")");
           o.radius = in.number;
         },
         number_value(&Options::radius)});
    add({"strength_threshold", Kind::NUMBER, false, true, {}, "X", "drop crest lines weaker than X",
         [](Options& o, In in) {
           require(in.number >= 0, in.name + " must be >= 0 (got '" + in.got + "')");
           o.strength_threshold = in.number;
         },
         [](const Options& o) { return fs_app::number_text(o.strength_threshold.value_or(FS::default_strength_threshold)); }});
    add({"alpha", Kind::NUMBER, false, true, {}, "X", "how strongly features cut: larger, more patches",
         [](Options& o, In in) { o.alpha = in.number; }, number_value(&Options::alpha)});
    add({"gamma", Kind::NUMBER, false, true, {}, "X", "anisotropy of the metric, >= 0",
         [](Options& o, In in) {
           require(in.number >= 0, in.name + " must be >= 0 (got '" + in.got + "')");
           o.gamma = in.number;
         },
         number_value(&Options::gamma)});
    add({"crease_angle", Kind::NUMBER, false, true, {}, "D",
         "creases: edges whose faces bend by D degrees or more; 180: none",
         [](Options& o, In in) {
           require(in.number > 0, in.name + " must be > 0 degrees (got '" + in.got + "')");
           o.crease_angle = in.number;
         },
         number_value(&Options::crease_angle)});
    add({"crease_filter", Kind::INTEGER, false, true, {}, "N", "most rounds of normal filtering on noisy meshes",
         [](Options& o, In in) {
           require(in.integer >= 0 && in.integer <= 1000,
                   in.name + " must be an integer in 0 .. 1000 (got '" + in.got + "')");
           o.crease_filter = int(in.integer);
         },
         integer_value(&Options::crease_filter)});
    add({"solver", Kind::TEXT, false, true, {}, "NAME", "gaec+klj, gaec or klj",
         [](Options& o, In in) {
           require(in.text == "gaec+klj" || in.text == "gaec" || in.text == "klj",
                   in.name + " must be gaec+klj, gaec or klj (got '" + in.text + "')");
           o.solver = in.text;
         },
         text_value(&Options::solver)});
    add({"watershed", Kind::TEXT, false, true, {}, "NAME", "anisotropic or geodesic",
         [](Options& o, In in) {
           require(in.text == "anisotropic" || in.text == "geodesic",
                   in.name + " must be anisotropic or geodesic (got '" + in.text + "')");
           o.watershed = in.text;
         },
         text_value(&Options::watershed)});
    add({"full_graph", Kind::SWITCH, false, true, {}, "", "solve on every vertex, not the oversegmentation",
         set_switch(&Options::full_graph), switch_value(&Options::full_graph)});
    add({"ridges", Kind::SWITCH, true, true, {}, "", "do not detect ridges", set_switch(&Options::ridges),
         switch_value(&Options::ridges)});
    add({"valleys", Kind::SWITCH, true, true, {}, "", "do not detect valleys", set_switch(&Options::valleys),
         switch_value(&Options::valleys)});
    add({"crest_lines_on_clean_tessellations", Kind::SWITCH, false, true, {}, "",
         "crest lines at the full alpha on CAD meshes", set_switch(&Options::crest_lines_on_clean_tessellations),
         switch_value(&Options::crest_lines_on_clean_tessellations)});
    add({"tangent_discontinuities", Kind::SWITCH, true, true, {}, "", "no seams where a fillet meets a plane",
         set_switch(&Options::tangent_discontinuities), switch_value(&Options::tangent_discontinuities)});
    add({"feature_edges", Kind::TEXT, false, true, {}, "FILE",
         "the user's feature lines (CGAL polylines along mesh edges)",
         set_text(&Options::feature_edges_file, "a file name"), text_value(&Options::feature_edges_file)});
    add({"smoothing_iterations", Kind::INTEGER, false, true, {}, "N", "boundary smoothing, 0: none",
         [](Options& o, In in) {
           require(in.integer >= 0,
                   in.name + " must be an integer >= 0 (got " + std::to_string(in.integer) + ")");
           o.smoothing_iterations = int(in.integer);
         },
         [](const Options& o) { return o.smoothing_iterations ? std::to_string(*o.smoothing_iterations) : ""; },
         std::to_string(default_smoothing_iterations)});
    // The program's options.
    add({"output_dir", Kind::TEXT, false, false, {}, "DIR", "output folder",
         set_text(&Options::output_dir, "a non-empty folder name"), text_value(&Options::output_dir)});
    add({"edits", Kind::TEXT, false, false, {}, "FILE", "apply an edit script after the segmentation",
         set_text(&Options::edits_file, "a file name"), text_value(&Options::edits_file)});
    add({"threads", Kind::INTEGER, false, false, {}, "N", "threads, 0: all cores",
         set_integer(&Options::threads, 0, 1024), integer_value(&Options::threads)});
    add({"quiet", Kind::SWITCH, false, false, {}, "", "no progress or notice lines on stderr",
         set_switch(&Options::quiet), switch_value(&Options::quiet)});
    add({"undo_memory", Kind::INTEGER, false, false, {}, "MIB", "memory kept for undo",
         [](Options& o, In in) {
           require(in.integer >= 0 && in.integer <= 1 << 20,
                   in.name + " must be an integer of MiB in 0 .. 1048576 (got " + in.got + ")");
           o.undo_memory_mib = std::size_t(in.integer);
         },
         [](const Options& o) { return std::to_string(o.undo_memory_mib); }});
    add({"port", Kind::INTEGER, false, false, Command::EDIT, "N", "where the editor listens",
         set_integer(&Options::port, 0, 65535), integer_value(&Options::port)});
    add({"host", Kind::TEXT, false, false, Command::EDIT, "H", "the editor's address",
         set_text(&Options::host, "a non-empty value"), text_value(&Options::host)});
    add({"web_root", Kind::TEXT, false, false, Command::EDIT, "DIR", "the editor's page (default: the installed one)",
         set_text(&Options::web_root, "a non-empty value"), text_value(&Options::web_root)});
    add({"no_token", Kind::SWITCH, false, false, Command::EDIT, "", "no session token on the API (scripted local use)",
         set_switch(&Options::no_token), switch_value(&Options::no_token)});
    add({"jobs", Kind::INTEGER, false, false, Command::BATCH, "N", "meshes at once",
         set_integer(&Options::jobs, 1, 1024), integer_value(&Options::jobs)});
    add({"force", Kind::SWITCH, false, false, Command::BATCH, "", "redo meshes whose outputs are complete",
         set_switch(&Options::force), switch_value(&Options::force)});
    add({"help", Kind::SWITCH, false, false, {}, "", "the short usage", set_switch(&Options::help),
         switch_value(&Options::help)});
    add({"help_all", Kind::SWITCH, false, false, {}, "", "every option in full",
         [](Options& o, In in) { o.help = o.help_all = in.on; }, switch_value(&Options::help_all)});
    return t;
  }();
  return table;
}

/// Stores `in` into `o` through `e` after the checks of its kind: a number must be
/// finite, an integer must be an `int`.
/// \throws Usage_error naming `in.name`
inline void apply_option(const Option_entry& e, Options& o, const Option_input& in)
{
  if(e.kind == Option_kind::NUMBER)
    require(std::isfinite(in.number), in.name + " expects a finite number (got '" + in.got + "')");
  if(e.kind == Option_kind::INTEGER)
    require(in.integer >= std::numeric_limits<int>::min() && in.integer <= std::numeric_limits<int>::max(),
            in.name + " is out of range (got '" + in.got + "')");
  e.set(o, in);
}

/// The entry of `keyword` ("crease_angle"), or null.
inline const Option_entry* find_option(const std::string& keyword)
{
  for(const Option_entry& e : option_table())
    if(e.keyword == keyword) return &e;
  return nullptr;
}

/// The options that decide the segmentation, as command-line flags (" --rings 2 ..."),
/// every valued one explicit, numbers in the shortest form that reads back exactly: what
/// a replay of an editor session (`--edits edits.txt`) must be given.
inline std::string segmentation_options_text(const Options& o)
{
  std::string t;
  for(const Option_entry& e : option_table())
  {
    if(!e.segmentation) continue;
    const std::string v = e.value(o);
    if(e.kind != Option_kind::SWITCH)
      t += v.empty() ? "" : " " + e.flag() + " " + v;
    else if((v == "true") != e.negated)
      t += " " + e.flag();
  }
  return t;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_OPTION_TABLE_H
