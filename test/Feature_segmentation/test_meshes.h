// Analytic test surfaces built as polygon soups, so every mesh type (Surface_mesh,
// Polyhedron_3) and kernel can be made from them with polygon_soup_to_polygon_mesh.
#ifndef FS_TEST_MESHES_H
#define FS_TEST_MESHES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace fs_test {

struct Soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::vector<std::size_t> > faces;
};

template <typename Mesh>
Mesh to_mesh(const Soup& s)
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> pts;
  for(const auto& p : s.points) pts.emplace_back(p[0], p[1], p[2]);
  Mesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, s.faces, m);
  return m;
}

// A grid of (nu x nv) quads over [0,1]^2 mapped by f, each quad split into two triangles
// along alternating diagonals (no preferred direction); periodic in u and/or v if asked.
template <typename F>
Soup parametric_grid(int nu, int nv, bool periodic_u, bool periodic_v, F f)
{
  Soup s;
  const int pu = periodic_u ? nu : nu + 1, pv = periodic_v ? nv : nv + 1;
  for(int j = 0; j < pv; ++j)
    for(int i = 0; i < pu; ++i)
      s.points.push_back(f(double(i) / nu, double(j) / nv));
  auto id = [&](int i, int j) { return std::size_t((j % pv) * pu + (i % pu)); };
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
    {
      std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 2 == 0) { s.faces.push_back({a, b, c}); s.faces.push_back({a, c, d}); }
      else { s.faces.push_back({a, b, d}); s.faces.push_back({b, c, d}); }
    }
  return s;
}

// Every triangle of s into four (the midpoints of its edges; same geometry): face f
// becomes faces 4f .. 4f+3, the corners' triangles then the middle one.
inline void subdivide_flat(Soup& s)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
  auto midpoint = [&](std::size_t a, std::size_t b) {
    auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mid.find(key);
    if(it != mid.end()) return it->second;
    std::array<double, 3> m;
    for(int k = 0; k < 3; ++k) m[k] = 0.5 * (s.points[a][k] + s.points[b][k]);
    s.points.push_back(m);
    return mid[key] = s.points.size() - 1;
  };
  std::vector<std::vector<std::size_t> > nf;
  nf.reserve(4 * s.faces.size());
  for(const auto& f : s.faces)
  {
    std::size_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
    nf.push_back({f[0], a, c}); nf.push_back({f[1], b, a});
    nf.push_back({f[2], c, b}); nf.push_back({a, b, c});
  }
  s.faces.swap(nf);
}

// The box [0,a]x[0,b]x[0,c], each side an n x n grid of quads split in two triangles,
// oriented outwards. `side` receives the side (0..5) of every triangle, in face order.
inline Soup box(double a, double b, double c, int n, std::vector<int>& side)
{
  Soup s;
  std::map<std::array<int, 3>, std::size_t> id;
  const double size[3] = { a, b, c };
  auto point = [&](std::array<int, 3> q) {
    auto it = id.find(q);
    if(it != id.end()) return it->second;
    s.points.push_back({ size[0] * q[0] / n, size[1] * q[1] / n, size[2] * q[2] / n });
    return id[q] = s.points.size() - 1;
  };
  side.clear();
  for(int d = 0; d < 3; ++d)
    for(int far = 0; far < 2; ++far)
    {
      const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          std::array<int, 3> p{}, q{}, r{}, t{};
          p[d] = q[d] = r[d] = t[d] = far * n;
          p[d1] = i;     p[d2] = j;
          q[d1] = i + 1; q[d2] = j;
          r[d1] = i + 1; r[d2] = j + 1;
          t[d1] = i;     t[d2] = j + 1;
          std::size_t v[4] = { point(p), point(q), point(r), point(t) };
          // e1 x e2 points along +d: keep that order on the far side, reverse on the near
          if(far) { s.faces.push_back({ v[0], v[1], v[2] }); s.faces.push_back({ v[0], v[2], v[3] }); }
          else    { s.faces.push_back({ v[0], v[2], v[1] }); s.faces.push_back({ v[0], v[3], v[2] }); }
          side.push_back(2 * d + far);
          side.push_back(2 * d + far);
        }
    }
  return s;
}

