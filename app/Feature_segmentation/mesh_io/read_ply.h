// SPDX-License-Identifier: GPL-3.0-or-later
// PLY reader of the programs: ASCII, binary little endian and binary big endian; vertex
// coordinates x, y, z of any scalar type; faces as a list property `vertex_indices` (or
// `vertex_index`) with any integer count and index types; every other element and
// property (normals, colours, edges, materials, ...) skipped. The header's counts are
// checked against the size of the body before anything is allocated.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_PLY_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_PLY_H

#include "mesh_soup.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace fs_app {
namespace internal {

enum class Ply_kind { signed_integer, unsigned_integer, floating };

struct Ply_type
{
  std::size_t size = 0; // 0: not a type
  Ply_kind kind = Ply_kind::signed_integer;
};

inline Ply_type ply_type(std::string_view name)
{
  struct Entry { const char* name; std::size_t size; Ply_kind kind; };
  static const Entry table[] = {
    {"char", 1, Ply_kind::signed_integer},   {"int8", 1, Ply_kind::signed_integer},
    {"uchar", 1, Ply_kind::unsigned_integer}, {"uint8", 1, Ply_kind::unsigned_integer},
    {"short", 2, Ply_kind::signed_integer},  {"int16", 2, Ply_kind::signed_integer},
    {"ushort", 2, Ply_kind::unsigned_integer}, {"uint16", 2, Ply_kind::unsigned_integer},
    {"int", 4, Ply_kind::signed_integer},    {"int32", 4, Ply_kind::signed_integer},
    {"uint", 4, Ply_kind::unsigned_integer}, {"uint32", 4, Ply_kind::unsigned_integer},
    {"float", 4, Ply_kind::floating},        {"float32", 4, Ply_kind::floating},
    {"double", 8, Ply_kind::floating},       {"float64", 8, Ply_kind::floating}};
  for(const Entry& e : table)
    if(name == e.name)
      return Ply_type{e.size, e.kind};
  return Ply_type();
}

struct Ply_property
{
  std::string name;
  Ply_type type;        // of the value, or of the list's items
  bool is_list = false;
  Ply_type count_type;  // of a list's count
  int role = -1;        // 0, 1, 2: x, y, z of a vertex; 3: a face's index list
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::size_t line = 0;
  std::vector<Ply_property> properties;

