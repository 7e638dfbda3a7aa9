// SPDX-License-Identifier: GPL-3.0-or-later
// Reading and validation of the input mesh of the package's programs. A mesh file is
// read as a polygon soup with CGAL's readers (OFF, OBJ, PLY, STL), checked for what the
// pipeline cannot process (non-finite coordinates, degenerate or folded faces,
// non-manifold edges), repaired where a repair is harmless (duplicate points and faces,
// pinched vertices, inconsistent orientation, quads and polygons), and turned into a
// triangle mesh. Every failure is an `Input_error` whose message is one line naming the
// cause, so that a program prints it and exits instead of crashing further down; every
// repair is reported as a notice line. The repairs keep track of where each point and
// face of the file went, so that results on the mesh can be written in the file's order.

#ifndef CGAL_FEATURE_SEGMENTATION_DEMO_READ_INPUT_MESH_H
#define CGAL_FEATURE_SEGMENTATION_DEMO_READ_INPUT_MESH_H

#include <CGAL/Feature_segmentation/input_checks.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fs_demo {

/// Bad input: `what()` is one line, "<file>: <reason>".
class Input_error : public std::runtime_error
{
public:
  explicit Input_error(const std::string& what) : std::runtime_error(what) {}
};

/// What reading did to the file's content, for the summary and the notice lines.
struct Read_report
{
  std::string format;                        ///< "off", "obj", "ply" or "stl"
  std::size_t number_of_file_points = 0;     ///< points in the file
  std::size_t number_of_file_faces = 0;      ///< faces in the file
  std::size_t number_of_merged_points = 0;   ///< duplicate or unused points removed
  std::size_t number_of_removed_faces = 0;   ///< duplicate faces removed
  std::size_t number_of_duplicated_points = 0; ///< points split to make pinched vertices manifold
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

inline std::string lower_case_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  if(!ext.empty() && ext[0] == '.')
    ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// A file that does not exist, is not a regular file or cannot be opened gets its own
// message: CGAL's readers would only return `false`.
inline void check_readable_file(const std::string& path)
{
  namespace sfs = std::filesystem;
  std::error_code ec;
  const sfs::file_status st = sfs::status(path, ec);
  if(!sfs::exists(st))
    throw Input_error(path + ": no such file");
  if(sfs::is_directory(st))
    throw Input_error(path + ": is a directory, not a mesh file");
  if(!sfs::is_regular_file(st))
    throw Input_error(path + ": is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Input_error(path + ": cannot be opened for reading");
  if(in.peek() == std::ifstream::traits_type::eof())
    throw Input_error(path + ": the file is empty");
}

template <typename Point>
bool has_finite_coordinates(const Point& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

// `true` if all points of the polygon lie on one line (or coincide): such a face has no
// area and no normal, so every later stage would divide by zero on it.
template <typename Point, typename Polygon>
bool is_degenerate_polygon(const std::vector<Point>& points, const Polygon& polygon)
{
  const Point& p = points[polygon[0]];
  std::size_t j = 1;
  while(j < polygon.size() && points[polygon[j]] == p)
    ++j;
  if(j == polygon.size())
    return true;
  const Point& q = points[polygon[j]];
  for(std::size_t k = j + 1; k < polygon.size(); ++k)
    if(!CGAL::collinear(p, q, points[polygon[k]]))
      return false;
  return true;
}

// CGAL's text readers stop at "nan" or "inf" and only return `false`; this finds the
// token, so that the message names the real cause. Returns 0 if there is none.
inline std::size_t line_of_non_finite_token(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text;
  std::size_t line_number = 0;
  while(std::getline(in, text))
  {
    ++line_number;
    std::istringstream words(text);
    std::string word;
    while(words >> word)
    {
      std::transform(word.begin(), word.end(), word.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      if(!word.empty() && (word[0] == '-' || word[0] == '+'))
        word.erase(0, 1);
      if(word == "nan" || word == "inf" || word == "infinity" || word.rfind("nan(", 0) == 0)
        return line_number;
    }
  }
  return 0;
}

// CGAL's STL reader merges equal points through an ordered map, where a NaN compares
// equal to any point: a NaN vertex of a binary STL file would silently become another
// vertex. The coordinates of a binary file are therefore checked before reading.
// Returns the 1-based number of the first triangle with a non-finite vertex, else 0.
inline std::size_t binary_stl_non_finite_triangle(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char header[84];
  if(!in.read(header, 84))
    return 0;
  const auto le32 = [](const char* b) {
    return std::uint32_t(static_cast<unsigned char>(b[0])) |
           std::uint32_t(static_cast<unsigned char>(b[1])) << 8 |
           std::uint32_t(static_cast<unsigned char>(b[2])) << 16 |
           std::uint32_t(static_cast<unsigned char>(b[3])) << 24;
  };
  const std::uint64_t count = le32(header + 80);
  std::error_code ec;
  if(std::filesystem::file_size(path, ec) != 84 + 50 * count || ec)
    return 0; // not a binary STL file (an ASCII one is checked by its reader)
  char record[50];
  for(std::uint64_t t = 0; t < count && in.read(record, 50); ++t)
    for(int k = 3; k < 12; ++k) // 3 floats of normal, then 3 points
    {
      const std::uint32_t bits = le32(record + 4 * k);
      float x;
      std::memcpy(&x, &bits, sizeof(float));
      if(!std::isfinite(x))
        return static_cast<std::size_t>(t + 1);
    }
  return 0;
}

// CGAL's readers print some diagnostics of their own on std::cerr; the program's
// contract is one line per error, so they are silenced while a reader runs.
class Silence_standard_error
{
public:
  Silence_standard_error() : m_cerr(std::cerr.rdbuf(m_sink.rdbuf())), m_clog(std::clog.rdbuf(m_sink.rdbuf())) {}
  ~Silence_standard_error()
  {
    std::cerr.rdbuf(m_cerr);
    std::clog.rdbuf(m_clog);
  }
  Silence_standard_error(const Silence_standard_error&) = delete;
  Silence_standard_error& operator=(const Silence_standard_error&) = delete;

private:
  std::ostringstream m_sink;
  std::streambuf* m_cerr;
  std::streambuf* m_clog;
};

inline std::string face_name(std::size_t f) { return "face " + std::to_string(f); }

// Checks that come before any repair, on the soup exactly as in the file: what a repair
// would silently change (a degenerate face dropped by repair_polygon_soup) or cannot fix
// is an error here.
template <typename Point, typename Polygon>
void check_soup(const std::string& path, const std::vector<Point>& points,
                const std::vector<Polygon>& polygons)
{
  if(polygons.empty())
    throw Input_error(path + ": contains no faces");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!has_finite_coordinates(points[i]))
      throw Input_error(path + ": vertex " + std::to_string(i) +
                        " has a NaN or infinite coordinate");
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const Polygon& polygon = polygons[f];
    if(polygon.size() < 3)
      throw Input_error(path + ": " + face_name(f) + " has " + std::to_string(polygon.size()) +
                        " vertices (at least 3 are needed)");
    for(std::size_t id : polygon)
      if(id >= points.size())
        throw Input_error(path + ": " + face_name(f) + " refers to vertex " + std::to_string(id) +
                          " but the file has " + std::to_string(points.size()) + " vertices");
    std::vector<std::size_t> sorted(polygon.begin(), polygon.end());
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw Input_error(path + ": " + face_name(f) + " is degenerate (it uses a vertex twice)");
    if(is_degenerate_polygon(points, polygon))
      throw Input_error(path + ": " + face_name(f) +
                        " is degenerate (its points are collinear: zero area)");
  }
}

// Faces are vertex cycles; an edge is an unordered pair of point indices. Points with the
// same coordinates must be merged first (repair_polygon_soup) so that equal points share
// one index.
template <typename Polygon>
std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t> >
soup_edge_faces(const std::vector<Polygon>& polygons)
{
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t> > edge_faces;
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const Polygon& polygon = polygons[f];
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      std::size_t a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      edge_faces[std::make_pair((std::min)(a, b), (std::max)(a, b))].push_back(f);
    }
  }
  return edge_faces;
}

