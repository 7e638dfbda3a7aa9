// SPDX-License-Identifier: GPL-3.0-or-later
// Writers for a segmentation: the mesh as an ASCII PLY file whose faces carry their patch
// id and a colour (what MeshLab, CloudCompare or CGAL's readers show and read back), and
// plain text with one patch id per line (what a script reads). Colours depend on the
// patch id only, so that two runs give identical files and a patch keeps its colour
// across files with the same numbering.

#ifndef CGAL_FEATURE_SEGMENTATION_IO_WRITE_SEGMENTATION_H
#define CGAL_FEATURE_SEGMENTATION_IO_WRITE_SEGMENTATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/IO/write_feature_lines.h>
#include <CGAL/Feature_segmentation/internal/ordered_text.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/range/adaptor/transformed.hpp>
#include <boost/range/value_type.hpp>

#include <cstddef>
#include <iterator>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {

/// \ingroup PkgFeatureSegmentationIO
/// Returns the colour of patch `id`: hues a golden angle apart (137 degrees, so that
/// consecutive ids differ strongly), with three levels of saturation and brightness
/// that change every 360 ids. Integer arithmetic only: the same id gives the same
/// colour on every platform. Neighbouring patches are not guaranteed distinct colours.
/// A negative id (no patch) is grey.
///
/// \tparam Integer an integer type
/// \param id the patch id
template <typename Integer>
CGAL::IO::Color segmentation_colour(Integer id)
{
  static_assert(std::is_integral<Integer>::value, "patch ids are integers");
  if constexpr(std::is_signed<Integer>::value)
  {
    if(id < 0)
      return CGAL::IO::Color(128, 128, 128);
  }
  const unsigned long long n = static_cast<unsigned long long>(id);
  const unsigned int hue = static_cast<unsigned int>((n * 137u) % 360u); // degrees
  static const unsigned int saturation[3] = {200, 140, 255};       // out of 255
  static const unsigned int value[3] = {235, 200, 165};            // out of 255
  const unsigned int level = static_cast<unsigned int>((n / 360u) % 3u);
  const unsigned int s = saturation[level], v = value[level];

  // HSV to RGB on integers: the hue's sector (60 degrees each) and its position in it.
  const unsigned int sector = hue / 60u, position = hue % 60u;
  const unsigned int p = v * (255u - s) / 255u;
  const unsigned int q = v * (255u * 60u - s * position) / (255u * 60u);
  const unsigned int t = v * (255u * 60u - s * (60u - position)) / (255u * 60u);
  unsigned int r = v, g = t, b = p;
  switch(sector)
  {
    case 0: r = v; g = t; b = p; break;
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    default: r = v; g = p; b = q; break;
  }
  return CGAL::IO::Color(static_cast<unsigned char>(r), static_cast<unsigned char>(g),
                         static_cast<unsigned char>(b));
}