  /// The fewest bytes one instance can take in the body.
  double minimum_bytes(bool binary) const
  {
    double bytes = 0;
    for(const Ply_property& p : properties)
      bytes += binary ? double(p.is_list ? p.count_type.size : p.type.size) : 2.0;
    return bytes;
  }
};

// A binary scalar, byte-swapped when the file's byte order is not the machine's.
inline double ply_binary_value(const char* b, const Ply_type& t, bool swap)
{
  unsigned char v[8];
  std::memcpy(v, b, t.size);
  if(swap)
    std::reverse(v, v + t.size);
  switch(t.size)
  {
  case 1:
    return t.kind == Ply_kind::signed_integer ? double(static_cast<signed char>(v[0])) : double(v[0]);
  case 2:
  {
    std::uint16_t u; std::memcpy(&u, v, 2);
    return t.kind == Ply_kind::signed_integer ? double(static_cast<std::int16_t>(u)) : double(u);
  }
  case 4:
  {
    if(t.kind == Ply_kind::floating) { float f; std::memcpy(&f, v, 4); return double(f); }
    std::uint32_t u; std::memcpy(&u, v, 4);
    return t.kind == Ply_kind::signed_integer ? double(static_cast<std::int32_t>(u)) : double(u);
  }
  default:
  {
    double d; std::memcpy(&d, v, 8); return d;
  }
  }
}

// An index as it may appear in a message: an integer if it is one.
inline std::string number_text(double v)
{
  if(std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e18)
    return std::to_string(static_cast<long long>(v));
  return std::to_string(v);
}

inline bool is_little_endian_machine()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

inline void read_ply(const std::string& path, const File_content& content, Mesh_soup& soup)
{
  soup.format = "ply";
  Text_cursor in(path, content.data(), content.data() + content.size(), '\0');
  if(in.word() != "ply" || !in.at_line_end())
    in.fail("not a PLY file (the first line is not 'ply')");
  in.next_line();

  enum { ascii, little, big, unknown } format = unknown;
  std::vector<Ply_element> elements;
  for(;;)
  {
    if(in.at_end())
      in.fail("the header has no 'end_header' line");
    const std::string_view keyword = in.word();
    if(keyword == "end_header")
    {
      if(!in.at_line_end())
        in.fail("unexpected " + quoted(in.word()) + " after 'end_header'");
      in.next_line();
      break;
    }
    if(keyword == "comment" || keyword == "obj_info" || keyword.empty())
    {
      in.next_line();
      continue;
    }
    if(keyword == "format")
    {
      const std::string_view f = in.word();
      if(f == "ascii") format = ascii;
      else if(f == "binary_little_endian") format = little;
      else if(f == "binary_big_endian") format = big;
      else in.fail("unknown PLY format " + quoted(f) +
                   " (expected ascii, binary_little_endian or binary_big_endian)");
      if(in.word() != "1.0")
        in.fail("unknown PLY version (expected 1.0)");
    }
    else if(keyword == "element")
    {
      Ply_element e;
      e.name = std::string(in.word());
      if(e.name.empty())
        in.fail("an element without a name");
      e.count = in.count("the element count", std::size_t(-1) / 2);
      e.line = in.line();
      elements.push_back(std::move(e));
    }
    else if(keyword == "property")
    {
      if(elements.empty())
        in.fail("a property before any element");
      Ply_property p;
      std::string_view t = in.word();
      if(t == "list")
      {
        p.is_list = true;
        const std::string_view c = in.word();
        p.count_type = ply_type(c);
        if(p.count_type.size == 0 || p.count_type.kind == Ply_kind::floating)
          in.fail("a list count type must be an integer type, found " + quoted(c));
        t = in.word();
      }
      p.type = ply_type(t);
      if(p.type.size == 0)
        in.fail("unknown property type " + quoted(t));
      p.name = std::string(in.word());
      if(p.name.empty())
        in.fail("a property without a name");
      elements.back().properties.push_back(std::move(p));
    }
    else
      in.fail("unknown header line starting with " + quoted(keyword));
    if(!in.at_line_end())
      in.fail("unexpected " + quoted(in.word()) + " at the end of a header line");
    in.next_line();
  }
  if(format == unknown)
    in.fail("the header has no 'format' line");

  // Which properties the soup needs: those of the first element named vertex and of
  // the first named face.
  std::size_t vertex_count = 0;
  const Ply_element* vertex_element = nullptr;
  const Ply_element* face_element = nullptr;
  for(Ply_element& e : elements)
  {
    if(e.name == "vertex" && vertex_element == nullptr)
    {
      vertex_element = &e;
      vertex_count = e.count;
      for(const char* axis : {"x", "y", "z"})
      {
        const auto it = std::find_if(e.properties.begin(), e.properties.end(),
                                     [axis](const Ply_property& p) { return p.name == axis; });
        if(it == e.properties.end() || it->is_list)
          throw Input_error(path + ":" + std::to_string(e.line) + ": the vertex element has no '" +
                            axis + "' coordinate");
        it->role = axis[0] - 'x';
      }
    }
    else if(e.name == "face" && face_element == nullptr)
    {
      face_element = &e;
      const auto it = std::find_if(e.properties.begin(), e.properties.end(), [](const Ply_property& p) {
        return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
      });
      if(it == e.properties.end())
        throw Input_error(path + ":" + std::to_string(e.line) +
                          ": the face element has no list property 'vertex_indices'");
      if(it->type.kind == Ply_kind::floating)
        throw Input_error(path + ":" + std::to_string(e.line) +
                          ": face vertex indices must have an integer type");
      it->role = 3;
    }
  }
  if(face_element == nullptr)
    throw Input_error(path + ": contains no faces (no 'face' element in the header)");

  // Every announced element must fit in the body before anything is allocated.
  const bool binary = format != ascii;
  double needed = 0;
  for(const Ply_element& e : elements)
    needed += double(e.count) * e.minimum_bytes(binary);
  if(needed > double(in.bytes_left()))
    throw Input_error(path + ": the header announces more elements than the " +
                      std::to_string(in.bytes_left()) +
                      " bytes of the body can hold (truncated file or wrong counts)");
  if(vertex_count > max_soup_count)
    throw Input_error(path + ": too many vertices for one mesh");

  const bool swap = binary && ((format == little) != is_little_endian_machine());
  const char* p = in.position();
  const char* const end = content.data() + content.size();
  double point[3] = {0, 0, 0};
  // The next binary value of type `t`, or the error of a body that ends too early.
  const auto next_binary = [&](const Ply_type& t, const auto& where) {
    if(std::size_t(end - p) < t.size)
      throw Input_error(path + ": the body ends " + where() +
                        "the file is truncated or its counts are wrong");
    const double value = ply_binary_value(p, t, swap);
    p += t.size;
    return value;
  };
  for(const Ply_element& e : elements)
  {
    if(e.properties.empty())
      continue; // no bytes in the body, whatever its count (fuzzing found a count of 88e9)
    const bool is_vertex = &e == vertex_element;
    const bool is_face = &e == face_element;
    if(is_vertex)
      soup.points.reserve(e.count);
    for(std::size_t i = 0; i < e.count; ++i)
    {
      std::size_t line = 0;
      for(const Ply_property& prop : e.properties)
      {
        std::size_t n = 1;
        const auto where = [&]() {
          return "in " + e.name + " " + std::to_string(i) + ": ";
        };
        if(prop.is_list)
        {
          double count;
          if(binary)
            count = next_binary(prop.count_type, where);
          else
          {
            count = double(in.count("a list count", in.bytes_left() / 2 + 1, true));
            line = in.line();
          }
          const double item_bytes = binary ? double(prop.type.size) : 2.0;
          if(count < 0 || count * item_bytes > double(binary ? std::size_t(end - p) : in.bytes_left() + 1))
            throw Input_error(path + ": " + where() + "a list of " + number_text(count) +
                              " items does not fit in the rest of the file");
          n = static_cast<std::size_t>(count);
          if(is_face && prop.role == 3 && n < 3)
            throw Input_error(path + ": face " + std::to_string(i) + " has " + std::to_string(n) +
                              " vertices (at least 3 are needed)");
        }
        for(std::size_t k = 0; k < n; ++k)
        {
          double value;
          if(binary)
            value = next_binary(prop.type, where);
          else
          {
            const std::string_view w = in.word_across_lines();
            if(w.empty())
              in.fail("the file ends " + where() + "it is truncated or its counts are wrong");
            if(!parse_double(w, value))
              in.fail(where() + "expected a number for '" + prop.name + "', found " + quoted(w));
          }
          if(is_face && prop.role == 3)
          {
            if(!(value >= 0) || value != std::floor(value) || value >= double(vertex_count))
              throw Input_error(path + (binary ? std::string() : ":" + std::to_string(in.line())) +
                                ": face " + std::to_string(i) + " refers to vertex " +
                                number_text(value) + " but the file has " +
                                std::to_string(vertex_count) + " vertices");
            soup.indices.push_back(static_cast<std::uint32_t>(value));
          }
          else if(is_vertex && prop.role >= 0)
          {
            if(!std::isfinite(value))
              throw Input_error(path + (binary ? std::string() : ":" + std::to_string(in.line())) +
                                ": vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
            point[prop.role] = value;
          }
        }
      }
      if(is_vertex)
        add_point(soup, point[0], point[1], point[2]);
      else if(is_face)
      {
        if(soup.indices.size() > max_soup_count)
          throw Input_error(path + ": too many face indices for one mesh");
        end_face(soup, binary ? 0 : line);
      }
    }
  }
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_PLY_H
