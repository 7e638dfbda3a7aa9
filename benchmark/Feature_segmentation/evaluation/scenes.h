// SPDX-License-Identifier: GPL-3.0-or-later
// The scenes of the quality evaluation's contact sheets: a mesh and its tiles (patches as
// face colours, feature lines or boundary curves as segments), the input of
// render_scenes; and the relabelling that colours corresponding patches alike across the
// tiles of one model.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_SCENES_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_SCENES_H

#include "methods.h"

#include <CGAL/Feature_segmentation/IO/write_segmentation.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fs_evaluation {

// Relabels `labels` so that each patch takes the id of the reference patch it overlaps
// most, largest patches first, when that id is still free: the tiles of one model then
// colour corresponding patches alike.
inline std::vector<std::size_t> match_to_reference(const std::vector<std::size_t>& labels,
                                                   const std::vector<std::size_t>& reference,
                                                   const std::vector<double>& area)
{
  std::map<std::size_t, std::map<std::size_t, double> > overlap;
  std::map<std::size_t, double> size;
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    overlap[labels[f]][reference[f]] += area[f];
    size[labels[f]] += area[f];
  }
  std::vector<std::pair<double, std::size_t> > order;
  for(const auto& s : size) order.emplace_back(-s.second, s.first);
  std::sort(order.begin(), order.end());
  std::set<std::size_t> taken;
  std::map<std::size_t, std::size_t> to;
  std::size_t next = *std::max_element(reference.begin(), reference.end()) + 1;
  for(const auto& o : order)
  {
    std::size_t best = 0;
    double best_area = -1;
    for(const auto& c : overlap[o.second])
      if(c.second > best_area) { best = c.first; best_area = c.second; }
    to[o.second] = taken.insert(best).second ? best : next++;
  }
  std::vector<std::size_t> result(labels.size());
  for(std::size_t f = 0; f < labels.size(); ++f) result[f] = to[labels[f]];
  return result;
}

// The input of render_scenes: the mesh once, then one tile per picture (a label, a
// colour per face, and segments to draw over the surface).
class Scene_writer
{
public:
  Scene_writer(const std::string& path, const Mesh& mesh) : m_os(path), m_mesh(mesh)
  {
    m_os << "fs_scene 1\nvertices " << mesh.number_of_vertices() << "\n" << std::setprecision(7);
    for(auto v : vertices(mesh)) m_os << mesh.point(v) << "\n";
    m_os << "faces " << mesh.number_of_faces() << "\n";
    for(auto f : faces(mesh))
    {
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) m_os << v.idx() << " ";
      m_os << "\n";
    }
  }
  bool good() const { return m_os.good(); }

  // Patches as face colours; with `curves`, the curves are drawn instead of the edges
  // between faces of different colours.
  void tile_with_patches(const std::string& label, const std::vector<std::size_t>& face_patch,
                         const Boundaries* curves = nullptr)
  {
    m_os << "tile " << label << "\ncolours\n";
    char buf[8];
    for(std::size_t f = 0; f < face_patch.size(); ++f)
    {
      const CGAL::IO::Color c = FS::segmentation_colour(face_patch[f]);
      std::snprintf(buf, sizeof(buf), "%02x%02x%02x", c.red(), c.green(), c.blue());
      m_os << buf << ((f % 16 == 15) ? "\n" : " ");
    }
    m_os << "\n";
    if(curves == nullptr)
    {
      m_os << "segments 0\n";
      return;
    }
    std::vector<std::pair<const std::array<double, 3>*, const std::array<double, 3>*> > segments;
    for(const auto& c : curves->curves())
    {
      const std::size_t n = c.points.size();
      const std::size_t m = c.is_closed() ? (n > 1 ? n : 0) : (n > 0 ? n - 1 : 0);
      for(std::size_t i = 0; i < m; ++i) segments.emplace_back(&c.points[i].point, &c.points[(i + 1) % n].point);
    }
    m_os << "face_boundaries 0\nsegments " << segments.size() << "\n";
    for(const auto& sg : segments)
      m_os << (*sg.first)[0] << " " << (*sg.first)[1] << " " << (*sg.first)[2] << " " << (*sg.second)[0] << " "
           << (*sg.second)[1] << " " << (*sg.second)[2] << " 141414 2\n";
  }

  // An empty place in the sheet, so that each CC variant keeps its own row.
  void blank_tile() { m_os << "blank\n"; }

  // Feature lines over a grey surface: strong ridges red, strong valleys blue, weaker
  // lines thinner and lighter.
  void tile_with_lines(const std::string& label, const Lines& lines)
  {
    m_os << "tile " << label << "\ncolours uniform d9d9d9\n";
    std::size_t n = 0;
    for(const auto& l : lines.lines) n += l.is_closed ? l.points.size() : (l.points.empty() ? 0 : l.points.size() - 1);
    m_os << "segments " << n << "\n";
    for(const auto& l : lines.lines)
    {
      const bool strong = l.strength >= FS::default_strong_feature_strength;
      const bool ridge = l.type == FS::Feature_line_type::RIDGE;
      const char* colour = ridge ? (strong ? "d01010" : "f08080") : (strong ? "1030d0" : "80a0f0");
      if(l.type == FS::Feature_line_type::SEAM) colour = "10a010";
      if(l.type == FS::Feature_line_type::USER) colour = "101010";
      const std::size_t m = l.is_closed ? l.points.size() : (l.points.empty() ? 0 : l.points.size() - 1);
      for(std::size_t i = 0; i < m; ++i)
        m_os << l.points[i].point(m_mesh, m_mesh.points()) << " "
             << l.points[(i + 1) % l.points.size()].point(m_mesh, m_mesh.points()) << " " << colour << " "
             << ((strong || l.type == FS::Feature_line_type::USER) ? 3 : 1) << "\n";
    }
  }

private:
  std::ofstream m_os;
  const Mesh& m_mesh;
};

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_SCENES_H
