// SPDX-License-Identifier: GPL-3.0-or-later
// Ground truth of CAD models in the format of the ABC dataset as NH-Rep distributes it:
// NAME.obj, a triangle mesh, beside NAME.yml, whose surfaces[i].face_indices list the
// faces of patch i (faces numbered in the OBJ's order) and whose curves[j].vert_indices
// chain mesh vertices along feature curve j, curves[j].sharp telling a crease from a
// smooth junction. The mesh is built face by face in the file's order, so that face i of
// the mesh is face i of the file (a general reader may reorder or repair).

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_ABC_GROUND_TRUTH_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_ABC_GROUND_TRUTH_H

#include "yaml_reader.h"

#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs_evaluation {

/// The ground truth of one model.
struct Abc_ground_truth
{
  std::vector<int> face_patch;                     ///< per face of the OBJ, -1 if in no surface
  std::vector<std::string> patch_type;             ///< per patch: Plane, Cone, Cylinder, BSpline, ...
  std::vector<std::vector<std::size_t> > curves;   ///< vertex chains of the feature curves
  std::vector<bool> curve_is_sharp;                ///< per curve
  std::size_t number_of_patches() const { return patch_type.size(); }
};

inline std::size_t yaml_index(const Yaml_node& n, std::size_t bound, const char* what)
{
  char* end = nullptr;
  const long long v = std::strtoll(n.scalar.c_str(), &end, 10);
  if(n.kind != Yaml_node::SCALAR || end == n.scalar.c_str() || *end != '\0' || v < 0 ||
     static_cast<unsigned long long>(v) >= bound)
    throw std::runtime_error(std::string("bad ") + what + " index '" + n.scalar + "'");
  return static_cast<std::size_t>(v);
}

/// Reads the YAML annotations for a mesh of `number_of_vertices` vertices and
/// `number_of_faces` faces. Throws `std::runtime_error` (or `Yaml_error`) with a reason.
inline Abc_ground_truth read_abc_ground_truth(const std::string& yml, std::size_t number_of_vertices,
                                              std::size_t number_of_faces)
{
  const Yaml_node root = read_yaml_file(yml);
  const Yaml_node* surfaces = root.find("surfaces");
  if(surfaces == nullptr || surfaces->kind != Yaml_node::SEQUENCE)
    throw std::runtime_error(yml + ": no 'surfaces' sequence");
  Abc_ground_truth gt;
  gt.face_patch.assign(number_of_faces, -1);
  for(const Yaml_node& s : surfaces->items)
  {
    const Yaml_node* fi = s.find("face_indices");
    if(fi == nullptr || fi->kind != Yaml_node::SEQUENCE)
      throw std::runtime_error(yml + ": a surface without 'face_indices'");
    const Yaml_node* type = s.find("type");
    const int id = static_cast<int>(gt.patch_type.size());
    gt.patch_type.push_back(type ? type->scalar : std::string("?"));
    for(const Yaml_node& f : fi->items)
    {
      const std::size_t k = yaml_index(f, number_of_faces, "face");
      if(gt.face_patch[k] != -1)
        throw std::runtime_error(yml + ": face " + std::to_string(k) + " in two surfaces");
      gt.face_patch[k] = id;
    }
  }
  if(const Yaml_node* curves = root.find("curves"))
    for(const Yaml_node& c : curves->items)
    {
      const Yaml_node* vi = c.find("vert_indices");
      if(vi == nullptr) continue;
      std::vector<std::size_t> chain;
      for(const Yaml_node& v : vi->items) chain.push_back(yaml_index(v, number_of_vertices, "vertex"));
      const Yaml_node* sharp = c.find("sharp");
      gt.curves.push_back(chain);
      gt.curve_is_sharp.push_back(sharp != nullptr && (sharp->scalar == "true" || sharp->scalar == "True"));
    }
  return gt;
}

/// Reads an OBJ triangle mesh keeping the file's vertex and face order. Returns false
/// with `error` set if the file is unreadable, not triangles or not a manifold mesh.
template <typename Mesh>
bool read_mesh_in_file_order(const std::string& path, Mesh& mesh, std::string& error)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_OBJ(path, points, polygons) || polygons.empty())
  {
    error = "unreadable OBJ";
    return false;
  }
  for(const auto& p : polygons)
    if(p.size() != 3)
    {
      error = "a face is not a triangle";
      return false;
    }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    error = "not a manifold, consistently oriented polygon mesh";
    return false;
  }
  mesh.clear();
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return true;
}

/// The models of a ground-truth folder: every NAME.obj with a NAME.yml beside it, sorted.
inline std::vector<std::filesystem::path> ground_truth_models(const std::filesystem::path& folder)
{
  std::vector<std::filesystem::path> result;
  std::error_code ec;
  if(!std::filesystem::is_directory(folder, ec)) return result;
  for(const auto& entry : std::filesystem::directory_iterator(folder, ec))
  {
    const auto& p = entry.path();
    if(p.extension() == ".obj" && std::filesystem::exists(std::filesystem::path(p).replace_extension(".yml")))
      result.push_back(p);
  }
  std::sort(result.begin(), result.end());
  return result;
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_ABC_GROUND_TRUTH_H
