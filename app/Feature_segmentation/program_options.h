// SPDX-License-Identifier: GPL-3.0-or-later
// The command line of the program `feature_segmentation`: the options of option_table.h,
// read once by Boost.Program_options (subcommands `segment`, the default, `edit` and
// `batch`).

#ifndef CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_OPTIONS_H
#define CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_OPTIONS_H

#include "option_table.h"
#include "options.h"

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

// Strict number parsing: the whole argument must be the number ("1.5x", "", " 1", "abc"
// are refused; apply_option() checks the range).
inline long long parse_int(const std::string& option, const std::string& text)
{
  std::size_t used = 0; // stays 0 if stoll throws
  long long value = 0;
  try { value = std::stoll(text, &used, 10); } catch(const std::exception&) {}
  require(used != 0 && used == text.size() && !std::isspace(static_cast<unsigned char>(text[0])),
          option + " expects an integer (got '" + text + "')");
  return value;
}

inline double parse_double(const std::string& option, const std::string& text)
{
  std::size_t used = 0; // stays 0 if stod throws
  double value = 0;
  try { value = std::stod(text, &used); } catch(const std::exception&) {}
  require(used != 0 && used == text.size() && !std::isspace(static_cast<unsigned char>(text[0])),
          option + " expects a number (got '" + text + "')");
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
  for(const Option_entry& e : option_table())
    if(e.flag() == flag && e.only && *e.only != command)
    {
      const bool edit = *e.only == Command::EDIT;
      throw Usage_error(flag + " is an option of '" + (edit ? "edit" : "batch") + "' (" + program_name +
                        (edit ? " edit MESH " : " batch INPUTS ") + flag + (e.metavar.empty() ? "" : " " + e.metavar) +
                        ")");
    }
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
  for(const Option_entry& e : option_table())
  {
    const std::string flag = e.flag();
    const std::string name = flag.substr(2) + (e.keyword == "help" ? ",h" : "");
    if(e.kind == Option_kind::SWITCH)
    {
      described.add_options()(name.c_str(), flag_option([&o, &e, flag] {
                                 Option_input in;
                                 in.name = flag;
                                 in.on = !e.negated;
                                 apply_option(e, o, in);
                               }));
      continue;
    }
    described.add_options()(name.c_str(), value_option([&o, &e, flag](Text t) {
                               Option_input in;
                               in.name = flag;
                               in.got = in.text = t;
                               if(e.kind == Option_kind::INTEGER) in.integer = parse_int(flag, t);
                               if(e.kind == Option_kind::NUMBER) in.number = parse_double(flag, t);
                               apply_option(e, o, in);
                             }));
  }
  described.add_options()
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

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_PROGRAM_OPTIONS_H
