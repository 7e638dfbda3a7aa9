// SPDX-License-Identifier: GPL-3.0-or-later
// Seams between the faces of a surface of revolution on a noisy mesh. A turned part is
// cylinders, cones, planes, tori and spheres about one axis, and many of them meet
// without a crease (a cone running into a torus) or with one too weak to stand out of
// the noise (a nail's cylinder into its tip, 15 degrees). Under noise of 0.3% of the
// diagonal no per-vertex curvature sees such a seam (manual, Creases); over a whole
// region it is plain: every normal of a surface of revolution meets the axis, so the
// axis is the line that the normal lines of the region's faces meet best (a least-squares
// linear line complex, Pottmann and Randrup 1998), and about it the faces' centroids
// collapse into a profile in the (height, radius) plane, a chain of straight pieces
// (cylinders, cones, planes) and circular arcs (tori, spheres) that thousands of faces
// around the axis make plain. The profile is ordered along its length, cut into the
// fewest pieces that fit within the noise (optimal segmentation by dynamic programming,
// a penalty per piece), a cut between two pieces that meet tangentially moves to where
// their fits touch, and the faces of different pieces are parted by seams.
// A region is left alone unless its profile is as thin as the noise of its surface: a
// region that is no surface of revolution (a plane, a bent pipe, faces of several axes)
// has no thin profile.
// A region that is no surface of revolution may be a pipe (a round tube bent along a
// planar curve: cylinders and torus sections meeting tangentially). Its faces' normal
// lines pass through its spine at the pipe's radius, so the centroids moved inwards by
// that radius along their normals collapse onto the spine, a planar chain of straight
// pieces (cylinders) and arcs (tori) that the same dynamic programming cuts.
// Under noise creases also appear inside such faces; where stronger creases bound
// a surface of revolution of a thin profile, the creases within one of its pieces are
// noise and are unmarked, and so are those between two such regions that are one
// surface and those round a small island inside a piece whose normals follow the
// piece's.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_REVOLUTION_SEAMS_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_REVOLUTION_SEAMS_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/crease_staircase.h>
#include <CGAL/Feature_segmentation/internal/face_components.h>
#include <CGAL/Feature_segmentation/internal/union_find.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the revolution seams, chosen on the 30 development parts and the 14
// generated ones at 0.1% and 0.3% noise of the diagonal (manual, Creases).
struct Revolution_seams
{
  // the fewest faces of a region that is looked at (100 and 400 give the same means over
  // three noise realisations)
  static constexpr std::size_t least_faces = 200;
  // rounds of averaging the raw normals over the faces sharing a vertex before the axis
  // is fitted (the raw normals of a heavily noisy mesh are off by 20 to 40 degrees; 3
  // and 8 rounds give the means within 0.0015)
  static constexpr int smoothing_rounds = 5;
  // the profile's spread (the root mean square distance of the centroids from straight
  // pieces or arcs over windows of `noise_bins` bins) may be at most this many times the
  // noise of the surface (measured across its edges): 1.4 to 1.9 on the turned parts,
  // nails and hoppers of the evaluation, 3 and more on planes and on regions of several
  // axes; 2 and 2.5 give the same means over three noise realisations, 1.75 loses the
  // generated mean at 0.3% noise 0.013
  static constexpr double spread_ratio = 2.25;
  static constexpr std::size_t noise_bins = 8;
  // the bins of the profile's length are half a median edge long (longer if there would
  // be more than `most_bins`: the pieces take time quadratic in the bins); a piece holds
  // at least `least_bins` of them (with 2, the development mean at 0.3% noise falls by
  // 0.01 over three noise realisations: ABC 00006566 from 1.00 to 0.67)
  static constexpr std::size_t least_bins = 4, most_bins = 2048;
  // the cost of a piece, in units of a face's squared noise, times the log of the
  // region's face count (a Bayesian information criterion with a wide margin): 60, 150
  // and 300 give the development and generated means within 0.0025 of 100's over three
  // noise realisations
  static constexpr double penalty = 100.;
  // A pipe's spine (pipe_pieces()) wobbles with the facets round the tube by a few
  // hundredths of an edge, more than the noise of 0.1% of the diagonal on a coarse tube
  // (the coarse bent pipe: 0.06 edges, 3 times its noise): its spread may always reach
  // `pipe_least_spread` median edges. Its pieces are at least `pipe_least_length` times
  // its radius long: next to a noisy crease the spine bends into short end pieces
  // (two radii: the generated mean at 0.3% noise within 0.001 over three realisations).
  static constexpr double pipe_least_spread = 0.1;
  static constexpr double pipe_least_length = 1.;
  // the least middle eigenvalue of the second moments of a pipe's normals (pipe_pieces():
  // at least 1/4 on a tube)
  static constexpr double pipe_least_normal_moment = 0.2;
  // A cut between two pieces whose fits touch within `tangent_angle` degrees moves to
  // where they touch, by at most `seam_shift` bins (curve_pieces()): over three noise
  // realisations, with the refined radius of pipe_pieces(), the generated parts' mean
  // goes from 0.922 to 0.946 at 0.1% noise and from 0.769 to 0.814 at 0.3% (the bent
  // pipes 0.74 - 0.90 to 0.97 - 1.00, the turned parts 0.89 - 0.97 to 0.96 - 1.00), the
  // development parts' rows unchanged; 5 degrees (noisy fits of a tangent joint are
  // further apart) loses 0.026 of the generated mean at 0.3%, 20 is within 0.001; 2
  // bins lose 0.018, 8 are the same.
  static constexpr double tangent_angle = 10.;
  static constexpr double seam_shift = 4.;
  // Noise leaves creases inside the faces of a heavily noisy surface of revolution (the
  // long tube's walls: 0.3% of the diagonal is half their thickness). The regions that
  // creases of at least `clear_below_angle` degrees (filtered) bound are looked at as
  // above, and in one of a thin profile the creases between two faces of the same
  // piece, each at least `clear_margin` bins from the nearest cut between pieces, are
  // noise and are unmarked (the ones that bound the region are between two regions):
  // over three noise realisations, unmarking only the creases below
  // `clear_below_angle` took the development mean from 0.950 to 0.954 at 0.1% noise and
  // from 0.922 to 0.927 at 0.3%, the generated parts' from 0.759 to 0.765 at 0.3% (the
  // coarse long tube 0.75 to 0.80); 50 degrees gives the same means within 0.001, 60
  // cuts the torus of ABC 00006566 once in three (0.3%: development 0.915). Unmarking
  // the stronger ones inside a piece too, with the islands below, takes the development
  // mean from 0.954 to 0.958 at 0.1% and from 0.927 to 0.930 at 0.3%, the generated
  // parts' at 0.3% from 0.825 to 0.840 (the coarse long tube 0.80 to 0.99, the nail ABC
  // 00000655 0.86 to 0.97).
  static constexpr double clear_below_angle = 55.;
  static constexpr std::size_t clear_margin = 4;
  // An island: a region of fewer than `least_faces` faces that those creases bound (on
  // a heavily noisy mesh, a cluster of adjacent ones), smaller than the region round it,
  // whose every neighbour across them lies in one piece, `clear_margin` bins or more
  // from a cut. It is noise, and joins the piece, if its mean normal in the profile
  // plane of the piece's axis makes at most `island_angle` degrees with the piece's (a
  // cap or a flat end across a cylinder makes 90). Without islands, the single-face ABC
  // 00000691 at 0.3% noise gets a 15-face patch once in three realisations (F 0
  // there). Two regions of one surface of revolution that creases of noise part are
  // joined under the same angle (join_coaxial_regions()).
  static constexpr double island_angle = 30.;
  // The pairs of regions are tried in at most `join_rounds` rounds, while a round joins
  // some: over three noise realisations at 0.3%, the fine long tube goes from 0.71 (one
  // round) to 0.75 (no other part changes); on it no round after the second joins any.
  static constexpr int join_rounds = 4;
  // On a heavily noisy mesh, the small regions left join a piece round by round
  // (join_islands()) if `grow_border_share` of their border edges or more run along it
  // and their centroids' mean squared offset from its profile line is at most
  // `grow_offset` squared times the piece's own, in at most `grow_rounds` rounds. Over
  // three noise realisations at 0.3% (with one round of joins), the fine long tube goes
  // from 0.39 to 0.71 with them; with shares of 0.5 and 0.7 (and no offset test) it
  // reaches only 0.42 and 0.40, and without the offset test the fine filleted bar falls
  // from 0.94 to 0.56 (near a fillet its tangent planes face as the fillet's cylinder
  // does). A small region may also touch another piece whose profile normal disagrees
  // with its own (at a tube's end, the end's ring); with that, with a share of 0.2
  // instead of 0.3 and with joins retried without the clusters between two regions
  // (join_coaxial_regions()), the tube goes from 0.75 to 0.97 over three realisations
  // (0.81 with the retries alone, 0.88 with a share of 0.2 too, 0.85 with the other
  // pieces instead), and no other part moves by more than 0.001.
  static constexpr double grow_border_share = 0.2;
  static constexpr double grow_offset = 2.;
  static constexpr int grow_rounds = 100;
};

