// SPDX-License-Identifier: GPL-3.0-or-later
// The measure behind the gap test of the crease candidates (crease_gap_test.h): the
// thresholds of the test, and the search that sums, within a ball around a candidate,
// the lengths of the crease candidates and of the edges in the band just below them.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_SEARCH_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_SEARCH_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/breadth_first_clusters.h>

#include <CGAL/assertions.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The constants of the gap test, which tells a crease from a strong bend of a smooth
// surface: within the ball around a candidate edge's midpoint (radius `radius` of the
// diagonal, at least two mean edge lengths), on the surface reached from the candidate,
// the edges bending by [band * crease_angle, crease_angle), each weighted by the
// squared cosine of its angle with the candidate on a tessellation with large planar
// regions (band_weight()), may have at most `ratio` times the length of the
// candidates. A CAD tessellation leaves a gap below its creases (on the 14 parts of the
// evaluation, no edge between 15 and 30 degrees apart from the creases); a coarse or
// scanned smooth surface bends by every angle, so its strong bends come with as many
// slightly weaker ones around them.
struct Crease_gap
{
  static constexpr double band = 0.75, ratio = 0.5, radius = 0.05;
  // A candidate bending by `strong_angle` degrees or more is a crease whatever its ball
  // holds: the facets of a curved face bend far less (by 22.5 degrees with 16 round a
  // circle), while the ball of a long thin part's end (a tube twenty times longer than
  // wide: radius 5% of the diagonal, twice its width) holds more of them than of the
  // end's crease, and so does the ball of a coarse plate's hole rims under light noise
  // (the generated coarse plate with holes at 0.1% of the diagonal, read on its raw
  // angles: 0.91 with the test for every bend, 1.00 without; the coarse hopper 0.95 and
  // 0.92 at 0.1% and 0.3% noise, 1.00 and 0.99 without). No other row of the CAD table
  // or the quality table (the paper's smooth models, clean and noisy) changes by more
  // than 1e-5 over three noise realisations.
  static constexpr double strong_angle = 85.;
  // The raw roughness (normal_roughness) up to which the band is read on the raw angles:
  // clean CAD parts measure at most 0.0085 and the paper's smooth models 0.012 to 0.028,
  // whose filtered normals turn smooth bends into staircases with gaps; noisy meshes
  // (0.035 and more at 0.1% of the diagonal) are read on the filtered angles.
  static constexpr double raw_roughness = 0.03;
};

// The lengths one ball of the gap test holds: of the edges bending by crease_angle or
// more, and of those in the band below, each band edge's length times the squared
// cosine of its angle with the candidate (band_weight()).
struct Gap_lengths
{
  double crease = 0, band = 0;
};

// The weight of a band edge along `d` in the ball of a candidate along the unit vector
// `t`: the squared cosine of their angle (1 for a zero-length d, which adds nothing).
// The weaker bends that make a strong bend one of a smooth surface run beside it (a
// ridge's flanks), while the rulings of a coarse cylinder or cone that ends in a crease
// run across it: those bend by 18 to 22.5 degrees with 16 to 20 facets round, in the
// band, yet a cone meeting a cylinder at 35 degrees, or a tube's 90-degree end, is a
// crease. A squared cosine, so that the band of a cluster of edges is one symmetric
// tensor, read for any candidate (Band_tensor).
inline double band_weight(const Eigen::Vector3d& d, const Eigen::Vector3d& t)
{
  const double dd = d.squaredNorm();
  if(!(dd > 0)) return 1.;
  const double c = d.dot(t);
  return c * c / dd;
}

// The band edges of a cluster as one symmetric tensor, the sum of length * d d^T / |d|^2
// over its edges: along(t) = t^T M t is their length weighted by band_weight(d, t).
struct Band_tensor
{
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;

  void add(const Eigen::Vector3d& d, double length)
  {
    const double dd = d.squaredNorm();
    if(!(dd > 0)) return;
    const double w = length / dd;
    xx += w * d.x() * d.x(); xy += w * d.x() * d.y(); xz += w * d.x() * d.z();
    yy += w * d.y() * d.y(); yz += w * d.y() * d.z(); zz += w * d.z() * d.z();
  }
  void add(const Band_tensor& o)
  {
    xx += o.xx; xy += o.xy; xz += o.xz; yy += o.yy; yz += o.yz; zz += o.zz;
  }
  // their length, unweighted
  double trace() const { return xx + yy + zz; }
  double along(const Eigen::Vector3d& t) const
  {
    return xx * t.x() * t.x() + yy * t.y() * t.y() + zz * t.z() * t.z() +
           2 * (xy * t.x() * t.y() + xz * t.x() * t.z() + yz * t.y() * t.z());
  }
};

