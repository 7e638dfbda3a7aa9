// SPDX-License-Identifier: GPL-3.0-or-later
// The runner of the edit scripts of the program `feature_segmentation` (edit_script.h):
// turns a script's regions and sketch points into mesh faces and located points, and
// applies its edits one by one to a Feature_aligned_segmentation, timing each
// (Edit_runner, which the interactive editor shares, and Edit_record, what an edit did).

#ifndef CGAL_FEATURE_SEGMENTATION_APP_EDIT_RUNNER_H
#define CGAL_FEATURE_SEGMENTATION_APP_EDIT_RUNNER_H

#include "edit_script.h"
#include "read_input_mesh.h"

#include <CGAL/Feature_segmentation/Feature_aligned_segmentation.h>
#include <CGAL/Feature_segmentation/input_checks.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace fs_app {

/// What one edit did, for the summary.
struct Edit_record
{
  std::size_t line = 0;
  std::string verb;
  std::size_t patches = 0;        ///< after the edit
  double cut_cost = 0;            ///< after the edit
  double seconds = 0;             ///< the library's edit call (re-weighting and re-solving)
  double prepare_seconds = 0;     ///< finding the region's faces or locating the sketch's points
  double solver_seconds = 0;      ///< the solver's part of `seconds`
  std::size_t faces = 0;          ///< refine, coarsen, scale, merge: faces of the region
  std::size_t points = 0;         ///< sketch: its points
  std::size_t undone_line = 0;    ///< undo: the line of the edit it took back
  std::size_t redone_line = 0;    ///< redo: the line of the edit it made again
};

/// Applies the edits of a script to a segmentation, in order.
///
/// \tparam Mesh a `CGAL::Surface_mesh` (or another FaceListGraph with an internal point map)
/// \tparam Kernel its kernel
/// The number of patches of `segmentation` that hold a face of `mesh` (its face_patches();
/// a patch of the vertex labels may win no face's majority): the program's patch count.
template <typename Mesh, typename Segmentation>
std::size_t number_of_face_patches(const Mesh& mesh, const Segmentation& segmentation)
{
  auto face_patch = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  segmentation.face_patches(face_patch);
  std::vector<char> seen(segmentation.number_of_patches(), 0);
  std::size_t n = 0;
  for(auto f : faces(mesh))
  {
    const std::size_t p = get(face_patch, f);
    if(p < seen.size() && !seen[p]) { seen[p] = 1; ++n; }
  }
  return n;
}

template <typename Mesh, typename Kernel>
class Edit_runner
{
public:
  typedef CGAL::Feature_segmentation::Feature_aligned_segmentation<Mesh> Segmentation;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;

  /// `solver_seconds` is where the segmentation's solver writes the time of its last
  /// run (set to 0 before each edit, since a merge or an undo runs no solver).
  Edit_runner(const Mesh& mesh, const Input_correspondence<Mesh>& correspondence,
              Segmentation& segmentation, double& solver_seconds)
    : m_mesh(mesh), m_correspondence(correspondence), m_segmentation(segmentation),
      m_solver_seconds(solver_seconds)
  {}

  /// Whether an edit's record counts the patches that hold a face (the program's count,
  /// a pass over the faces) rather than the segmentation's `number_of_patches()`.
  bool count_face_patches = false;

  /// The edits an `undo` line would take back, and those a `redo` line would make again.
  std::size_t number_of_undoable_edits() const { return m_done.size(); }
  std::size_t number_of_redoable_edits() const { return m_undone.size(); }

  /// Applies the edit `e` of `script`.
  /// \throws Edit_script_error "FILE:LINE: verb: reason" if the edit is refused
  Edit_record apply(const Edit_script& script, const Script_edit& e)
  {
    try
    {
      return apply(e);
    }
    catch(const Edit_refused& refused)
    {
      throw Edit_script_error(internal::script_place(script.path, e.line) + refused.what());
    }
  }

