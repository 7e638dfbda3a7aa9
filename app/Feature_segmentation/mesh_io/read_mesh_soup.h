// SPDX-License-Identifier: GPL-3.0-or-later
// Reads a mesh file of the programs into a polygon soup, choosing the reader by the
// file's extension (.off, .obj, .ply, .stl, in any case).

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_MESH_SOUP_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_MESH_SOUP_H

#include "mesh_soup.h"
#include "read_obj.h"
#include "read_off.h"
#include "read_ply.h"
#include "read_stl.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <new>
#include <string>

namespace fs_app {
namespace internal {

inline std::string lower_case_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  if(!ext.empty() && ext[0] == '.')
    ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

} // namespace internal

/// Reads `content`, the bytes of a file in `format` ("off", "obj", "ply" or "stl"), into
/// `soup`; `path` only names the file in messages. Throws as the other overload.
inline void read_mesh_soup(const std::string& path, const std::string& format,
                           const internal::File_content& content, Mesh_soup& soup)
{
  soup = Mesh_soup();
  if(content.size() == 0)
    throw Input_error(path + ": the file is empty");
  try
  {
    if(format == "off")
      internal::read_off(path, content, soup);
    else if(format == "obj")
      internal::read_obj(path, content, soup);
    else if(format == "ply")
      internal::read_ply(path, content, soup);
    else if(format == "stl")
      internal::read_stl(path, content, soup);
    else
      throw Input_error(path + ": unknown format '" + format + "'");
  }
  catch(const std::bad_alloc&)
  {
    // Counts are checked against the file size first, so this is a machine without
    // memory for a file of this size.
    throw Input_error(path + ": out of memory while reading " + std::to_string(content.size()) +
                      " bytes");
  }
  if(soup.number_of_faces() == 0)
    throw Input_error(path + ": contains no faces");
}

/// Reads `path` into `soup`. Throws `Input_error` ("<file>[:<line>]: <reason>") when the
/// file cannot be read, its format is not known, or its content is malformed; on
/// success every index is in range and every coordinate finite. Faces with fewer than 3
/// vertices are refused; degenerate faces and duplicates are left to the caller.
inline void read_mesh_soup(const std::string& path, Mesh_soup& soup)
{
  soup = Mesh_soup();
  const std::string format = internal::lower_case_extension(path);
  if(format != "off" && format != "obj" && format != "ply" && format != "stl")
    throw Input_error(path + ": unknown format " +
                      (format.empty() ? std::string("(no extension)") : "'." + format + "'") +
                      " (expected .off, .obj, .ply or .stl)");
  const internal::File_content content(path);
  read_mesh_soup(path, format, content, soup);
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_READ_MESH_SOUP_H