// Whether an edge is in the band below the creases: bending by less than crease_angle,
// but by Crease_gap::band * crease_angle or more on the band's angles.
inline bool is_crease_gap_band_edge(double angle, double band_angle, double crease_angle)
{
  return angle < crease_angle && band_angle >= Crease_gap::band * crease_angle;
}

// The radius of the gap test's balls (Crease_gap::radius of the diagonal of the bounding
// box, at least two mean edge lengths: on a coarse mesh the ball must still reach the
// candidate's neighbours), from the vertices and the edges' two vertices.
template <typename Point, typename Ends>
double crease_gap_ball_radius(const std::vector<Point>& points, const std::vector<Ends>& ends)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  double mean_edge = 0;
  for(const auto& e : ends)
  {
    const Eigen::Vector3d& a = points[e[0]];
    const Eigen::Vector3d& b = points[e[1]];
    lo = lo.cwiseMin(a).cwiseMin(b);
    hi = hi.cwiseMax(a).cwiseMax(b);
    mean_edge += (b - a).norm();
  }
  mean_edge /= double((std::max)(ends.size(), std::size_t(1)));
  return (std::max)(Crease_gap::radius * (hi - lo).norm(), 2 * mean_edge);
}

// The length of the part of segment [a, b] inside the ball of radius r around c: lengths
// of curves within a ball, the same on a mesh and on its flat subdivision.
inline double length_in_ball(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double r)
{
  const Eigen::Vector3d d = b - a, m = a - c;
  const double aa = d.squaredNorm(), bb = m.dot(d), k = m.squaredNorm() - r * r;
  const double disc = bb * bb - aa * k;
  if(aa == 0 || disc <= 0) return 0.;
  const double root = std::sqrt(disc);
  const double t0 = (std::max)(0., (-bb - root) / aa), t1 = (std::min)(1., (-bb + root) / aa);
  return t1 > t0 ? (t1 - t0) * std::sqrt(aa) : 0.;
}

// What the gap test reads of the mesh's geometry, made once: the vertices' positions
// and every edge's two vertices (32-bit ids).
struct Edge_geometry
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::uint32_t, 2> > ends;
};

template <typename TriangleMesh, typename VPM>
Edge_geometry edge_geometry(const Mesh_indexing<TriangleMesh>& idx, VPM vpm)
{
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces(), ne = idx.number_of_edges(), nv = idx.number_of_vertices();
  if((std::max)({ nf, ne, nv }) >= std::size_t(std::uint32_t(-1)))
    throw std::length_error("the crease gap test stores element ids in 32 bits");
  Edge_geometry g;
  g.points.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    const auto& p = get(vpm, idx.vertex_at(v));
    g.points[v] = Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  g.ends.resize(ne);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const auto h = halfedge(idx.edge_at(e), tm);
    g.ends[e] = { std::uint32_t(idx.id(source(h, tm))), std::uint32_t(idx.id(target(h, tm))) };
  }
  return g;
}

// The search behind the gap test. The ball of a candidate holds a fixed share of the
// surface, so a search face by face costs the faces of the ball, which grow with the
// resolution (fandisk at 828k faces: 6,900 faces per ball, for each of its 7,008
// candidates; with the clusters, 1,360 faces and 760 clusters). The faces are
// therefore grouped into a hierarchy of connected clusters (about 16 faces, then 8
// clusters per level), each with a bounding sphere, the lengths of the edges it owns
// (an edge belongs to the cluster of the face of its halfedge) and the faces across its
// border. A cluster whose sphere lies inside the ball is reached whole once one of its
// faces is: its lengths are added at once and the search goes on from its border;
// face by face only in the clusters the ball's sphere cuts; levels whose clusters are
// all larger than a ball are not kept. The lengths are those of the face-by-face search
// (`max_levels` 0) up to the order of the additions: a cluster with a zero-length edge,
// which the face search does not cross, is never taken whole.
template <typename TriangleMesh>
class Crease_gap_search
{
  typedef std::uint32_t Index;
  static constexpr Index none = Index(-1);

