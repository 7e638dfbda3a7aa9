// SPDX-License-Identifier: GPL-3.0-or-later
#include "ransac.h"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Random.h>
#include <CGAL/Shape_detection/Efficient_RANSAC.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <tuple>
#include <utility>

namespace fs_evaluation {

std::vector<std::size_t> efficient_ransac_face_patches(
  const CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& mesh)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  // a face's centroid, normal and index (the detection reorders its input)
  typedef std::tuple<K::Point_3, K::Vector_3, std::size_t> Sample;
  typedef std::vector<Sample> Points;
  typedef CGAL::Shape_detection::Efficient_RANSAC_traits<K, Points, CGAL::Nth_of_tuple_property_map<0, Sample>,
                                                         CGAL::Nth_of_tuple_property_map<1, Sample> >
    Traits;
  typedef CGAL::Shape_detection::Efficient_RANSAC<Traits> Ransac;

  const std::size_t nf = mesh.number_of_faces();
  Points points(nf);
  for(Mesh::Face_index f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const K::Point_3 c = CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                        mesh.point(target(next(h, mesh), mesh)));
    points[f.idx()] = Sample(c, CGAL::Polygon_mesh_processing::compute_face_normal(f, mesh), f.idx());
  }
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  double edge_sum = 0;
  for(auto e : edges(mesh))
    edge_sum += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                                 mesh.point(target(halfedge(e, mesh), mesh))));
  const double mean_edge = edge_sum / (std::max)(std::size_t(1), std::size_t(mesh.number_of_edges()));

  CGAL::get_default_random() = CGAL::Random(1); // the detection draws its samples there
  Ransac ransac;
  ransac.set_input(points);
  ransac.add_shape_factory<CGAL::Shape_detection::Plane<Traits> >();
  ransac.add_shape_factory<CGAL::Shape_detection::Cylinder<Traits> >();
  ransac.add_shape_factory<CGAL::Shape_detection::Cone<Traits> >();
  ransac.add_shape_factory<CGAL::Shape_detection::Sphere<Traits> >();
  ransac.add_shape_factory<CGAL::Shape_detection::Torus<Traits> >();
  Ransac::Parameters parameters;
  parameters.probability = 0.01;
  parameters.min_points = (std::max)(std::size_t(10), nf / 500);
  parameters.epsilon = 0.005 * diagonal;
  parameters.cluster_epsilon = 3 * mean_edge; // face centroids are about an edge apart
  parameters.normal_threshold = std::cos(25. * CGAL_PI / 180.);
  ransac.detect(parameters);

  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> shape(nf, none);
  std::size_t k = 0;
  for(const auto& s : ransac.shapes())
  {
    for(std::size_t i : s->indices_of_assigned_points()) shape[std::get<2>(points[i])] = k;
    ++k;
  }
  // faces of no shape take their neighbours' (breadth first from the assigned faces)
  std::deque<Mesh::Face_index> queue;
  for(Mesh::Face_index f : faces(mesh))
    if(shape[f.idx()] != none) queue.push_back(f);
  if(queue.empty()) return std::vector<std::size_t>(nf, 0);
  while(!queue.empty())
  {
    const Mesh::Face_index f = queue.front();
    queue.pop_front();
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const auto g = face(opposite(h, mesh), mesh);
      if(g == Mesh::null_face() || shape[g.idx()] != none) continue;
      shape[g.idx()] = shape[f.idx()];
      queue.push_back(g);
    }
  }
  // a patch: a connected set of faces of one shape (a face of another component, which
  // the flood did not reach, is a patch of its own kind: none)
  std::vector<std::size_t> patch(nf, none);
  std::size_t patches = 0;
  for(Mesh::Face_index seed : faces(mesh))
  {
    if(patch[seed.idx()] != none) continue;
    patch[seed.idx()] = patches;
    std::deque<Mesh::Face_index> component{seed};
    while(!component.empty())
    {
      const Mesh::Face_index f = component.front();
      component.pop_front();
      for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      {
        const auto g = face(opposite(h, mesh), mesh);
        if(g == Mesh::null_face() || patch[g.idx()] != none || shape[g.idx()] != shape[f.idx()]) continue;
        patch[g.idx()] = patches;
        component.push_back(g);
      }
    }
    ++patches;
  }
  return patch;
}

} // namespace fs_evaluation
