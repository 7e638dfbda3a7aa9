// SPDX-License-Identifier: GPL-3.0-or-later
// numpy arrays in and out of the Python module: the (n, 3) and (m, 3) arrays as a
// polygon soup, face index lists, int64 label arrays.

#ifndef FS_PYTHON_ARRAYS_H
#define FS_PYTHON_ARRAYS_H

#include "read_input_mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace fs_python {

namespace py = pybind11;
using namespace fs_app;

// `x` through numpy.asarray, as numpy functions take their inputs (a list of lists is
// an array); what numpy cannot make an array of is a short ValueError naming `what`.
inline py::array as_array(const py::object& x, const char* what)
{
  try
  {
    return py::module_::import("numpy").attr("asarray")(x);
  }
  catch(const py::error_already_set&)
  {
    throw py::value_error(std::string(what) + " must be an array or a nested sequence of numbers (got " +
                          std::string(py::str(py::type::of(x).attr("__name__"))) + ")");
  }
}

// The (n, 3) and (m, 3) arrays as a polygon soup: the one copy in.
inline Mesh_soup soup_from_arrays(const py::object& vertices_in, const py::object& faces_in)
{
  const py::array vertices = as_array(vertices_in, "vertices");
  const py::array faces = as_array(faces_in, "faces");
  if(vertices.ndim() != 2 || vertices.shape(1) != 3)
    throw py::value_error("vertices must be an (n, 3) array of coordinates");
  if(faces.ndim() != 2 || faces.shape(1) != 3)
    throw py::value_error("faces must be an (m, 3) array of vertex indices");
  if(!py::isinstance<py::array_t<double> >(vertices) && !py::isinstance<py::array_t<float> >(vertices) &&
     vertices.dtype().kind() != 'i' && vertices.dtype().kind() != 'u')
    throw py::value_error("vertices must hold numbers (got dtype " + std::string(py::str(vertices.dtype())) + ")");
  if(faces.dtype().kind() != 'i' && faces.dtype().kind() != 'u')
    throw py::value_error("faces must hold integers (got dtype " + std::string(py::str(faces.dtype())) + ")");
  const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  const auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
  Mesh_soup soup;
  soup.format = "arrays";
  const std::size_t n = std::size_t(v.shape(0)), m = std::size_t(f.shape(0));
  soup.points.resize(n);
  const double* pv = v.data();
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 3; ++k)
    {
      if(!std::isfinite(pv[3 * i + k]))
        throw py::value_error("vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
      soup.points[i][k] = pv[3 * i + k];
    }
  const std::int64_t* pf = f.data();
  soup.indices.resize(3 * m);
  soup.begin.resize(m + 1);
  for(std::size_t i = 0; i < 3 * m; ++i)
  {
    if(pf[i] < 0 || std::size_t(pf[i]) >= n)
      throw py::value_error("face " + std::to_string(i / 3) + " refers to vertex " + std::to_string(pf[i]) +
                            ", out of range (there are " + std::to_string(n) + " vertices)");
    soup.indices[i] = std::uint32_t(pf[i]);
  }
  for(std::size_t i = 0; i <= m; ++i) soup.begin[i] = std::uint32_t(3 * i);
  return soup;
}

inline py::array_t<std::int64_t> to_array(const std::vector<long>& v)
{
  py::array_t<std::int64_t> a(py::ssize_t(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

inline std::vector<std::size_t> face_list(const py::handle& faces)
{
  const auto a = py::array::ensure(faces);
  if(!a || a.ndim() != 1 || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
    throw py::value_error("faces must be a 1-D array (or list) of face indices");
  const auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  std::vector<std::size_t> out;
  for(py::ssize_t i = 0; i < f.shape(0); ++i)
  {
    if(f.data()[i] < 0) throw py::value_error("face indices must be >= 0");
    out.push_back(std::size_t(f.data()[i]));
  }
  if(out.empty()) throw py::value_error("faces is empty");
  return out;
}

} // namespace fs_python

#endif // FS_PYTHON_ARRAYS_H