  struct Level
  {
    std::vector<Index> parent;                   // per child (a face, or a cluster of the level below)
    std::vector<Eigen::Vector3d> center;         // per cluster: its bounding sphere
    std::vector<double> radius;
    std::vector<double> crease;                  // the length of the crease edges it owns
    std::vector<Band_tensor> band;               // its band edges (an edge belongs to one cluster)
    std::vector<char> has_zero_length_edge;
    std::vector<std::size_t> border_begin;       // CSR over `border`
    std::vector<std::array<Index, 2> > border;   // (face outside, edge) pairs, by neighbour
    std::vector<std::size_t> group_begin;        // CSR over `groups`
    std::vector<std::pair<Index, std::size_t> > groups; // (neighbour, its first pair in `border`)
  };

public:
  // `geometry` is edge_geometry(idx, the vertex point map); `max_levels` 0: the search
  // face by face; `by_direction`: the band edges weigh by band_weight(), else their
  // lengths count whole.
  Crease_gap_search(const Mesh_indexing<TriangleMesh>& idx, Edge_geometry geometry, const std::vector<double>& angle,
                    const std::vector<double>& band_angle, double crease_angle, int max_levels = 8,
                    bool by_direction = true)
    : m_idx(idx), m_crease_angle(crease_angle), m_by_direction(by_direction), m_points(std::move(geometry.points)),
      m_ends(std::move(geometry.ends))
  {
    const TriangleMesh& tm = idx.mesh();
    const std::size_t nf = idx.number_of_faces(), ne = idx.number_of_edges();
    CGAL_precondition(m_points.size() == idx.number_of_vertices() && m_ends.size() == ne);
    // what the search reads per edge, compactly (it visits millions of edges in no
    // particular order): its two vertices (m_ends) and what its angles make it
    m_kind.resize(ne);
    m_owner.assign(ne, none);
    for(std::size_t e = 0; e < ne; ++e)
    {
      const auto h = halfedge(idx.edge_at(e), tm);
      m_kind[e] = is_crease_gap_band_edge(angle[e], band_angle[e], crease_angle) ? BAND
                  : angle[e] >= crease_angle ? CREASE : OTHER;
      std::size_t f = idx.face_id(h);
      if(f == idx.npos) f = idx.face_id(opposite(h, tm));
      if(f != idx.npos) m_owner[e] = Index(f);
    }
    m_radius = crease_gap_ball_radius(m_points, m_ends);
    m_adj.resize(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
      {
        const std::size_t g = idx.face_id(opposite(h, tm));
        m_adj[f][k] = { g == idx.npos ? none : Index(g), Index(idx.edge_id(h)) };
        if(++k == 3) break;
      }
    }
    build_levels(max_levels);
  }

  double radius() const { return m_radius; }
  std::size_t number_of_levels() const { return m_levels.size(); }

  // A thread's stamps and queue.
  struct Work_space
  {
    // stamps: the number of the search (32 bits: the search numbers stay below `none`)
    std::vector<Index> face_stamp, edge_stamp;
    std::vector<std::size_t> queue;
    std::vector<std::vector<Index> > inside_stamp, done_stamp; // per level, per cluster
    std::vector<std::vector<char> > inside;
  };

  // The lengths in the ball of the search numbered `stamp` (distinct per call with one
  // work space) around the midpoint of edge `e`, from its faces.
  Gap_lengths lengths(std::size_t e, std::size_t search_number, Work_space& ws) const
  {
    return lengths(e, search_number, ws, [](const Gap_lengths&) { return false; });
  }

