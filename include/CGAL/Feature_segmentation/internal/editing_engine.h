// SPDX-License-Identifier: GPL-3.0-or-later
// The editing engine behind Feature_aligned_segmentation: one read-only precomputation
// (Edit_precomputation) and a history of immutable states (Edit_history). Every edit
// builds its new state aside, sharing the parts it does not change with the current
// state, and publishes it only once it is complete: an edit that throws (a user solver,
// memory) leaves the engine as it was, and undo and redo are exact because no state is
// ever modified.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_EDITING_ENGINE_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_EDITING_ENGINE_H

#include <CGAL/Feature_segmentation/internal/boundary_state.h>
#include <CGAL/Feature_segmentation/internal/edit_history.h>
#include <CGAL/Feature_segmentation/internal/edit_precomputation.h>
#include <CGAL/Feature_segmentation/internal/face_patch_rule.h>
#include <CGAL/Feature_segmentation/internal/sketch_walk.h>
#include <CGAL/Feature_segmentation/internal/small_patches.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

template <typename TriangleMesh>
class Editing_engine
{
public:
  typedef Edit_precomputation<TriangleMesh> Precomputation;
  typedef typename Precomputation::face_descriptor face_descriptor;

  template <typename NamedParameters>
  Editing_engine(const TriangleMesh& tm, const NamedParameters& np)
  {
    m_pre = std::make_shared<const Precomputation>(tm, np, m_times);
    const Precomputation& p = *m_pre;
    auto s = std::make_shared<Edit_state>();
    s->alpha = p.opt.alpha;
    s->alpha_e = p.alpha_e; // shared
    // the initial features are those of the precomputation's data (aliasing: no copy)
    s->features = std::shared_ptr<const Feature_terms>(m_pre, &p.data->features);
    auto red = std::make_shared<Reduction>();
    {
      Stage_timer timer(&m_times.oversegmentation);
      build_reduction(*red, *s->features, nullptr);
    }
    s->reduction = red;
    std::vector<std::size_t> group(red->os.number_of_segments);
    for(std::size_t i = 0; i < group.size(); ++i) group[i] = i;
    s->group = std::make_shared<const std::vector<std::size_t> >(std::move(group));
    s->segment_patch = std::make_shared<const std::vector<std::size_t> >();
    solve(*s, nullptr);
    m_history = Edit_history(std::move(s));
  }

  const Precomputation& precomputation() const { return *m_pre; }
  const Edit_state& state() const { return m_history.current(); }
  const Edit_history& history() const { return m_history; }
  Edit_history& history() { return m_history; }
  const Stage_times& stage_times() const { return m_times; }

  // The global edit: the state's alpha moves, its alpha_e follow it (edge_alphas.h);
  // nothing per edge or per vertex is written.
  std::size_t set_alpha(double a)
  {
    return edit([&](Edit_state& s) {
      s.alpha = a;
      solve(s, nullptr);
      return true;
    });
  }

  // Applies `change` to the alpha_e of the feature edges of `faces` (and the ties of their
  // creases), then re-solves the patches the faces touch.
  template <typename FaceRange, typename Change>
  std::size_t edit_region(const FaceRange& faces, Change change)
  {
    return edit([&](Edit_state& s) {
      const std::set<std::size_t> touched = patches_of(s, faces);
      if(touched.empty()) return false;
      const Precomputation& p = *m_pre;
      const TriangleMesh& tm = p.working_mesh();
      std::vector<std::size_t> edges; // each changed once
      for(face_descriptor f : faces)
        for(auto h : CGAL::halfedges_around_face(halfedge(p.working_face(f), tm), tm))
        {
          const std::size_t e = p.working_indexing().edge_id(h);
          const auto t = p.ties_of_working_edge(e);
          for(std::size_t i = t.first; i < t.second; ++i) edges.push_back(i); // a crease's ties
          if(s.features->is_feature_edge[e]) edges.push_back(e);
        }
      std::sort(edges.begin(), edges.end());
      edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
      for(std::size_t e : edges) s.alpha_e.set(e, change(s.alpha_of(e)), true, s.alpha); // feature edges
      solve_patches(s, touched, nullptr);
      return true;
    });
  }