  /// Applies `e` (the editor's requests and the Python module's calls; `e.line` numbers
  /// it in the history).
  /// \throws Edit_refused "verb: reason" if the edit is refused; nothing changes
  Edit_record apply(const Script_edit& e)
  {
    typedef std::chrono::steady_clock Clock;
    if(const std::string refusal = edit_refusal(e); !refusal.empty())
      throw Edit_refused(refusal);
    Edit_record r;
    r.line = e.line;
    r.verb = e.verb;
    m_solver_seconds = 0;
    const auto start = Clock::now();
    std::vector<face_descriptor> faces;
    std::vector<typename Segmentation::Sketch_point> sketch;
    if(e.verb == "refine" || e.verb == "coarsen" || e.verb == "scale" || e.verb == "merge")
    {
      faces = region_faces(e.region);
      r.faces = faces.size();
    }
    else if(e.verb == "sketch")
    {
      sketch = locate(e.points);
      r.points = sketch.size();
    }
    const auto prepared = Clock::now();
    const std::size_t recorded = m_segmentation.number_of_recorded_edits();
    try
    {
      if(e.verb == "alpha")
        m_segmentation.set_alpha(e.value);
      else if(e.verb == "refine" || e.verb == "coarsen")
        m_segmentation.add_to_alpha(faces, e.value);
      else if(e.verb == "scale")
        m_segmentation.multiply_alpha(faces, e.value);
      else if(e.verb == "merge")
        m_segmentation.merge_patches(faces);
      else if(e.verb == "sketch")
        m_segmentation.add_sketch(sketch, e.value);
    }
    catch(const CGAL::Feature_segmentation::Invalid_input& error)
    {
      throw Edit_refused(e.verb + ": " + error.what());
    }
    if(e.verb == "undo")
    {
      // The library records no undo step for an edit that changed nothing (an empty
      // region, a merge inside one patch): undoing such an edit changes nothing either.
      if(m_done.empty())
        throw Edit_refused("undo: no edit to undo");
      const Done last = m_done.back();
      if(last.recorded && !m_segmentation.undo())
        throw Edit_refused("undo: cannot take back line " + std::to_string(last.line) +
                           ": the segmentation's history keeps " +
                           std::to_string(m_segmentation.undo_memory_limit() >> 20) +
                           " MiB of earlier states, and that edit's state was dropped");
      m_done.pop_back();
      m_undone.push_back(last);
      r.undone_line = last.line;
    }
    else if(e.verb == "redo")
    {
      if(m_undone.empty())
        throw Edit_refused("redo: no undone edit to redo");
      const Done last = m_undone.back();
      if(last.recorded && !m_segmentation.redo())
        throw Edit_refused("redo: cannot make line " + std::to_string(last.line) + " again");
      m_undone.pop_back();
      m_done.push_back(last);
      r.redone_line = last.line;
    }
    else
    {
      m_done.push_back({e.line, m_segmentation.number_of_recorded_edits() > recorded});
      m_undone.clear();
    }
    const auto end = Clock::now();
    r.prepare_seconds = std::chrono::duration<double>(prepared - start).count();
    r.seconds = std::chrono::duration<double>(end - prepared).count();
    r.solver_seconds = m_solver_seconds;
    // the program's count (the patches holding a face) costs a pass over the faces: after
    // the timing, and only where asked (the editor and Python keep the edit's cost)
    r.patches = count_face_patches ? number_of_face_patches(m_mesh, m_segmentation) : m_segmentation.number_of_patches();
    r.cut_cost = m_segmentation.cut_cost();
    return r;
  }

private:
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> > Tree;
  struct Done
  {
    std::size_t line;
    bool recorded; // whether the library recorded an undo step for it
  };

  std::vector<face_descriptor> region_faces(const Script_region& region)
  {
    std::vector<face_descriptor> found;
    if(region.kind == Script_region::BALL)
    {
      const typename Kernel::Point_3 c(region.center[0], region.center[1], region.center[2]);
      const double r2 = region.radius * region.radius;
      for(face_descriptor f : faces(m_mesh))
      {
        std::array<typename Kernel::Point_3, 3> p;
        int k = 0;
        for(auto v : CGAL::vertices_around_face(halfedge(f, m_mesh), m_mesh))
          p[k++] = m_mesh.point(v);
        if(CGAL::to_double(CGAL::squared_distance(CGAL::centroid(p[0], p[1], p[2]), c)) <= r2)
          found.push_back(f);
      }
      return found;
    }
    if(region.kind == Script_region::TRIANGLES)
    {
      if(m_triangles.empty())
        m_triangles.assign(faces(m_mesh).begin(), faces(m_mesh).end());
      for(std::size_t f : region.faces)
        found.push_back(m_triangles.at(f)); // checked by check_face_indices()
    }
    else
      for(std::size_t f : region.faces)
        m_correspondence.mesh_faces_of_file_face(f, found);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }

  // Each point moves to the nearest point of the surface (the AABB tree is built once).
  std::vector<typename Segmentation::Sketch_point>
  locate(const std::vector<std::array<double, 3> >& points)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    if(!m_tree)
    {
      m_tree = std::make_unique<Tree>();
      PMP::build_AABB_tree(m_mesh, *m_tree);
    }
    std::vector<typename Segmentation::Sketch_point> sketch;
    for(const std::array<double, 3>& q : points)
    {
      const auto location =
        PMP::locate_with_AABB_tree(typename Kernel::Point_3(q[0], q[1], q[2]), *m_tree, m_mesh);
      sketch.push_back({location.first, PMP::construct_point(location, m_mesh)});
    }
    return sketch;
  }

  const Mesh& m_mesh;
  const Input_correspondence<Mesh>& m_correspondence;
  Segmentation& m_segmentation;
  double& m_solver_seconds;
  std::unique_ptr<Tree> m_tree;
  std::vector<Done> m_done;
  std::vector<Done> m_undone;                  // taken back, in the order a redo makes them again
  std::vector<face_descriptor> m_triangles;    // the mesh's faces in order, for 'triangles'
};

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_EDIT_RUNNER_H
