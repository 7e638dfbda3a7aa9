// SPDX-License-Identifier: GPL-3.0-or-later
// The edit script of the program `feature_segmentation` (option --edits): a small
// line-based language that reaches every edit of Feature_aligned_segmentation (paper,
// Section 4) in batch form. This file reads and checks a script and writes one back;
// edit_runner.h turns its regions and sketch points into mesh faces and located points,
// and applies its edits one by one, timing each. Every mistake in a script is one
// Edit_script_error "FILE:LINE: reason".
//
// The language, one edit per line ('#' starts a comment; blank lines are ignored):
//   alpha A                  set the global alpha to A (global refine/coarsen)
//   refine REGION D          add D to alpha_e on the feature edges of REGION
//   coarsen REGION D         subtract D from alpha_e on the feature edges of REGION
//   scale REGION F           multiply alpha_e on the feature edges of REGION by F >= 0
//   merge REGION             merge the patches that REGION touches
//   sketch [alpha A] X Y Z X Y Z ...   a sketched feature line through >= 2 points,
//                            each moved to the nearest point of the surface (A > 1, default 2)
//   undo                     take back the last edit not yet undone
//   redo                     make again the last edit taken back by undo (any other
//                            edit after an undo forgets what could be redone)
// REGION is 'ball X Y Z R' (the faces whose centroid lies within R > 0 of (X, Y, Z)),
// 'faces I J ...' (faces of the input file, numbered from 0 in file order; a polygon
// that was triangulated stands for all its triangles) or 'triangles I J ...' (triangles
// of the repaired, triangulated mesh, in the order of segmentation.ply; the interactive
// editor saves its regions so).
//
// The same edits arrive as JSON objects at the interactive editor (editor_api.h), which
// turns them into Script_edit and applies them with the same Edit_runner, and saves its
// history as a script with `write_edit_script()`, so the two cannot drift.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_EDIT_SCRIPT_H
#define CGAL_FEATURE_SEGMENTATION_APP_EDIT_SCRIPT_H

#include "number_text.h"

#include <CGAL/Feature_segmentation/defaults.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs_app {

/// A mistake in an edit script (or a script that cannot be read); the message is
/// "FILE:LINE: reason" (or "FILE: reason").
class Edit_script_error : public std::runtime_error { public: using std::runtime_error::runtime_error; };

/// An edit that cannot be made (a value out of range, nothing to undo, an edit the
/// library refuses); the message is "verb: reason". Nothing changed.
class Edit_refused : public std::runtime_error { public: using std::runtime_error::runtime_error; };

/// A region of the mesh named in a script.
struct Script_region
{
  enum Kind { BALL, FILE_FACES, TRIANGLES };
  Kind kind = BALL;
  std::array<double, 3> center = {0., 0., 0.}; ///< a ball's centre
  double radius = 0;                           ///< a ball's radius, > 0
  std::vector<std::size_t> faces;              ///< 'faces': faces of the input file;
                                               ///< 'triangles': faces of the mesh
};

/// One line of a script.
struct Script_edit
{
  std::size_t line = 0;
  std::string verb;  ///< alpha, refine, coarsen, scale, merge, sketch, undo or redo
  double value = 0;  ///< alpha: A; refine: D; coarsen: -D; scale: F; sketch: its alpha
  Script_region region;                        ///< refine, coarsen, scale, merge
  std::vector<std::array<double, 3> > points;  ///< sketch
};

/// A parsed script.
struct Edit_script
{
  std::string path;
  std::vector<Script_edit> edits;
};

/// The sketch alpha when a `sketch` line gives none (the library's default).
using CGAL::Feature_segmentation::default_sketch_alpha;

/// The largest magnitude of an edit's value (alpha, amount, factor, sketch alpha), and the
/// smallest of a nonzero one: outside, the weights or the cut cost overflow, or the edit's
/// text does not read back (a subnormal number).
constexpr double edit_largest_value = 1e9, edit_smallest_value = 1e-9;
/// The most points a sketch may have (each is located on the surface and each segment
/// walked across the mesh: the work of one edit stays bounded).
constexpr std::size_t edit_max_sketch_points = 1000;