// The vertex of `polygon` that follows the edge {a, b} in the triangle fan of the
// polygon containing that edge; for a triangle, its third vertex.
template <typename Polygon>
std::size_t opposite_vertex(const Polygon& polygon, std::size_t a, std::size_t b)
{
  const std::size_t n = polygon.size();
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t u = polygon[i], v = polygon[(i + 1) % n];
    if((u == a && v == b) || (u == b && v == a))
      return polygon[(i + 2) % n];
  }
  return polygon[0];
}

// An edge shared by three faces or more cannot be made manifold without tearing the
// surface apart, and two faces folded onto each other across an edge (coplanar, on the
// same side of it) overlap: both are errors.
template <typename Point, typename Polygon>
void check_edges(const std::string& path, const std::vector<Point>& points,
                 const std::vector<Polygon>& polygons)
{
  const auto edge_faces = soup_edge_faces(polygons);
  for(const auto& ef : edge_faces)
  {
    const std::size_t a = ef.first.first, b = ef.first.second;
    const std::vector<std::size_t>& faces = ef.second;
    if(faces.size() > 2)
      throw Input_error(path + ": the edge between vertices " + std::to_string(a) + " and " +
                        std::to_string(b) + " is shared by " + std::to_string(faces.size()) +
                        " faces (non-manifold edge)");
    if(faces.size() == 2)
    {
      const Point& p = points[a];
      const Point& q = points[b];
      const Point& r = points[opposite_vertex(polygons[faces[0]], a, b)];
      const Point& s = points[opposite_vertex(polygons[faces[1]], a, b)];
      if(CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE)
        throw Input_error(path + ": " + face_name(faces[0]) + " and " + face_name(faces[1]) +
                          " overlap (folded onto each other across an edge)");
    }
  }
}