  // The same, ending as soon as `stop` holds for the lengths added so far (read after
  // each addition; the sums only grow): the lengths then are those added so far.
  template <typename Stop>
  Gap_lengths lengths(std::size_t e, std::size_t search_number, Work_space& ws, const Stop& stop) const
  {
    CGAL_precondition(search_number < std::size_t(none));
    const Index stamp = Index(search_number);
    prepare(ws);
    const TriangleMesh& tm = m_idx.mesh();
    const Eigen::Vector3d c = 0.5 * (end0(e) + end1(e));
    Eigen::Vector3d t = end1(e) - end0(e); // the candidate's direction
    if(t.squaredNorm() > 0) t.normalize();
    const double r_whole = m_radius * (1 - 1e-9); // a cluster inside this radius is inside the ball
    const std::size_t nl = m_levels.size();
    // whether cluster x of level l lies inside the ball, once per search
    auto inside = [&](std::size_t l, Index x) {
      if(ws.inside_stamp[l][x] != stamp)
      {
        ws.inside_stamp[l][x] = stamp;
        const Level& L = m_levels[l];
        ws.inside[l][x] = !L.has_zero_length_edge[x] && (L.center[x] - c).norm() + L.radius[x] <= r_whole;
      }
      return ws.inside[l][x] != 0;
    };
    // the highest level of a cluster that holds face f and lies inside the ball, its
    // cluster in `cluster`; -1: none
    auto whole = [&](Index f, Index& cluster) {
      std::array<Index, 16> chain;
      Index x = f;
      for(std::size_t l = 0; l < nl; ++l) chain[l] = x = m_levels[l].parent[x];
      for(std::size_t l = nl; l-- > 0;)
        if(inside(l, chain[l])) { cluster = chain[l]; return int(l); }
      return -1;
    };
    Gap_lengths sum;
    ws.queue.clear();
    const auto h = halfedge(m_idx.edge_at(e), tm);
    for(std::size_t f : { m_idx.face_id(h), m_idx.face_id(opposite(h, tm)) })
      if(f != m_idx.npos && ws.face_stamp[f] != stamp) { ws.face_stamp[f] = stamp; ws.queue.push_back(f); }
    for(std::size_t j = 0; j < ws.queue.size(); ++j)
    {
      const Index x = Index(ws.queue[j]);
      Index cluster = none;
      const int l = whole(x, cluster);
      if(l >= 0)
      {
        if(ws.done_stamp[l][cluster] == stamp) continue;
        ws.done_stamp[l][cluster] = stamp;
        const Level& L = m_levels[l];
        sum.crease += L.crease[cluster];
        sum.band += m_by_direction ? L.band[cluster].along(t) : L.band[cluster].trace();
        if(stop(sum)) return sum;
        for(std::size_t g = L.group_begin[cluster]; g < L.group_begin[cluster + 1]; ++g)
        {
          const std::size_t first = L.groups[g].second,
                            last = g + 1 < L.group_begin[cluster + 1] ? L.groups[g + 1].second : L.border_begin[cluster + 1];
          // a neighbour inside the ball is reached whole through any of the pairs (the
          // edges between two clusters inside the ball are inside and of nonzero length)
          if(inside(l, L.groups[g].first))
          {
            const Index y = L.border[first][0];
            Index whole_cluster = none;
            const int k = whole(y, whole_cluster);
            if(ws.face_stamp[y] == stamp || ws.done_stamp[k][whole_cluster] == stamp) continue;
            ws.face_stamp[y] = stamp;
            ws.queue.push_back(y);
            continue;
          }
          for(std::size_t i = first; i < last; ++i)
          {
            const Index y = L.border[i][0];
            if(ws.face_stamp[y] == stamp || length_inside(L.border[i][1], c) <= 0) continue;
            ws.face_stamp[y] = stamp;
            ws.queue.push_back(y);
          }
        }
        continue;
      }
      for(const auto& a : m_adj[x])
      {
        const Index y = a[0], ye = a[1];
        if(ws.edge_stamp[ye] == stamp) continue; // seen from its other face
        ws.edge_stamp[ye] = stamp;
        const double in = length_inside(ye, c);
        if(in <= 0) continue;
        Index owner_cluster;
        // counted here unless its cluster is taken whole (most edges count for nothing)
        if(counts(ye) && whole(m_owner[ye], owner_cluster) < 0)
        {
          add(ye, in, t, sum);
          if(stop(sum)) return sum;
        }
        if(y == none || ws.face_stamp[y] == stamp) continue;
        ws.face_stamp[y] = stamp;
        ws.queue.push_back(y);
      }
    }
    return sum;
  }

private:
  // The length of the part of edge x inside the ball around c: lengths of curves within
  // a ball, the same on a mesh and on its flat subdivision.
  const Eigen::Vector3d& end0(std::size_t x) const { return m_points[m_ends[x][0]]; }
  const Eigen::Vector3d& end1(std::size_t x) const { return m_points[m_ends[x][1]]; }

  double length_inside(std::size_t x, const Eigen::Vector3d& c) const
  {
    return length_in_ball(end0(x), end1(x), c, m_radius);
  }

