// SPDX-License-Identifier: GPL-3.0-or-later
// Reading and validation of the input mesh of the package's programs. A mesh file is
// read as a polygon soup by the readers of `mesh_io/` (OFF, OBJ, PLY, STL), checked for what the
// pipeline cannot process (non-finite coordinates, degenerate or folded faces),
// repaired where a repair is harmless (duplicate points and faces, pinched vertices,
// edges of more than two faces, inconsistent orientation, quads and polygons), and turned into a
// triangle mesh. Every failure is an `Input_error` whose message is one line naming the
// cause, so that a program prints it and exits instead of crashing further down; every
// repair is reported as a notice line. The repairs keep track of where each point and
// face of the file went, so that results on the mesh can be written in the file's order.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_READ_INPUT_MESH_H
#define CGAL_FEATURE_SEGMENTATION_APP_READ_INPUT_MESH_H

#include "mesh_io/read_mesh_soup.h"
#include "mesh_io/soup_topology.h"
#include "mesh_io/triangulate_polygon.h"

#include <CGAL/Feature_segmentation/input_checks.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace fs_app {

/// What reading did to the file's content, for the summary and the notice lines.
struct Read_report
{
  std::string format;                        ///< "off", "obj", "ply" or "stl"
  std::size_t number_of_file_points = 0;     ///< points in the file
  std::size_t number_of_file_faces = 0;      ///< faces in the file
  std::size_t number_of_merged_points = 0;   ///< duplicate or unused points removed
  std::size_t number_of_removed_faces = 0;   ///< duplicate faces removed
  std::size_t number_of_duplicated_points = 0; ///< points split to make pinched vertices manifold
  std::size_t number_of_non_manifold_edges = 0; ///< edges of more than two faces, whose faces were separated
  std::size_t number_of_triangulated_faces = 0; ///< quads and polygons split into triangles
  std::size_t number_of_border_edges = 0;    ///< border edges of the final mesh
  std::vector<std::string> notices;          ///< one line per repair, without prefix
};

/// Where the points and faces of the file went. For STL, which stores no shared
/// vertices, the file's points are the distinct points in order of first appearance (as
/// CGAL's reader numbers them).
template <typename Mesh>
struct Input_correspondence
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;

  /// For each point of the file, in file order: its mesh vertex; for a duplicate point,
  /// the vertex of the first point at the same position; for a pinched vertex that was
  /// split, the copy in the first face (in file order) that uses it (orient_polygon_soup
  /// keeps the point's index for the faces around its first incident face);
  /// `null_vertex()` for a point that no face uses.
  std::vector<vertex_descriptor> vertex_of_file_point;
  /// For each face of the file, in file order: its mesh face, the first triangle of a
  /// triangulated polygon; for a duplicate face, the face of its first occurrence.
  std::vector<face_descriptor> face_of_file_face;
  /// Every mesh face that a face of the file became (one triangle, or the triangles of a
  /// triangulated polygon): for face `f` of the file, `number_of_triangles[f]` faces of
  /// `triangles` from `triangles_begin[f]` on. A duplicate face has its first
  /// occurrence's. Read through `mesh_faces_of_file_face()`.
  std::vector<face_descriptor> triangles;
  std::vector<std::size_t> triangles_begin;     ///< see `triangles`
  std::vector<std::size_t> number_of_triangles; ///< see `triangles`

  /// Appends to `out` every mesh face that face `f` of the file became.
  void mesh_faces_of_file_face(std::size_t f, std::vector<face_descriptor>& out) const
  {
    out.insert(out.end(), triangles.begin() + static_cast<std::ptrdiff_t>(triangles_begin[f]),
               triangles.begin() + static_cast<std::ptrdiff_t>(triangles_begin[f] + number_of_triangles[f]));
  }
};

