// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive editor's requests (editor_api.h), checked and turned into the edit
// script's Script_edit (script_edit_from_json); the bounds of its answers, and the bytes
// of its binary answers.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_EDITOR_REQUESTS_H
#define CGAL_FEATURE_SEGMENTATION_APP_EDITOR_REQUESTS_H

#include "edit_script.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs_app {

/// A request the editor refuses; the message says why. The state is unchanged.
class Request_error : public std::runtime_error { public: using std::runtime_error::runtime_error; };

namespace internal {

/// The edits a state carries (the last ones; GET /api/history pages through them all),
/// and the most a page of the history holds: answers of bounded size however long the
/// session.
constexpr std::size_t editor_state_edits = 50, editor_max_history_page = 1000;
/// The longest edit line a state carries: a longer one (a region of many faces) is cut
/// after its first words and ends with " ... (N more)"; GET /api/history gives it whole.
constexpr std::size_t editor_state_line_chars = 200;

inline std::vector<std::string> abbreviated(std::vector<std::string> lines)
{
  for(std::string& line : lines)
  {
    if(line.size() <= editor_state_line_chars) continue;
    const std::size_t cut = line.rfind(' ', editor_state_line_chars - 40);
    const std::size_t rest = static_cast<std::size_t>(std::count(line.begin() + std::ptrdiff_t(cut), line.end(), ' '));
    line = line.substr(0, cut) + " ... (" + std::to_string(rest) + " more)";
  }
  return lines;
}

inline double json_finite(const nlohmann::json& j, const char* key, const std::string& op)
{
  const auto it = j.find(key);
  if(it == j.end())
    throw Request_error(op + ": '" + key + "' is missing");
  if(!it->is_number())
    throw Request_error(op + ": '" + key + "' must be a number");
  const double x = it->get<double>();
  if(!std::isfinite(x))
    throw Request_error(op + ": '" + key + "' must be a finite number");
  return x;
}

inline std::vector<std::size_t> json_faces(const nlohmann::json& j, const std::string& op,
                                           std::size_t number_of_triangles)
{
  const auto it = j.find("faces");
  if(it == j.end() || !it->is_array())
    throw Request_error(op + ": 'faces' must be an array of triangle indices");
  if(it->empty())
    throw Request_error(op + ": 'faces' is empty");
  std::vector<std::size_t> faces;
  faces.reserve(it->size());
  for(const nlohmann::json& f : *it)
  {
    // an integer (parsed ones >= 0 are unsigned, built ones may be signed)
    if(!f.is_number_integer() || (!f.is_number_unsigned() && f.get<std::int64_t>() < 0))
      throw Request_error(op + ": 'faces' must hold integers >= 0 (got " + f.dump() + ")");
    const auto i = f.get<std::uint64_t>();
    if(i >= number_of_triangles)
      throw Request_error(op + ": face index " + std::to_string(i) + " is out of range (the mesh has " +
                          std::to_string(number_of_triangles) + " triangles)");
    faces.push_back(static_cast<std::size_t>(i));
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

inline void json_keys(const nlohmann::json& j, const std::string& op, std::set<std::string> allowed)
{
  allowed.insert("op");
  for(const auto& item : j.items())
    if(!allowed.count(item.key()))
      throw Request_error(op + ": unknown key '" + item.key() + "'");
}

// Bytes of numbers in little-endian order, whatever the machine's, for the binary answers.
class Little_endian_bytes
{
public:
  explicit Little_endian_bytes(std::size_t size) { m_bytes.reserve(size); }
  void u32(std::size_t x)
  {
    if(x > 0xffffffffu) throw std::length_error("a count or index beyond 32 bits");
    put(std::uint32_t(x));
  }
  void f32(float x)
  {
    std::uint32_t bits;
    std::memcpy(&bits, &x, 4);
    put(bits);
  }
  void f64(double x)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &x, 8);
    put(std::uint32_t(bits & 0xffffffffu));
    put(std::uint32_t(bits >> 32));
  }
  // Appends `count` zero ids of `width` bytes (1, 2 or 4) and returns where they start,
  // for write_id(); the pointer holds until the next append.
  char* id_block(std::size_t count, unsigned width)
  {
    const std::size_t at = m_bytes.size();
    m_bytes.resize(at + std::size_t(width) * count);
    return &m_bytes[at];
  }
  // The fewest bytes (1, 2 or 4) that hold every id up to `largest`.
  static unsigned id_width(std::uint32_t largest) { return largest < 0x100u ? 1 : largest < 0x10000u ? 2 : 4; }
  static void write_id(char* at, std::uint32_t x, unsigned width)
  {
    for(unsigned k = 0; k < width; ++k) at[k] = char((x >> (8 * k)) & 0xff);
  }
  void append(const std::string& bytes) { m_bytes += bytes; }
  std::string take() { return std::move(m_bytes); }

private:
  void put(std::uint32_t x)
  {
    const char b[4] = { char(x & 0xff), char((x >> 8) & 0xff), char((x >> 16) & 0xff), char(x >> 24) };
    m_bytes.append(b, 4);
  }
  std::string m_bytes;
};

} // namespace internal

