// SPDX-License-Identifier: GPL-3.0-or-later
// The watershed oversegmentation of the mesh (paper, Section 3.3) and the reduced graph
// G' it induces: distances on the dual graph from the faces that hold a feature edge,
// the immersion watershed of their negation, basin labels pulled to the vertices, and the
// edges of G' with the mesh edges each one stands for.

#ifndef CGAL_FEATURE_SEGMENTATION_INTERNAL_OVERSEGMENTATION_IMPL_H
#define CGAL_FEATURE_SEGMENTATION_INTERNAL_OVERSEGMENTATION_IMPL_H

#include <CGAL/Feature_segmentation/Correlation_clustering_graph.h>
#include <CGAL/Feature_segmentation/internal/Segmentation_data.h>
#include <CGAL/Feature_segmentation/internal/parallel_for.h>
#include <CGAL/Feature_segmentation/internal/watershed.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Feature_segmentation {
namespace internal {

struct Oversegmentation
{
  std::vector<std::size_t> vertex_segment;  // oversegment of every vertex, 0..k-1
  std::size_t number_of_segments = 0;
};

// From face basins to vertex oversegments: see the three steps below.
template <typename TriangleMesh>
//
// With `vertex_in_region`, only the region is oversegmented (a sketch edit redoes the
// patches it touches): the faces whose three vertices are in the region, and the
// region's vertices; the others get `std::size_t(-1)` in `vertex_segment`.
Oversegmentation compute_oversegmentation(const Segmentation_data<TriangleMesh>& data, const Feature_terms& features,
                                          bool anisotropic, const std::vector<char>* vertex_in_region = nullptr,
                                          bool parallel = false)
{
  const auto& idx = data.idx;
  const TriangleMesh& tm = idx.mesh();
  const std::size_t nf = idx.number_of_faces(), nv = idx.number_of_vertices();
  // dual graph: one dual edge per interior mesh edge, of length Similarity (anisotropic
  // distance) or Award (Euclidean, the geodesic variant of Mitani-Suzuki and Levy et al.)
  std::vector<char> face_in(nf, 1);
  auto in_region = [&](std::size_t v) { return vertex_in_region == nullptr || (*vertex_in_region)[v] != 0; };
  if(vertex_in_region != nullptr)
    for(std::size_t f = 0; f < nf; ++f)
      for(auto h : CGAL::halfedges_around_face(halfedge(idx.face_at(f), tm), tm))
        if(!in_region(idx.id(target(h, tm)))) face_in[f] = 0;
  // With a region, the graph's nodes are the region's faces only, in face order (a
  // sketch's watershed costs its patches, not the mesh). The faces outside would be
  // isolated nodes whose basins are dropped below, and the region's basin ids keep
  // their order, so the oversegments are the same.
  std::vector<Compact_index> node_of, face_of_node;
  if(vertex_in_region != nullptr)
  {
    node_of.assign(nf, Compact_index(std::size_t(-1)));
    for(std::size_t f = 0; f < nf; ++f)
      if(face_in[f]) { node_of[f] = face_of_node.size(); face_of_node.push_back(f); }
  }
  const std::size_t nodes = vertex_in_region != nullptr ? face_of_node.size() : nf;
  auto node = [&](std::size_t f) { return vertex_in_region != nullptr ? std::size_t(node_of[f]) : f; };
  std::vector<char> source(nodes, 0);
  // (the edge list is freed once the graph is made)
  const Csr_graph g = [&]() {
    std::vector<std::pair<Compact_index, Compact_index> > dual;
    std::vector<double> len;
    dual.reserve(idx.number_of_edges());
    len.reserve(idx.number_of_edges());
    for(std::size_t e = 0; e < idx.number_of_edges(); ++e)
    {
      auto h = halfedge(idx.edge_at(e), tm);
      std::size_t f1 = idx.face_id(h), f2 = idx.face_id(opposite(h, tm));
      if(f1 != Mesh_indexing<TriangleMesh>::npos && !face_in[f1]) f1 = Mesh_indexing<TriangleMesh>::npos;
      if(f2 != Mesh_indexing<TriangleMesh>::npos && !face_in[f2]) f2 = Mesh_indexing<TriangleMesh>::npos;
      if(features.is_feature_edge[e])
      {
        if(f1 != Mesh_indexing<TriangleMesh>::npos) source[node(f1)] = 1;
        if(f2 != Mesh_indexing<TriangleMesh>::npos) source[node(f2)] = 1;
      }
      if(f1 == Mesh_indexing<TriangleMesh>::npos || f2 == Mesh_indexing<TriangleMesh>::npos) continue;
      dual.emplace_back(node(f1), node(f2));
      len.push_back(anisotropic ? features.similarity[e] : features.award[e]);
    }
    return Csr_graph::from_edges(nodes, dual, len);
  }();
  std::vector<double> height = multi_source_distances(g, source);
  for(double& h : height) h = -h; // basins lie far from the features
  Oversegmentation os;
  // face basins are only a step towards the vertex oversegments: not kept
  std::vector<long> face_basin = immersion_watershed(g, height);
  if(vertex_in_region != nullptr)
  {
    // outside the region: not a basin face
    std::vector<long> node_basin;
    node_basin.swap(face_basin);
    face_basin.assign(nf, watershed_label);
    for(std::size_t i = 0; i < node_basin.size(); ++i) face_basin[face_of_node[i]] = node_basin[i];
  }

  // 1. Majority basin of the basin faces around each vertex, ties to the smallest id.
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> basin(nv, none);
  // each vertex alone: by TBB's threads if `parallel`
  for_each_range(nv, parallel, 4096, [&](std::size_t first, std::size_t last) {
    std::vector<std::pair<long, int> > counts;
    for(std::size_t v = first; v < last; ++v)
    {
      if(!in_region(v)) continue;
      counts.clear();
      for(auto h : CGAL::halfedges_around_target(idx.vertex_at(v), tm))
      {
        const std::size_t f = idx.face_id(h);
        if(f == Mesh_indexing<TriangleMesh>::npos || face_basin[f] == watershed_label) continue;
        auto it = std::find_if(counts.begin(), counts.end(),
                               [&](const std::pair<long, int>& c) { return c.first == face_basin[f]; });
        if(it == counts.end()) counts.emplace_back(face_basin[f], 1);
        else ++it->second;
      }
      if(counts.empty()) continue;
      auto best = counts.begin();
      for(auto it = counts.begin(); it != counts.end(); ++it)
        if(it->second > best->second || (it->second == best->second && it->first < best->first)) best = it;
      basin[v] = std::size_t(best->first);
    }
  });
  // Vertex adjacency through non-feature edges (feature edges are never crossed below).
  std::vector<std::size_t> adj_begin(nv + 1, 0), adj;
  for(std::size_t e = 0; e < data.edge_vertices.size(); ++e)
    if(!features.is_feature_edge[e] && in_region(data.edge_vertices[e].first) && in_region(data.edge_vertices[e].second))
    { ++adj_begin[data.edge_vertices[e].first + 1]; ++adj_begin[data.edge_vertices[e].second + 1]; }
  for(std::size_t v = 0; v < nv; ++v) adj_begin[v + 1] += adj_begin[v];
  adj.resize(adj_begin[nv]);
  {
    std::vector<std::size_t> fill(adj_begin.begin(), adj_begin.end() - 1);
    for(std::size_t e = 0; e < data.edge_vertices.size(); ++e)
      if(!features.is_feature_edge[e] && in_region(data.edge_vertices[e].first) && in_region(data.edge_vertices[e].second))
      {
        const auto& ev = data.edge_vertices[e];
        adj[fill[ev.first]++] = ev.second;
        adj[fill[ev.second]++] = ev.first;
      }
  }
  // 2. A vertex whose faces all lie on the watershed takes the basin of the nearest
  //    labelled vertex (breadth first, in vertex order: deterministic); one that none
  //    reaches keeps no basin and ends up alone.
  {
    std::vector<std::size_t> queue;
    for(std::size_t v = 0; v < nv; ++v) if(basin[v] != none) queue.push_back(v);
    for(std::size_t i = 0; i < queue.size(); ++i)
      for(std::size_t k = adj_begin[queue[i]]; k < adj_begin[queue[i] + 1]; ++k)
        if(basin[adj[k]] == none) { basin[adj[k]] = basin[queue[i]]; queue.push_back(adj[k]); }
  }
  // 3. Oversegments: connected components of same-basin vertices through non-feature
  //    edges, so that every feature line is an oversegment boundary (paper, 3.3: the
  //    oversegmentation should include all input feature lines as boundaries).
  std::vector<std::size_t> seg(nv, none);
  std::size_t k = 0;
  std::vector<std::size_t> stack;
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(seg[v] != none || !in_region(v)) continue;
    seg[v] = k;
    stack.assign(1, v);
    while(!stack.empty())
    {
      const std::size_t x = stack.back();
      stack.pop_back();
      for(std::size_t j = adj_begin[x]; j < adj_begin[x + 1]; ++j)
      {
        const std::size_t y = adj[j];
        if(seg[y] == none && basin[y] != none && basin[y] == basin[x]) { seg[y] = k; stack.push_back(y); }
      }
    }
    ++k;
  }
  os.vertex_segment.swap(seg);
  os.number_of_segments = k;
  return os;
}