constexpr std::size_t no_index = std::size_t(-1);

// A face as a key that is the same for every starting vertex and both orientations, as
// CGAL's merge_duplicate_polygons_in_polygon_soup compares faces by default.
template <typename Polygon>
std::vector<std::size_t> canonical_face(const Polygon& polygon)
{
  const std::size_t n = polygon.size();
  const std::size_t first = static_cast<std::size_t>(
    std::min_element(polygon.begin(), polygon.end()) - polygon.begin());
  std::vector<std::size_t> forward(n), backward(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    forward[k] = polygon[(first + k) % n];
    backward[k] = polygon[(first + n - k) % n];
  }
  return (std::min)(forward, backward);
}

// What CGAL's repair_polygon_soup does to a soup that passed check_soup, with the
// correspondence it does not give: points at the same position become the first of them,
// a face listing one position twice in a row keeps it once, a face equal to an earlier
// one (up to its start and orientation) is removed in favour of that one, and points no
// face uses are removed. The kept points and faces keep their file order.
// `point_of_file_point[i]` is the new index of file point i (`no_index` if unused),
// `polygon_of_file_face[f]` the new index of file face f.
template <typename Point, typename Polygon>
void merge_duplicates(const std::string& path, std::vector<Point>& points,
                      std::vector<Polygon>& polygons,
                      std::vector<std::size_t>& point_of_file_point,
                      std::vector<std::size_t>& polygon_of_file_face)
{
  // Coordinates are finite here (check_soup), so the lexicographic order is a strict order.
  std::vector<std::size_t> first_at_position(points.size());
  {
    std::map<Point, std::size_t> first;
    for(std::size_t i = 0; i < points.size(); ++i)
      first_at_position[i] = first.emplace(points[i], i).first->second;
  }

  std::vector<Polygon> kept;
  polygon_of_file_face.assign(polygons.size(), no_index);
  std::map<std::vector<std::size_t>, std::size_t> face_of_key;
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    Polygon merged;
    for(std::size_t i : polygons[f])
    {
      const std::size_t j = first_at_position[i];
      if(merged.empty() || merged.back() != j)
        merged.push_back(j);
    }
    if(merged.size() > 1 && merged.back() == merged.front())
      merged.pop_back();
    std::vector<std::size_t> sorted(merged.begin(), merged.end());
    std::sort(sorted.begin(), sorted.end());
    if(merged.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw Input_error(path + ": " + face_name(f) +
                        " is degenerate (two of its vertices are at the same position)");
    const auto inserted = face_of_key.emplace(canonical_face(merged), kept.size());
    polygon_of_file_face[f] = inserted.first->second;
    if(inserted.second)
      kept.push_back(std::move(merged));
  }

  std::vector<std::size_t> new_index(points.size(), no_index);
  for(const Polygon& polygon : kept)
    for(std::size_t i : polygon)
      new_index[i] = 0; // used; numbered below in file order
  std::vector<Point> used_points;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(new_index[i] != no_index)
    {
      new_index[i] = used_points.size();
      used_points.push_back(points[i]);
    }
  for(Polygon& polygon : kept)
    for(std::size_t& i : polygon)
      i = new_index[i];
  point_of_file_point.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    point_of_file_point[i] = new_index[first_at_position[i]];

  points.swap(used_points);
  polygons.swap(kept);
}

