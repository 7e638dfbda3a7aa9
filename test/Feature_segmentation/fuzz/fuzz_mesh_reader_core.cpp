// SPDX-License-Identifier: GPL-3.0-or-later
// The body of the libFuzzer targets of the programs' mesh readers (fuzz_read_off, ...,
// see fuzz_mesh_reader.cpp), compiled once for all four: the reader of `format` and the
// repairs after it. Any input must end in a mesh or in one `Input_error`; a crash, a
// sanitizer report, a hang or any other exception is a bug.
#include "read_input_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

int fs_fuzz_mesh_reader(const char* format, const std::uint8_t* data, std::size_t size)
{
  const std::string name = std::string("input.") + format;
  const fs_app::internal::File_content content(reinterpret_cast<const char*>(data), size);
  fs_app::Mesh_soup soup;
  Mesh mesh;
  fs_app::Input_correspondence<Mesh> correspondence;
  try
  {
    fs_app::read_mesh_soup(name, format, content, soup);
    fs_app::mesh_from_soup(name, soup, mesh, correspondence);
  }
  catch(const fs_app::Input_error&)
  {
    return 0;
  }
  // A mesh that passed is valid and every file face has its triangles.
  if(!CGAL::is_valid_polygon_mesh(mesh) || !CGAL::is_triangle_mesh(mesh))
    __builtin_trap();
  for(std::size_t f = 0; f < correspondence.face_of_file_face.size(); ++f)
    if(correspondence.number_of_triangles[f] == 0)
      __builtin_trap();
  return 0;
}