/// Why `e` is refused, or "" if it is accepted: the one check of every edit, from an edit
/// script, the editor or Python, so that every accepted edit replays from its script line.
/// A value (alpha, refine's and coarsen's amount, scale's factor, sketch's alpha) is 0 or
/// of magnitude in [edit_smallest_value, edit_largest_value]; a scale factor is >= 0; a
/// sketch has alpha > 1 and 2 to edit_max_sketch_points points of finite coordinates.
inline std::string edit_refusal(const Script_edit& e)
{
  const auto number = [](double x) {
    std::ostringstream text;
    text << x;
    return text.str();
  };
  const bool valued = e.verb == "alpha" || e.verb == "refine" || e.verb == "coarsen" || e.verb == "scale" ||
                      e.verb == "sketch";
  if(valued && (!std::isfinite(e.value) || std::abs(e.value) > edit_largest_value ||
                (e.value != 0 && std::abs(e.value) < edit_smallest_value)))
    return e.verb + ": the value must be 0 or of magnitude between 1e-9 and 1e9 (got " + number(e.value) + ")";
  if(e.verb == "scale" && e.value < 0)
    return "scale: the factor must be >= 0 (got " + number(e.value) + ")";
  if(e.verb == "sketch")
  {
    if(!(e.value > 1))
      return "sketch: alpha must be > 1 (got " + number(e.value) + ")";
    if(e.points.size() < 2 || e.points.size() > edit_max_sketch_points)
      return "sketch: 2 to " + std::to_string(edit_max_sketch_points) + " points (got " +
             std::to_string(e.points.size()) + ")";
    for(const auto& p : e.points)
      if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        return "sketch: the points' coordinates must be finite";
  }
  return {};
}

namespace internal {

inline std::string script_place(const std::string& path, std::size_t line)
{
  return path + ":" + std::to_string(line) + ": ";
}

// The whole token must be a finite number ("1.5x", "nan", "inf" and overflows are refused).
inline double script_number(const std::string& token, const std::string& where, const std::string& what)
{
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(begin, &end);
  if(end == begin || *end != '\0')
    throw Edit_script_error(where + what + ": '" + token + "' is not a number");
  if(!std::isfinite(x) || errno == ERANGE)
    throw Edit_script_error(where + what + ": '" + token + "' is not a finite number");
  return x;
}

inline std::size_t script_face_index(const std::string& token, const std::string& where)
{
  if(token.empty() || token.find_first_not_of("0123456789") != std::string::npos)
    throw Edit_script_error(where + "'" + token + "' is not a face index (an integer >= 0)");
  errno = 0;
  const unsigned long long i = std::strtoull(token.c_str(), nullptr, 10);
  if(errno == ERANGE)
    throw Edit_script_error(where + "face index " + token + " is out of range");
  return static_cast<std::size_t>(i);
}

// The region in tokens [first, last): 'ball X Y Z R' or 'faces I J ...'.
inline Script_region script_region(const std::vector<std::string>& tokens, std::size_t first,
                                   std::size_t last, const std::string& where,
                                   const std::string& usage)
{
  Script_region r;
  const std::string kind = first < tokens.size() ? tokens[first] : std::string();
  if(kind == "ball")
  {
    if(last - first != 5)
      throw Edit_script_error(where + tokens[0] + ": a ball is 'ball X Y Z R' (usage: " + usage + ")");
    for(int k = 0; k < 3; ++k)
      r.center[k] = script_number(tokens[first + 1 + k], where, "ball");
    r.radius = script_number(tokens[first + 4], where, "ball");
    if(!(r.radius > 0))
      throw Edit_script_error(where + "ball: the radius must be > 0 (got " + tokens[first + 4] + ")");
    return r;
  }
  if(kind == "faces" || kind == "triangles")
  {
    if(last - first < 2)
      throw Edit_script_error(where + tokens[0] + ": '" + kind + "' needs at least one face index (usage: " +
                              usage + ")");
    r.kind = kind == "faces" ? Script_region::FILE_FACES : Script_region::TRIANGLES;
    for(std::size_t i = first + 1; i < last; ++i)
      r.faces.push_back(script_face_index(tokens[i], where + kind + ": "));
    return r;
  }
  throw Edit_script_error(where + tokens[0] + ": expected a region, 'ball X Y Z R', 'faces I J ...' or "
                          "'triangles I J ...' (got " +
                          (kind.empty() ? std::string("nothing") : "'" + kind + "'") + "; usage: " +
                          usage + ")");
}

} // namespace internal