// G': one node per oversegment, one edge per pair of adjacent oversegments, standing for
// the mesh edges between them (the cross edges); its weight is the sum of theirs.
struct Reduced_graph
{
  std::size_t number_of_nodes = 0;
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  std::vector<std::size_t> cross_begin; // cross edges of G' edge i: cross[cross_begin[i] .. cross_begin[i+1])
  std::vector<std::size_t> cross;       // mesh edge ids

  void build(const std::vector<std::size_t>& vertex_segment, std::size_t k,
             const Edge_vertex_list& edge_vertices)
  {
    number_of_nodes = k;
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t> > c;
    for(std::size_t e = 0; e < edge_vertices.size(); ++e)
    {
      std::size_t a = vertex_segment[edge_vertices[e].first], b = vertex_segment[edge_vertices[e].second];
      if(a == b) continue;
      if(a > b) std::swap(a, b);
      c.emplace_back(a, b, e);
    }
    std::sort(c.begin(), c.end());
    edges.clear(); cross.clear(); cross_begin.clear();
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      if(i == 0 || std::get<0>(c[i]) != std::get<0>(c[i - 1]) || std::get<1>(c[i]) != std::get<1>(c[i - 1]))
      {
        edges.emplace_back(std::get<0>(c[i]), std::get<1>(c[i]));
        cross_begin.push_back(cross.size());
      }
      cross.push_back(std::get<2>(c[i]));
    }
    cross_begin.push_back(cross.size());
  }

  // The weighted G' for the per-edge weights `w` of the mesh edges.
  template <typename WeightOfEdge>
  Correlation_clustering_graph graph(WeightOfEdge w) const
  {
    Correlation_clustering_graph g(number_of_nodes);
    g.reserve_edges(edges.size());
    for(std::size_t i = 0; i < edges.size(); ++i)
    {
      double sum = 0;
      for(std::size_t k = cross_begin[i]; k < cross_begin[i + 1]; ++k) sum += w(cross[k]);
      g.add_edge(edges[i].first, edges[i].second, sum);
    }
    return g;
  }
};

} // namespace internal
} // namespace Feature_segmentation
} // namespace CGAL

#endif // CGAL_FEATURE_SEGMENTATION_INTERNAL_OVERSEGMENTATION_IMPL_H