// The axis of a surface of revolution through faces with centroids `c`, unit normals
// `n` and weights `w`: the unit direction `direction` and the point `point` of the line
// that the normal lines meet best (the least-squares linear complex: the axis (a, a_bar)
// in Pluecker coordinates minimises the weighted sum of (a . (c x n) + a_bar . n)^2 over
// unit a). False if the normals span less than two directions (a plane: every line along
// its normal is an axis).
inline bool fit_revolution_axis(const std::vector<Eigen::Vector3d>& c, const std::vector<Eigen::Vector3d>& n,
                                const std::vector<double>& w, Eigen::Vector3d& direction, Eigen::Vector3d& point)
{
  // about the weighted mean of the centroids, for the conditioning
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double total = 0.;
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    mean += w[i] * c[i];
    total += w[i];
  }
  if(!(total > 0)) return false;
  mean /= total;
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  for(std::size_t i = 0; i < c.size(); ++i)
  {
    Eigen::Matrix<double, 6, 1> v;
    v << (c[i] - mean).cross(n[i]), n[i];
    m.noalias() += w[i] * v * v.transpose();
  }
  const Eigen::Matrix3d m11 = m.topLeftCorner<3, 3>(), m12 = m.topRightCorner<3, 3>();
  Eigen::Matrix3d m22 = m.bottomRightCorner<3, 3>();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> normals(m22);
  // the middle eigenvalue of the normals' moments: 0 on a plane; a cylinder's normals
  // spread over a plane, a cone's and a torus's over more
  if(!(normals.eigenvalues()(1) > 1e-3 * m22.trace())) return false;
  // A cylinder's normals miss its axis's direction (its smallest eigenvalue is 0): the
  // normal lines meet a helix of any pitch as well as the axis. A tiny ridge makes the
  // solve take the axis (no moment along the direction), and leaves every other case
  // as it is.
  m22 += 1e-9 * m22.trace() * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d x = m22.ldlt().solve(m12.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axis(m11 - m12 * x);
  direction = axis.eigenvectors().col(0);
  const Eigen::Vector3d moment = -x * direction;
  point = mean + direction.cross(moment);
  return true;
}