  template <typename FaceRange>
  std::size_t merge_patches(const FaceRange& faces)
  {
    return edit([&](Edit_state& s) {
      const std::set<std::size_t> touched = patches_of(s, faces);
      if(touched.size() < 2) return false;
      // the touched patches' groups become the first of them
      const std::vector<char> group_in = groups_in_patches(s, touched);
      const std::size_t target_group = std::size_t(std::find(group_in.begin(), group_in.end(), 1) - group_in.begin());
      auto group = std::make_shared<std::vector<std::size_t> >(*s.group);
      for(std::size_t& g : *group)
        if(group_in[g]) g = target_group;
      auto patch = std::make_shared<std::vector<std::size_t> >(*s.segment_patch);
      const std::size_t merged = *touched.begin();
      for(std::size_t& l : *patch) if(touched.count(l)) l = merged;
      s.number_of_patches = normalize_patches(*s.reduction, *patch);
      s.group = group;
      s.segment_patch = patch;
      return true;
    });
  }

  // The edges that `sketch` crosses become feature edges with alpha_e at least
  // `sketch_alpha`; the terms around them, the oversegmentation inside the patches the
  // sketch touches, and those patches' clustering are redone.
  std::size_t add_sketch(const std::vector<Sketch_input>& sketch, double sketch_alpha)
  {
    const Precomputation& p = *m_pre;
    const std::vector<Sketch_crossing> crossings = walk_sketch(*p.data, sketch);
    if(crossings.empty()) return state().number_of_patches;
    return edit([&](Edit_state& s) {
      const Segmentation_data<TriangleMesh>& d = *p.data;
      const TriangleMesh& tm = p.working_mesh();
      auto features = std::make_shared<Feature_terms>(*s.features);
      std::vector<std::size_t> faces;
      std::set<std::size_t> touched;
      for(const Sketch_crossing& c : crossings)
      {
        // its alpha_e before (read as a feature edge if an earlier crossing made it one)
        const double before = s.alpha_e(c.edge, features->is_feature_edge[c.edge] != 0, s.alpha);
        features->add_point(c.edge, c.point);
        features->is_feature_edge[c.edge] = 1;
        s.alpha_e.set(c.edge, (std::max)(before, sketch_alpha), true, s.alpha);
        auto h = halfedge(d.idx.edge_at(c.edge), tm);
        for(auto hh : { h, opposite(h, tm) })
          if(!is_border(hh, tm)) faces.push_back(d.idx.face_id(hh));
        touched.insert(s.vertex_patch(d.edge_vertices[c.edge].first));
        touched.insert(s.vertex_patch(d.edge_vertices[c.edge].second));
      }
      std::sort(faces.begin(), faces.end());
      faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
      Edge_weight_terms<TriangleMesh>::update_faces(d.idx, d.points, *d.metrics, *features, faces);
      features->number_of_feature_edges = p.count_feature_edges(*features);
      // redo the oversegmentation inside the touched patches
      std::vector<char> region(s.reduction->os.vertex_segment.size(), 0);
      for(std::size_t v = 0; v < region.size(); ++v) region[v] = touched.count(s.vertex_patch(v)) ? 1 : 0;
      auto red = std::make_shared<Reduction>();
      std::vector<std::size_t> group, patch;
      {
        m_times.oversegmentation = 0;
        Stage_timer timer(&m_times.oversegmentation);
        rebuild_reduction_in(s, *features, region, *red, group, patch);
      }
      s.features = features;
      s.reduction = red;
      s.group = std::make_shared<const std::vector<std::size_t> >(std::move(group));
      s.segment_patch = std::make_shared<const std::vector<std::size_t> >(std::move(patch));
      solve_patches(s, touched, &region);
      return true;
    });
  }

  bool undo() { return m_history.undo(); }
  bool redo() { return m_history.redo(); }

