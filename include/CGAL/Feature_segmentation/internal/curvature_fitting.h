// SPDX-License-Identifier: GPL-3.0-or-later
// The work behind estimate_principal_curvatures(): vertex normals, the per-vertex cubic
// fit of positions and normals over a ring neighbourhood (Goldfeather-Interrante), and
// the extremality coefficients by averaged per-triangle gradients (Yoshizawa et al.).

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_CURVATURE_FITTING_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_CURVATURE_FITTING_H

#include <CGAL/Feature_segmentation/internal/Mesh_indexing.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>
#include <CGAL/Feature_segmentation/internal/vertex_clusters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <CGAL/use.h>

#include <Eigen/Dense>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

typedef Eigen::Vector3d Vec3;

// What the fit gives at one vertex, in double precision and in 3D.
struct Vertex_curvature
{
  double k1 = 0, k2 = 0;          // |k1| >= |k2|
  Vec3 d1 = Vec3::Zero(), d2 = Vec3::Zero();
  double dk1 = 0, dk2 = 0;        // derivative of k1 along d1, of k2 along d2
  bool k1_is_max() const { return k1 >= k2; }
  double k_max() const { return k1_is_max() ? k1 : k2; }
  double k_min() const { return k1_is_max() ? k2 : k1; }
  const Vec3& d_max() const { return k1_is_max() ? d1 : d2; }
  const Vec3& d_min() const { return k1_is_max() ? d2 : d1; }
};

// Geometry of the faces and vertex normals, in double precision; shared by the stages.
template <typename TriangleMesh, typename VPM>
struct Mesh_geometry
{
  typedef Mesh_indexing<TriangleMesh> Indexing;
  const Indexing& idx;
  std::vector<Vec3> points;        // per vertex
  std::vector<Vec3> face_normals;  // unit, zero for a degenerate face
  std::vector<double> face_areas;
  std::vector<Vec3> vertex_normals; // unit (angle-weighted), zero where undefined
  std::vector<std::array<std::size_t, 3> > face_vertices;
  double mean_edge_length = 0;

  double bounding_box_diagonal() const
  {
    if(points.empty())
      return 0.;
    Vec3 lo = points.front(), hi = points.front();
    for(const Vec3& p : points) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
    return (hi - lo).norm();
  }

  // `parallel`: the points, the faces and the vertex normals' directions by TBB's
  // threads; each vertex normal sums its faces in face order and the mean edge length
  // its edges in edge order, so the geometry is the same at any thread count.
  Mesh_geometry(const Indexing& indexing, VPM vpm, bool parallel = false) : idx(indexing)
  {
    const TriangleMesh& tm = idx.mesh();
    points.resize(idx.number_of_vertices());
    for_each_range(points.size(), parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
      {
        const auto& p = get(vpm, idx.vertex_at(i));
        points[i] = Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
    });
    const std::size_t nf = idx.number_of_faces();
    face_normals.assign(nf, Vec3::Zero());
    face_areas.assign(nf, 0.);
    face_vertices.resize(nf);
    // angle-weighted vertex normals (Thurmer and Wuthrich): insensitive to how a flat
    // region of a CAD mesh happens to be triangulated; the corner angles by face, then
    // summed per vertex in face order
    std::vector<std::array<double, 3> > corner_angle(nf);
    for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        auto h = halfedge(idx.face_at(f), tm);
        std::array<std::size_t, 3> t = { idx.id(source(h, tm)), idx.id(target(h, tm)),
                                         idx.id(target(next(h, tm), tm)) };
        face_vertices[f] = t;
        Vec3 n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
        const double len = n.norm();
        face_areas[f] = 0.5 * len;
        if(len > 0 && std::isfinite(len))
          face_normals[f] = n / len;
        for(int c = 0; c < 3; ++c)
        {
          corner_angle[f][c] = 0.;
          Vec3 a = points[t[(c + 1) % 3]] - points[t[c]];
          Vec3 b = points[t[(c + 2) % 3]] - points[t[c]];
          const double na = a.norm(), nb = b.norm();
          if(na <= 0 || nb <= 0 || len <= 0)
            continue;
          const double cosang = std::max(-1., std::min(1., a.dot(b) / (na * nb)));
          corner_angle[f][c] = std::acos(cosang);
        }
      }
    });
    vertex_normals.assign(points.size(), Vec3::Zero());
    for(std::size_t f = 0; f < nf; ++f)
      for(int c = 0; c < 3; ++c)
        if(corner_angle[f][c] != 0.)
          vertex_normals[face_vertices[f][c]] += corner_angle[f][c] * face_normals[f];
    for_each_range(vertex_normals.size(), parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t v = first; v < last; ++v)
      {
        Vec3& n = vertex_normals[v];
        const double len = n.norm();
        n = len > 0 ? Vec3(n / len) : Vec3(Vec3::Zero());
      }
    });
    double sum = 0;
    for(auto e : idx.edge_list())
    {
      auto h = halfedge(e, tm);
      sum += (points[idx.id(source(h, tm))] - points[idx.id(target(h, tm))]).norm();
    }
    mean_edge_length = idx.number_of_edges() > 0 ? sum / double(idx.number_of_edges()) : 0.;
  }
};