/// Turns one JSON edit into the edit script's form (its line is `line`).
/// \throws Request_error if the request is not a valid edit
inline Script_edit script_edit_from_json(const nlohmann::json& j, std::size_t number_of_triangles,
                                         std::size_t line)
{
  if(!j.is_object())
    throw Request_error("an edit must be a JSON object, e.g. {\"op\": \"alpha\", \"value\": 0.8}");
  const auto op_it = j.find("op");
  if(op_it == j.end() || !op_it->is_string())
    throw Request_error("an edit needs \"op\": one of alpha, refine, coarsen, scale, merge, sketch, undo, redo");
  Script_edit e;
  e.line = line;
  e.verb = op_it->get<std::string>();
  const std::string& op = e.verb;
  if(op == "alpha")
  {
    internal::json_keys(j, op, {"value"});
    e.value = internal::json_finite(j, "value", op);
  }
  else if(op == "refine" || op == "coarsen" || op == "scale")
  {
    const char* key = op == "scale" ? "factor" : "amount";
    internal::json_keys(j, op, {"faces", key});
    e.region.kind = Script_region::TRIANGLES;
    e.region.faces = internal::json_faces(j, op, number_of_triangles);
    e.value = internal::json_finite(j, key, op);
    if(op == "coarsen")
      e.value = -e.value;
  }
  else if(op == "merge")
  {
    internal::json_keys(j, op, {"faces"});
    e.region.kind = Script_region::TRIANGLES;
    e.region.faces = internal::json_faces(j, op, number_of_triangles);
  }
  else if(op == "sketch")
  {
    internal::json_keys(j, op, {"points", "alpha"});
    e.value = j.contains("alpha") ? internal::json_finite(j, "alpha", op) : default_sketch_alpha;
    const auto it = j.find("points");
    if(it == j.end() || !it->is_array() || it->size() < 2)
      throw Request_error("sketch: 'points' must be an array of at least two [x, y, z] points");
    if(it->size() > edit_max_sketch_points)
      throw Request_error("sketch: 2 to " + std::to_string(edit_max_sketch_points) + " points (got " +
                          std::to_string(it->size()) + ")"); // before reading them
    for(const nlohmann::json& p : *it)
    {
      if(!p.is_array() || p.size() != 3)
        throw Request_error("sketch: every point must be [x, y, z] (got " + p.dump() + ")");
      std::array<double, 3> q;
      for(int k = 0; k < 3; ++k)
      {
        if(!p[k].is_number() || !std::isfinite(p[k].get<double>()))
          throw Request_error("sketch: coordinates must be finite numbers (got " + p.dump() + ")");
        q[k] = p[k].get<double>();
      }
      e.points.push_back(q);
    }
  }
  else if(op == "undo" || op == "redo")
    internal::json_keys(j, op, {});
  else
    throw Request_error("unknown op '" + op + "' (expected alpha, refine, coarsen, scale, merge, sketch, undo or redo)");
  return e;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_EDITOR_REQUESTS_H