  // The patches of the vertices of `faces` in state `s`.
  template <typename FaceRange>
  std::set<std::size_t> patches_of(const Edit_state& s, const FaceRange& faces) const
  {
    const Precomputation& p = *m_pre;
    const TriangleMesh& tm = p.working_mesh();
    std::set<std::size_t> touched;
    for(face_descriptor f : faces)
    {
      check_face(f);
      for(auto h : CGAL::halfedges_around_face(halfedge(p.working_face(f), tm), tm))
        touched.insert(s.vertex_patch(p.working_indexing().id(target(h, tm))));
    }
    return touched;
  }

  // The patch of working face `f` in state `s` by the one face rule (face_patch_rule.h)
  // under the boundaries of its labels as patch_boundaries() makes them, computed on the
  // face alone: the same as majority_patch() on make_patch_boundaries(), without it.
  std::size_t face_patch(const Edit_state& s, std::size_t f) const
  {
    typedef Boundary_state<TriangleMesh> B;
    const Segmentation_data<TriangleMesh>& d = *m_pre->data;
    const std::array<std::uint32_t, 3>& v = m_pre->face_corners[f];
    const std::array<std::size_t, 3> l = { s.vertex_patch(v[0]), s.vertex_patch(v[1]), s.vertex_patch(v[2]) };
    if(l[0] == l[1] && l[1] == l[2]) return l[0];
    const Mesh_indexing<TriangleMesh>& idx = d.idx;
    const TriangleMesh& tm = idx.mesh();
    const auto h = halfedge(idx.face_at(f), tm);
    const std::array<decltype(h), 3> hs = { h, next(h, tm), prev(h, tm) };
    std::array<Eigen::Vector3d, 3> p, edge_point;
    for(int k = 0; k < 3; ++k) p[k] = d.points[v[k]];
    const std::vector<Eigen::Vector3d>& dual = s.features->dual_vertices;
    for(int k = 0; k < 3; ++k)
    {
      if(l[k] == l[(k + 1) % 3]) continue;
      // as Boundary_state::initialize, in the orientation of the edge's own halfedge
      const auto eh = halfedge(edge(hs[k], tm), tm);
      const Eigen::Vector3d& a = d.points[idx.id(source(eh, tm))];
      const Eigen::Vector3d& b = d.points[idx.id(target(eh, tm))];
      const std::size_t f0 = idx.face_id(eh), f1 = idx.face_id(opposite(eh, tm));
      const double t = (f0 == B::npos || f1 == B::npos) ? 0.5 : B::initial_edge_t(a, b, dual[f0], dual[f1]);
      edge_point[k] = (1 - t) * a + t * b;
    }
    return area_majority_patch(l, p, edge_point, B::keep_inside(p[0], p[1], p[2], dual[f], B::face_margin));
  }

  // The patch of every working face (as face_patch()), by TBB's threads if the
  // precomputation's are on: the same patches at any thread count.
  std::vector<std::size_t> face_patches(const Edit_state& s) const
  {
    std::vector<std::size_t> patch(m_pre->face_corners.size());
    for_each_range(patch.size(), m_pre->parallel, 16384, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f) patch[f] = face_patch(s, f);
    });
    return patch;
  }

  static void check_face(face_descriptor f)
  {
    if(f == boost::graph_traits<TriangleMesh>::null_face())
      throw Invalid_input("a face of the edit is the null face");
  }