// Eigen-decomposition of the symmetric 2x2 shape operator [[a, b], [b, c]] in the frame
// (u, v): principal curvatures ordered by absolute value and 3D directions.
inline void principal_from_shape_operator(double a, double b, double c,
                                          const Vec3& u, const Vec3& v,
                                          Vertex_curvature& out)
{
  const double mean = 0.5 * (a + c);
  const double radius = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  const double lplus = mean + radius, lminus = mean - radius;
  const double theta = 0.5 * std::atan2(2. * b, a - c); // direction of lplus
  Vec3 dplus = std::cos(theta) * u + std::sin(theta) * v;
  Vec3 dminus = -std::sin(theta) * u + std::cos(theta) * v;
  if(std::abs(lplus) >= std::abs(lminus))
  { out.k1 = lplus; out.k2 = lminus; out.d1 = dplus; out.d2 = dminus; }
  else
  { out.k1 = lminus; out.k2 = lplus; out.d1 = dminus; out.d2 = dplus; }
}

template <typename TriangleMesh, typename VPM, typename GT>
class Curvature_fitting
{
public:
  typedef Mesh_indexing<TriangleMesh> Indexing;

  // `idx`: an indexing of the mesh, which must outlive the object; `parallel`: the
  // geometry by TBB's threads (Mesh_geometry)
  Curvature_fitting(const Indexing& idx, VPM vpm, bool parallel = false)
    : m_idx(idx), m_geom(m_idx, vpm, parallel)
  {}

  // The neighbourhood of a vertex: its `rings` rings, extended through the edges to
  // the vertices within `radius` of it whose normals are within the cone (0: rings
  // only). The rings set the scale on coarse meshes, the radius on fine ones, so a
  // finer tessellation of the same shape is fitted over the same piece of surface.
  // Beyond the rings, a neighbour joins only if its normal is within 30 degrees of the
  // vertex's: the radius must not carry the fit round a thin wall or a rounded edge
  // onto the other side (blade: 89 patches without the cone, 40 on rings alone).
  static constexpr double cone_cosine = 0.8660254;
  // The most neighbours a fit takes (see collect_neighborhood()).
  static constexpr std::size_t max_fit_points = 32;

  // On a mesh so fine that the radius spans many rings, the search beyond the rings
  // goes over clusters of vertices (Vertex_clusters), each standing for its first vertex,
  // sized so that the ball holds about cluster_budget of them: the neighbourhood is then
  // found in a time that does not grow with the resolution. A regular tessellation has
  // about 3.6 (radius / mean edge length)^2 vertices within the radius; clusters are used
  // from min_cluster_size vertices each (a radius of 3 mean edge lengths or more: fandisk
  // subdivided to 828k faces and finer), below that the search goes vertex by vertex.
  static constexpr double vertices_per_squared_radius = 3.6;
  static constexpr double cluster_budget = 16.;
  static constexpr std::size_t min_cluster_size = 2;

