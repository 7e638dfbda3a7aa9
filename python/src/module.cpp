// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module `feature_segmentation` (its compiled part, `_core`): numpy arrays in,
// numpy arrays out, over the same pipeline as the program (the application layer's
// pipeline.h, app/Feature_segmentation/): the same mesh repairs, the same options with the same checks, the same
// edits (the edit script's Edit_runner), the same outputs. The GIL is released while the
// pipeline runs, so threads segment meshes at once. Bad input raises ValueError with the
// library's message.

#include "batch_command.h"
#include "pipeline.h"
#include "program_options.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cerrno>
#include <filesystem>
#include <memory>
#include <set>
#include <regex>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace fs_app;

namespace {

// Options from keyword arguments, through the program's own parser (same checks, same
// messages, with the flags renamed as keywords: "--crease-angle" -> "crease_angle").
Options options_from_kwargs(const py::kwargs& kwargs)
{
  std::vector<std::string> args{"feature_segmentation", "unused.off"};
  for(const auto& item : kwargs)
  {
    std::string key = py::str(item.first);
    const py::handle value = item.second;
    std::string flag = "--" + std::regex_replace(key, std::regex("_"), "-");
    if(key == "ridges" || key == "valleys" || key == "tangent_discontinuities" || key == "full_graph" ||
       key == "crest_lines_on_clean_tessellations")
    {
      if(!py::isinstance<py::bool_>(value)) throw py::type_error(key + " must be a bool");
      const bool on = value.cast<bool>();
      if(key == "full_graph" || key == "crest_lines_on_clean_tessellations") { if(on) args.push_back(flag); }
      else if(!on) args.push_back("--no-" + std::regex_replace(key, std::regex("_"), "-"));
      continue;
    }
    static const std::set<std::string> known{"alpha", "gamma", "rings", "radius", "strength_threshold",
                                             "crease_angle", "crease_filter", "solver", "watershed",
                                             "smoothing_iterations", "feature_edges"};
    if(!known.count(key))
      throw py::type_error("unexpected keyword argument '" + key + "'");
    if(value.is_none()) continue; // the default
    if(py::isinstance<py::bool_>(value)) throw py::type_error(key + " must be a number or a string, not a bool");
    args.push_back(flag);
    args.push_back(py::str(value));
  }
  args.push_back("--quiet");
  std::vector<char*> argv;
  for(std::string& a : args) argv.push_back(a.data());
  try
  {
    Options o = parse_command_line(int(argv.size()), argv.data());
    o.input.clear();
    return o;
  }
  catch(const Usage_error& e)
  {
    std::string what = e.what();
    what = std::regex_replace(what, std::regex("unknown option '--([a-z-]+)' \\(see --help\\)"),
                              "unexpected keyword argument '$1'");
    what = std::regex_replace(what, std::regex("--no-([a-z]+)"), "$1");
    std::smatch m;
    std::string out;
    // --crease-angle -> crease_angle
    std::string rest = what;
    const std::regex flag_re("--([a-z]+(-[a-z]+)*)");
    while(std::regex_search(rest, m, flag_re))
    {
      out += m.prefix().str() + std::regex_replace(m[1].str(), std::regex("-"), "_");
      rest = m.suffix().str();
    }
    throw py::value_error(out + rest);
  }
}

// `x` through numpy.asarray, as numpy functions take their inputs (a list of lists is
// an array); what numpy cannot make an array of is a short ValueError naming `what`.
py::array as_array(const py::object& x, const char* what)
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
Mesh_soup soup_from_arrays(const py::object& vertices_in, const py::object& faces_in)
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

py::array_t<std::int64_t> to_array(const std::vector<long>& v)
{
  py::array_t<std::int64_t> a(py::ssize_t(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

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
    Edit_script script;
    script.path = "edit";
    {
      py::gil_scoped_release release;
      try
      {
        m_results.edits.push_back(m_pipeline.edit_runner().apply(script, e));
      }
      catch(const Edit_script_error& error)
      {
        std::string what = error.what();
        const std::string prefix = "edit:" + std::to_string(e.line) + ": ";
        if(what.rfind(prefix, 0) == 0) what.erase(0, prefix.size());
        py::gil_scoped_acquire acquire;
        throw py::value_error(what);
      }
    }
    m_history.push_back(e);
    return m_pipeline.segmentation->number_of_patches();
  }

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
      d["kind"] = line.type == FS::Feature_line_type::RIDGE ? "ridge"
                  : line.type == FS::Feature_line_type::VALLEY ? "valley" : "user";
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

std::vector<std::size_t> face_list(const py::handle& faces)
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

Script_edit region_edit(const std::string& verb, const py::handle& faces, double value)
{
  Script_edit e;
  e.verb = verb;
  e.region.faces = face_list(faces);
  e.value = value;
  return e;
}

} // namespace

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
    .def("undo", [](Session& s) {
           Script_edit e; e.verb = "undo";
           try { s.edit(e); } catch(const py::value_error&) { return false; }
           return true;
         }, "take back the last edit; False if there is none")
    .def("redo", [](Session& s) {
           Script_edit e; e.verb = "redo";
           try { s.edit(e); } catch(const py::value_error&) { return false; }
           return true;
         }, "make the last undone edit again; False if there is none")
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