inline Edit_script read_edit_script(std::istream& in, const std::string& path);

/// Reads and checks the script `path` (everything but the range of face indices, which
/// needs the mesh: see `check_face_indices()`).
/// \throws Edit_script_error on the first mistake
inline Edit_script read_edit_script(const std::string& path)
{
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if(!std::filesystem::exists(st))
    throw Edit_script_error(path + ": no such file");
  if(std::filesystem::is_directory(st))
    throw Edit_script_error(path + ": is a directory, not an edit script");
  std::ifstream in(path);
  if(!in)
    throw Edit_script_error(path + ": cannot be opened");
  return read_edit_script(in, path);
}

/// Reads and checks the script in `in`; `path` names it in messages.
/// \throws Edit_script_error on the first mistake
inline Edit_script read_edit_script(std::istream& in, const std::string& path)
{
  Edit_script script;
  script.path = path;
  std::size_t undoable = 0; // edits that an 'undo' can still take back
  std::size_t redoable = 0; // undone edits that a 'redo' can still make again
  std::string text;
  for(std::size_t line = 1; std::getline(in, text); ++line)
  {
    const std::size_t hash = text.find('#');
    if(hash != std::string::npos)
      text.erase(hash);
    std::istringstream words(text);
    std::vector<std::string> t;
    for(std::string w; words >> w;)
      t.push_back(w);
    if(t.empty())
      continue;

    const std::string where = internal::script_place(path, line);
    Script_edit e;
    e.line = line;
    e.verb = t[0];
    const std::size_t n = t.size();
    auto arity = [&](bool ok, const std::string& usage) {
      if(!ok)
        throw Edit_script_error(where + e.verb + ": wrong number of arguments (usage: " + usage + ")");
    };
    if(e.verb == "alpha")
    {
      arity(n == 2, "alpha A");
      e.value = internal::script_number(t[1], where, "alpha");
    }
    else if(e.verb == "refine" || e.verb == "coarsen" || e.verb == "scale")
    {
      const std::string usage = e.verb + " REGION " + (e.verb == "scale" ? "F" : "D");
      arity(n >= 3, usage);
      e.region = internal::script_region(t, 1, n - 1, where, usage);
      e.value = internal::script_number(t[n - 1], where, e.verb);
      if(e.verb == "coarsen")
        e.value = -e.value;
    }
    else if(e.verb == "merge")
    {
      arity(n >= 2, "merge REGION");
      e.region = internal::script_region(t, 1, n, where, "merge REGION");
    }
    else if(e.verb == "sketch")
    {
      std::size_t first = 1;
      e.value = default_sketch_alpha;
      if(n > 1 && t[1] == "alpha")
      {
        arity(n >= 3, "sketch [alpha A] X Y Z X Y Z ...");
        e.value = internal::script_number(t[2], where, "sketch alpha");
        first = 3;
      }
      const std::size_t numbers = n - first;
      if(numbers % 3 != 0 || numbers < 6)
        throw Edit_script_error(where + "sketch: expected at least two points of three coordinates (got " +
                                std::to_string(numbers) + " numbers)");
      for(std::size_t i = first; i < n; i += 3)
        e.points.push_back({internal::script_number(t[i], where, "sketch"),
                            internal::script_number(t[i + 1], where, "sketch"),
                            internal::script_number(t[i + 2], where, "sketch")});
    }
    else if(e.verb == "undo")
    {
      arity(n == 1, "undo");
      if(undoable == 0)
        throw Edit_script_error(where + "undo: no edit to undo");
    }
    else if(e.verb == "redo")
    {
      arity(n == 1, "redo");
      if(redoable == 0)
        throw Edit_script_error(where + "redo: no undone edit to redo");
    }
    else
      throw Edit_script_error(where + "unknown verb '" + e.verb +
                              "' (expected alpha, refine, coarsen, scale, merge, sketch, undo or redo)");
    if(const std::string refusal = edit_refusal(e); !refusal.empty())
      throw Edit_script_error(where + refusal);
    if(e.verb == "undo") { --undoable; ++redoable; }
    else if(e.verb == "redo") { ++undoable; --redoable; }
    else { ++undoable; redoable = 0; }
    script.edits.push_back(e);
  }
  if(in.bad())
    throw Edit_script_error(path + ": read failed");
  return script;
}