// The sum of squared distances of weighted points to the best straight line or circle
// through them, from their moments (sums of w, z, r, z^2, zr, r^2, q, zq, rq, q^2 with
// q = z^2 + r^2): the line's is the smaller eigenvalue of their covariance times the
// weight; the circle's is Kasa's algebraic fit, its residual d^2 - R^2 divided by 2R
// (the distance to the circle, for points near it).
struct Profile_moments
{
  double s[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  void add(double w, double z, double r)
  {
    const double q = z * z + r * r;
    const double v[10] = { 1, z, r, z * z, z * r, r * r, q, z * q, r * q, q * q };
    for(int k = 0; k < 10; ++k) s[k] += w * v[k];
  }
  Profile_moments operator-(const Profile_moments& o) const
  {
    Profile_moments d;
    for(int k = 0; k < 10; ++k) d.s[k] = s[k] - o.s[k];
    return d;
  }
  // The best straight line through the points (through `point` along the unit
  // `direction`) and its error, and Kasa's circle (centre `centre`, `radius`; 0 if there
  // is none) and its error (infinity if there is none).
  struct Fits
  {
    Eigen::Vector2d point = Eigen::Vector2d::Zero(), direction = Eigen::Vector2d::Zero(),
                    centre = Eigen::Vector2d::Zero();
    double line = 0., radius = 0., circle = std::numeric_limits<double>::infinity();
  };
  Fits fits(bool with_direction = false) const
  {
    Fits r;
    const double w = s[0];
    if(!(w > 0)) return r;
    const double mz = s[1] / w, mr = s[2] / w;
    const double czz = s[3] / w - mz * mz, czr = s[4] / w - mz * mr, crr = s[5] / w - mr * mr;
    const double half = 0.5 * (czz + crr), det = std::sqrt(0.25 * (czz - crr) * (czz - crr) + czr * czr);
    r.line = (std::max)(0., half - det) * w;
    if(with_direction)
    {
      // the covariance's eigenvector of its larger eigenvalue, half + det
      r.point = Eigen::Vector2d(mz, mr);
      r.direction = czr != 0. ? Eigen::Vector2d(czr, half + det - czz).normalized()
                              : (czz >= crr ? Eigen::Vector2d(1., 0.) : Eigen::Vector2d(0., 1.));
    }
    Eigen::Matrix3d a;
    a << s[3], s[4], s[1], s[4], s[5], s[2], s[1], s[2], w;
    const Eigen::Vector3d b(-s[7], -s[8], -s[6]);
    Eigen::Matrix3d inverse;
    bool invertible = false;
    a.computeInverseWithCheck(inverse, invertible, 1e-12 * a.cwiseAbs().maxCoeff());
    if(!invertible) return r;
    const Eigen::Vector3d x = inverse * b;
    const double d = x(0), e = x(1), f = x(2);
    const double r2 = 0.25 * (d * d + e * e) - f;
    if(!(r2 > 0)) return r;
    // the sum of (q + d z + e r + f)^2
    const double algebraic = s[9] + d * d * s[3] + e * e * s[5] + f * f * w + 2 * d * s[7] + 2 * e * s[8] +
                             2 * f * s[6] + 2 * d * e * s[4] + 2 * d * f * s[1] + 2 * e * f * s[2];
    r.circle = (std::max)(0., algebraic) / (4 * r2);
    r.centre = Eigen::Vector2d(-0.5 * d, -0.5 * e);
    r.radius = std::sqrt(r2);
    return r;
  }
  double fit_error() const
  {
    const Fits f = fits();
    return (std::min)(f.line, f.circle);
  }
  // The fit of fit_error(): a line through `point` along the unit `direction` (a radius
  // of 0), or a circle of centre `point` and `radius`. False without points.
  bool fit(Eigen::Vector2d& point, Eigen::Vector2d& direction, double& radius) const
  {
    if(!(s[0] > 0)) return false;
    const Fits f = fits(true);
    const bool circle = f.circle < f.line;
    point = circle ? f.centre : f.point;
    direction = f.direction;
    radius = circle ? f.radius : 0.;
    return true;
  }
};

// The point where two fits of Profile_moments::fit() (a radius of 0: a line) touch, if
// they meet tangentially within `tangent_angle` degrees (a line touching a circle, two
// circles touching, from outside or inside): the foot of the perpendicular from the
// circle's centre on the line, or the point of the line of centres on both circles.
inline bool tangent_point(const Eigen::Vector2d& p1, const Eigen::Vector2d& d1, double r1, const Eigen::Vector2d& p2,
                          const Eigen::Vector2d& d2, double r2, double tangent_angle, Eigen::Vector2d& at)
{
  if(r1 == 0. && r2 == 0.) return false; // two lines meet at a crease or are one line
  const double tolerance = 1. - std::cos(tangent_angle * CGAL_PI / 180.);
  if(r1 == 0. || r2 == 0.)
  {
    const Eigen::Vector2d& p = r1 == 0. ? p1 : p2;
    const Eigen::Vector2d& d = r1 == 0. ? d1 : d2;
    const Eigen::Vector2d& c = r1 == 0. ? p2 : p1;
    const double r = r1 == 0. ? r2 : r1;
    const Eigen::Vector2d foot = p + (c - p).dot(d) * d;
    if(std::abs((c - foot).norm() - r) > tolerance * r) return false;
    at = foot;
    return true;
  }
  const Eigen::Vector2d between = p2 - p1;
  const double d = between.norm();
  if(!(d > 0)) return false;
  const double small = (std::min)(r1, r2);
  if(std::abs(d - (r1 + r2)) <= tolerance * small) // from outside
    at = p1 + r1 / d * between;
  else if(std::abs(d - std::abs(r1 - r2)) <= tolerance * small) // the smaller inside the larger
    at = r1 > r2 ? Eigen::Vector2d(p1 + r1 / d * between) : Eigen::Vector2d(p2 - r2 / d * between);
  else
    return false;
  return true;
}

// The pieces of a profile of `bins` bins with prefix moments `prefix` (prefix[i]: bins 0
// to i - 1): the first bin of each piece (0 first), of at least `least` bins each,
// minimising the sum of their fit errors divided by `unit` plus `penalty` per piece.
inline std::vector<std::size_t> profile_pieces(const std::vector<Profile_moments>& prefix, std::size_t least,
                                               double unit, double penalty)
{
  const std::size_t bins = prefix.size() - 1;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> best(bins + 1, inf);
  std::vector<std::size_t> from(bins + 1, 0);
  best[0] = 0.;
  for(std::size_t j = least; j <= bins; ++j)
    for(std::size_t i = 0; i + least <= j; ++i)
    {
      if(best[i] == inf) continue;
      const double cost = best[i] + (prefix[j] - prefix[i]).fit_error() / unit + penalty;
      if(cost < best[j])
      {
        best[j] = cost;
        from[j] = i;
      }
    }
  std::vector<std::size_t> first;
  if(best[bins] == inf) return { 0 };
  for(std::size_t j = bins; j > 0; j = from[j]) first.push_back(from[j]);
  std::reverse(first.begin(), first.end());
  return first;
}

// Per face of `faces`, its piece (0 ...) of the planar curve that the points `z`, `r`
// (one per face, weighted by `w`) form, or an empty vector if they form no curve as thin
// as the noise of the surface (Revolution_seams) or as `least_spread`. `centroid`,
// `normal` (smoothed): per face of the mesh; `pairs`: the pairs of adjacent faces of the
// region; `h`: the median edge length; `least_length`: the shortest piece (at least
// Revolution_seams::least_bins bins). With `spread_only`, only the curve's squared
// spread is stored there (infinity if it has none) and no pieces are returned; with
// `cut_distance`, each face's distance in bins from the nearest cut between two pieces
// (std::size_t(-1) for a curve of one piece).
inline std::vector<std::size_t> curve_pieces(const std::vector<std::size_t>& faces, const std::vector<double>& z,
                                             const std::vector<double>& r, const std::vector<double>& w,
                                             const std::vector<std::pair<std::size_t, std::size_t> >& pairs,
                                             const std::vector<Eigen::Vector3d>& centroid,
                                             const std::vector<Eigen::Vector3d>& normal, double h,
                                             double least_length = 0., double least_spread = 0.,
                                             double* spread_only = nullptr,
                                             std::vector<std::size_t>* cut_distance = nullptr)
{
  typedef Revolution_seams Limits;
  const std::size_t n = faces.size();
  if(spread_only) *spread_only = std::numeric_limits<double>::infinity();
  if(n == 0 || !(h > 0)) return {};
  // Cells of one edge length over the profile plane, joined to their 8 neighbours: the
  // profile is one chain of them, ordered by the breadth-first distance from one end
  // (the cell farthest from the first face's).
  typedef std::pair<std::int64_t, std::int64_t> Cell;
  std::map<Cell, std::size_t> cell_id;
  std::vector<std::size_t> cell_of(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Cell k(std::int64_t(std::floor(z[i] / h)), std::int64_t(std::floor(r[i] / h)));
    cell_of[i] = cell_id.emplace(k, cell_id.size()).first->second;
  }
  std::vector<Cell> cells(cell_id.size());
  for(const auto& kv : cell_id) cells[kv.second] = kv.first;
  auto distances = [&](std::size_t source) {
    std::vector<std::size_t> dist(cells.size(), std::size_t(-1));
    std::deque<std::size_t> queue{ source };
    dist[source] = 0;
    while(!queue.empty())
    {
      const std::size_t u = queue.front();
      queue.pop_front();
      for(std::int64_t dz = -1; dz <= 1; ++dz)
        for(std::int64_t dr = -1; dr <= 1; ++dr)
        {
          const auto it = cell_id.find(Cell(cells[u].first + dz, cells[u].second + dr));
          if(it == cell_id.end() || dist[it->second] != std::size_t(-1)) continue;
          dist[it->second] = dist[u] + 1;
          queue.push_back(it->second);
        }
    }
    return dist;
  };
  std::vector<std::size_t> dist = distances(cell_of[0]);
  if(std::count(dist.begin(), dist.end(), std::size_t(-1)) > 0) return {}; // not one chain
  dist = distances(std::size_t(std::max_element(dist.begin(), dist.end()) - dist.begin()));
  const std::size_t levels = *std::max_element(dist.begin(), dist.end()) + 1;
  if(levels < 2) return {};
  // the weighted mean of each level: a polyline along the profile, onto which each
  // centroid is projected (onto the segments next to its level) to give its position
  std::vector<Eigen::Vector2d> mid(levels, Eigen::Vector2d::Zero());
  std::vector<double> level_weight(levels, 0.);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t l = dist[cell_of[i]];
    mid[l] += w[i] * Eigen::Vector2d(z[i], r[i]);
    level_weight[l] += w[i];
  }
  for(std::size_t l = 0; l < levels; ++l)
    if(level_weight[l] > 0) mid[l] /= level_weight[l];
  std::vector<double> along(levels, 0.);
  for(std::size_t l = 1; l < levels; ++l) along[l] = along[l - 1] + (mid[l] - mid[l - 1]).norm();
  const double bin = (std::max)(0.5 * h, along[levels - 1] / double(Limits::most_bins));
  // the position along the polyline of the point x, projected onto its segments from
  // the level `from` to the level `to`
  auto position_of = [&](const Eigen::Vector2d& x, std::size_t from, std::size_t to) {
    double nearest = std::numeric_limits<double>::infinity(), s = 0.;
    for(std::size_t k = from; k + 1 < levels && k <= to; ++k)
    {
      const Eigen::Vector2d d = mid[k + 1] - mid[k];
      const double len2 = d.squaredNorm();
      const double t = len2 > 0 ? (std::max)(0., (std::min)(1., (x - mid[k]).dot(d) / len2)) : 0.;
      const double e = (x - mid[k] - t * d).squaredNorm();
      if(e < nearest)
      {
        nearest = e;
        s = along[k] + t * std::sqrt(len2);
      }
    }
    return s;
  };
  std::vector<std::size_t> bin_of(n);
  std::vector<double> position(n);
  std::size_t bins = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t l = dist[cell_of[i]];
    position[i] = position_of(Eigen::Vector2d(z[i], r[i]), l > 2 ? l - 2 : 0, l + 1);
    bin_of[i] = std::size_t(position[i] / bin);
    bins = (std::max)(bins, bin_of[i] + 1);
  }
  if(bins < 2 * Limits::least_bins || bins < Limits::noise_bins) return {};
  // prefix moments per bin, about the profile's mean
  std::vector<Profile_moments> per_bin(bins);
  double mz = 0., mr = 0., wsum = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    mz += w[i] * z[i];
    mr += w[i] * r[i];
    wsum += w[i];
  }
  if(!(wsum > 0)) return {};
  mz /= wsum;
  mr /= wsum;
  for(std::size_t i = 0; i < n; ++i) per_bin[bin_of[i]].add(w[i], z[i] - mz, r[i] - mr);
  std::vector<Profile_moments> prefix(bins + 1);
  for(std::size_t b = 0; b < bins; ++b)
    for(int k = 0; k < 10; ++k) prefix[b + 1].s[k] = prefix[b].s[k] + per_bin[b].s[k];
  // the profile's spread over short windows, against the surface's noise: the offsets
  // of adjacent faces' centroids along their mean normal (each centroid's noise twice)
  double window_error = 0., window_weight = 0.;
  for(std::size_t b = 0; b + Limits::noise_bins <= bins; b += Limits::noise_bins)
  {
    const Profile_moments m = prefix[b + Limits::noise_bins] - prefix[b];
    window_error += m.fit_error();
    window_weight += m.s[0];
  }
  double offsets = 0.;
  std::size_t counted = 0;
  for(const auto& fg : pairs)
  {
    Eigen::Vector3d m = normal[fg.first] + normal[fg.second];
    if(!(m.norm() > 0)) continue;
    m.normalize();
    const double d = (centroid[fg.first] - centroid[fg.second]).dot(m);
    offsets += d * d;
    ++counted;
  }
  if(!(window_weight > 0) || counted == 0) return {};
  const double spread2 = window_error / window_weight, surface2 = offsets / (2. * double(counted));
  if(spread_only)
  {
    *spread_only = spread2;
    return {};
  }
  if(!(spread2 > 0) ||
     spread2 > (std::max)(Limits::spread_ratio * Limits::spread_ratio * surface2, least_spread * least_spread))
    return {};
  // the pieces: fit errors in units of a mean face's squared spread
  const std::size_t least = (std::max)(Limits::least_bins, std::size_t(std::ceil((std::min)(least_length / bin, 1e9))));
  const std::vector<std::size_t> first =
    profile_pieces(prefix, least, spread2 * wsum / double(n), Limits::penalty * std::log(double(n)));
  std::vector<std::size_t> piece(n, 0);
  for(std::size_t i = 0; i < n; ++i)
    piece[i] = std::size_t(std::upper_bound(first.begin(), first.end(), bin_of[i]) - first.begin()) - 1;
  // A cut between two pieces that meet tangentially is poorly placed by the fit errors
  // (an arc leaves its tangent by only d^2 / 2R at a distance d from the seam) but well
  // by the two fits, each over a whole piece: it moves to the point where they touch
  // (its position along the profile), if that is within Revolution_seams::seam_shift
  // bins, and the faces of the two pieces are parted there.
  std::vector<double> cut(first.size(), -1.); // per cut k >= 1, its position, or -1: the bins' cut
  const std::size_t pieces = first.size();
  for(std::size_t k = 1; k < pieces; ++k)
  {
    const std::size_t end = k + 1 < pieces ? first[k + 1] : bins;
    Eigen::Vector2d p1, d1, p2, d2, at;
    double r1 = 0., r2 = 0.;
    if(!(prefix[first[k]] - prefix[first[k - 1]]).fit(p1, d1, r1) || !(prefix[end] - prefix[first[k]]).fit(p2, d2, r2) ||
       !tangent_point(p1, d1, r1, p2, d2, r2, Limits::tangent_angle, at))
      continue;
    const double s = position_of(at + Eigen::Vector2d(mz, mr), 0, levels);
    // within the halves of the two pieces next to the cut, so that the cuts keep their order
    const double lowest = (std::max)(0.5 * double(first[k - 1] + first[k]), double(first[k]) - Limits::seam_shift) * bin;
    const double highest = (std::min)(0.5 * double(first[k] + end), double(first[k]) + Limits::seam_shift) * bin;
    if(!(s >= lowest && s <= highest)) continue;
    cut[k] = s;
    for(std::size_t i = 0; i < n; ++i)
      if(piece[i] == k - 1 || piece[i] == k) piece[i] = position[i] < s ? k - 1 : k;
  }
  if(cut_distance)
  {
    // the distance in bins from the cut at the start of piece k, and from that at its end
    auto from_start = [&](std::size_t i, std::size_t k) {
      return cut[k] >= 0 ? std::size_t((std::max)(0., position[i] - cut[k]) / bin) : bin_of[i] - first[k];
    };
    auto to_end = [&](std::size_t i, std::size_t k) {
      return cut[k + 1] >= 0 ? std::size_t((std::max)(0., cut[k + 1] - position[i]) / bin) : first[k + 1] - 1 - bin_of[i];
    };
    cut_distance->assign(n, std::size_t(-1));
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t k = piece[i];
      std::size_t d = std::size_t(-1);
      if(k > 0) d = from_start(i, k);
      if(k + 1 < pieces) d = (std::min)(d, to_end(i, k));
      (*cut_distance)[i] = d;
    }
  }
  return piece;
}