namespace internal {

// A file that does not exist, is not a regular file or cannot be opened gets its own
// message (used by the readers of the programs' other input files).
inline void check_readable_file(const std::string& path)
{
  check_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Input_error(path + ": cannot be opened for reading");
  if(in.peek() == std::ifstream::traits_type::eof())
    throw Input_error(path + ": the file is empty");
}

// `true` if all points of the polygon lie on one line (or coincide): such a face has no
// area and no normal, so every later stage would divide by zero on it.
template <typename Point>
bool is_degenerate_polygon(const std::vector<Point>& points, const std::uint32_t* polygon,
                           std::size_t n)
{
  const Point& p = points[polygon[0]];
  std::size_t j = 1;
  while(j < n && points[polygon[j]] == p)
    ++j;
  if(j == n)
    return true;
  const Point& q = points[polygon[j]];
  for(std::size_t k = j + 1; k < n; ++k)
    if(!CGAL::collinear(p, q, points[polygon[k]]))
      return false;
  return true;
}

// Checks that come before any repair, on the soup exactly as in the file: what a repair
// would silently change (a degenerate face dropped) is an error here.
template <typename Point>
void check_faces(const std::string& path, const Mesh_soup& soup, const std::vector<Point>& points)
{
  std::vector<std::uint32_t> sorted;
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
  {
    const std::uint32_t* face = soup.face(f);
    const std::size_t n = soup.face_size(f);
    sorted.assign(face, face + n);
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw Input_error(path + ": " + face_name(soup, f) + " is degenerate (it uses a vertex twice)");
    if(is_degenerate_polygon(points, face, n))
      throw Input_error(path + ": " + face_name(soup, f) +
                        " is degenerate (its points are collinear: zero area)");
  }
}

constexpr std::size_t no_index = std::size_t(-1);

// What CGAL's repair_polygon_soup does to a soup that passed check_faces, with the
// correspondence it does not give: points at the same position become the first of them,
// a face listing one position twice in a row keeps it once, a face equal to an earlier
// one (up to its start and orientation) is removed in favour of that one, and points no
// face uses are removed. The kept points and faces keep their file order; the soup is
// changed in place. `point_of_file_point[i]` is the new index of file point i
// (`no_index` if unused), `polygon_of_file_face[f]` the new index of file face f.
// Returns the vertex-to-corner table of the result.
template <typename Point>
Vertex_corners merge_duplicates(const std::string& path, Mesh_soup& soup, std::vector<Point>& points,
                                std::vector<std::size_t>& point_of_file_point,
                                std::vector<std::size_t>& polygon_of_file_face)
{
  const std::vector<std::uint32_t> first = first_at_position(soup);
  soup.points = std::vector<std::array<double, 3> >(); // `points` has them
  const std::size_t number_of_file_faces = soup.number_of_faces();
  std::uint32_t out = 0, start = 0;
  std::vector<std::uint32_t> sorted;
  for(std::size_t f = 0; f < number_of_file_faces; ++f)
  {
    const std::uint32_t face_start = out;
    for(std::uint32_t c = start; c < soup.begin[f + 1]; ++c)
    {
      const std::uint32_t j = first[soup.indices[c]];
      if(out == face_start || soup.indices[out - 1] != j)
        soup.indices[out++] = j;
    }
    if(out - face_start > 1 && soup.indices[out - 1] == soup.indices[face_start])
      --out;
    sorted.assign(soup.indices.begin() + face_start, soup.indices.begin() + out);
    std::sort(sorted.begin(), sorted.end());
    const bool repeated =
      sorted.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    if(repeated)
      throw Input_error(path + ": " + face_name(soup, f) +
                        " is degenerate (two of its vertices are at the same position)");
    start = soup.begin[f + 1];
    soup.begin[f + 1] = out;
  }
  soup.indices.resize(out);

  Vertex_corners corners(soup, points.size());
  const std::vector<std::uint32_t> first_face = first_equal_face(soup, corners);
  polygon_of_file_face.assign(number_of_file_faces, no_index);
  std::vector<std::uint32_t> new_index(points.size(), no_corner);
  out = 0;
  std::size_t kept = 0;
  for(std::size_t f = 0; f < number_of_file_faces; ++f)
  {
    if(first_face[f] != f)
    {
      polygon_of_file_face[f] = polygon_of_file_face[first_face[f]];
      continue;
    }
    polygon_of_file_face[f] = kept;
    const std::uint32_t face_start = out;
    for(std::uint32_t c = soup.begin[f]; c < soup.begin[f + 1]; ++c)
    {
      new_index[soup.indices[c]] = 0; // used; numbered below in file order
      soup.indices[out++] = soup.indices[c];
    }
    soup.begin[kept] = face_start;
    if(f < soup.face_line.size())
      soup.face_line[kept] = soup.face_line[f];
    ++kept;
  }
  soup.begin[kept] = out;
  soup.begin.resize(kept + 1);
  soup.indices.resize(out);
  if(!soup.face_line.empty())
    soup.face_line.resize(kept);

  std::uint32_t used = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(new_index[i] != no_corner)
    {
      new_index[i] = used;
      points[used++] = points[i];
    }
  const bool unchanged = kept == number_of_file_faces && used == points.size();
  points.resize(used);
  for(std::uint32_t& i : soup.indices)
    i = new_index[i];
  point_of_file_point.resize(first.size());
  for(std::size_t i = 0; i < first.size(); ++i)
    point_of_file_point[i] = new_index[first[i]] == no_corner ? no_index : new_index[first[i]];
  if(unchanged) // the usual case: the table is still right
    return corners;
  return Vertex_corners(soup, points.size());
}

// The slow path, for a soup whose faces must be reoriented, whose vertices must be split
// or whose edges have more than two faces: CGAL's orient_polygon_soup (which cuts the
// soup along an edge of more than two faces), then Euler::add_face one face at a time. Point i
// becomes the i-th vertex and polygon p the p-th face; orient_polygon_soup appends the
// copies of split points, so the originals stay first. Returns the number of points
// that were duplicated.
template <typename Mesh, typename Point>
std::size_t orient_and_build(const std::string& path, const Mesh_soup& soup,
                             std::vector<Point>& points, Mesh& mesh,
                             std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& vertex_of_point,
                             std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& face_of_polygon)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<std::vector<std::size_t> > polygons(soup.number_of_faces());
  for(std::size_t f = 0; f < polygons.size(); ++f)
    polygons[f].assign(soup.face(f), soup.face(f) + soup.face_size(f));
  const std::size_t number_of_points = points.size();
  PMP::orient_polygon_soup(points, polygons);
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error(path + ": the faces do not form a manifold surface, even after repair");
  mesh.clear();
  vertex_of_point.resize(points.size());
  auto vpm = get(CGAL::vertex_point, mesh);
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    vertex_of_point[i] = add_vertex(mesh);
    put(vpm, vertex_of_point[i], points[i]);
  }
  face_of_polygon.resize(polygons.size());
  std::vector<vertex_descriptor> face_vertices;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    face_vertices.clear();
    for(std::size_t i : polygons[p])
      face_vertices.push_back(vertex_of_point[i]);
    face_of_polygon[p] = CGAL::Euler::add_face(face_vertices, mesh);
    if(face_of_polygon[p] == boost::graph_traits<Mesh>::null_face())
      throw Input_error(path + ": the faces do not form a manifold surface, even after repair");
  }
  return points.size() - number_of_points;
}