/// Checks that every face index of `script` names a face of the input file ('faces') or
/// a triangle of the mesh ('triangles').
/// \throws Edit_script_error on the first index out of range
inline void check_face_indices(const Edit_script& script, std::size_t number_of_file_faces,
                               std::size_t number_of_triangles)
{
  for(const Script_edit& e : script.edits)
  {
    if(e.region.kind == Script_region::BALL) continue;
    const bool file = e.region.kind == Script_region::FILE_FACES;
    const std::size_t n = file ? number_of_file_faces : number_of_triangles;
    for(std::size_t f : e.region.faces)
      if(f >= n)
        throw Edit_script_error(internal::script_place(script.path, e.line) + (file ? "faces" : "triangles") +
                                ": face index " + std::to_string(f) + " is out of range (the mesh " +
                                (file ? "file has " : "has ") + std::to_string(n) +
                                (file ? " faces)" : " triangles)"));
  }
}

/// Writes `edits` as a script that `read_edit_script()` reads back to the same edits
/// (every number in the shortest form that reads back exactly).
inline void write_edit_script(std::ostream& os, const std::vector<Script_edit>& edits)
{
  for(const Script_edit& e : edits)
  {
    const bool coarsen = e.verb == "coarsen";
    os << e.verb;
    if(e.verb == "refine" || coarsen || e.verb == "scale" || e.verb == "merge")
    {
      const Script_region& r = e.region;
      if(r.kind == Script_region::BALL)
        os << " ball " << number_text(r.center[0]) << ' ' << number_text(r.center[1]) << ' '
           << number_text(r.center[2]) << ' ' << number_text(r.radius);
      else
      {
        os << (r.kind == Script_region::FILE_FACES ? " faces" : " triangles");
        for(std::size_t f : r.faces) os << ' ' << f;
      }
      if(e.verb != "merge") os << ' ' << number_text(coarsen ? -e.value : e.value);
    }
    else if(e.verb == "alpha")
      os << ' ' << number_text(e.value);
    else if(e.verb == "sketch")
    {
      os << " alpha " << number_text(e.value);
      for(const std::array<double, 3>& p : e.points)
        os << ' ' << number_text(p[0]) << ' ' << number_text(p[1]) << ' ' << number_text(p[2]);
    }
    os << '\n';
  }
}

/// `edits` as script lines (what write_edit_script() writes, a line each).
inline std::vector<std::string> edit_script_lines(const std::vector<Script_edit>& edits)
{
  std::ostringstream os;
  write_edit_script(os, edits);
  std::vector<std::string> lines;
  std::istringstream in(os.str());
  for(std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_EDIT_SCRIPT_H