// The height along the axis `axis` (its unit direction and a point) of the point c and
// its distance from the axis: c in the profile plane.
inline Eigen::Vector2d profile_point(const Eigen::Vector3d& c, const std::pair<Eigen::Vector3d, Eigen::Vector3d>& axis)
{
  const Eigen::Vector3d d = c - axis.second;
  const double z = axis.first.dot(d);
  return Eigen::Vector2d(z, (d - z * axis.first).norm());
}

// Per face of `faces` (a region of one surface of revolution or not), its piece of the
// profile about the axis that fit_revolution_axis() finds (curve_pieces() of the
// centroids' heights along the axis and distances from it), or an empty vector;
// `cut_distance` as curve_pieces().
inline std::vector<std::size_t> revolution_pieces(const std::vector<std::size_t>& faces,
                                                  const std::vector<std::pair<std::size_t, std::size_t> >& pairs,
                                                  const std::vector<Eigen::Vector3d>& centroid,
                                                  const std::vector<Eigen::Vector3d>& normal,
                                                  const std::vector<double>& area, double h,
                                                  std::vector<std::size_t>* cut_distance = nullptr,
                                                  std::pair<Eigen::Vector3d, Eigen::Vector3d>* axis = nullptr)
{
  const std::size_t n = faces.size();
  std::vector<Eigen::Vector3d> c(n), nn(n);
  std::vector<double> w(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    c[i] = centroid[faces[i]];
    nn[i] = normal[faces[i]];
    w[i] = area[faces[i]];
  }
  Eigen::Vector3d a, p;
  if(!fit_revolution_axis(c, nn, w, a, p)) return {};
  const std::pair<Eigen::Vector3d, Eigen::Vector3d> fitted(a, p);
  if(axis) *axis = fitted;
  std::vector<double> z(n), r(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Vector2d q = profile_point(c[i], fitted);
    z[i] = q(0);
    r[i] = q(1);
  }
  return curve_pieces(faces, z, r, w, pairs, centroid, normal, h, 0., 0., nullptr, cut_distance);
}

// Per face of `faces` (a region of one pipe or not), its piece of the pipe's spine: the
// radius rho is the least-squares ratio of the position and vertex-normal differences
// along the region's edges `edges` (pairs of vertex indices; exact on a tube), the spine
// points are the centroids moved by -rho along the faces' normals, and curve_pieces()
// cuts them, in their best plane, into straight pieces (cylinders) and arcs (tori); an
// empty vector if the spine is not that thin and planar.
inline std::vector<std::size_t> pipe_pieces(const std::vector<std::size_t>& faces,
                                            const std::vector<std::pair<std::size_t, std::size_t> >& pairs,
                                            const std::vector<std::pair<std::size_t, std::size_t> >& edges,
                                            const std::vector<Eigen::Vector3d>& point,
                                            const std::vector<Eigen::Vector3d>& vertex_normal,
                                            const std::vector<Eigen::Vector3d>& centroid,
                                            const std::vector<Eigen::Vector3d>& normal, const std::vector<double>& area,
                                            double h)
{
  // A tube's normals cover the circle round its spine: the second moments of its
  // normals have the eigenvalue 1/2 along the binormal of the spine's plane and two that
  // add up to 1/2, so the middle one is at least 1/4. Planes (0) and fillets (0.18 for a
  // quarter circle) are left alone without the search below.
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  double weight = 0.;
  for(std::size_t f : faces)
  {
    moments.noalias() += area[f] * normal[f] * normal[f].transpose();
    weight += area[f];
  }
  if(!(weight > 0) ||
     Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moments / weight, Eigen::EigenvaluesOnly).eigenvalues()(1) <
       Revolution_seams::pipe_least_normal_moment)
    return {};
  double dot = 0., norm2 = 0.;
  for(const auto& e : edges)
  {
    const Eigen::Vector3d dn = vertex_normal[e.first] - vertex_normal[e.second];
    dot += (point[e.first] - point[e.second]).dot(dn);
    norm2 += dn.squaredNorm();
  }
  if(!(norm2 > 0)) return {};
  const std::size_t n = faces.size();
  std::vector<double> w(n), x(n), y(n);
  for(std::size_t i = 0; i < n; ++i) w[i] = area[faces[i]];
  // the spine of radius rho in its best plane (x, y); false if it is not that planar
  double off_plane = 0.;
  auto spine_of = [&](double rho) {
    std::vector<Eigen::Vector3d> spine(n);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double total = 0.;
    for(std::size_t i = 0; i < n; ++i)
    {
      spine[i] = centroid[faces[i]] - rho * normal[faces[i]];
      mean += w[i] * spine[i];
      total += w[i];
    }
    if(!(total > 0)) return false;
    mean /= total;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for(std::size_t i = 0; i < n; ++i) cov.noalias() += w[i] * (spine[i] - mean) * (spine[i] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> plane(cov / total);
    const Eigen::Vector3d u = plane.eigenvectors().col(2), v = plane.eigenvectors().col(1);
    off_plane = plane.eigenvalues()(0);
    for(std::size_t i = 0; i < n; ++i)
    {
      x[i] = u.dot(spine[i] - mean);
      y[i] = v.dot(spine[i] - mean);
    }
    return true;
  };
  // Adjacent vertices' normals differ by little more than their noise, which biases the
  // ratio towards 0: the radius is the one from 0.8 to 2 times it whose spine is thinnest.
  const double rho0 = dot / norm2;
  double best = std::numeric_limits<double>::infinity(), rho = rho0;
  auto spread_at = [&](double r) {
    double spread = std::numeric_limits<double>::infinity();
    if(spine_of(r)) curve_pieces(faces, x, y, w, pairs, centroid, normal, h, 0., 0., &spread);
    if(spread < best)
    {
      best = spread;
      rho = r;
    }
    return spread;
  };
  for(int k = 0; k <= 24; ++k) spread_at(rho0 * (0.8 + 0.05 * k));
  // then a golden-section search within a step of the best: a radius off by a twentieth
  // of a 1.5 radius moves the spine points round a circle of 0.07, three times the
  // spread that 0.1% noise of the diagonal gives a fine tube
  double lo = rho - 0.05 * rho0, hi = rho + 0.05 * rho0;
  const double g = 0.5 * (std::sqrt(5.) - 1.);
  double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
  double fa = spread_at(a), fb = spread_at(b);
  for(int k = 0; k < 10; ++k)
  {
    if(fa < fb)
    {
      hi = b;
      b = a;
      fb = fa;
      a = hi - g * (hi - lo);
      fa = spread_at(a);
    }
    else
    {
      lo = a;
      a = b;
      fa = fb;
      b = lo + g * (hi - lo);
      fb = spread_at(b);
    }
  }
  if(!(best < std::numeric_limits<double>::infinity()) || !spine_of(rho)) return {};
  // off its plane the spine may spread no more than spread_ratio times its spread along it
  if(off_plane > Revolution_seams::spread_ratio * Revolution_seams::spread_ratio * best) return {};
  return curve_pieces(faces, x, y, w, pairs, centroid, normal, h, Revolution_seams::pipe_least_length * std::abs(rho),
                      Revolution_seams::pipe_least_spread * h);
}

