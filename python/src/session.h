// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module's Segmentation: one mesh through the application layer's Pipeline,
// its results, and its edits as typed calls on the edit runner.

#ifndef FS_PYTHON_SESSION_H
#define FS_PYTHON_SESSION_H

#include "arrays.h"
#include "keywords.h"
#include "pipeline.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <string>
#include <vector>

namespace fs_python {

/// What a segmentation measured (the Python `Result`).
struct Result
{
  std::size_t patches = 0, faces = 0, vertices = 0, feature_edges = 0, crease_edges = 0;
  double cut_cost = 0;
  std::map<std::string, double> seconds;
};

// A Pipeline on arrays, with its options, timer and results: one segmentation.
class Session
{
public:
  Session(const py::object& vertices, const py::object& faces, const py::kwargs& kwargs)
    : m_options(options_from_kwargs(kwargs)), m_timer(true), m_pipeline(m_options, m_timer, m_results)
  {
    Mesh_soup soup = soup_from_arrays(vertices, faces);
    py::gil_scoped_release release;
    run_translated([&] {
      m_pipeline.load(soup, "the arrays");
      m_pipeline.segment();
    });
  }

  Result result() const
  {
    const auto& seg = *m_pipeline.segmentation;
    Result r;
    r.patches = seg.number_of_patches();
    r.cut_cost = seg.cut_cost();
    r.faces = num_faces(m_pipeline.mesh);
    r.vertices = num_vertices(m_pipeline.mesh);
    r.feature_edges = seg.number_of_feature_edges();
    r.crease_edges = seg.number_of_crease_edges();
    for(const auto& s : m_timer.seconds()) r.seconds[s.first] = s.second;
    return r;
  }

  // Per face of the input arrays, in their order, and per vertex (-1: a vertex no face
  // uses): the patches of the smoothed boundaries, as the program's face_patches.txt and
  // vertex_patches.txt.
  py::array_t<std::int64_t> face_patches() const { return to_array(file_patches().faces); }
  py::array_t<std::int64_t> vertex_patches() const { return to_array(file_patches().vertices); }
  // Both from one smoothing of the boundaries.
  py::tuple patch_arrays() const
  {
    const Pipeline::File_patches p = file_patches();
    return py::make_tuple(to_array(p.faces), to_array(p.vertices));
  }

  Pipeline::File_patches file_patches() const
  {
    py::gil_scoped_release release;
    return m_pipeline.file_patches(m_pipeline.boundaries(true));
  }

  // One edit of the edit script; faces are indices of the input arrays' faces.
  std::size_t edit(Script_edit e)
  {
    const std::size_t n = m_results.read_report.number_of_file_faces;
    for(std::size_t f : e.region.faces)
      if(f >= n)
        throw py::value_error(e.verb + ": face index " + std::to_string(f) + " is out of range (there are " +
                              std::to_string(n) + " faces)");
    e.region.kind = Script_region::FILE_FACES;
    e.line = m_history.size() + 1;
    {
      py::gil_scoped_release release;
      try
      {
        m_results.edits.push_back(m_pipeline.edit_runner().apply(e));
      }
      catch(const Edit_refused& refused)
      {
        py::gil_scoped_acquire acquire;
        throw py::value_error(refused.what());
      }
    }
    m_history.push_back(e);
    return m_pipeline.segmentation->number_of_patches();
  }

  // Undo or redo, if there is an edit to take back or make again.
  bool step(const char* verb, std::size_t available)
  {
    if(available == 0) return false;
    Script_edit e;
    e.verb = verb;
    edit(e);
    return true;
  }
  bool undo() { return step("undo", m_pipeline.edit_runner().number_of_undoable_edits()); }
  bool redo() { return step("redo", m_pipeline.edit_runner().number_of_redoable_edits()); }

  std::vector<std::string> edits() const { return edit_script_lines(m_history); }

  double alpha() const { return m_pipeline.segmentation->alpha(); }

  py::list boundaries(bool smooth) const
  {
    FS::Patch_boundaries<Mesh> b = [&] {
      py::gil_scoped_release release;
      return m_pipeline.boundaries(smooth);
    }();
    py::list curves;
    for(const auto& c : b.curves())
    {
      const std::vector<double> xyz = Pipeline::curve_coordinates(c);
      py::array_t<double> a({py::ssize_t(xyz.size() / 3), py::ssize_t(3)});
      std::copy(xyz.begin(), xyz.end(), a.mutable_data());
      curves.append(a);
    }
    return curves;
  }

  py::list feature_lines() const
  {
    py::list lines;
    for(const auto& line : m_pipeline.segmentation->feature_lines().lines)
    {
      std::vector<double> xyz = m_pipeline.line_coordinates(line);
      if(line.is_closed && !xyz.empty()) xyz.resize(xyz.size() - 3); // the points, once each
      py::array_t<double> a({py::ssize_t(xyz.size() / 3), py::ssize_t(3)});
      std::copy(xyz.begin(), xyz.end(), a.mutable_data());
      py::dict d;
      d["kind"] = FS::internal::feature_line_type_name(line.type);
      d["points"] = a;
      d["closed"] = line.is_closed;
      lines.append(d);
    }
    return lines;
  }

  // The crease edges as a (c, 2, 3) array of segments.
  py::array_t<double> creases() const
  {
    const std::vector<double> xyz = m_pipeline.crease_segments();
    py::array_t<double> a({py::ssize_t(xyz.size() / 6), py::ssize_t(2), py::ssize_t(3)});
    std::copy(xyz.begin(), xyz.end(), a.mutable_data());
    return a;
  }

  void save(const std::string& dir)
  {
    m_options.output_dir = dir;
    py::gil_scoped_release release;
    run_translated([&] {
      create_output_dir(m_options);
      m_pipeline.write_edits_file(m_history, "feature_segmentation.Segmentation");
      m_pipeline.write_outputs();
    });
  }

private:
  // Runs `f`, turning the package's exceptions into Python's (GIL released or not).
  template <typename F>
  static void run_translated(F&& f)
  {
    try
    {
      f();
    }
    catch(const Input_error& e)
    {
      py::gil_scoped_acquire acquire;
      throw py::value_error(e.what());
    }
    catch(const FS::Invalid_input& e)
    {
      py::gil_scoped_acquire acquire;
      throw py::value_error(e.what());
    }
  }

  Options m_options;
  Stage_timer m_timer;
  Results m_results;
  Pipeline m_pipeline;
  std::vector<Script_edit> m_history;
};

inline Script_edit region_edit(const std::string& verb, const py::handle& faces, double value)
{
  Script_edit e;
  e.verb = verb;
  e.region.faces = face_list(faces);
  e.value = value;
  return e;
}

} // namespace fs_python

#endif // FS_PYTHON_SESSION_H