// A plate pierced by a rectangular slot: the cells of the grid xs x ys (sorted
// breakpoints, so cells may be of any width) but those with i0 <= i < i1 and
// j0 <= j < j1, extruded from z = 0 to z = height in nz layers; triangles oriented
// outwards. Its ten faces are the top, the bottom, four outer walls and the slot's four
// walls; `side` receives the face (0..9) of every triangle, in face order.
inline Soup slotted_plate(const std::vector<double>& xs, const std::vector<double>& ys, int i0, int i1, int j0,
                          int j1, double height, int nz, std::vector<int>& side)
{
  Soup s;
  std::map<std::array<int, 3>, std::size_t> id;
  auto point = [&](int i, int j, int k) {
    const std::array<int, 3> q{ i, j, k };
    auto it = id.find(q);
    if(it != id.end()) return it->second;
    s.points.push_back({ xs[i], ys[j], height * k / nz });
    return id[q] = s.points.size() - 1;
  };
  const int nx = int(xs.size()) - 1, ny = int(ys.size()) - 1;
  auto kept = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < nx && j < ny && !(i >= i0 && i < i1 && j >= j0 && j < j1);
  };
  side.clear();
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j)
      if(kept(i, j))
        for(int top = 0; top < 2; ++top)
        {
          const int k = top ? nz : 0;
          const std::size_t a = point(i, j, k), b = point(i + 1, j, k), c = point(i + 1, j + 1, k),
                            d = point(i, j + 1, k);
          if(top) { s.faces.push_back({ a, b, c }); s.faces.push_back({ a, c, d }); }
          else    { s.faces.push_back({ a, c, b }); s.faces.push_back({ a, d, c }); }
          side.insert(side.end(), 2, top);
        }
  // A wall quad on every grid edge between a kept cell and a removed or outside one,
  // walked with the kept cell on the left: (p, q) then up, outward on the right.
  auto wall = [&](int pi, int pj, int qi, int qj, int face) {
    for(int k = 0; k < nz; ++k)
    {
      const std::size_t p0 = point(pi, pj, k), q0 = point(qi, qj, k), q1 = point(qi, qj, k + 1),
                        p1 = point(pi, pj, k + 1);
      s.faces.push_back({ p0, q0, q1 });
      s.faces.push_back({ p0, q1, p1 });
      side.insert(side.end(), 2, face);
    }
  };
  // faces 2..5: the outer walls facing -y, +x, +y, -x; 6..9: the slot's walls (a wall
  // below a kept cell of the slot's columns faces -y into the slot, and so on)
  for(int i = 0; i < nx; ++i)
    for(int j = 0; j < ny; ++j)
    {
      if(!kept(i, j)) continue;
      if(!kept(i, j - 1)) wall(i, j, i + 1, j, j == 0 ? 2 : 8);              // faces -y
      if(!kept(i + 1, j)) wall(i + 1, j, i + 1, j + 1, i + 1 == nx ? 3 : 9); // faces +x
      if(!kept(i, j + 1)) wall(i + 1, j + 1, i, j + 1, j + 1 == ny ? 4 : 6); // faces +y
      if(!kept(i - 1, j)) wall(i, j + 1, i, j, i == 0 ? 5 : 7);              // faces -x
    }
  return s;
}

// Icosahedron subdivided `level` times and projected on the sphere of radius r (outward).
inline Soup icosphere(double r, int level)
{
  const double t = (1. + std::sqrt(5.)) / 2.;
  Soup s;
  s.points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  s.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for(int l = 0; l < level; ++l)
    subdivide_flat(s);
  for(auto& p : s.points)
  {
    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for(int k = 0; k < 3; ++k) p[k] *= r / len;
  }
  return s;
}

// Open cylinder of radius r and height hgt around the z axis, outward normals.
inline Soup cylinder(double r, double hgt, int n_around, int n_along)
{
  return parametric_grid(n_around, n_along, true, false, [&](double u, double v) {
    const double a = 2 * M_PI * u;
    return std::array<double, 3>{r * std::cos(a), r * std::sin(a), hgt * (v - 0.5)};
  });
}

// The saddle z = x^2 - y^2 over [-a, a]^2 (upward normals).
inline Soup saddle(double a, int n)
{
  return parametric_grid(n, n, false, false, [&](double u, double v) {
    const double x = a * (2 * u - 1), y = a * (2 * v - 1);
    return std::array<double, 3>{x, y, x * x - y * y};
  });
}

// Every vertex of `s` moved along `normal` (per vertex) by a deterministic pseudo-random
// amount, uniform in [-amplitude, amplitude] (the same numbers on every platform).
inline void add_noise_along(Soup& s, const std::vector<std::array<double, 3> >& normal, double amplitude)
{
  unsigned long long state = 20170601;
  for(std::size_t v = 0; v < s.points.size(); ++v)
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = double(state >> 11) / double(1ULL << 53);
    for(int k = 0; k < 3; ++k) s.points[v][k] += amplitude * (2 * u - 1) * normal[v][k];
  }
}

