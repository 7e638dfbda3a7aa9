// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module `feature_segmentation` (its compiled part, `_core`): numpy arrays in,
// numpy arrays out, over the application layer's pipeline (app/Feature_segmentation/):
// the program's mesh repairs, options (by keyword, keywords.h), edits (typed calls on
// the edit runner, session.h) and outputs. The GIL is released while the pipeline runs,
// so threads segment meshes at once. A bad value raises ValueError with the program's
// message, a value of the wrong type TypeError.

#include "batch_command.h"
#include "session.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace fs_app;
using namespace fs_python;

PYBIND11_MODULE(_core, m)
{
  m.doc() = "Feature-aligned mesh segmentation by correlation clustering (compiled core).";

  py::class_<Result>(m, "Result", "What a segmentation measured.")
    .def_readonly("patches", &Result::patches, "number of patches")
    .def_readonly("cut_cost", &Result::cut_cost, "total weight of the cut edges")
    .def_readonly("faces", &Result::faces, "triangles of the (repaired) mesh")
    .def_readonly("vertices", &Result::vertices, "vertices of the (repaired) mesh")
    .def_readonly("feature_edges", &Result::feature_edges, "edges that carry a feature line or a crease")
    .def_readonly("crease_edges", &Result::crease_edges, "crease edges")
    .def_readonly("seconds", &Result::seconds, "seconds per stage (load, segmentation, ...)")
    .def("__repr__", [](const Result& r) {
      return "Result(patches=" + std::to_string(r.patches) + ", cut_cost=" + number_text(r.cut_cost) +
             ", faces=" + std::to_string(r.faces) + ")";
    });

  py::class_<Session>(m, "Segmentation", R"doc(
A segmentation that can be edited (the paper's Section 4).

Segmentation(vertices, faces, **options): vertices an (n, 3) float array, faces an
(m, 3) integer array; options as for segment(). Face indices of the edits, and
face_patches(), follow the rows of `faces`.)doc")
    .def(py::init<const py::object&, const py::object&, const py::kwargs&>(), py::arg("vertices"), py::arg("faces"))
    .def_property_readonly("patches", [](const Session& s) { return s.result().patches; }, "number of patches")
    .def_property_readonly("cut_cost", [](const Session& s) { return s.result().cut_cost; }, "cut cost")
    .def_property_readonly("alpha", &Session::alpha, "the global alpha")
    .def_property_readonly("edits", &Session::edits, "the edits so far, as edit-script lines")
    .def("result", &Session::result, "what the segmentation measured (Result)")
    .def("face_patches", &Session::face_patches,
         "patch of every face under the smoothed boundaries, as face_patches.txt (int64 array, the rows of `faces`)")
    .def("vertex_patches", &Session::vertex_patches,
         "patch of every vertex after the smoothing, as vertex_patches.txt (int64 array; -1: unused vertex)")
    .def("patch_arrays", &Session::patch_arrays,
         "(face_patches(), vertex_patches()) from one smoothing of the boundaries")
    .def("set_alpha", [](Session& s, double a) { Script_edit e; e.verb = "alpha"; e.value = a; return s.edit(e); },
         py::arg("alpha"), "global refine (larger) or coarsen; returns the number of patches")
    .def("refine", [](Session& s, const py::handle& f, double d) { return s.edit(region_edit("refine", f, d)); },
         py::arg("faces"), py::arg("amount"), "add `amount` to alpha_e on the feature edges of `faces`")
    .def("coarsen", [](Session& s, const py::handle& f, double d) { return s.edit(region_edit("coarsen", f, -d)); },
         py::arg("faces"), py::arg("amount"), "subtract `amount` from alpha_e on the feature edges of `faces`")
    .def("scale", [](Session& s, const py::handle& f, double x) {
           return s.edit(region_edit("scale", f, x));
         }, py::arg("faces"), py::arg("factor"), "multiply alpha_e on the feature edges of `faces` by `factor` >= 0")
    .def("merge", [](Session& s, const py::handle& f) { return s.edit(region_edit("merge", f, 0)); }, py::arg("faces"),
         "merge the patches that `faces` touch")
    .def("sketch", [](Session& s, const py::array& points, double alpha) {
           const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
           if(!p || p.ndim() != 2 || p.shape(1) != 3 || p.shape(0) < 2)
             throw py::value_error("sketch: points must be a (k, 3) array, k >= 2");
           Script_edit e;
           e.verb = "sketch";
           e.value = alpha;
           for(py::ssize_t i = 0; i < p.shape(0); ++i)
           {
             e.points.push_back({p.at(i, 0), p.at(i, 1), p.at(i, 2)});
           }
           return s.edit(e);
         }, py::arg("points"), py::arg("alpha") = default_sketch_alpha,
         "a feature curve through `points` (moved to the surface); returns the number of patches")
    .def("undo", &Session::undo, "take back the last edit; False if there is none")
    .def("redo", &Session::redo, "make the last undone edit again; False if there is none")
    .def("boundaries", &Session::boundaries, py::arg("smooth") = true,
         "the patch boundaries: a list of (k, 3) arrays (closed curves repeat their first point)")
    .def("feature_lines", &Session::feature_lines,
         "the feature lines: a list of {'kind': 'ridge'|'valley'|'user', 'points': (k, 3) array, 'closed': bool}")
    .def("creases", &Session::creases, "the crease edges: a (c, 2, 3) array of segments")
    .def("save", &Session::save, py::arg("directory"),
         "write the program's outputs and edits.txt (replayable with --edits) into `directory`");

  m.def("segment_file", [](const std::string& mesh, const std::string& output_dir, const py::kwargs& kwargs) {
          Options o = options_from_kwargs(kwargs);
          o.input = mesh;
          o.output_dir = output_dir;
          Results r;
          {
            py::gil_scoped_release release;
            r = segment_and_write(o);
          }
          return py::make_tuple(r.number_of_faces, r.number_of_patches, r.cut_cost);
        }, py::arg("mesh"), py::arg("output_dir"),
        "the program on one file: segments `mesh`, writes every output into `output_dir`; returns "
        "(faces, patches, cut_cost); raises on failure");
  m.def("check_options", [](const py::kwargs& kwargs) { options_from_kwargs(kwargs); },
        "raises ValueError (or TypeError) if the options are not valid");
  m.def("options", &option_descriptions,
        "the segmentation options: {keyword: {'type', 'default', 'help', 'flag'}} (default None: the library "
        "chooses; 'flag' is the program's command-line flag)");
  m.def("batch_plan", [](const std::vector<std::string>& inputs, const std::string& output_dir) {
          const std::vector<std::string> meshes = internal::batch_meshes(inputs);
          const std::vector<std::string> folders = internal::batch_folders(meshes);
          std::vector<std::pair<std::string, std::string> > plan;
          for(std::size_t i = 0; i < meshes.size(); ++i)
            plan.emplace_back(meshes[i], (std::filesystem::path(output_dir) / folders[i]).string());
          return plan;
        }, py::arg("inputs"), py::arg("output_dir"),
        "the meshes of a batch's inputs and their output folders, as `feature_segmentation batch` plans them");
  m.def("finished_row", [](const std::string& mesh, const std::string& output) -> py::object {
          Batch_row row;
          row.mesh = mesh;
          row.output = output;
          if(!internal::read_finished_row(std::filesystem::path(output) / "summary.json", row)) return py::none();
          return py::make_tuple(row.faces, row.patches, row.cut_cost, row.seconds);
        }, py::arg("mesh"), py::arg("output"),
        "(faces, patches, cut_cost, seconds) of a mesh whose outputs are complete, else None");
  m.def("write_batch_summary", [](const std::string& dir, const std::vector<py::dict>& rows) {
          std::vector<Batch_row> out;
          for(const py::dict& d : rows)
          {
            Batch_row r;
            r.mesh = d["mesh"].cast<std::string>();
            r.output = d["output"].cast<std::string>();
            r.faces = d["faces"].cast<std::size_t>();
            r.patches = d["patches"].cast<std::size_t>();
            r.cut_cost = d["cut_cost"].cast<double>();
            r.seconds = d["seconds"].cast<double>();
            r.status = d["status"].cast<std::string>();
            r.error = d["error"].cast<std::string>();
            out.push_back(r);
          }
          write_batch_summary(dir, out);
        }, py::arg("directory"), py::arg("rows"),
        "writes batch_summary.csv and batch_summary.jsonl, as `feature_segmentation batch` does");
  m.def("read_mesh", [](const std::string& path) {
          std::error_code ec;
          if(!std::filesystem::exists(path, ec))
          {
            // FileNotFoundError, as open() raises it: errno ENOENT and the file name
            PyErr_SetObject(PyExc_FileNotFoundError,
                            py::make_tuple(ENOENT, "No such file", path).ptr());
            throw py::error_already_set();
          }
          Mesh mesh;
          {
            py::gil_scoped_release release;
            try { read_input_mesh(path, mesh); }
            catch(const Input_error& e) { py::gil_scoped_acquire a; throw py::value_error(e.what()); }
          }
          py::array_t<double> v({py::ssize_t(num_vertices(mesh)), py::ssize_t(3)});
          py::array_t<std::int64_t> f({py::ssize_t(num_faces(mesh)), py::ssize_t(3)});
          std::size_t i = 0;
          for(Mesh::Vertex_index x : mesh.vertices())
          {
            v.mutable_at(i, 0) = mesh.point(x).x(); v.mutable_at(i, 1) = mesh.point(x).y();
            v.mutable_at(i, 2) = mesh.point(x).z(); ++i;
          }
          i = 0;
          for(Mesh::Face_index x : mesh.faces())
          {
            int k = 0;
            for(Mesh::Vertex_index y : CGAL::vertices_around_face(mesh.halfedge(x), mesh)) f.mutable_at(i, k++) = y;
            ++i;
          }
          return py::make_tuple(v, f);
        }, py::arg("path"),
        "reads OFF, OBJ, PLY or STL with the program's readers (triangulated, repaired): (vertices, faces)");
}
