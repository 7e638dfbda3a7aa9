// SPDX-License-Identifier: GPL-3.0-or-later
// The borders of the planes of a noisy CAD part (or of a lightly noisy one, as rough as a
// smooth model: crease_detection.h), where a plane runs into a fillet or any curved face
// without a crease. Noise hides what the curvature discontinuities of a
// clean tessellation (tangent_discontinuities.h) read from exactly flat regions, but
// after the crease filter (crease_detection.h) a plane's face normals agree to a degree
// or two while a fillet's turn steadily. Regions are grown from the flattest faces: a
// face joins a region across a non-crease edge while its filtered normal is within
// Plane_thresholds::angle of the region's mean normal. A cylinder or a fillet gives
// strips so grown too; what sets a plane apart is that its normals keep close to their
// mean (median deviation) with no steady turn across it (the least-squares gradient of
// the normals over the face centroids explains little of their spread), and that it is
// wide (most of its faces inside it, where a fillet's strip is one or two faces across).
// A narrow plane between fillets fails the first two tests: the filter bends its normals
// towards the fillets over its whole width, so they turn as a cylinder's do. Its raw
// normals do not turn: a wide region whose raw normals' gradient explains at most
// Plane_thresholds::raw_trend is a plane too (on a strip of a cylinder the turn is the
// strip's, and the raw normals' noise only adds to it: noise cannot make a strip pass).
// The planes then grow once more over the faces of rejected regions (a rough spot of a
// plane seeds a region of its own), small pieces that one plane surrounds join it, and
// the non-crease edges between a plane and other faces are marked, except within a few
// rows of a crease: the filter bends the normals there towards the crease's other side.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_PLANE_BORDERS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_PLANE_BORDERS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/tangent_discontinuities.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the plane borders, chosen on the 30 development parts and the
// generated ones at 0.1% and 0.3% noise (evaluate_quality; manual, Creases). Angles in
// degrees, of the filtered normals.
struct Plane_thresholds
{
  // The largest angle between a face's normal and its region's mean normal.
  static constexpr double angle = 6.;
  // A plane's largest median angle from its mean normal, as a fraction of `angle`: a
  // strip of a cylinder grown so spreads its normals evenly over [0, angle] (median
  // about 0.5), a plane only the filter's residue (0.1 to 0.3 at 0.1% and 0.3% noise).
  static constexpr double median = 0.35;
  // A plane's largest root mean square turn explained by the normals' gradient, as a
  // fraction of `angle`: 0.5 to 0.6 on strips of cylinders, at most 0.4 on planes
  // (their rim turns where a fillet begins).
  static constexpr double trend = 0.45;
  // The least share of a plane's faces whose three neighbours are in it: strips of a
  // fillet or of a narrow cylinder have 0.2 to 0.6, planes 0.8 and more.
  static constexpr double inner_share = 0.65;
  // The largest root mean square turn explained by the gradient of the raw (unfiltered)
  // normals of a region that fails the two tests above (degrees). The narrow flats of
  // the generated rounded bar at 0.1% noise measure 0.25 to 1.45, the sides of the
  // rounded boxes 0.1 to 0.9; the regions that fail the filtered tests on the development
  // parts mostly 1.3 to 6 (a strip's 12-degree spread alone gives about 3.5). Chosen
  // among 0.6, 1 and 1.4 on the development and generated parts at 0.1% and 0.3% noise:
  // 1.4 takes strips of the cylinders of ABC 00004493 for planes, 0.6 half the bar's
  // flats for strips (manual, Creases).
  static constexpr double raw_trend = 1.;
  // The least number of faces of a plane; its least area is that of the flat side of a
  // curvature discontinuity (Tangent_thresholds::least_flat_side).
  static constexpr std::size_t least_faces = 10;
  // The rows of faces next to a crease (steps across edges) that bear no plane border.
  static constexpr int crease_rows = 3;
};