  bool counts(std::size_t x) const { return m_kind[x] != OTHER; }

  // adds `length` of edge x to the sums of a candidate along t
  void add(std::size_t x, double length, const Eigen::Vector3d& t, Gap_lengths& sum) const
  {
    if(m_kind[x] == CREASE) sum.crease += length;
    else if(m_kind[x] == BAND) sum.band += m_by_direction ? length * band_weight(end1(x) - end0(x), t) : length;
  }

  void prepare(Work_space& ws) const
  {
    if(ws.face_stamp.size() == m_adj.size()) return;
    ws.face_stamp.assign(m_adj.size(), none);
    ws.edge_stamp.assign(m_ends.size(), none);
    ws.inside_stamp.resize(m_levels.size());
    ws.done_stamp.resize(m_levels.size());
    ws.inside.resize(m_levels.size());
    for(std::size_t l = 0; l < m_levels.size(); ++l)
    {
      ws.inside_stamp[l].assign(m_levels[l].radius.size(), none);
      ws.done_stamp[l].assign(m_levels[l].radius.size(), none);
      ws.inside[l].assign(m_levels[l].radius.size(), 0);
    }
  }

  // Groups the n children into connected clusters of about `size`, grown breadth first
  // from the first child not yet grouped (breadth_first_clusters.h;
  // for_each_neighbour(child, f) calls f on each neighbour); a cluster left under half
  // the size (the growth ran out of children around it) joins a neighbouring cluster.
  // Returns the number of clusters.
  template <typename ForEachNeighbour>
  static std::size_t grow_clusters(std::size_t n, std::size_t size, ForEachNeighbour for_each_neighbour,
                                   std::vector<Index>& parent)
  {
    Breadth_first_clusters grown;
    grown.grow(n, size, for_each_neighbour);
    parent.swap(grown.cluster_of);
    // the small clusters join a neighbour (union-find over the clusters, the root the
    // cluster joined), then the roots are numbered in order
    const std::vector<Index>& first = grown.first;
    const std::size_t m = grown.size();
    std::vector<Index> root(m);
    for(std::size_t c = 0; c < m; ++c) root[c] = Index(c);
    auto find = [&](Index c) { while(root[c] != c) c = root[c] = root[root[c]]; return c; };
    for(std::size_t c = 0; c < m; ++c)
    {
      if(2 * (first[c + 1] - first[c]) >= size) continue;
      for(std::size_t i = first[c]; i < first[c + 1] && root[c] == Index(c); ++i)
      {
        bool joined = false; // to the first neighbour in another cluster
        for_each_neighbour(grown.order[i], [&](Index y) {
          if(!joined && y != none && find(parent[y]) != find(Index(c)))
          {
            root[find(Index(c))] = find(parent[y]);
            joined = true;
          }
        });
      }
    }
    std::vector<Index> number(m, none);
    Index clusters = 0;
    for(std::size_t c = 0; c < m; ++c)
      if(find(Index(c)) == Index(c)) number[c] = clusters++;
    for(std::size_t x = 0; x < n; ++x) parent[x] = number[find(parent[x])];
    return clusters;
  }

