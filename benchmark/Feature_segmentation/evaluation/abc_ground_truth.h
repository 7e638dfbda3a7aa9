// SPDX-License-Identifier: GPL-3.0-or-later
// Ground truth of CAD models in the format of the ABC dataset as NH-Rep distributes it:
// NAME.obj, a triangle mesh, beside NAME.yml, whose surfaces[i].face_indices list the
// faces of patch i (faces numbered in the OBJ's order) and whose curves[j].vert_indices
// chain mesh vertices along feature curve j, curves[j].sharp telling a crease from a
// smooth junction. The mesh is built face by face in the file's order, so that face i of
// the mesh is face i of the file (a general reader may reorder or repair). The .yml is
// parsed by yaml-cpp: a program including this header links the yaml-cpp target.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_ABC_GROUND_TRUTH_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_ABC_GROUND_TRUTH_H

#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <yaml-cpp/yaml.h>

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

// The value of `key` in `map`, or an undefined node when `map` is not a mapping or lacks
// the key: yaml-cpp throws when a scalar is subscripted, and the node it returns for a
// missing key throws on every query but IsDefined().
inline YAML::Node yaml_value(const YAML::Node& map, const char* key)
{
  if(map.IsMap())
    if(const YAML::Node value = map[key]) return value;
  return YAML::Node(YAML::NodeType::Undefined);
}

// A face or vertex index below `bound`, in decimal: strtoll in base 10 rather than
// as<>(), whose stream conversion reads "010" as octal and "0x10" as hexadecimal.
inline std::size_t yaml_index(const std::string& yml, const YAML::Node& n, std::size_t bound, const char* what)
{
  const bool scalar = n.IsScalar();
  const std::string text = scalar ? n.Scalar() : std::string();
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if(!scalar || end == text.c_str() || *end != '\0' || v < 0 || static_cast<unsigned long long>(v) >= bound)
    throw std::runtime_error(yml + ": bad " + what + " index '" + text + "'");
  return static_cast<std::size_t>(v);
}

/// Reads the YAML annotations for a mesh of `number_of_vertices` vertices and
/// `number_of_faces` faces. Throws `std::runtime_error` with the file and the reason.
inline Abc_ground_truth read_abc_ground_truth(const std::string& yml, std::size_t number_of_vertices,
                                              std::size_t number_of_faces)
{
  YAML::Node root;
  try
  {
    root = YAML::LoadFile(yml);
  }
  catch(const YAML::BadFile&)
  {
    throw std::runtime_error("cannot read " + yml);
  }
  catch(const YAML::Exception& e) // malformed YAML; what() says the line and column
  {
    throw std::runtime_error(yml + ": " + e.what());
  }
  const YAML::Node surfaces = yaml_value(root, "surfaces");
  if(!surfaces.IsSequence())
    throw std::runtime_error(yml + ": no 'surfaces' sequence");
  Abc_ground_truth gt;
  gt.face_patch.assign(number_of_faces, -1);
  for(const YAML::Node& s : surfaces)
  {
    const YAML::Node fi = yaml_value(s, "face_indices");
    if(!fi.IsSequence())
      throw std::runtime_error(yml + ": a surface without 'face_indices'");
    const YAML::Node type = yaml_value(s, "type");
    const int id = static_cast<int>(gt.patch_type.size());
    gt.patch_type.push_back(type.IsScalar() ? type.Scalar() : std::string("?"));
    for(const YAML::Node& f : fi)
    {
      const std::size_t k = yaml_index(yml, f, number_of_faces, "face");
      if(gt.face_patch[k] != -1)
        throw std::runtime_error(yml + ": face " + std::to_string(k) + " in two surfaces");
      gt.face_patch[k] = id;
    }
  }
  // The curves are optional, and so are their vertices: a curve without 'vert_indices'
  // is not on the mesh and is left out.
  const YAML::Node curves = yaml_value(root, "curves");
  if(curves.IsSequence())
    for(const YAML::Node& c : curves)
    {
      const YAML::Node vi = yaml_value(c, "vert_indices");
      if(!vi.IsDefined()) continue;
      std::vector<std::size_t> chain;
      if(vi.IsSequence())
        for(const YAML::Node& v : vi) chain.push_back(yaml_index(yml, v, number_of_vertices, "vertex"));
      const YAML::Node sharp = yaml_value(c, "sharp");
      gt.curves.push_back(chain);
      gt.curve_is_sharp.push_back(sharp.IsScalar() && (sharp.Scalar() == "true" || sharp.Scalar() == "True"));
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