// A triangulation visitor that records the triangles made from a face, in the order of
// their creation.
template <typename Mesh>
class Subface_visitor
{
public:
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;

  explicit Subface_visitor(std::vector<face_descriptor>& subfaces) : m_subfaces(&subfaces) {}

  void before_subface_creations(face_descriptor) { m_subfaces->clear(); }
  void after_subface_created(face_descriptor f) { m_subfaces->push_back(f); }
  void after_subface_creations() {}

private:
  std::vector<face_descriptor>* m_subfaces; // the visitor is copied: the result lives with the caller
};

} // namespace internal

/// Reads `path` into `mesh` (which is cleared first) and returns what was repaired;
/// `correspondence` receives where each point and face of the file went.
/// Throws `Input_error` when the file cannot be read or the mesh cannot be processed.
template <typename Mesh>
Read_report read_input_mesh(const std::string& path, Mesh& mesh,
                            Input_correspondence<Mesh>& correspondence)
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef std::vector<std::size_t> Polygon;
  namespace PMP = CGAL::Polygon_mesh_processing;

  Read_report report;
  internal::check_readable_file(path);
  report.format = internal::lower_case_extension(path);
  if(report.format != "off" && report.format != "obj" && report.format != "ply" &&
     report.format != "stl")
    throw Input_error(path + ": unknown format " +
                      (report.format.empty() ? std::string("(no extension)")
                                             : "'." + report.format + "'") +
                      " (expected .off, .obj, .ply or .stl)");

  if(report.format == "stl")
    if(const std::size_t t = internal::binary_stl_non_finite_triangle(path))
      throw Input_error(path + ": triangle " + std::to_string(t) +
                        " has a NaN or infinite coordinate");

  std::vector<Point> points;
  std::vector<Polygon> polygons;
  bool ok = false;
  try
  {
    internal::Silence_standard_error silence;
    ok = CGAL::IO::read_polygon_soup(path, points, polygons);
  }
  catch(const std::bad_alloc&)
  {
    throw Input_error(path + ": cannot be read as " + report.format +
                      " (out of memory: are the element counts of the header right?)");
  }
  catch(const std::exception& e)
  {
    throw Input_error(path + ": cannot be read as " + report.format + " (" + e.what() + ")");
  }
  if(!ok)
  {
    if(const std::size_t line = internal::line_of_non_finite_token(path))
      throw Input_error(path + ": line " + std::to_string(line) +
                        " has a NaN or infinite coordinate");
    throw Input_error(path + ": cannot be read as " + report.format +
                      " (malformed or truncated file)");
  }
  report.number_of_file_points = points.size();
  report.number_of_file_faces = polygons.size();

  internal::check_soup(path, points, polygons);

  // Merges points with equal coordinates, removes duplicate faces and unused points,
  // recording where each point and face of the file goes. Degenerate faces were
  // rejected above.
  std::vector<std::size_t> point_of_file_point, polygon_of_file_face;
  internal::merge_duplicates(path, points, polygons, point_of_file_point, polygon_of_file_face);
  if(points.size() < report.number_of_file_points)
  {
    report.number_of_merged_points = report.number_of_file_points - points.size();
    report.notices.push_back("removed " + std::to_string(report.number_of_merged_points) +
                             " duplicate or unused vertices");
  }
  if(polygons.size() < report.number_of_file_faces)
  {
    report.number_of_removed_faces = report.number_of_file_faces - polygons.size();
    report.notices.push_back("removed " + std::to_string(report.number_of_removed_faces) +
                             " duplicate faces");
  }

  internal::check_edges(path, points, polygons);

  const std::size_t number_of_points = points.size();
  if(!PMP::orient_polygon_soup(points, polygons) || points.size() != number_of_points)
  {
    report.number_of_duplicated_points = points.size() - number_of_points;
    report.notices.push_back("duplicated " + std::to_string(report.number_of_duplicated_points) +
                             " non-manifold or non-orientable vertices");
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error(path + ": the faces do not form a manifold surface, even after repair");

  // Built here rather than by polygon_soup_to_polygon_mesh, which does not say which
  // face a polygon became. Point i becomes the i-th vertex, polygon p the p-th face.
  // orient_polygon_soup appends the copies of split points: the originals stay first.
  mesh.clear();
  std::vector<vertex_descriptor> vertex_of_point(points.size());
  auto vpm = get(CGAL::vertex_point, mesh);
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    vertex_of_point[i] = add_vertex(mesh);
    put(vpm, vertex_of_point[i], points[i]);
  }
  std::vector<face_descriptor> face_of_polygon(polygons.size());
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

  // One face at a time, so that each polygon's first triangle is known.
  std::vector<std::size_t> file_face_of_polygon(polygons.size(), internal::no_index);
  for(std::size_t f = polygon_of_file_face.size(); f-- > 0;)
    file_face_of_polygon[polygon_of_file_face[f]] = f; // the first file face wins
  std::vector<std::size_t> polygon_begin(polygons.size() + 1, 0);
  std::vector<face_descriptor> subfaces;
  correspondence.triangles.clear();
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    polygon_begin[p] = correspondence.triangles.size();
    if(polygons[p].size() == 3)
    {
      correspondence.triangles.push_back(face_of_polygon[p]);
      continue;
    }
    ++report.number_of_triangulated_faces;
    subfaces.clear();
    if(!PMP::triangulate_face(face_of_polygon[p], mesh,
                              CGAL::parameters::visitor(internal::Subface_visitor<Mesh>(subfaces))) ||
       subfaces.empty())
      throw Input_error(path + ": " + internal::face_name(file_face_of_polygon[p]) +
                        " (a quad or polygon) cannot be triangulated");
    face_of_polygon[p] = subfaces.front();
    correspondence.triangles.insert(correspondence.triangles.end(), subfaces.begin(), subfaces.end());
  }
  polygon_begin[polygons.size()] = correspondence.triangles.size();
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

/// Reads `path` into `mesh`, without the correspondence to the file.
template <typename Mesh>
Read_report read_input_mesh(const std::string& path, Mesh& mesh)
{
  Input_correspondence<Mesh> correspondence;
  return read_input_mesh(path, mesh, correspondence);
}

} // namespace fs_demo

#endif // CGAL_FEATURE_SEGMENTATION_DEMO_READ_INPUT_MESH_H
