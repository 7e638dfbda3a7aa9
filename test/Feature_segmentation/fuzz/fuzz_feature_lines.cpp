// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the reader of user feature lines (CGAL polylines) on a fixed mesh,
// a unit cube of 12 triangles: any text must give lines or one `Input_error`.
#include "read_user_feature_lines.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const Mesh cube = [] {
    Mesh m;
    CGAL::make_hexahedron(Kernel::Point_3(0, 0, 0), Kernel::Point_3(1, 0, 0), Kernel::Point_3(1, 1, 0),
                          Kernel::Point_3(0, 1, 0), Kernel::Point_3(0, 1, 1), Kernel::Point_3(0, 0, 1),
                          Kernel::Point_3(1, 0, 1), Kernel::Point_3(1, 1, 1), m);
    CGAL::Polygon_mesh_processing::triangulate_faces(m);
    return m;
  }();
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  CGAL::Feature_segmentation::Feature_lines<Mesh> lines;
  try
  {
    fs_app::read_user_feature_lines(in, "input.polylines.txt", cube, lines);
  }
  catch(const fs_app::Input_error&)
  {
  }
  return 0;
}