namespace internal {

// The header of a segmentation's PLY file (see write_PLY_segmentation()).
inline void write_PLY_segmentation_header(std::ostream& os, std::size_t number_of_vertices,
                                          std::size_t number_of_faces)
{
  os << "ply\n"
     << "format ascii 1.0\n"
     << "comment feature-aligned segmentation: patch_id and colour per face\n"
     << "element vertex " << number_of_vertices << '\n'
     << "property double x\n"
     << "property double y\n"
     << "property double z\n"
     << "element face " << number_of_faces << '\n'
     << "property list uchar int vertex_indices\n"
     << "property int patch_id\n"
     << "property uchar red\n"
     << "property uchar green\n"
     << "property uchar blue\n"
     << "end_header\n";
}

// A face's line: its degree, its vertex indices, its patch id and colour, appended to
// `text`.
template <typename IndexRange, typename Id>
void append_PLY_segmentation_face(std::string& text, std::size_t degree, const IndexRange& vertex_indices, Id id)
{
  append_integer(text, static_cast<long long>(degree), ' ');
  for(const auto i : vertex_indices)
    append_integer(text, static_cast<long long>(i), ' ');
  const CGAL::IO::Color c = segmentation_colour(id);
  append_integer(text, static_cast<long long>(id), ' ');
  append_integer(text, c.red(), ' ');
  append_integer(text, c.green(), ' ');
  append_integer(text, c.blue(), '\n');
}

// A vertex's line: its coordinates.
inline void append_PLY_vertex(std::string& text, double x, double y, double z)
{
  append_double(text, x, ' ');
  append_double(text, y, ' ');
  append_double(text, z, '\n');
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationIO
/// Writes `tm` as an ASCII PLY file whose faces carry their patch: the vertices
/// (`x`, `y`, `z` as doubles at full precision) in the order of `vertices(tm)`, then the
/// faces in the order of `faces(tm)`, each with its vertex indices, an `int` property
/// `patch_id` and `uchar` properties `red`, `green`, `blue` given by
/// `segmentation_colour()` of its patch id. CGAL's `read_PLY()` and
/// `read_polygon_soup()` read the file back; viewers show the colours. With TBB
/// (`CGAL_LINKED_WITH_TBB`), the lines are formatted by TBB's threads in ordered chunks
/// (the file is the same byte for byte at any thread count; `face_patch_map` is read from
/// several threads, and the points too when their coordinates are doubles).
///
/// \tparam TriangleMesh a model of `FaceListGraph` (any face degree is written)
/// \tparam FacePatchMap a `ReadablePropertyMap` from `face_descriptor` to an integer type
///         (the `face_patch_map` output of `segment_along_features()`)
/// \param os the output stream
/// \param tm the mesh
/// \param face_patch_map the patch of every face
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t` must
///                     be available in `TriangleMesh`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return `true` if the stream is still good after writing
template <typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_PLY_segmentation(std::ostream& os, const TriangleMesh& tm,
                            FacePatchMap face_patch_map,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = internal::vertex_point_map(tm, np);
  // A face refers to its vertices by their position in `vertices(tm)`, whatever the
  // mesh's own indices (which a mesh with removed elements does not keep contiguous).
  auto vim = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t next_index = 0;
  for(vertex_descriptor v : vertices(tm))
    put(vim, v, next_index++);

  internal::write_PLY_segmentation_header(os, vertices(tm).size(), faces(tm).size());
  // The lines are made by TBB's threads (the same file at any thread count); the
  // points' lines only if their coordinates are doubles already (an exact kernel's
  // conversion may compute and store the exact value, which is not safe from several
  // threads at once).
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
  const std::vector<vertex_descriptor> vertex_list(vertices(tm).begin(), vertices(tm).end());
  internal::write_ordered_text(
    os, vertex_list.size(),
    [&](std::size_t i, std::string& text) {
      const auto& p = get(vpm, vertex_list[i]);
      internal::append_PLY_vertex(text, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    },
    std::is_floating_point<FT>::value);
  const std::vector<face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  internal::write_ordered_text(os, face_list.size(), [&](std::size_t i, std::string& text) {
    const face_descriptor f = face_list[i];
    internal::append_PLY_segmentation_face(
      text, CGAL::halfedges_around_face(halfedge(f, tm), tm).size(),
      boost::adaptors::transform(CGAL::vertices_around_face(halfedge(f, tm), tm),
                                 [&vim](vertex_descriptor v) { return get(vim, v); }),
      get(face_patch_map, f));
  });
  return os.good();
}

/// \ingroup PkgFeatureSegmentationIO
/// Writes one patch id per line: `get(patch_map, k)` for every `k` of `keys`, in order.
/// With `keys = faces(tm)` and the `face_patch_map` of `segment_along_features()` this
/// lists the patch of every face; with a range of indices and a map from index to id, the
/// patch of every element of a file. With TBB, the lines are formatted by TBB's threads
/// in ordered chunks (the same bytes at any thread count; `patch_map` is read from
/// several threads).
///
/// \tparam KeyRange a range of keys of `PatchMap`
/// \tparam PatchMap a `ReadablePropertyMap` whose value type is an integer type
/// \param os the output stream
/// \param keys the elements, in the order of the output lines
/// \param patch_map the patch of every element
/// \return `true` if the stream is still good after writing
template <typename KeyRange, typename PatchMap>
bool write_patch_ids(std::ostream& os, const KeyRange& keys, PatchMap patch_map)
{
  typedef typename boost::range_value<KeyRange>::type Key;
  const std::vector<Key> key_list(std::begin(keys), std::end(keys));
  internal::write_ordered_text(os, key_list.size(), [&](std::size_t i, std::string& text) {
    internal::append_integer(text, static_cast<long long>(get(patch_map, key_list[i])), '\n');
  });
  return os.good();
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_IO_WRITE_SEGMENTATION_H
