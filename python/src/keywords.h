// SPDX-License-Identifier: GPL-3.0-or-later
// The Python module's keyword arguments: the segmentation options of the application
// layer's option table (option_table.h), converted by type and checked by the table.

#ifndef FS_PYTHON_KEYWORDS_H
#define FS_PYTHON_KEYWORDS_H

#include "option_table.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>
#include <string>

namespace fs_python {

namespace py = pybind11;
using namespace fs_app;

inline std::string type_name(const py::handle& x) { return py::str(py::type::of(x).attr("__name__")); }


// Options from keyword arguments: the segmentation options of option_table.h by their
// keywords, converted to the option's kind (TypeError for a wrong type) and stored by
// the table's own check (ValueError with its message); None keeps the default.
inline Options options_from_kwargs(const py::kwargs& kwargs)
{
  Options o;
  o.input.clear();
  o.quiet = true;
  for(const auto& item : kwargs)
  {
    const std::string key = py::str(item.first);
    const Option_entry* e = find_option(key);
    if(!e || !e->segmentation) throw py::type_error("unexpected keyword argument '" + key + "'");
    const py::handle value = item.second;
    if(value.is_none()) continue;
    Option_input in;
    in.name = key;
    in.got = py::str(value);
    const bool is_bool = py::isinstance<py::bool_>(value);
    switch(e->kind)
    {
    case Option_kind::SWITCH:
      if(!is_bool) throw py::type_error(key + " must be a bool (got " + type_name(value) + ")");
      in.on = value.cast<bool>();
      break;
    case Option_kind::INTEGER:
      if(is_bool || !PyIndex_Check(value.ptr()))
        throw py::type_error(key + " must be an integer (got " + type_name(value) + ")");
      {
        int overflow = 0;
        in.integer = PyLong_AsLongLongAndOverflow(py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr())).ptr(),
                                                  &overflow);
        if(overflow) in.integer = overflow > 0 ? std::numeric_limits<long long>::max() : std::numeric_limits<long long>::min();
      }
      break;
    case Option_kind::NUMBER:
      if(is_bool || py::isinstance<py::str>(value) || !py::hasattr(value, "__float__"))
        throw py::type_error(key + " must be a number (got " + type_name(value) + ")");
      in.number = py::float_(py::reinterpret_borrow<py::object>(value));
      break;
    case Option_kind::TEXT:
      if(!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__"))
        throw py::type_error(key + " must be a str (got " + type_name(value) + ")");
      in.text = in.got = py::str(py::module_::import("os").attr("fspath")(value));
      break;
    }
    try
    {
      apply_option(*e, o, in);
    }
    catch(const Usage_error& error)
    {
      throw py::value_error(error.what());
    }
  }
  return o;
}


// The segmentation options of option_table.h: {keyword: {"type", "default", "help"}}.
inline py::dict option_descriptions()
{
  static const char* const types[] = {"bool", "int", "float", "str"};
  const Options defaults;
  py::dict d;
  for(const Option_entry& e : option_table())
  {
    if(!e.segmentation) continue;
    const std::string shown = e.effective_value(defaults);
    py::object value = py::none();
    if(e.kind == Option_kind::SWITCH) value = py::bool_(shown == "true");
    else if(e.kind == Option_kind::INTEGER && !shown.empty()) value = py::int_(std::stoll(shown));
    else if(e.kind == Option_kind::NUMBER && !shown.empty()) value = py::float_(std::stod(shown));
    else if(e.kind == Option_kind::TEXT && !shown.empty()) value = py::str(shown);
    py::dict entry;
    entry["type"] = types[int(e.kind)];
    entry["default"] = value;
    entry["help"] = e.kind != Option_kind::SWITCH ? e.help : (e.negated ? "False: " : "True: ") + e.help;
    entry["flag"] = e.flag();
    d[py::str(e.keyword)] = entry;
  }
  return d;
}

} // namespace fs_python

#endif // FS_PYTHON_KEYWORDS_H
