// SPDX-License-Identifier: GPL-3.0-or-later
// The patches of a rough mesh too small to be a surface of their own. On a mesh that is
// not a clean tessellation, noise that survived the normal filter tilts a few faces far
// from their neighbours; join_isolated_crease_faces() joins the pieces that creases
// alone cut out, but the solve also cuts out pieces bounded partly by creases and partly
// by cut edges. After every solve, each patch of at most small_patch_max_vertices
// vertices joins the neighbouring patch whose join costs the clustering's objective
// least.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_SMALL_PATCHES_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_SMALL_PATCHES_H

#include <CGAL/Feature_segmentation/internal/oversegmentation_impl.h>

#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

// The most vertices of a patch (of the working mesh) that joins a neighbour on a rough
// mesh (join_small_patches()).
constexpr std::size_t small_patch_max_vertices = 10;

// Joins every patch of `patch` (per oversegment, ids below the largest plus one) whose
// oversegments hold at most `max_vertices` vertices together (`segment_size`: vertices
// per oversegment) into the neighbouring patch (across an edge of `rg`) with the largest
// sum of weights (`weight`: per mesh edge or tie, as rg.cross lists them) between the
// two, that is the join that raises the objective (the weight of the cut edges) least;
// ties go to the smaller id. The smallest patch joins first (then the smaller id); a
// patch that a join leaves small joins again. A patch without a neighbour stays. Every
// patch id of the result is one of the input's (not renumbered).
template <typename Weight>
void join_small_patches(const Reduced_graph& rg, const std::vector<std::size_t>& segment_size, const Weight& weight,
                        std::size_t max_vertices, std::vector<std::size_t>& patch)
{
  if(patch.empty() || max_vertices == 0) return;
  std::size_t np = 0;
  for(std::size_t p : patch) np = (std::max)(np, p + 1);
  std::vector<std::size_t> size(np, 0);
  for(std::size_t i = 0; i < patch.size(); ++i) size[patch[i]] += segment_size[i];
  std::set<std::pair<std::size_t, std::size_t> > small; // (size, patch)
  for(std::size_t p = 0; p < np; ++p)
    if(size[p] > 0 && size[p] <= max_vertices) small.insert({ size[p], p });
  if(small.empty()) return;
  // the weights between every small patch and its neighbours
  std::vector<std::map<std::size_t, double> > between(np);
  for(std::size_t i = 0; i < rg.edges.size(); ++i)
  {
    const std::size_t a = patch[rg.edges[i].first], b = patch[rg.edges[i].second];
    if(a == b || (size[a] > max_vertices && size[b] > max_vertices)) continue;
    double sum = 0;
    for(std::size_t k = rg.cross_begin[i]; k < rg.cross_begin[i + 1]; ++k) sum += weight(rg.cross[k]);
    if(size[a] <= max_vertices) between[a][b] += sum;
    if(size[b] <= max_vertices) between[b][a] += sum;
  }
  std::vector<std::size_t> into(np);
  for(std::size_t p = 0; p < np; ++p) into[p] = p;
  while(!small.empty())
  {
    const std::size_t p = small.begin()->second;
    small.erase(small.begin());
    if(between[p].empty()) continue; // a component of its own
    std::size_t q = between[p].begin()->first;
    double best = between[p].begin()->second;
    for(const auto& [r, w] : between[p])
      if(w > best) { best = w; q = r; }
    into[p] = q;
    // q's neighbours gain p's; a small neighbour of p now borders q instead
    const bool q_small = small.erase({ size[q], q }) > 0;
    size[q] += size[p];
    for(const auto& [r, w] : between[p])
    {
      if(r == q) continue;
      if(q_small) between[q][r] += w;
      if(size[r] <= max_vertices)
      {
        between[r].erase(p);
        between[r][q] += w;
      }
    }
    if(q_small)
    {
      between[q].erase(p);
      if(size[q] <= max_vertices) small.insert({ size[q], q });
    }
    between[p].clear();
  }
  for(std::size_t& l : patch)
  {
    std::size_t r = l;
    while(into[r] != r) r = into[r];
    l = r;
  }
}

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_SMALL_PATCHES_H