// Noise along the radial directions of a surface round the z axis, by add_noise_along()
// of `amplitude`.
inline void add_radial_noise(Soup& s, double amplitude)
{
  std::vector<std::array<double, 3> > radial;
  for(const auto& p : s.points)
  {
    const double rho = std::hypot(p[0], p[1]);
    radial.push_back({ p[0] / rho, p[1] / rho, 0. });
  }
  add_noise_along(s, radial, amplitude);
}

// cylinder(r, hgt, n_around, n_along) with every vertex moved along its radial direction
// by add_noise_along() of `amplitude`.
inline Soup noisy_cylinder(double r, double hgt, int n_around, int n_along, double amplitude)
{
  Soup s = cylinder(r, hgt, n_around, n_along);
  add_radial_noise(s, amplitude);
  return s;
}

// A turned surface round the z axis, 48 facets round: a cylinder of radius 2 from z = 0
// to 6 (24 rows of 0.25) and a cone from radius 2 at z = 6 to 1 at z = 8 (9 rows), which
// bends from the cylinder by atan(1/2) = 26.6 degrees along the circle z = 6 (48 edges);
// diagonal 9.8.
inline Soup cylinder_and_cone()
{
  const int around = 48, rows = 33, cylinder_rows = 24;
  return parametric_grid(around, rows, true, false, [&](double u, double v) {
    const double a = 2 * M_PI * u, j = v * rows;
    const double t = j <= cylinder_rows ? 0. : (j - cylinder_rows) / (rows - cylinder_rows);
    const double r = 2. - t, z = j <= cylinder_rows ? 0.25 * j : 6. + 2. * t;
    return std::array<double, 3>{ r * std::cos(a), r * std::sin(a), z };
  });
}

// cylinder_and_cone() with every vertex moved along its radial direction by
// add_noise_along() of `amplitude`.
inline Soup noisy_cylinder_and_cone(double amplitude)
{
  Soup s = cylinder_and_cone();
  add_radial_noise(s, amplitude);
  return s;
}

// A square [-a, a]^2 in the plane z = 0.
inline Soup plane(double a, int n)
{
  return parametric_grid(n, n, false, false, [&](double u, double v) {
    return std::array<double, 3>{a * (2 * u - 1), a * (2 * v - 1), 0.};
  });
}

// A torus around the z axis whose tube has a lobed cross-section
// rho(phi) = r0 (1 + eps cos(lobes phi)): a surface of revolution, so meridians and
// parallels are lines of curvature, and by symmetry the profile curvature is extremal
// at the crests (phi = 2 pi j / lobes: convex, ridge circles) and at the troughs
// (phi = pi (2j+1) / lobes: concave when eps lobes^2 > 1, valley circles).
struct Lobed_torus
{
  double R = 3., r0 = 1., eps = 0.12;
  int lobes = 4;
  // The crest and trough circles are at phi = phase + k pi / lobes. At phase 0 they run
  // through rings of vertices of the soups below, where the extremality is zero up to
  // round-off; a phase of half a ring step puts them midway between two rings.
  double phase = 0.;
  double rho(double phi) const { return r0 * (1 + eps * std::cos(lobes * (phi - phase))); }
  std::array<double, 3> point(double theta, double phi) const
  {
    const double q = R + rho(phi) * std::cos(phi);
    return {q * std::cos(theta), q * std::sin(theta), rho(phi) * std::sin(phi)};
  }
  Soup soup(int n_around, int n_tube) const
  {
    // parameter order (theta, phi) with theta along u gives outward normals
    return parametric_grid(n_around, n_tube, true, true, [&](double u, double v) {
      return point(2 * M_PI * u, 2 * M_PI * v);
    });
  }
  // Distance from p to the nearest crest (ridge) or trough (valley) circle.
  double distance_to_circles(const std::array<double, 3>& p, bool ridges) const
  {
    const double q = std::sqrt(p[0] * p[0] + p[1] * p[1]);
    double best = 1e300;
    for(int j = 0; j < lobes; ++j)
    {
      const double phi = phase + (ridges ? 2 * M_PI * j : M_PI * (2 * j + 1)) / lobes;
      const double cq = R + rho(phi) * std::cos(phi), cz = rho(phi) * std::sin(phi);
      best = std::min(best, std::hypot(q - cq, p[2] - cz));
    }
    return best;
  }
};

} // namespace fs_test

#endif // FS_TEST_MESHES_H