  void build_levels(int max_levels)
  {
    const std::size_t nf = m_adj.size();
    std::vector<Index> face_cluster(nf); // the cluster of each face at the last level built
    for(std::size_t f = 0; f < nf; ++f) face_cluster[f] = Index(f);
    std::size_t children = nf;
    for(int level = 0; level < max_levels && level < 16 && children > 1; ++level)
    {
      Level L;
      const Level* below = level == 0 ? nullptr : &m_levels.back();
      const std::size_t n = level == 0
        ? grow_clusters(nf, 16, [&](Index f, const auto& visit) {
            for(const auto& a : m_adj[f]) visit(a[0]);
          }, L.parent)
        : grow_clusters(children, 8, [&](Index x, const auto& visit) {
            for(std::size_t i = below->border_begin[x]; i < below->border_begin[x + 1]; ++i)
              visit(face_cluster[below->border[i][0]]);
          }, L.parent);
      if(level > 0 && n > children / 2) break; // no longer coarsening
      // the children's clusters, and the faces'
      std::vector<std::vector<Index> > members(n);
      for(std::size_t x = 0; x < children; ++x) members[L.parent[x]].push_back(Index(x));
      std::vector<Index> next_face_cluster(nf);
      for(std::size_t f = 0; f < nf; ++f) next_face_cluster[f] = L.parent[face_cluster[f]];
      L.center.resize(n);
      L.radius.assign(n, 0.);
      L.crease.assign(n, 0.);
      L.band.assign(n, Band_tensor());
      L.has_zero_length_edge.assign(n, 0);
      L.border_begin.assign(n + 1, 0);
      L.group_begin.assign(n + 1, 0);
      if(level == 0)
        for(std::size_t e = 0; e < m_owner.size(); ++e)
        {
          if(m_owner[e] == none) continue;
          const Index x = L.parent[m_owner[e]];
          const double length = (end1(e) - end0(e)).norm();
          if(length == 0) L.has_zero_length_edge[x] = 1;
          if(m_kind[e] == CREASE) L.crease[x] += length;
          else if(m_kind[e] == BAND) L.band[x].add(end1(e) - end0(e), length);
        }
      for(std::size_t x = 0; x < n; ++x)
      {
        // the sphere: the centre of the children's box, a radius over all of them
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
        auto corners = [&](auto visit) {
          for(Index child : members[x])
            if(level == 0)
              for(const auto& a : m_adj[child]) { visit(end0(a[1]), 0.); visit(end1(a[1]), 0.); }
            else
              visit(below->center[child], below->radius[child]);
        };
        corners([&](const Eigen::Vector3d& p, double rho) {
          lo = lo.cwiseMin(p - Eigen::Vector3d::Constant(rho));
          hi = hi.cwiseMax(p + Eigen::Vector3d::Constant(rho));
        });
        L.center[x] = 0.5 * (lo + hi);
        corners([&](const Eigen::Vector3d& p, double rho) {
          L.radius[x] = (std::max)(L.radius[x], (p - L.center[x]).norm() + rho);
        });
        if(level > 0)
          for(Index child : members[x])
          {
            L.crease[x] += below->crease[child];
            L.band[x].add(below->band[child]);
            if(below->has_zero_length_edge[child]) L.has_zero_length_edge[x] = 1;
          }
        // the border: the children's pairs that leave the cluster
        for(Index child : members[x])
        {
          if(level == 0)
          {
            for(const auto& a : m_adj[child])
              if(a[0] != none && next_face_cluster[a[0]] != Index(x)) L.border.push_back(a);
          }
          else
            for(std::size_t i = below->border_begin[child]; i < below->border_begin[child + 1]; ++i)
              if(next_face_cluster[below->border[i][0]] != Index(x)) L.border.push_back(below->border[i]);
        }
        L.border_begin[x + 1] = L.border.size();
        // grouped by the neighbouring cluster
        const auto first = L.border.begin() + std::ptrdiff_t(L.border_begin[x]);
        std::stable_sort(first, L.border.end(), [&](const std::array<Index, 2>& a, const std::array<Index, 2>& b) {
          return next_face_cluster[a[0]] < next_face_cluster[b[0]];
        });
        for(std::size_t i = L.border_begin[x]; i < L.border.size(); ++i)
          if(i == L.border_begin[x] || next_face_cluster[L.border[i][0]] != next_face_cluster[L.border[i - 1][0]])
            L.groups.emplace_back(next_face_cluster[L.border[i][0]], i);
        L.group_begin[x + 1] = L.groups.size();
      }
      // a level none of whose clusters fits in a ball is never taken whole, nor those above
      if(*std::min_element(L.radius.begin(), L.radius.end()) >= m_radius) break;
      m_levels.push_back(std::move(L));
      face_cluster.swap(next_face_cluster);
      children = n;
    }
  }

  const Mesh_indexing<TriangleMesh>& m_idx;
  enum Kind : char { OTHER, CREASE, BAND };
  double m_crease_angle;
  bool m_by_direction;
  double m_radius = 0;
  std::vector<Eigen::Vector3d> m_points;            // per vertex
  std::vector<std::array<Index, 2> > m_ends;        // per edge: its vertices
  std::vector<Kind> m_kind;                         // per edge: crease, band or neither
  std::vector<Index> m_owner;                       // per edge: the face it belongs to
  std::vector<std::array<std::array<Index, 2>, 3> > m_adj; // per face: (face across, edge) per side
  std::vector<Level> m_levels;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CREASE_GAP_SEARCH_H
