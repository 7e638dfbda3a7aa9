// SPDX-License-Identifier: GPL-3.0-or-later
// The Efficient RANSAC baseline of the CAD table: CGAL's shape detection (Schnabel et
// al. 2007) on the face centroids and normals, compiled once in its own translation unit
// (fs_evaluation_ransac), since its templates are slow to compile.

#ifndef FS_EVALUATION_RANSAC_H
#define FS_EVALUATION_RANSAC_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <vector>

namespace fs_evaluation {

/// A patch per face: CGAL's Efficient RANSAC detects planes, cylinders, cones, spheres and
/// tori among the face centroids with their normals (distance 0.5% of the bounding-box
/// diagonal, normals within 25 degrees, at least 0.2% of the faces or 10 per shape,
/// probability 0.01, a fixed seed); each face takes its shape; a face of no shape takes
/// that of the neighbour it shares an edge with, breadth first; a patch is a connected
/// set of faces of one shape.
std::vector<std::size_t> efficient_ransac_face_patches(
  const CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& mesh);

} // namespace fs_evaluation

#endif // FS_EVALUATION_RANSAC_H
