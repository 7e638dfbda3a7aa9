// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the whole pipeline on small meshes: an OFF file (at most 4 KiB)
// read by the program's reader, then segmented with the defaults and with the crease
// cut, then edited. Input the library refuses must be refused with `Invalid_input`;
// anything else must give one patch id in range per face.
#include "read_input_mesh.h"

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace FS = CGAL::Feature_segmentation;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size > 4096)
    return 0;
  const fs_app::internal::File_content content(reinterpret_cast<const char*>(data), size);
  fs_app::Mesh_soup soup;
  Mesh mesh;
  fs_app::Input_correspondence<Mesh> correspondence;
  try
  {
    fs_app::read_mesh_soup("input.off", "off", content, soup);
    fs_app::mesh_from_soup("input.off", soup, mesh, correspondence);
  }
  catch(const fs_app::Input_error&)
  {
    return 0;
  }
  for(const double crease_angle : {180., 30.})
  {
    try
    {
      FS::Feature_aligned_segmentation<Mesh> segmentation(mesh, FS::parameters::crease_angle(crease_angle));
      segmentation.set_alpha(1.2);
      const std::size_t patches = segmentation.number_of_patches();
      if(patches == 0)
        __builtin_trap();
      for(const auto f : faces(mesh))
        if(segmentation.patch(f) >= patches)
          __builtin_trap();
    }
    catch(const FS::Invalid_input&)
    {
    }
  }
  return 0;
}