// `true` if no two vertices of the triangles `subfaces` are joined by two edges. CGAL's
// triangulate_face can add, in a non-planar or self-overlapping polygon, a diagonal
// between two vertices that an edge outside the polygon already joins, and reports
// success: the mesh is then not a surface any more.
template <typename Mesh>
bool has_simple_edges(const std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& subfaces,
                      const Mesh& mesh)
{
  const std::size_t bound = num_halfedges(mesh); // a broken mesh must not loop forever
  for(const auto f : subfaces)
    for(const auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      std::size_t joining = 0, steps = 0;
      auto g = h;
      do
      {
        if(target(g, mesh) == target(h, mesh) && ++joining > 1)
          return false;
        g = next(opposite(g, mesh), mesh); // the next halfedge leaving source(h)
        if(++steps > bound)
          return false;
      } while(g != h);
    }
  return true;
}

} // namespace internal

/// Turns the polygon soup of the file `path` (as a reader gave it) into `mesh` (which
/// is cleared first) and returns what was repaired; `correspondence` receives where each
/// point and face of the file went. `path` only names the file in messages.
/// Throws `Input_error` when the soup cannot be made a mesh the pipeline can process.
template <typename Mesh>
Read_report mesh_from_soup(const std::string& path, Mesh_soup& soup, Mesh& mesh,
                           Input_correspondence<Mesh>& correspondence)
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;

  Read_report report;
  report.format = soup.format;
  report.number_of_file_points = soup.points.size();
  report.number_of_file_faces = soup.number_of_faces();

  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const std::array<double, 3>& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  internal::check_faces(path, soup, points);

  // Merges points with equal coordinates, removes duplicate faces and unused points,
  // recording where each point and face of the file goes. Degenerate faces were
  // rejected above.
  std::vector<std::size_t> point_of_file_point, polygon_of_file_face;
  const internal::Vertex_corners corners =
    internal::merge_duplicates(path, soup, points, point_of_file_point, polygon_of_file_face);
  if(points.size() < report.number_of_file_points)
  {
    report.number_of_merged_points = report.number_of_file_points - points.size();
    report.notices.push_back("removed " + std::to_string(report.number_of_merged_points) +
                             " duplicate or unused vertices");
  }
  if(soup.number_of_faces() < report.number_of_file_faces)
  {
    report.number_of_removed_faces = report.number_of_file_faces - soup.number_of_faces();
    report.notices.push_back("removed " + std::to_string(report.number_of_removed_faces) +
                             " duplicate faces");
  }

  // Point i becomes the i-th vertex, polygon p the p-th face, so that the file's order
  // is kept. A consistently oriented soup with one fan per vertex is built directly;
  // anything else goes through CGAL's reorientation, which may split vertices.
  std::vector<vertex_descriptor> vertex_of_point;
  std::vector<face_descriptor> face_of_polygon;
  const internal::Soup_topology topology = internal::analyse_edges(path, soup, points, corners);
  if(topology.is_consistently_oriented && topology.has_manifold_vertices)
    internal::build_mesh(soup, points, topology, mesh, vertex_of_point, face_of_polygon);
  else
  {
    report.number_of_duplicated_points =
      internal::orient_and_build(path, soup, points, mesh, vertex_of_point, face_of_polygon);
    report.number_of_non_manifold_edges = topology.number_of_non_manifold_edges;
    if(topology.number_of_non_manifold_edges > 0)
      report.notices.push_back("separated the faces of " + std::to_string(topology.number_of_non_manifold_edges) +
                               " non-manifold edges (shared by more than two faces), duplicating " +
                               std::to_string(report.number_of_duplicated_points) + " vertices");
    else if(report.number_of_duplicated_points > 0)
      report.notices.push_back("duplicated " + std::to_string(report.number_of_duplicated_points) +
                               " non-manifold or non-orientable vertices");
    else
      report.notices.push_back("reoriented faces that disagreed with their neighbours");
  }
  const std::size_t number_of_polygons = face_of_polygon.size();

  // One face at a time, so that each polygon's first triangle is known.
  std::vector<std::size_t> file_face_of_polygon(number_of_polygons, internal::no_index);
  for(std::size_t f = polygon_of_file_face.size(); f-- > 0;)
    file_face_of_polygon[polygon_of_file_face[f]] = f; // the first file face wins
  std::vector<std::size_t> polygon_begin(number_of_polygons + 1, 0);
  std::vector<face_descriptor> subfaces;
  correspondence.triangles.clear();
  for(std::size_t p = 0; p < number_of_polygons; ++p)
  {
    polygon_begin[p] = correspondence.triangles.size();
    if(soup.face_size(p) == 3)
    {
      correspondence.triangles.push_back(face_of_polygon[p]);
      continue;
    }
    ++report.number_of_triangulated_faces;
    subfaces.clear();
    const std::string name = path + ": face " + std::to_string(file_face_of_polygon[p]) +
                             " (a polygon of " + std::to_string(soup.face_size(p)) + " vertices)";
    if(soup.face_size(p) > internal::max_polygon_size)
      throw Input_error(name + " has more than " + std::to_string(internal::max_polygon_size) +
                        " vertices: it is not triangulated");
    if(!internal::triangulate_polygon(face_of_polygon[p], mesh, subfaces) || subfaces.empty())
      throw Input_error(name + " cannot be triangulated: it is not a simple polygon in its plane");
    if(!internal::has_simple_edges(subfaces, mesh))
      throw Input_error(name + " cannot be triangulated: a diagonal would join two vertices"
                        " that an edge outside it already joins");
    face_of_polygon[p] = subfaces.front();
    correspondence.triangles.insert(correspondence.triangles.end(), subfaces.begin(), subfaces.end());
  }
  polygon_begin[number_of_polygons] = correspondence.triangles.size();
  // A last guard: later stages walk around vertices and would not stop on a broken mesh.
  if(report.number_of_triangulated_faces > 0 && !CGAL::is_valid_polygon_mesh(mesh))
    throw Input_error(path + ": the quads or polygons of the file cannot be triangulated into a"
                      " surface (non-planar or self-overlapping polygons)");
  if(report.number_of_triangulated_faces > 0)
    report.notices.push_back("triangulated " + std::to_string(report.number_of_triangulated_faces) +
                             " faces (quads or polygons)");

  correspondence.vertex_of_file_point.assign(point_of_file_point.size(),
                                             boost::graph_traits<Mesh>::null_vertex());
  for(std::size_t i = 0; i < point_of_file_point.size(); ++i)
    if(point_of_file_point[i] != internal::no_index)
      correspondence.vertex_of_file_point[i] = vertex_of_point[point_of_file_point[i]];
  correspondence.face_of_file_face.resize(polygon_of_file_face.size());
  correspondence.triangles_begin.resize(polygon_of_file_face.size());
  correspondence.number_of_triangles.resize(polygon_of_file_face.size());
  for(std::size_t f = 0; f < polygon_of_file_face.size(); ++f)
  {
    const std::size_t p = polygon_of_file_face[f];
    correspondence.face_of_file_face[f] = face_of_polygon[p];
    correspondence.triangles_begin[f] = polygon_begin[p];
    correspondence.number_of_triangles[f] = polygon_begin[p + 1] - polygon_begin[p];
  }

  try
  {
    const CGAL::Feature_segmentation::Mesh_check_report checks =
      CGAL::Feature_segmentation::check_input_mesh(mesh, /*allow_degenerate_faces=*/false);
    report.number_of_border_edges = checks.number_of_border_edges;
  }
  catch(const CGAL::Feature_segmentation::Invalid_input& e)
  {
    throw Input_error(path + ": " + e.what());
  }
  return report;
}

/// Reads `path` into `mesh` (which is cleared first) and returns what was repaired;
/// `correspondence` receives where each point and face of the file went.
/// Throws `Input_error` when the file cannot be read or the mesh cannot be processed.
template <typename Mesh>
Read_report read_input_mesh(const std::string& path, Mesh& mesh,
                            Input_correspondence<Mesh>& correspondence)
{
  Mesh_soup soup;
  read_mesh_soup(path, soup);
  return mesh_from_soup(path, soup, mesh, correspondence);
}

/// Reads `path` into `mesh`, without the correspondence to the file.
template <typename Mesh>
Read_report read_input_mesh(const std::string& path, Mesh& mesh)
{
  Input_correspondence<Mesh> correspondence;
  return read_input_mesh(path, mesh, correspondence);
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_READ_INPUT_MESH_H