private:
  // Runs `make` on a copy of the current state (sharing all its parts); if it returns
  // true, the copy becomes the new current state. Returns the number of patches.
  template <typename Make>
  std::size_t edit(Make make)
  {
    const auto start = std::chrono::steady_clock::now();
    auto s = std::make_shared<Edit_state>(state());
    if(make(*s)) m_history.push(std::move(s));
    m_times.last_edit = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return state().number_of_patches;
  }

  void build_reduction(Reduction& r, const Feature_terms& features, const std::vector<char>* region) const
  {
    const Precomputation& p = *m_pre;
    r.os = p.reduced ? compute_oversegmentation(*p.data, features, p.anisotropic, region, p.parallel) : singletons(region);
    if(region == nullptr)
    {
      r.rg.build(r.os.vertex_segment, r.os.number_of_segments, p.data->edge_vertices);
      r.order_segments();
    }
  }

  Oversegmentation singletons(const std::vector<char>* region) const
  {
    Oversegmentation os;
    os.vertex_segment.assign(m_pre->working_indexing().number_of_vertices(), std::size_t(-1));
    for(std::size_t v = 0; v < os.vertex_segment.size(); ++v)
      if(region == nullptr || (*region)[v]) os.vertex_segment[v] = os.number_of_segments++;
    return os;
  }

  // The oversegmentation of state `s` with its segments inside `region` redone on
  // `features`: the segments outside keep their merge groups (ids compacted) and their
  // patches, the new ones are free (patch 0 until solved).
  void rebuild_reduction_in(const Edit_state& s, const Feature_terms& features, const std::vector<char>& region,
                            Reduction& out, std::vector<std::size_t>& group, std::vector<std::size_t>& patch) const
  {
    Reduction local;
    build_reduction(local, features, &region);
    const std::vector<std::size_t>& old_seg = s.reduction->os.vertex_segment;
    const std::vector<std::size_t>& old_group = *s.group;
    std::vector<std::size_t> renum(s.reduction->os.number_of_segments, std::size_t(-1));
    group.clear();
    patch.clear();
    std::size_t k = 0;
    for(std::size_t v = 0; v < region.size(); ++v)
    {
      if(region[v]) continue;
      std::size_t& r = renum[old_seg[v]];
      if(r == std::size_t(-1))
      {
        r = k++;
        group.push_back(old_group[old_seg[v]]);
        patch.push_back((*s.segment_patch)[old_seg[v]]);
      }
    }
    const std::size_t first_new = k;
    patch.resize(first_new + local.os.number_of_segments, 0);
    out.os.vertex_segment.resize(region.size());
    for(std::size_t v = 0; v < region.size(); ++v)
      out.os.vertex_segment[v] = region[v] ? first_new + local.os.vertex_segment[v] : renum[old_seg[v]];
    out.os.number_of_segments = first_new + local.os.number_of_segments;
    std::vector<std::size_t> group_renum(old_group.size() + local.os.number_of_segments, std::size_t(-1));
    std::size_t ng = 0;
    for(std::size_t& g : group)
    {
      if(group_renum[g] == std::size_t(-1)) group_renum[g] = ng++;
      g = group_renum[g];
    }
    for(std::size_t i = 0; i < local.os.number_of_segments; ++i) group.push_back(ng++);
    out.rg.build(out.os.vertex_segment, out.os.number_of_segments, m_pre->data->edge_vertices);
    out.order_segments();
  }

  // Re-solves the patches in `touched` (given by patch; or by `vertex_region` after a
  // sketch, whose segments are new and have no patch yet).
  void solve_patches(Edit_state& s, const std::set<std::size_t>& touched, const std::vector<char>* vertex_region)
  {
    if(vertex_region == nullptr)
    {
      const std::vector<char> in = groups_in_patches(s, touched);
      solve(s, &in);
      return;
    }
    const std::vector<std::size_t>& group = *s.group;
    std::vector<char> in(*std::max_element(group.begin(), group.end()) + 1, 0);
    const std::vector<std::size_t>& seg = s.reduction->os.vertex_segment;
    for(std::size_t v = 0; v < seg.size(); ++v)
      if((*vertex_region)[v]) in[group[seg[v]]] = 1;
    solve(s, &in);
  }

  // Per merge group of state `s`: whether its oversegments are in the patches `touched`
  // (a group lies in one patch).
  static std::vector<char> groups_in_patches(const Edit_state& s, const std::set<std::size_t>& touched)
  {
    const std::vector<std::size_t>& group = *s.group;
    const std::vector<std::size_t>& patch = *s.segment_patch;
    std::vector<char> patch_in(s.number_of_patches, 0), in(*std::max_element(group.begin(), group.end()) + 1, 0);
    for(std::size_t t : touched) patch_in[t] = 1;
    for(std::size_t i = 0; i < patch.size(); ++i)
      if(patch_in[patch[i]]) in[group[i]] = 1;
    return in;
  }

  // Renumbers the patches of the oversegments 0, 1, ... in the order of their first
  // vertex (as normalize_labels() on the vertex labels would); returns their number.
  static std::size_t normalize_patches(const Reduction& r, std::vector<std::size_t>& patch)
  {
    if(patch.empty()) return 0;
    const std::size_t none = std::size_t(-1);
    std::vector<std::size_t> new_id(*std::max_element(patch.begin(), patch.end()) + 1, none);
    std::size_t k = 0;
    for(std::size_t i : r.segments_in_vertex_order)
      if(new_id[patch[i]] == none) new_id[patch[i]] = k++;
    for(std::size_t& l : patch) l = new_id[l];
    return k;
  }

  // Clusters the groups of oversegments whose `group_in_region` is set (all if null);
  // the others keep their labels. Nodes of the solved graph are merge groups (a
  // constraint never cut).
  void solve(Edit_state& s, const std::vector<char>* group_in_region)
  {
    const Reduction& r = *s.reduction;
    const std::vector<std::size_t>& group = *s.group;
    std::vector<std::size_t> node;
    std::size_t n = 0;
    Correlation_clustering_graph graph(0);
    {
      m_times.graph = 0;
      Stage_timer timer(&m_times.graph);
      const std::size_t ngroups = group.empty() ? 0 : *std::max_element(group.begin(), group.end()) + 1;
      node.assign(ngroups, std::size_t(-1));
      for(std::size_t g = 0; g < ngroups; ++g)
        if(group_in_region == nullptr || (*group_in_region)[g]) node[g] = n++;
      graph = Correlation_clustering_graph(n);
      for(std::size_t i = 0; i < r.rg.edges.size(); ++i)
      {
        const std::size_t a = node[group[r.rg.edges[i].first]], b = node[group[r.rg.edges[i].second]];
        if(a == std::size_t(-1) || b == std::size_t(-1) || a == b) continue;
        double sum = 0;
        for(std::size_t k = r.rg.cross_begin[i]; k < r.rg.cross_begin[i + 1]; ++k) sum += s.weight(r.rg.cross[k]);
        graph.add_edge(a, b, sum);
      }
    }
    std::vector<std::size_t> lab;
    {
      m_times.solve = 0;
      Stage_timer timer(&m_times.solve);
      m_pre->solver(graph, lab);
    }
    CGAL_postcondition(lab.size() == n);
    m_times.labels = 0;
    Stage_timer timer(&m_times.labels);
    // the patch of every oversegment: the solved ones get new ids after the old ones
    const bool everything = (group_in_region == nullptr);
    const std::size_t offset = everything ? 0 : s.number_of_patches;
    CGAL_assertion(everything || s.segment_patch->size() == r.os.number_of_segments);
    auto patch = everything ? std::make_shared<std::vector<std::size_t> >(r.os.number_of_segments, 0)
                            : std::make_shared<std::vector<std::size_t> >(*s.segment_patch);
    for(std::size_t i = 0; i < patch->size(); ++i)
    {
      const std::size_t nd = node[group[i]];
      if(nd != std::size_t(-1)) (*patch)[i] = offset + lab[nd];
    }
    // on a rough mesh, the few faces that noise cuts out join a neighbour
    if(m_pre->joins_small_patches())
      join_small_patches(r.rg, r.segment_size, [&s](std::size_t e) { return s.weight(e); }, small_patch_max_vertices,
                         *patch);
    s.number_of_patches = normalize_patches(r, *patch);
    s.segment_patch = patch;
  }

  std::shared_ptr<const Precomputation> m_pre;
  Edit_history m_history;
  Stage_times m_times;
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_EDITING_ENGINE_H