// The regions of faces that the interior edges e with `join(e)` join (face_components),
// with, for each region of at least Revolution_seams::least_faces faces (by its root, the
// smallest face index in it), its faces and the pairs of its faces adjacent across an
// edge in index order; `edge_faces`: the two faces of each edge (npos on a border).
struct Seam_regions
{
  std::vector<std::size_t> root;
  std::vector<std::vector<std::size_t> > members;
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > pairs;

  template <typename TriangleMesh, typename Join>
  Seam_regions(const Mesh_indexing<TriangleMesh>& idx, const std::vector<std::size_t>& edge_faces, Join join)
    : root(face_components(idx, join)), members(root.size()), pairs(root.size())
  {
    for(std::size_t f = 0; f < root.size(); ++f) members[root[f]].push_back(f);
    for(std::size_t e = 0; 2 * e < edge_faces.size(); ++e)
    {
      const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
      if(f != idx.npos && g != idx.npos && root[f] == root[g] && fitted(root[f])) pairs[root[f]].emplace_back(f, g);
    }
  }

  // whether f is the root of a region large enough to be fitted
  bool fitted(std::size_t f) const
  {
    return root[f] == f && members[f].size() >= Revolution_seams::least_faces;
  }

  // whether the face f lies in a region too small to be fitted
  bool small(std::size_t f) const { return !fitted(root[f]); }
};

// The unit normal n at the point c in the profile plane of the axis `axis`: its
// components along the axis and away from it; zero on the axis.
inline Eigen::Vector2d profile_normal(const Eigen::Vector3d& c, const Eigen::Vector3d& n,
                                      const std::pair<Eigen::Vector3d, Eigen::Vector3d>& axis)
{
  const Eigen::Vector3d d = c - axis.second;
  const Eigen::Vector3d radial = d - axis.first.dot(d) * axis.first;
  if(!(radial.norm() > 0)) return Eigen::Vector2d::Zero();
  return Eigen::Vector2d(axis.first.dot(n), radial.normalized().dot(n));
}

// Per face of `regions`' small regions (those too small to be fitted), the root of the
// cluster of adjacent small regions it lies in (noise tears a piece into clusters of
// them); per face of a larger region, the root of that region.
template <typename TriangleMesh>
std::vector<std::size_t> small_region_clusters(const Mesh_indexing<TriangleMesh>& idx,
                                               const std::vector<std::size_t>& edge_faces, const Seam_regions& regions)
{
  const std::size_t nf = regions.root.size(), ne = edge_faces.size() / 2;
  Smallest_root_union_find clusters(nf);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
    if(f != idx.npos && g != idx.npos && regions.small(f) && regions.small(g)) clusters.unite(f, g);
  }
  std::vector<std::size_t> key = clusters.roots();
  for(std::size_t f = 0; f < nf; ++f)
    if(!regions.small(f)) key[f] = regions.root[f];
  return key;
}

