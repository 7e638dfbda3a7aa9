// SPDX-License-Identifier: GPL-3.0-or-later
// The command line of evaluate_quality (Boost.Program_options): what to evaluate, where
// the data and the outputs are, and the settings of the CAD table.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_EVALUATE_QUALITY_OPTIONS_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_EVALUATE_QUALITY_OPTIONS_H

#include "evaluation/cad_parts.h"

#include <boost/program_options.hpp>

#include <cstdlib>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs_evaluation {

struct Evaluation_options
{
  std::string data;
  std::string out = "evaluation";
  // what --only names: models of the quality table, "cad" (the CAD table), "resolution"
  // (fandisk's resolution series); empty: everything
  std::set<std::string> only;
  std::set<std::string> parts; // --parts: the parts of the CAD table to evaluate; empty: all
#ifdef FS_GENERATED_PARTS_DIR
  std::string generated = FS_GENERATED_PARTS_DIR; // --generated: the gmsh parts with their labels
#else
  std::string generated;
#endif
  bool robustness = true;
  Cad_options cad_options;

  bool selected(const std::string& name) const { return only.empty() || only.count(name) > 0; }
  // whether the quality table is asked for: a model named, or nothing named
  bool quality_table() const
  {
    for(const std::string& name : only)
      if(name != "cad" && name != "resolution") return true;
    return only.empty();
  }
};

// The CSV names of the CAD table's columns (cad_methods()), separated by commas.
inline std::string method_names()
{
  std::string names;
  for(const auto& m : cad_methods()) names += (names.empty() ? "" : ", ") + m.first;
  return names;
}

// Reads the command line into `opt`. Returns the exit status when the program is to stop
// there (0 after --help, 2 for a wrong command line), else nothing.
inline std::optional<int> read_command_line(int argc, char** argv, Evaluation_options& opt)
{
  namespace po = boost::program_options;
  Cad_options& cad = opt.cad_options;
  std::string only, noise, parts, methods;
  for(double sigma : cad.noise) noise += (noise.empty() ? "" : ",") + plain(sigma);
  bool no_robustness = false, no_tangent = false, crest_lines = false, no_crest_lines = false;
  po::options_description options("Usage: evaluate_quality [options]  (a negative number as --alpha=-0.5)\nOptions");
  options.add_options()
    ("help", "this text")
    ("data", po::value(&opt.data)->value_name("DIR"),
     "folder of paper-models/, abc/, cad/ and abc-dev/ (default: $FEATURE_SEGMENTATION_DATA; without it, fandisk only and "
     "no CAD table)")
    ("out", po::value(&opt.out)->value_name("DIR")->default_value(opt.out), "output folder")
    ("only", po::value(&only)->value_name("NAME[,NAME...]"),
     "only these: models of the quality table (fandisk, abc_00000006, bunny, ...), cad (the CAD table), "
     "resolution (fandisk's resolution series); default: everything")
    ("parts", po::value(&parts)->value_name("NAME[,NAME...]"),
     "CAD table: only these parts (file names without extension, e.g. 24051_4852a192_5,abc_00000026)")
    ("generated", po::value(&opt.generated)->value_name("DIR")->default_value(opt.generated),
     "CAD table: the folder of the generated parts (NAME.obj and NAME.labels, made by the target generated_parts)")
    ("no-robustness", po::bool_switch(&no_robustness), "quality table: without the noise columns")
    ("methods", po::value(&methods)->value_name("NAME[,NAME...]"),
     ("CAD table: only these columns (" + method_names() + "); default: all").c_str())
    ("noise", po::value(&noise)->value_name("X,Y,...")->default_value(noise),
     "CAD table: the noise levels, standard deviations as fractions of the diagonal")
    ("noise-seeds", po::value(&cad.noise_seeds)->value_name("N")->default_value(cad.noise_seeds),
     "CAD table: score each noisy level on N noise realisations (seeds 1 to N) and give their means")
    ("alpha", po::value(&cad.alpha)->value_name("A")->default_value(cad.alpha, plain(cad.alpha)),
     "CAD table and resolution series: alpha of this package (the paper's pipeline keeps 0.6)")
    ("strength-threshold",
     po::value(&cad.strength_threshold)->value_name("S")->default_value(cad.strength_threshold,
                                                                        plain(cad.strength_threshold)),
     "the same: the crest lines' strength threshold (>= 0)")
    ("crease-filter", po::value(&cad.crease_filter)->value_name("N")->default_value(cad.crease_filter),
     "the same, and the paper's pipeline: rounds of normal filtering before the creases are found (0 .. 1000)")
    ("no-tangent", po::bool_switch(&no_tangent),
     "the same: without the curvature discontinuities (tangent_discontinuities(false))")
    ("crest-lines", po::bool_switch(&crest_lines),
     "the same: crest lines on clean tessellations too (crest_lines_on_clean_tessellations(true))")
    ("no-crest-lines", po::bool_switch(&no_crest_lines),
     "the same: no crest lines on clean tessellations (crest_lines_on_clean_tessellations(false)); without "
     "either, the library's default");
  try
  {
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv)
                .options(options)
                .style(po::command_line_style::unix_style ^ po::command_line_style::allow_short)
                .run(),
              vm);
    if(vm.count("help"))
    {
      std::cout << options;
      return 0;
    }
    po::notify(vm);
    if(!std::isfinite(cad.alpha)) throw po::error("--alpha takes a finite number");
    if(!(cad.strength_threshold >= 0) || !std::isfinite(cad.strength_threshold))
      throw po::error("--strength-threshold takes a finite number >= 0");
    if(cad.crease_filter < 0 || cad.crease_filter > 1000)
      throw po::error("--crease-filter takes an integer in 0 .. 1000");
    cad.noise.clear();
    for(const std::string& x : split_commas(noise))
    {
      char* end = nullptr;
      const double sigma = std::strtod(x.c_str(), &end);
      if(x.empty() || *end != '\0' || !(sigma >= 0 && sigma < 1))
        throw po::error("--noise takes numbers in [0, 1), separated by commas (got '" + noise + "')");
      cad.noise.push_back(sigma);
    }
    if(cad.noise.empty()) throw po::error("--noise takes at least one level");
    if(cad.noise_seeds < 1 || cad.noise_seeds > 100) throw po::error("--noise-seeds takes an integer in 1 .. 100");
    if(crest_lines && no_crest_lines) throw po::error("--crest-lines and --no-crest-lines exclude each other");
    for(const std::string& name : split_commas(only)) opt.only.insert(name);
    for(const std::string& name : split_commas(parts)) opt.parts.insert(name);
    for(const std::string& name : split_commas(methods))
    {
      const auto& known = cad_methods();
      if(std::none_of(known.begin(), known.end(), [&](const auto& m) { return m.first == name; }))
        throw po::error("--methods takes names among " + method_names() + " (got '" + name + "')");
      cad.methods.insert(name);
    }
  }
  catch(const po::error& e)
  {
    std::cerr << "evaluate_quality: " << e.what() << "\n\n" << options;
    return 2;
  }
  opt.robustness = !no_robustness;
  if(no_tangent) cad.tangent = false;
  if(crest_lines || no_crest_lines) cad.crest_lines = crest_lines;
  return std::nullopt;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_EVALUATE_QUALITY_OPTIONS_H