  // `parallel`: the vertices are fitted by TBB's threads (CGAL_LINKED_WITH_TBB), each
  // with its own work space; every vertex's fit is the same at any thread count.
  void estimate(unsigned int rings, double radius = 0., bool parallel = false)
  {
    const std::size_t nv = m_idx.number_of_vertices();
    if(nv >= std::size_t(std::uint32_t(-1)))
      throw std::length_error("the curvature fit stores vertex ids in 32 bits: the mesh has too many vertices");
    m_curv.assign(nv, Vertex_curvature());
    build_adjacency();
    m_clusters = Vertex_clusters();
    m_sites.clear();
    if(radius > 0 && m_geom.mean_edge_length > 0)
    {
      const double across = radius / m_geom.mean_edge_length;
      const double size = vertices_per_squared_radius * across * across / cluster_budget;
      if(size >= double(min_cluster_size))
      {
        m_clusters.build(m_adj_begin, m_adj, static_cast<std::size_t>(size));
        m_sites.resize(m_clusters.size());
        for(std::size_t c = 0; c < m_sites.size(); ++c)
        {
          const std::size_t w = m_clusters.representative[c];
          m_sites[c] = Cluster_site{ m_geom.points[w], m_geom.vertex_normals[w], std::uint32_t(w) };
        }
      }
    }
    auto fit_range = [&](std::size_t first, std::size_t last, Work_space& ws) {
      if(ws.stamp.size() != nv) ws.stamp.assign(nv, std::uint32_t(-1));
      if(ws.cluster_stamp.size() != m_clusters.size()) ws.cluster_stamp.assign(m_clusters.size(), std::uint32_t(-1));
      for(std::size_t v = first; v < last; ++v)
      {
        collect_neighborhood(v, rings, radius * radius, ws, ws.neighborhood);
        fit_vertex(v, ws.neighborhood);
      }
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel)
    {
      tbb::enumerable_thread_specific<Work_space> spaces;
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 512),
                        [&](const tbb::blocked_range<std::size_t>& r) { fit_range(r.begin(), r.end(), spaces.local()); });
    }
    else
#endif
    {
      CGAL_USE(parallel);
      Work_space ws;
      fit_range(0, nv, ws);
    }
    extremality(parallel);
  }

  template <typename VertexCurvatureMap>
  void write(VertexCurvatureMap map) const
  {
    typedef typename boost::property_traits<VertexCurvatureMap>::value_type Value;
    typedef typename GT::Vector_3 Vector_3;
    for(std::size_t i = 0; i < m_curv.size(); ++i)
    {
      const Vertex_curvature& c = m_curv[i];
      Value val;
      val.k1 = c.k1; val.k2 = c.k2; val.dk1 = c.dk1; val.dk2 = c.dk2;
      val.d1 = Vector_3(c.d1.x(), c.d1.y(), c.d1.z());
      val.d2 = Vector_3(c.d2.x(), c.d2.y(), c.d2.z());
      put(map, m_idx.vertex_at(i), val);
    }
  }

  const std::vector<Vertex_curvature>& curvatures() const { return m_curv; }
  const Indexing& indexing() const { return m_idx; }
  const Mesh_geometry<TriangleMesh, VPM>& geometry() const { return m_geom; }