// Joins the regions of `regions` that are one surface of revolution: noise also leaves
// creases stronger than Revolution_seams::clear_below_angle, which part one face of the
// part into several regions and clusters of small ones between them (the outer wall of
// the fine long tube at 0.3% noise: 25 regions of 100 faces or more). Two regions that
// have pieces (`piece`, `cut_distance`: per face, as revolution_pieces(), piece none =
// std::size_t(-1) outside them) and touch, across creases or a cluster of small regions
// (`key`: small_region_clusters()), are joined if the faces of both have a thin profile
// together, their faces that touch lie in one piece, Revolution_seams::clear_margin bins
// or more from a cut, and the two sides' mean normals in that piece, in the profile
// plane, make at most Revolution_seams::island_angle degrees (on one surface they agree;
// the outer and inner walls of a thin tube, whose profiles noise runs together, face
// opposite ways); the clusters between them are fitted with them, and if that fails the
// two without them (a cluster that reaches round a tube's end cuts the profile there).
// The pairs are tried from the most faces that touch down, in rounds
// while a round joins some (Revolution_seams::join_rounds); the faces of a joined pair
// take the pieces of their common profile, and their root in `axis_of` the axis of that
// profile. `region`: per face, on return the root of the joined regions it lies in.
template <typename TriangleMesh>
void join_coaxial_regions(const Mesh_indexing<TriangleMesh>& idx, const std::vector<std::size_t>& edge_faces,
                          const Seam_regions& regions, const std::vector<std::size_t>& key,
                          const std::vector<Eigen::Vector3d>& centroid, const std::vector<Eigen::Vector3d>& smooth,
                          const std::vector<double>& area, double h, std::vector<std::size_t>& piece,
                          std::vector<std::size_t>& cut_distance, std::vector<std::size_t>& region,
                          std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d> >& axis_of)
{
  typedef Revolution_seams Limits;
  const std::size_t nf = regions.root.size(), ne = edge_faces.size() / 2, none = std::size_t(-1);
  // per pair of regions with pieces that touch, the faces of each that touch the other
  typedef std::pair<std::size_t, std::size_t> Pair;
  std::map<Pair, std::pair<std::vector<std::size_t>, std::vector<std::size_t> > > touching;
  auto touch = [&](std::size_t f, std::size_t g) {
    const std::size_t a = regions.root[f], b = regions.root[g];
    if(a == b) return;
    auto& sides = touching[std::minmax(a, b)];
    (a < b ? sides.first : sides.second).push_back(f);
    (a < b ? sides.second : sides.first).push_back(g);
  };
  // per cluster of small regions, the faces with pieces across its border
  std::map<std::size_t, std::vector<std::size_t> > around;
  for(std::size_t e = 0; e < ne; ++e)
  {
    const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
    if(f == idx.npos || g == idx.npos) continue;
    if(piece[f] != none && piece[g] != none) touch(f, g);
    else if(regions.small(f) && piece[g] != none) around[key[f]].push_back(g);
    else if(regions.small(g) && piece[f] != none) around[key[g]].push_back(f);
  }
  // the clusters between each pair, whose faces fill the gap between their profiles
  std::map<Pair, std::vector<std::size_t> > between;
  for(const auto& kv : around)
  {
    // the faces round the cluster by region, each region's touching those of every other
    std::map<std::size_t, std::vector<std::size_t> > by_region;
    for(std::size_t f : kv.second) by_region[regions.root[f]].push_back(f);
    for(auto a = by_region.begin(); a != by_region.end(); ++a)
      for(auto b = std::next(a); b != by_region.end(); ++b)
      {
        auto& sides = touching[Pair(a->first, b->first)];
        sides.first.insert(sides.first.end(), a->second.begin(), a->second.end());
        sides.second.insert(sides.second.end(), b->second.begin(), b->second.end());
        between[Pair(a->first, b->first)].push_back(kv.first);
      }
  }
  std::map<std::size_t, std::vector<std::size_t> > cluster_faces;
  if(!between.empty())
    for(std::size_t f = 0; f < nf; ++f)
      if(regions.small(f) && around.count(key[f])) cluster_faces[key[f]].push_back(f);
  if(touching.empty()) return;
  std::vector<std::pair<Pair, std::size_t> > order; // (pair, faces that touch)
  for(auto& kv : touching)
    for(std::vector<std::size_t>* side : { &kv.second.first, &kv.second.second })
    {
      std::sort(side->begin(), side->end());
      side->erase(std::unique(side->begin(), side->end()), side->end());
    }
  for(const auto& kv : touching) order.emplace_back(kv.first, kv.second.first.size() + kv.second.second.size());
  std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.second > y.second; });
  Smallest_root_union_find joined(nf);
  std::map<std::size_t, std::vector<std::size_t> > faces_of;
  std::map<std::size_t, std::vector<Pair> > pairs_of;
  auto faces_at = [&](std::size_t r) -> std::vector<std::size_t>& {
    auto it = faces_of.find(r);
    return it != faces_of.end() ? it->second : faces_of.emplace(r, regions.members[r]).first->second;
  };
  auto pairs_at = [&](std::size_t r) -> std::vector<Pair>& {
    auto it = pairs_of.find(r);
    return it != pairs_of.end() ? it->second : pairs_of.emplace(r, regions.pairs[r]).first->second;
  };
  const double least_cosine = std::cos(Limits::island_angle * CGAL_PI / 180.);
  std::vector<std::size_t> position(nf, none), distance;
  // whether the faces of the two regions of a pair that touch lie in one piece of their
  // union's pieces p (of `faces`, the first `split` of one region and those up to
  // `joining` of the other), Limits::clear_margin bins or more from a cut, and the two
  // sides' mean normals in that piece, in the profile plane (along the axis, away from
  // it), agree
  auto one_piece_across = [&](const std::vector<std::size_t>& p, const std::vector<std::size_t>& faces,
                              const Pair& pair, std::size_t split, std::size_t joining,
                              const std::pair<Eigen::Vector3d, Eigen::Vector3d>& axis) {
    if(p.empty()) return false;
    for(std::size_t i = 0; i < faces.size(); ++i) position[faces[i]] = i;
    const auto& sides = touching.at(pair);
    const std::size_t k = p[position[sides.first.front()]];
    for(const std::vector<std::size_t>* side : { &sides.first, &sides.second })
      for(std::size_t f : *side)
        if(p[position[f]] != k || distance[position[f]] < Limits::clear_margin) return false;
    Eigen::Vector2d mean[2] = { Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero() };
    for(std::size_t i = 0; i < joining; ++i)
      if(p[i] == k)
        mean[i < split ? 0 : 1] += area[faces[i]] * profile_normal(centroid[faces[i]], smooth[faces[i]], axis);
    return mean[0].norm() > 0 && mean[1].norm() > 0 && mean[0].normalized().dot(mean[1].normalized()) >= least_cosine;
  };
  // round after round while a pair is joined: a pair whose profiles a gap parts may join
  // once a third region fills it
  for(int round = 0; round < Limits::join_rounds; ++round)
  {
    bool joined_any = false;
    for(const auto& candidate : order)
    {
      const std::size_t a = joined.find(candidate.first.first), b = joined.find(candidate.first.second);
      if(a == b) continue;
      std::vector<std::size_t> faces = faces_at(a);
      const std::size_t split = faces.size();
      faces.insert(faces.end(), faces_at(b).begin(), faces_at(b).end());
      std::vector<Pair> pairs = pairs_at(a);
      pairs.insert(pairs.end(), pairs_at(b).begin(), pairs_at(b).end());
      const std::size_t joining = faces.size();
      // the union with the clusters between the two regions, and if it fails without them
      // (a cluster that reaches across a cut, such as an end of a tube, cuts the union's
      // profile there)
      const auto bridges = between.find(candidate.first);
      const bool bridged = bridges != between.end();
      std::vector<std::size_t> p;
      std::pair<Eigen::Vector3d, Eigen::Vector3d> axis;
      bool ok = false;
      for(int attempt = bridged ? 0 : 1; attempt < 2 && !ok; ++attempt)
      {
        faces.resize(joining);
        if(attempt == 0)
          for(std::size_t c : bridges->second)
          {
            const std::vector<std::size_t>& bridge = cluster_faces[c];
            if(bridge.size() < joining) faces.insert(faces.end(), bridge.begin(), bridge.end());
          }
        p = revolution_pieces(faces, pairs, centroid, smooth, area, h, &distance, &axis);
        ok = one_piece_across(p, faces, candidate.first, split, joining, axis);
      }
      if(!ok) continue;
      faces.resize(joining);
      for(std::size_t i = 0; i < joining; ++i)
      {
        piece[faces[i]] = p[i];
        cut_distance[faces[i]] = distance[i];
      }
      joined.unite(a, b);
      const std::size_t r = joined.find(a), other = r == a ? b : a;
      axis_of[r] = axis;
      faces_of[r] = std::move(faces);
      pairs_of[r] = std::move(pairs);
      faces_of.erase(other);
      pairs_of.erase(other);
      joined_any = true;
    }
    if(!joined_any) break;
  }
  for(std::size_t f = 0; f < nf; ++f) region[f] = joined.find(regions.root[f]);
}