// Marks with 2 in `is_crease` the non-crease edges of the mesh of `idx` that border a
// plane (file comment), if the planes hold `least_share` of the area or more; returns
// their share of the area. `normal`: the filtered unit face normals (zero for a
// degenerate face), `raw`: the unfiltered ones, `area` and `centroid`: the faces',
// `diagonal`: the bounding box's;
// `is_crease` holds the creases (1). Deterministic: seeds in order of flatness, then of
// index, each region grown breadth first.
template <typename TriangleMesh>
double mark_plane_borders(const Mesh_indexing<TriangleMesh>& idx, const std::vector<Eigen::Vector3d>& normal,
                          const std::vector<Eigen::Vector3d>& raw, const std::vector<double>& area,
                          const std::vector<Eigen::Vector3d>& centroid, double diagonal,
                          std::vector<char>& is_crease, double least_share = 0.)
{
  typedef Plane_thresholds Limits;
  // 32-bit face and edge ids (detect_creases() has checked that 3 ids per face fit)
  typedef std::uint32_t Id;
  const std::size_t nf = idx.number_of_faces();
  const Id none = Id(-1);
  const double to_degrees = 180. / 3.14159265358979323846;
  const double cos_angle = std::cos(Limits::angle / to_degrees);
  const double least_area = CGAL::square(Tangent_thresholds::least_flat_side * diagonal);
  auto valid = [&](std::size_t f) { return normal[f].squaredNorm() > 0; };

  // the faces across each face's three edges (none across a border or a crease)
  std::vector<Id> across_edge, across;
  face_edges_and_neighbours(idx, none, across_edge, across);
  for(std::size_t i = 0; i < across.size(); ++i)
    if(is_crease[across_edge[i]]) across[i] = none;
  // the seeds: faces by their largest bend (1 - cos) to a face across an edge
  std::vector<double> bend(nf, 2.);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!valid(f)) continue;
    double most = 0.;
    for(int k = 0; k < 3; ++k)
    {
      const Id g = across[3 * f + k];
      if(g != none && valid(g)) most = (std::max)(most, 1. - normal[f].dot(normal[g]));
    }
    bend[f] = most;
  }
  std::vector<Id> order(nf);
  std::iota(order.begin(), order.end(), Id(0));
  std::stable_sort(order.begin(), order.end(), [&](Id a, Id b) { return bend[a] < bend[b]; });

  std::vector<Id> region(nf, none), members;
  std::vector<char> is_plane;
  std::vector<Eigen::Vector3d> region_normal;
  std::vector<double> deviation;
  for(Id seed : order)
  {
    if(bend[seed] > 1. - cos_angle) break; // no flatter seed is left
    if(region[seed] != none) continue;
    const Id r = Id(is_plane.size());
    members.assign(1, seed);
    region[seed] = r;
    Eigen::Vector3d sum = area[seed] * normal[seed];
    for(std::size_t i = 0; i < members.size(); ++i)
      for(int k = 0; k < 3; ++k)
      {
        const Id g = across[3 * members[i] + k];
        if(g == none || region[g] != none || !valid(g) || normal[g].dot(sum.normalized()) < cos_angle) continue;
        region[g] = r;
        sum += area[g] * normal[g];
        members.push_back(g);
      }
    // area, inner faces, means
    double total = 0.;
    std::size_t inner = 0;
    Eigen::Vector3d c_mean = Eigen::Vector3d::Zero(), n_mean = Eigen::Vector3d::Zero();
    for(Id f : members)
    {
      total += area[f];
      c_mean += area[f] * centroid[f];
      n_mean += area[f] * normal[f];
      bool all = true;
      for(int k = 0; k < 3; ++k) all = all && across[3 * f + k] != none && region[across[3 * f + k]] == r;
      if(all) ++inner;
    }
    region_normal.push_back(n_mean.normalized());
    bool plane = members.size() >= Limits::least_faces && total >= least_area && total > 0 &&
                 double(inner) >= Limits::inner_share * double(members.size());
    if(plane)
    {
      c_mean /= total;
      n_mean /= total;
      // the median deviation from the mean normal
      deviation.clear();
      for(Id f : members)
        deviation.push_back(std::acos((std::min)(1., normal[f].dot(region_normal[r]))) * to_degrees);
      std::nth_element(deviation.begin(), deviation.begin() + std::ptrdiff_t(deviation.size() / 2), deviation.end());
      // the trend: the least-squares gradient G of the normal over the centroids,
      // n ~ n_mean + G (c - c_mean), and the root mean square of G (c - c_mean)
      Eigen::Matrix3d cc = Eigen::Matrix3d::Zero(), nc = Eigen::Matrix3d::Zero();
      for(Id f : members)
      {
        const Eigen::Vector3d dc = centroid[f] - c_mean;
        cc += area[f] * dc * dc.transpose();
        nc += area[f] * (normal[f] - n_mean) * dc.transpose();
      }
      const Eigen::Matrix3d cc_inverse = cc.completeOrthogonalDecomposition().pseudoInverse();
      const Eigen::Matrix3d gradient = nc * cc_inverse;
      double trend = 0.;
      for(Id f : members) trend += area[f] * (gradient * (centroid[f] - c_mean)).squaredNorm();
      trend = std::sqrt(trend / total) * to_degrees;
      plane = deviation[deviation.size() / 2] <= Limits::median * Limits::angle && trend <= Limits::trend * Limits::angle;
      if(!plane)
      {
        // the same trend on the raw normals (over the same centroids)
        Eigen::Vector3d r_mean = Eigen::Vector3d::Zero();
        for(Id f : members) r_mean += area[f] * raw[f];
        r_mean /= total;
        Eigen::Matrix3d rc = Eigen::Matrix3d::Zero();
        for(Id f : members) rc += area[f] * (raw[f] - r_mean) * (centroid[f] - c_mean).transpose();
        const Eigen::Matrix3d raw_gradient = rc * cc_inverse;
        double raw_trend = 0.;
        for(Id f : members) raw_trend += area[f] * (raw_gradient * (centroid[f] - c_mean)).squaredNorm();
        plane = std::sqrt(raw_trend / total) * to_degrees <= Limits::raw_trend;
      }
    }
    is_plane.push_back(plane ? 1 : 0);
  }
  auto in_plane = [&](Id f) { return region[f] != none && is_plane[region[f]]; };

  // the planes grow again over the faces of the other regions
  members.clear();
  for(Id f = 0; f < nf; ++f)
    if(in_plane(f)) members.push_back(f);
  for(std::size_t i = 0; i < members.size(); ++i)
    for(int k = 0; k < 3; ++k)
    {
      const Id f = members[i], g = across[3 * f + k];
      if(g == none || in_plane(g) || !valid(g) || normal[g].dot(region_normal[region[f]]) < cos_angle) continue;
      region[g] = region[f];
      members.push_back(g);
    }

  // pieces of other faces smaller than a plane that touch a single plane join it
  {
    std::vector<char> seen(nf, 0);
    for(Id f0 = 0; f0 < nf; ++f0)
    {
      if(seen[f0] || in_plane(f0)) continue;
      members.assign(1, f0);
      seen[f0] = 1;
      double total = 0.;
      Id plane = none;
      bool single = true;
      for(std::size_t i = 0; i < members.size(); ++i)
      {
        total += area[members[i]];
        for(int k = 0; k < 3; ++k)
        {
          const Id g = across[3 * members[i] + k];
          if(g == none) continue;
          if(in_plane(g))
          {
            if(plane == none) plane = region[g];
            else if(plane != region[g]) single = false;
          }
          else if(!seen[g]) { seen[g] = 1; members.push_back(g); }
        }
      }
      if(single && plane != none && total < least_area)
        for(Id f : members) region[f] = plane;
    }
  }

  double planar = 0., total = 0.;
  for(Id f = 0; f < nf; ++f)
  {
    total += area[f];
    if(in_plane(f)) planar += area[f];
  }
  const double share = total > 0 ? planar / total : 0.;
  if(share < least_share) return share;

  // the faces within Limits::crease_rows steps of a crease
  std::vector<unsigned char> near(nf, (unsigned char)(Limits::crease_rows + 1));
  {
    std::vector<Id> front, next;
    for(Id f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        if(is_crease[across_edge[3 * f + k]] == 1 && near[f] != 0) { near[f] = 0; front.push_back(f); }
    for(int d = 1; d <= Limits::crease_rows && !front.empty(); ++d)
    {
      next.clear();
      for(Id f : front)
        for(int k = 0; k < 3; ++k)
        {
          const Id g = across[3 * f + k];
          if(g != none && near[g] > d) { near[g] = (unsigned char)d; next.push_back(g); }
        }
      front.swap(next);
    }
  }
  for(Id f = 0; f < nf; ++f)
  {
    if(!in_plane(f) || near[f] <= Limits::crease_rows) continue;
    for(int k = 0; k < 3; ++k)
    {
      const Id g = across[3 * f + k];
      if(g != none && region[g] != region[f] && near[g] > Limits::crease_rows) is_crease[across_edge[3 * f + k]] = 2;
    }
  }
  return share;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_PLANE_BORDERS_H