private:
  void build_adjacency()
  {
    const TriangleMesh& tm = m_idx.mesh();
    const std::size_t nv = m_idx.number_of_vertices();
    m_adj_begin.assign(nv + 1, 0);
    for(auto e : m_idx.edge_list())
    {
      auto h = halfedge(e, tm);
      ++m_adj_begin[m_idx.id(source(h, tm)) + 1];
      ++m_adj_begin[m_idx.id(target(h, tm)) + 1];
    }
    for(std::size_t i = 0; i < nv; ++i) m_adj_begin[i + 1] += m_adj_begin[i];
    m_adj.resize(m_adj_begin[nv]);
    std::vector<std::size_t> fill(m_adj_begin.begin(), m_adj_begin.end() - 1);
    for(auto e : m_idx.edge_list())
    {
      auto h = halfedge(e, tm);
      std::size_t a = m_idx.id(source(h, tm)), b = m_idx.id(target(h, tm));
      m_adj[fill[a]++] = std::uint32_t(b);
      m_adj[fill[b]++] = std::uint32_t(a);
    }
  }

  // Breadth-first from v: ring by ring up to `rings`, then on while a ring still adds
  // vertices within sqrt(radius2) of v and the normal cone (the others are not entered);
  // beyond the rings over the clusters, if any (collect_clusters()).
  template <typename WorkSpace>
  void collect_neighborhood(std::size_t v, unsigned int rings, double radius2, WorkSpace& ws,
                            std::vector<std::size_t>& out) const
  {
    std::vector<std::uint32_t>& stamp = ws.stamp;
    const std::uint32_t mark = std::uint32_t(v);
    out.clear();
    stamp[v] = mark;
    std::size_t front_begin = 0;
    out.push_back(v);
    const Vec3& p0 = m_geom.points[v];
    const Vec3& n0 = m_geom.vertex_normals[v];
    for(unsigned int r = 0; front_begin < out.size(); ++r)
    {
      const bool within_rings = r < rings;
      if(!within_rings && radius2 <= 0)
        break;
      if(!within_rings && m_clusters.size() > 0)
      {
        collect_clusters(v, radius2, ws, out);
        break;
      }
      const std::size_t front_end = out.size();
      for(std::size_t i = front_begin; i < front_end; ++i)
        for(std::size_t k = m_adj_begin[out[i]]; k < m_adj_begin[out[i] + 1]; ++k)
        {
          const std::size_t w = m_adj[k];
          if(stamp[w] == mark)
            continue;
          if(!within_rings && ((m_geom.points[w] - p0).squaredNorm() > radius2 ||
                               m_geom.vertex_normals[w].dot(n0) < cone_cosine))
            continue;
          stamp[w] = mark;
          out.push_back(w);
        }
      front_begin = front_end;
    }
    out.erase(out.begin()); // the vertex itself is the origin of the fit
    // A neighbourhood of many rings (a fine mesh) is thinned to max_fit_points: the
    // first ring whole, the rest evenly in breadth-first order (so every ring keeps its
    // share). A cubic has 7 coefficients; 32 points give up to 96 equations, and the
    // fit costs what three rings cost, with the same patches (the manual's
    // Performance section measures it).
    if(out.size() > max_fit_points)
    {
      const std::size_t first_ring = std::min(out.size(), m_adj_begin[v + 1] - m_adj_begin[v]);
      const std::size_t keep = std::max(first_ring, max_fit_points);
      const std::size_t rest = out.size() - first_ring, slots = keep - first_ring;
      std::size_t j = first_ring;
      for(std::size_t i = 0; i < slots; ++i)
        out[j++] = out[first_ring + (i * rest) / slots];
      out.resize(j);
    }
  }

  // The search beyond the rings on the clusters: from those of the rings' vertices,
  // breadth first to the clusters whose vertex is within sqrt(radius2) of v and the
  // normal cone, each adding its vertex to `out`.
  template <typename WorkSpace>
  void collect_clusters(std::size_t v, double radius2, WorkSpace& ws, std::vector<std::size_t>& out) const
  {
    const std::uint32_t mark = std::uint32_t(v);
    const Vec3& p0 = m_geom.points[v];
    const Vec3& n0 = m_geom.vertex_normals[v];
    std::vector<std::size_t>& queue = ws.cluster_queue;
    queue.clear();
    for(std::size_t w : out)
    {
      const std::size_t c = m_clusters.cluster_of[w];
      if(ws.cluster_stamp[c] != mark) { ws.cluster_stamp[c] = mark; queue.push_back(c); }
    }
    for(std::size_t j = 0; j < queue.size(); ++j)
      for(std::size_t k = m_clusters.neighbour_begin[queue[j]]; k < m_clusters.neighbour_begin[queue[j] + 1]; ++k)
      {
        const std::size_t d = m_clusters.neighbours[k];
        if(ws.cluster_stamp[d] == mark) continue;
        ws.cluster_stamp[d] = mark;
        const Cluster_site& site = m_sites[d];
        if((site.point - p0).squaredNorm() > radius2 || site.normal.dot(n0) < cone_cosine) continue;
        queue.push_back(d);
        const std::size_t w = site.vertex;
        if(ws.stamp[w] != mark) { ws.stamp[w] = mark; out.push_back(w); }
      }
  }

  // Least-squares fit of z = A/2 x^2 + B xy + C/2 y^2 + D x^3 + E x^2 y + F x y^2 + G y^3
  // to neighbour positions (one equation each) and normals (two equations each) in the
  // frame of the vertex normal, in coordinates scaled by the neighbourhood size.
  // The work space of one thread: the visit stamps and neighbourhood of
  // collect_neighborhood().
  struct Work_space
  {
    std::vector<std::uint32_t> stamp, cluster_stamp; // 32 bits: half the memory the search reads
    std::vector<std::size_t> neighborhood, cluster_queue;
  };

  void fit_vertex(std::size_t v, const std::vector<std::size_t>& nbh)
  {
    const Vec3& n = m_geom.vertex_normals[v];
    if(n.squaredNorm() == 0 || nbh.size() < 2)
      return;
    Vec3 u = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    u = (u - u.dot(n) * n).normalized();
    const Vec3 w = n.cross(u);
    const Vec3& p0 = m_geom.points[v];
    double h = 0;
    for(std::size_t q : nbh) h = std::max(h, (m_geom.points[q] - p0).norm());
    if(h <= 0)
      return;
    const bool cubic = nbh.size() >= 4;
    const int nu = cubic ? 7 : 3;
    // the normal equations A^T A c = A^T b of the least-squares system (one row per
    // position, two per usable normal), summed row by row into the lower triangle
    double lower[7][8] = {}; // column 7: A^T b
    auto add_row = [&lower, nu](const double (&row)[8]) {
      for(int i = 0; i < nu; ++i)
      {
        for(int j = 0; j <= i; ++j) lower[i][j] += row[i] * row[j];
        lower[i][7] += row[i] * row[7];
      }
    };
    for(std::size_t q : nbh)
    {
      const Vec3 d = (m_geom.points[q] - p0) / h;
      const double x = d.dot(u), y = d.dot(w), z = d.dot(n);
      add_row({ 0.5 * x * x, x * y, 0.5 * y * y, x * x * x, x * x * y, x * y * y, y * y * y, z });
      const Vec3& nq = m_geom.vertex_normals[q];
      const double nz = nq.dot(n);
      if(nz > 0.2) // normals folded past ~78 degrees say nothing reliable about slopes
      {
        add_row({ x, y, 0, 3 * x * x, 2 * x * y, y * y, 0, -nq.dot(u) / nz });
        add_row({ 0, x, y, 0, x * x, 2 * x * y, 3 * y * y, -nq.dot(w) / nz });
      }
    }
    Eigen::Matrix<double, 7, 7> AtA = Eigen::Matrix<double, 7, 7>::Zero();
    Eigen::Matrix<double, 7, 1> Atb = Eigen::Matrix<double, 7, 1>::Zero();
    for(int i = 0; i < nu; ++i)
    {
      for(int j = 0; j <= i; ++j) AtA(i, j) = AtA(j, i) = lower[i][j];
      Atb(i) = lower[i][7];
    }
    // A small ridge term keeps the system well posed when the neighbourhood is nearly
    // collinear; it is negligible against the data term otherwise.
    const double lambda = 1e-9 * std::max(1e-300, AtA.trace());
    for(int i = 0; i < 7; ++i) AtA(i, i) += (i < nu) ? lambda : 1.;
    Eigen::Matrix<double, 7, 1> sol = AtA.ldlt().solve(Atb);
    if(!sol.allFinite())
      return;
    // Back to unscaled coordinates: second derivatives scale with 1/h. The curvature
    // is the Hessian of -z since the normal points away from where the surface bends.
    const double a = -sol(0) / h, b = -sol(1) / h, c = -sol(2) / h;
    principal_from_shape_operator(a, b, c, u, w, m_curv[v]);
  }

  // Yoshizawa et al.: gradient of the signed k_max and k_min fields, linear over each
  // triangle, averaged over the faces around each vertex weighted by area; the faces'
  // gradients by TBB's threads if `parallel`, summed per vertex in face order (the same
  // at any thread count).
  void extremality(bool parallel)
  {
    const std::size_t nv = m_idx.number_of_vertices(), nf = m_idx.number_of_faces();
    std::vector<Vec3> face_gmax(nf), face_gmin(nf);
    for_each_range(nf, parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        Vec3 gradmax = Vec3::Zero(), gradmin = Vec3::Zero();
        const double area = m_geom.face_areas[f];
        if(area > 0 && m_geom.face_normals[f].squaredNorm() != 0)
        {
          const auto& t = m_geom.face_vertices[f];
          const Vec3& fn = m_geom.face_normals[f];
          for(int c = 0; c < 3; ++c)
          {
            // gradient of the hat function of corner c: n x (opposite edge) / (2 area)
            const Vec3 opp = m_geom.points[t[(c + 2) % 3]] - m_geom.points[t[(c + 1) % 3]];
            const Vec3 gphi = fn.cross(opp) / (2. * area);
            gradmax += m_curv[t[c]].k_max() * gphi;
            gradmin += m_curv[t[c]].k_min() * gphi;
          }
        }
        face_gmax[f] = gradmax;
        face_gmin[f] = gradmin;
      }
    });
    std::vector<Vec3> gmax(nv, Vec3::Zero()), gmin(nv, Vec3::Zero());
    std::vector<double> wsum(nv, 0.);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const double area = m_geom.face_areas[f];
      if(area <= 0 || m_geom.face_normals[f].squaredNorm() == 0)
        continue;
      const auto& t = m_geom.face_vertices[f];
      for(int c = 0; c < 3; ++c)
      {
        gmax[t[c]] += area * face_gmax[f];
        gmin[t[c]] += area * face_gmin[f];
        wsum[t[c]] += area;
      }
    }
    for_each_range(nv, parallel, 8192, [&](std::size_t first, std::size_t last) {
      for(std::size_t v = first; v < last; ++v)
      {
        if(wsum[v] <= 0) continue;
        Vertex_curvature& c = m_curv[v];
        const double emax = gmax[v].dot(c.d_max()) / wsum[v];
        const double emin = gmin[v].dot(c.d_min()) / wsum[v];
        if(c.k1_is_max()) { c.dk1 = emax; c.dk2 = emin; }
        else { c.dk1 = emin; c.dk2 = emax; }
      }
    });
  }

  const Indexing& m_idx;
  Mesh_geometry<TriangleMesh, VPM> m_geom;
  std::vector<Vertex_curvature> m_curv;
  std::vector<std::size_t> m_adj_begin;
  std::vector<std::uint32_t> m_adj; // 32-bit vertex ids (estimate() checks the count)
  Vertex_clusters m_clusters; // empty unless the radius spans many rings
  // each cluster's representative vertex with its point and normal side by side: the
  // search beyond the rings tests one of these per cluster it reaches
  struct Cluster_site { Vec3 point, normal; std::uint32_t vertex; };
  std::vector<Cluster_site> m_sites;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_CURVATURE_FITTING_H