// The islands of `regions` inside the pieces of its surfaces of revolution (`piece`,
// `cut_distance`: per face, its piece, none = std::size_t(-1), and its distance in bins
// from the nearest cut between pieces; `region`: per face, the root of its joined
// regions, join_coaxial_regions()): a small region (`key`: per face, the root of the
// cluster of small regions it lies in, or of its region; small_region_clusters()) whose
// every neighbour lies in one piece, Revolution_seams::clear_margin bins or more from a
// cut, that has fewer faces than the piece's region and whose mean normal in the profile
// plane of the piece's axis (`axis`: per root of `region`) makes at most
// Revolution_seams::island_angle degrees with the piece's (a cap or a flat end across a
// cylinder makes 90). With `grow`, then, round by round, a small region left whose border
// runs along one such piece for Revolution_seams::grow_border_share of its edges or more,
// along no face of no piece nor near a cut of that piece, and along no other piece whose
// profile normal agrees with the region's (an end across a tube's wall is no
// alternative), whose mean profile normal agrees so with the piece's and whose centroids
// lie on the piece's profile line (mean squared offset at most
// Revolution_seams::grow_offset squared times the piece's own). Each island's faces take
// the piece's region, its piece and the least distance that counts as inside it.
// `smooth`: unit normals averaged over the faces sharing a vertex; `centroid`, `area`:
// per face; `edge_faces`: the two faces of each edge (idx.npos on a border).
template <typename TriangleMesh>
void join_islands(const Mesh_indexing<TriangleMesh>& idx, const std::vector<std::size_t>& edge_faces,
                  const Seam_regions& regions, const std::vector<std::size_t>& key,
                  const std::vector<Eigen::Vector3d>& centroid, const std::vector<Eigen::Vector3d>& smooth,
                  const std::vector<double>& area,
                  const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d> >& axis,
                  bool grow, std::vector<std::size_t>& piece, std::vector<std::size_t>& cut_distance,
                  std::vector<std::size_t>& region)
{
  typedef Revolution_seams Limits;
  const std::size_t nf = regions.root.size(), ne = edge_faces.size() / 2;
  const std::size_t none = std::size_t(-1), mixed = std::size_t(-2);
  auto inside = [&](std::size_t f) { return piece[f] != none && cut_distance[f] >= Limits::clear_margin; };
  const double least_cosine = std::cos(Limits::island_angle * CGAL_PI / 180.);
  auto agree = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.norm() > 0 && b.norm() > 0 && a.normalized().dot(b.normalized()) >= least_cosine;
  };
  // per piece (its region and piece): the area-weighted sums of its fitted faces' profile
  // normals and of the moments of their profile points (w, wz, wzz, wr, wzr, wrr)
  typedef std::pair<std::size_t, std::size_t> Piece;
  struct Sums
  {
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();
    Eigen::Matrix<double, 6, 1> moments = Eigen::Matrix<double, 6, 1>::Zero();
  };
  std::map<Piece, Sums> sums;
  std::vector<std::size_t> region_size(nf, 0), cluster_size(nf, 0);
  for(std::size_t f = 0; f < nf; ++f)
  {
    ++cluster_size[key[f]];
    if(regions.small(f) || piece[f] == none) continue;
    ++region_size[region[f]];
    Sums& x = sums[Piece(region[f], piece[f])];
    x.normal += area[f] * profile_normal(centroid[f], smooth[f], axis[region[f]]);
    const Eigen::Vector2d q = profile_point(centroid[f], axis[region[f]]);
    Eigen::Matrix<double, 6, 1> moments;
    moments << 1., q(0), q(0) * q(0), q(1), q(0) * q(1), q(1) * q(1);
    x.moments += area[f] * moments;
  }
  // per cluster of small regions (at its root): the region and piece of all its
  // neighbours, or mixed
  std::vector<std::size_t> around(nf, none), around_piece(nf, none);
  auto neighbour = [&](std::size_t r, std::size_t g) {
    if(around[r] == mixed) return;
    if(g == idx.npos || regions.small(g) || !inside(g))
      around[r] = mixed;
    else if(around[r] == none)
    {
      around[r] = region[g];
      around_piece[r] = piece[g];
    }
    else if(around[r] != region[g] || around_piece[r] != piece[g])
      around[r] = mixed;
  };
  for(std::size_t e = 0; e < ne; ++e)
  {
    const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
    if(f != idx.npos && regions.small(f) && (g == idx.npos || key[g] != key[f])) neighbour(key[f], g);
    if(g != idx.npos && regions.small(g) && (f == idx.npos || key[f] != key[g])) neighbour(key[g], f);
  }
  auto island = [&](std::size_t r) {
    return around[r] != none && around[r] != mixed && cluster_size[r] < region_size[around[r]];
  };
  std::vector<Eigen::Vector2d> mean(nf, Eigen::Vector2d::Zero());
  for(std::size_t f = 0; f < nf; ++f)
    if(island(key[f])) mean[key[f]] += area[f] * profile_normal(centroid[f], smooth[f], axis[around[key[f]]]);
  auto join = [&](std::size_t f, std::size_t r, std::size_t k) {
    region[f] = r;
    piece[f] = k;
    cut_distance[f] = Limits::clear_margin;
  };
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t r = key[f];
    if(island(r) && agree(mean[r], sums.at(Piece(around[r], around_piece[r])).normal))
      join(f, around[r], around_piece[r]);
  }
  if(!grow) return;
  // each piece's profile line r = a + b z, and its mean squared offset from it
  std::map<Piece, Eigen::Vector3d> line;
  for(const auto& kv : sums)
  {
    const Eigen::Matrix<double, 6, 1> m = kv.second.moments / kv.second.moments(0);
    const double szz = m(2) - m(1) * m(1), szr = m(4) - m(1) * m(3), srr = m(5) - m(3) * m(3);
    const double b = szz > 0 ? szr / szz : 0.;
    line[kv.first] = Eigen::Vector3d(m(3) - b * m(1), b, (std::max)(0., srr - b * szr));
  }
  // a face that is no candidate: one of a region that is not small, or one joined
  std::vector<char> settled(nf, 0);
  for(std::size_t f = 0; f < nf; ++f) settled[f] = !regions.small(f) || piece[f] != none;
  for(int round = 0; round < Limits::grow_rounds; ++round)
  {
    // per small region left (at its root): its border edges, and per piece of the settled
    // faces across them (none: a face of no piece), the edges to faces inside it and to
    // faces near its cuts
    std::vector<std::size_t> border(nf, 0);
    std::map<std::size_t, std::map<Piece, std::pair<std::size_t, std::size_t> > > next_to;
    for(std::size_t e = 0; e < ne; ++e)
    {
      const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
      if(f == idx.npos || g == idx.npos) continue;
      for(const auto& [a, b] : { std::make_pair(f, g), std::make_pair(g, f) })
      {
        const std::size_t r = regions.root[a];
        if(settled[a] || regions.root[b] == r) continue;
        ++border[r];
        if(!settled[b]) continue;
        auto& count = next_to[r][Piece(region[b], piece[b])];
        ++(inside(b) ? count.first : count.second);
      }
    }
    // the piece a small region may join: the one along whose inner faces (none near its
    // cuts) its border runs longest, for Limits::grow_border_share of its edges or more,
    // with no face of no piece across its border; the other pieces there are tested below
    std::vector<std::size_t> to(nf, none), to_piece(nf, none);
    std::vector<std::vector<Piece> > others(nf);
    for(const auto& [r, pieces] : next_to)
    {
      std::size_t best = 0;
      bool ok = true;
      for(const auto& [k, count] : pieces)
      {
        if(k.second == none) ok = false;
        if(count.first > best && count.second == 0) { best = count.first; to[r] = k.first; to_piece[r] = k.second; }
      }
      if(!ok || best == 0 || double(best) < Limits::grow_border_share * double(border[r]))
      {
        to[r] = none;
        continue;
      }
      for(const auto& kv : pieces)
        if(kv.first != Piece(to[r], to_piece[r])) others[r].push_back(kv.first);
    }
    auto candidate = [&](std::size_t r) { return to[r] != none; };
    std::vector<Eigen::Vector2d> normal(nf, Eigen::Vector2d::Zero());
    std::vector<double> offset(nf, 0.), weight(nf, 0.);
    std::map<std::pair<std::size_t, Piece>, Eigen::Vector2d> other_normal;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = regions.root[f];
      if(settled[f] || !candidate(r)) continue;
      const Eigen::Vector3d& l = line.at(Piece(to[r], to_piece[r]));
      const Eigen::Vector2d q = profile_point(centroid[f], axis[to[r]]);
      normal[r] += area[f] * profile_normal(centroid[f], smooth[f], axis[to[r]]);
      const double off = q(1) - l(0) - l(1) * q(0);
      offset[r] += area[f] * off * off;
      weight[r] += area[f];
      for(const Piece& k : others[r])
      {
        auto it = other_normal.emplace(std::make_pair(r, k), Eigen::Vector2d::Zero()).first;
        it->second += area[f] * profile_normal(centroid[f], smooth[f], axis[k.first]);
      }
    }
    std::vector<char> take(nf, 0);
    bool any = false;
    for(std::size_t r = 0; r < nf; ++r)
    {
      if(regions.root[r] != r || settled[r] || !candidate(r) || !(weight[r] > 0)) continue;
      const Piece k(to[r], to_piece[r]);
      take[r] = agree(normal[r], sums.at(k).normal) &&
                offset[r] <= Limits::grow_offset * Limits::grow_offset * line.at(k)(2) * weight[r];
      for(const Piece& o : others[r])
      {
        const auto it = sums.find(o);
        if(it == sums.end() || agree(other_normal.at(std::make_pair(r, o)), it->second.normal)) take[r] = 0;
      }
      any = any || take[r];
    }
    if(!any) break;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::size_t r = regions.root[f];
      if(settled[f] || !take[r]) continue;
      join(f, to[r], to_piece[r]);
      settled[f] = 1;
    }
  }
}

