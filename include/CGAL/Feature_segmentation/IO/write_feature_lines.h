// SPDX-License-Identifier: GPL-3.0-or-later
// Writers for feature lines: CGAL's polylines text format (what Mesh_3 and the
// Polyhedron demo read as feature edges) and OBJ line elements (what any mesh viewer
// shows over the mesh). Points are written at full double precision, so that a written
// file gives back the same points and two runs give identical files.

#ifndef CGAL_FEATURE_SEGMENTATION_IO_WRITE_FEATURE_LINES_H
#define CGAL_FEATURE_SEGMENTATION_IO_WRITE_FEATURE_LINES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Feature_segmentation/Feature_lines.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <ios>
#include <charconv>
#include <ostream>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The shortest text that reads back as exactly x (std::to_chars), a fraction of the
// time of a stream's 17 digits.
inline void write_double(std::ostream& os, double x)
{
  char text[32];
  const auto end = std::to_chars(text, text + sizeof(text), x).ptr;
  os.write(text, end - text);
}

template <typename Point>
void write_coordinates(std::ostream& os, const Point& p)
{
  write_double(os, CGAL::to_double(p.x()));
  os.put(' ');
  write_double(os, CGAL::to_double(p.y()));
  os.put(' ');
  write_double(os, CGAL::to_double(p.z()));
}

inline const char* feature_line_type_name(Feature_line_type type)
{
  switch(type)
  {
    case Feature_line_type::RIDGE: return "ridge";
    case Feature_line_type::VALLEY: return "valley";
    case Feature_line_type::SEAM: return "seam_line";
    default: return "user";
  }
}

// The two formats, on the points of `vpm`, at full precision.
template <typename TriangleMesh, typename VPM>
bool write_polylines(std::ostream& os, const TriangleMesh& tm, const Feature_lines<TriangleMesh>& lines, VPM vpm)
{
  for(const Feature_line<TriangleMesh>& line : lines.lines)
  {
    const bool repeat_first = line.is_closed && !line.points.empty();
    os << line.points.size() + (repeat_first ? 1 : 0);
    for(const Feature_point<TriangleMesh>& p : line.points)
    {
      os << ' ';
      write_coordinates(os, p.point(tm, vpm));
    }
    if(repeat_first)
    {
      os << ' ';
      write_coordinates(os, line.points.front().point(tm, vpm));
    }
    os << '\n';
  }
  return os.good();
}

template <typename TriangleMesh, typename VPM>
bool write_OBJ_lines(std::ostream& os, const TriangleMesh& tm, const Feature_lines<TriangleMesh>& lines, VPM vpm)
{
  os << "# feature lines: " << lines.lines.size() << '\n';
  std::size_t next_index = 1; // OBJ indices start at 1 and run over the whole file
  for(std::size_t i = 0; i < lines.lines.size(); ++i)
  {
    const Feature_line<TriangleMesh>& line = lines.lines[i];
    os << "o " << feature_line_type_name(line.type) << '_' << i << '\n';
    for(const Feature_point<TriangleMesh>& p : line.points)
    {
      os << "v ";
      write_coordinates(os, p.point(tm, vpm));
      os << '\n';
    }
    if(line.points.size() >= 2)
    {
      os << 'l';
      for(std::size_t k = 0; k < line.points.size(); ++k)
        os << ' ' << next_index + k;
      if(line.is_closed)
        os << ' ' << next_index;
      os << '\n';
    }
    next_index += line.points.size();
  }
  return os.good();
}

} // namespace internal

/// \ingroup PkgFeatureSegmentationIO
/// Writes `lines` in CGAL's polylines format: one line of text per feature line,
/// `n x1 y1 z1 ... xn yn zn`, a closed line repeating its first point at the end (so
/// `n` is one more than its number of points). Lines are written in the order of
/// `lines.lines`; coordinates at full double precision.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \param os the output stream
/// \param tm the mesh the feature points lie on
/// \param lines the feature lines
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
///                     must be available in `TriangleMesh`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return `true` if the stream is still good after writing
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_polylines(std::ostream& os, const TriangleMesh& tm, const Feature_lines<TriangleMesh>& lines,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::write_polylines(os, tm, lines, internal::vertex_point_map(tm, np));
}

/// \ingroup PkgFeatureSegmentationIO
/// Writes `lines` as an OBJ file of line elements: for each feature line, an object
/// `o <type>_<i>` (`ridge_0`, `valley_1`, `user_2`, `i` its index in `lines.lines`), a
/// `v` record per point and one `l` record joining them, a closed line repeating its
/// first vertex index at the end. Coordinates at full double precision.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \param os the output stream
/// \param tm the mesh the feature points lie on
/// \param lines the feature lines
/// \param np an optional sequence of \ref fs_api_np "named parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with
///                    `boost::graph_traits<TriangleMesh>::vertex_descriptor` as key type and `Point_3` as
///                    value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///     \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
///                     must be available in `TriangleMesh`.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return `true` if the stream is still good after writing
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
bool write_OBJ_lines(std::ostream& os, const TriangleMesh& tm, const Feature_lines<TriangleMesh>& lines,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::write_OBJ_lines(os, tm, lines, internal::vertex_point_map(tm, np));
}

} // namespace Feature_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_FEATURE_SEGMENTATION_IO_WRITE_FEATURE_LINES_H
