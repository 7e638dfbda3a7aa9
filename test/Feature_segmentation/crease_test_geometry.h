// The face geometry that the crease tests hand to the crease detection's parts (raw
// normals, areas, centroids, the faces around each face and the roughness, as
// detect_creases() computes them), and the whole detection at the defaults.
#ifndef FS_TEST_CREASE_TEST_GEOMETRY_H
#define FS_TEST_CREASE_TEST_GEOMETRY_H

#include <CGAL/Feature_segmentation/internal/crease_detection.h>

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

namespace fs_test {

struct Face_geometry
{
  std::vector<Eigen::Vector3d> normal, centroid;
  std::vector<double> area;
  std::vector<std::uint32_t> begin, ring;
  double roughness = 0;
};

template <typename TriangleMesh>
Face_geometry face_geometry_of(const CGAL::Feature_segmentation::internal::Mesh_indexing<TriangleMesh>& idx)
{
  namespace I = CGAL::Feature_segmentation::internal;
  Face_geometry g;
  I::face_geometry(idx, get(CGAL::vertex_point, idx.mesh()), g.normal, g.area, g.centroid);
  I::vertex_adjacent_faces(idx, g.begin, g.ring);
  g.roughness = I::normal_roughness(g.normal, g.begin, g.ring);
  return g;
}

// The creases detect_creases() finds at the package's defaults (crease angle 20 degrees,
// 40 filter rounds, curvature discontinuities), and whether it took the mesh for a clean
// tessellation.
struct Detected_creases
{
  std::vector<char> is_crease;
  bool clean = true;
};

template <typename TriangleMesh>
Detected_creases detect_creases_at_defaults(const CGAL::Feature_segmentation::internal::Mesh_indexing<TriangleMesh>& idx)
{
  Detected_creases d;
  std::vector<double> angle;
  bool cad = false;
  d.is_crease = CGAL::Feature_segmentation::internal::detect_creases(idx, get(CGAL::vertex_point, idx.mesh()), 20., 40,
                                                                      true, angle, d.clean, cad);
  return d;
}

} // namespace fs_test

#endif // FS_TEST_CREASE_TEST_GEOMETRY_H