// Marks 2 in `is_crease` (a curvature discontinuity) the edges that are no crease and
// part the faces of two pieces of the profile of a surface of revolution
// (revolution_pieces()) or of the spine of a pipe (pipe_pieces(), for a region that is
// no surface of revolution) in a region of at least Revolution_seams::least_faces faces
// that the marked edges of `is_crease` bound. With `angle` (per edge, the filtered
// dihedral angle in degrees), it also unmarks the creases inside the pieces of the
// surfaces of revolution that stronger creases bound (Revolution_seams::
// clear_below_angle), those between such regions of one surface
// (join_coaxial_regions()), and those inside and round their islands (join_islands(),
// with `clusters` as on a heavily noisy mesh: clusters of small regions as islands, and
// the regions left grown into the pieces); the seams are those of the regions before.
// `normal`, `area`,
// `centroid`: the faces' raw unit normals, areas and centroids; `begin`, `ring`: the
// faces sharing a vertex with each face (vertex_adjacent_faces). Without `pipes`, a
// region that is no surface of revolution is left alone. Returns the number of edges
// marked.
template <typename TriangleMesh, typename VPM>
std::size_t mark_revolution_seams(const Mesh_indexing<TriangleMesh>& idx, VPM vpm,
                                  const std::vector<Eigen::Vector3d>& normal, const std::vector<double>& area,
                                  const std::vector<Eigen::Vector3d>& centroid, const std::vector<std::uint32_t>& begin,
                                  const std::vector<std::uint32_t>& ring, std::vector<char>& is_crease,
                                  const std::vector<double>* angle = nullptr, bool pipes = true,
                                  bool clusters = false)
{
  typedef Revolution_seams Limits;
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces(), ne = idx.number_of_edges();
  if(ne == 0) return 0;
  // the two faces of each edge, and the regions the creases bound
  std::vector<std::size_t> edge_faces(2 * ne, idx.npos);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    edge_faces[2 * e] = idx.face_id(h);
    edge_faces[2 * e + 1] = idx.face_id(opposite(h, tm));
  }
  const Seam_regions regions(idx, edge_faces, [&](std::size_t e) { return !is_crease[e]; });
  const std::vector<std::size_t>& root = regions.root;
  const std::vector<std::vector<std::size_t> >& members = regions.members;
  // with `angle`, the regions that the creases of at least Limits::clear_below_angle bound
  const double strong = Limits::clear_below_angle;
  std::optional<Seam_regions> outer;
  if(angle)
    outer.emplace(idx, edge_faces, [&](std::size_t e) { return !(is_crease[e] == 1 && (*angle)[e] >= strong); });
  // nothing to do without a region large enough to be fitted
  bool fitted = false;
  for(std::size_t f = 0; f < nf && !fitted; ++f) fitted = regions.fitted(f) || (outer && outer->fitted(f));
  if(!fitted) return 0;
  // the median edge length, the unit of the profiles' bins
  std::vector<Eigen::Vector3d> middle, direction;
  std::vector<double> length;
  edge_middles_and_directions(idx, vpm, middle, direction, &length);
  const double median_edge = median_length(length);
  // The normals averaged over the faces sharing a vertex, for the axes, and averaged so
  // within each region, for the spines: across a crease they bend towards the other
  // side, which bends a pipe's spine at its ends into short pieces, while the axes fit
  // better on normals averaged across (over three noise realisations, averaging within
  // regions for both loses the generated mean at 0.3% noise 0.002).
  std::vector<Eigen::Vector3d> smooth = normal, within = normal, averaged(nf), next_within(nf);
  for(int round = 0; round < Limits::smoothing_rounds; ++round)
  {
    for(std::size_t f = 0; f < nf; ++f)
    {
      Eigen::Vector3d s = Eigen::Vector3d::Zero(), t = Eigen::Vector3d::Zero();
      for(std::size_t i = begin[f]; i < begin[f + 1]; ++i)
      {
        s += area[ring[i]] * smooth[ring[i]];
        if(root[ring[i]] == root[f]) t += area[ring[i]] * within[ring[i]];
      }
      averaged[f] = s.norm() > 0 ? Eigen::Vector3d(s.normalized()) : smooth[f];
      next_within[f] = t.norm() > 0 ? Eigen::Vector3d(t.normalized()) : within[f];
    }
    smooth.swap(averaged);
    within.swap(next_within);
  }
  std::vector<std::size_t> piece(nf, 0);
  bool any = false;
  // with `angle`, the profile pieces and cut distances of the regions that are surfaces
  // of revolution, for the regions of the stronger creases that are the same regions
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> revolution_piece(angle ? nf : 0, none), revolution_distance(angle ? nf : 0, 0), distance;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d> > region_axis(angle ? nf : 0);
  // the vertices' points, and per region that is no surface of revolution the normals
  // of its vertices (from its own faces) and its edges, for pipe_pieces()
  const std::size_t nv = idx.number_of_vertices();
  std::vector<Eigen::Vector3d> point(nv), vertex_normal(nv, Eigen::Vector3d::Zero());
  for(std::size_t v = 0; v < nv; ++v)
  {
    const auto& q = get(vpm, idx.vertex_at(v));
    point[v] = Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
  }
  std::vector<std::size_t> edge_stamp(ne, std::size_t(-1)), vertex_stamp(nv, std::size_t(-1)), touched;
  std::vector<std::pair<std::size_t, std::size_t> > region_edges;
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!regions.fitted(f)) continue;
    std::vector<std::size_t> p = revolution_pieces(members[f], regions.pairs[f], centroid, smooth, area, median_edge,
                                                   angle ? &distance : nullptr, angle ? &region_axis[f] : nullptr);
    for(std::size_t i = 0; angle && i < p.size(); ++i)
    {
      revolution_piece[members[f][i]] = p[i];
      revolution_distance[members[f][i]] = distance[i];
    }
    if(p.empty() && pipes)
    {
      region_edges.clear();
      touched.clear();
      for(std::size_t g : members[f])
      {
        const auto h0 = halfedge(idx.face_at(g), tm);
        auto h = h0;
        do
        {
          const std::size_t v = idx.id(target(h, tm));
          if(vertex_stamp[v] != f)
          {
            vertex_stamp[v] = f;
            vertex_normal[v] = Eigen::Vector3d::Zero();
            touched.push_back(v);
          }
          vertex_normal[v] += area[g] * within[g];
          const std::size_t e = idx.edge_id(h);
          if(edge_stamp[e] != f)
          {
            edge_stamp[e] = f;
            region_edges.emplace_back(idx.id(source(h, tm)), v);
          }
          h = next(h, tm);
        } while(h != h0);
      }
      for(std::size_t v : touched)
        if(vertex_normal[v].squaredNorm() > 0) vertex_normal[v].normalize();
      p = pipe_pieces(members[f], regions.pairs[f], region_edges, point, vertex_normal, centroid, within, area, median_edge);
    }
    for(std::size_t i = 0; i < p.size(); ++i)
    {
      piece[members[f][i]] = p[i];
      any = any || p[i] != 0;
    }
  }
  // the creases inside one piece of a surface of revolution that stronger creases bound
  if(outer)
  {
    std::vector<std::size_t> outer_piece(nf, none), cut_distance(nf, 0);
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d> > axis_of(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(!outer->fitted(f)) continue;
      const std::vector<std::size_t>& faces = outer->members[f];
      if(faces.size() == members[root[f]].size())
      {
        // the region the creases bound, fitted above (the same faces, the same pairs)
        for(std::size_t g : faces)
        {
          outer_piece[g] = revolution_piece[g];
          cut_distance[g] = revolution_distance[g];
        }
        axis_of[f] = region_axis[root[f]];
        continue;
      }
      const std::vector<std::size_t> p =
        revolution_pieces(faces, outer->pairs[f], centroid, smooth, area, median_edge, &distance, &axis_of[f]);
      for(std::size_t i = 0; i < p.size(); ++i)
      {
        outer_piece[faces[i]] = p[i];
        cut_distance[faces[i]] = distance[i];
      }
    }
    // per face, its region of the stronger creases, or that of the piece round its island
    std::vector<std::size_t> region = outer->root;
    const std::vector<std::size_t> key = clusters ? small_region_clusters(idx, edge_faces, *outer) : outer->root;
    join_coaxial_regions(idx, edge_faces, *outer, key, centroid, smooth, area, median_edge, outer_piece, cut_distance,
                         region, axis_of);
    join_islands(idx, edge_faces, *outer, key, centroid, smooth, area, axis_of, clusters, outer_piece, cut_distance,
                 region);
    for(std::size_t e = 0; e < ne; ++e)
    {
      const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
      if(is_crease[e] != 1 || f == idx.npos || g == idx.npos || region[f] != region[g] || outer_piece[f] == none ||
         outer_piece[f] != outer_piece[g] || cut_distance[f] < Limits::clear_margin ||
         cut_distance[g] < Limits::clear_margin)
        continue;
      is_crease[e] = 0;
    }
  }
  if(!any) return 0;
  std::size_t marked = 0;
  for(std::size_t e = 0; e < ne; ++e)
  {
    const std::size_t f = edge_faces[2 * e], g = edge_faces[2 * e + 1];
    if(is_crease[e] || f == idx.npos || g == idx.npos || root[f] != root[g] || piece[f] == piece[g]) continue;
    is_crease[e] = 2;
    ++marked;
  }
  return marked;
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_REVOLUTION_SEAMS_H
