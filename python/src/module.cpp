// The compiled half of the Python package `arksph` (python/arksph/__init__.py wraps it): the
// particle ODE of a scene (run/particle_ode.hpp) with NumPy arrays in and out.
//
// Errors cross as Python exceptions, never as a crash: bad input (a scene, a key, a y of the wrong
// length or with a NaN) raises arksph.InputError (a ValueError) with the command line's one-line
// message, a numerical failure arksph.NumericalFailure (a RuntimeError), an output error OSError,
// an allocation failure MemoryError. The evaluations run without the GIL.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "integrate/erk_integrator.hpp"
#include "io/input_file.hpp"
#include "io/scene_reader.hpp"
#include "run/omp_thread_limit.hpp"
#include "run/particle_ode.hpp"

namespace py = pybind11;
using arksph::ParticleOde;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The scene from a file (or the embedded default when path is empty) with its --set overrides; the
// reader's warnings are returned, one per line, for Python's warnings module.
arksph::Scene read_scene(const std::string& path, const std::string& text, const std::vector<std::string>& sets,
                         std::vector<std::string>& warnings) {
  std::ostringstream w;
  arksph::Scene scene = [&] {
    if (!text.empty()) return arksph::read_scene_text(text, "<text>", sets, w);
    if (!path.empty()) return arksph::read_scene_text(arksph::read_input_file(path, "scene"), path, sets, w);
    return arksph::read_scene_text(arksph::default_scene_toml(), "<embedded default>", sets, w);
  }();
  std::istringstream lines(w.str());
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) warnings.push_back(line);
  return scene;
}

// y as a contiguous vector of the state's length, or InputError naming both lengths.
const double* state_of(const ParticleOde& ode, const Array& y, const char* name) {
  const std::size_t want = ode.layout().size();
  if (y.ndim() != 1 || static_cast<std::size_t>(y.size()) != want)
    throw arksph::InputError(std::string(name) + " has " + std::to_string(y.size()) + " entries in " +
                             std::to_string(y.ndim()) + " dimension(s); the state has " + std::to_string(want) +
                             " (a flat array, model.layout gives its blocks)");
  return y.data();
}

// Calls body(y, out) without the GIL into a new array of the state's length.
template <class Body>
Array evaluate(ParticleOde& ode, const Array& y, Body&& body) {
  const double* in = state_of(ode, y, "y");
  Array out(static_cast<py::ssize_t>(ode.layout().size()));
  double* o = out.mutable_data();
  {
    py::gil_scoped_release free;
    body(in, o);
  }
  return out;
}

py::dict layout_of(const arksph::StateLayout& L) {
  py::dict d;
  auto block = [&](const char* name, std::size_t start) {
    d[name] = py::slice(static_cast<py::ssize_t>(start), static_cast<py::ssize_t>(start + L.n), 1);
  };
  const char* pos[] = {"x", "y"};
  const char* vel[] = {"u", "v"};
  for (int k = 0; k < L.dim; ++k) block(pos[k], L.pos(k));
  for (int k = 0; k < L.dim; ++k) block(vel[k], L.vel(k));
  if (L.has_density) block("rho", L.rho());
  if (L.has_energy) block("energy", L.energy());
  return d;
}

}  // namespace

PYBIND11_MODULE(_arksph, m) {
  m.doc() = "arksph's particle ODE (see the package arksph)";
  arksph::bound_omp_threads();

  static py::exception<arksph::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<arksph::NumericalFailure> numerical(m, "NumericalFailure", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const arksph::InputError& e) {
      input_error(e.what());
    } catch (const arksph::NumericalFailure& e) {
      numerical(e.what());
    } catch (const arksph::OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const arksph::OutOfMemory& e) {
      PyErr_SetString(PyExc_MemoryError, e.what());
    }
  });

  m.def(
      "read_scene",
      [](const std::string& path, const std::string& text, const std::vector<std::string>& sets) {
        std::vector<std::string> warnings;
        const arksph::Scene scene = read_scene(path, text, sets, warnings);
        return py::make_tuple(scene.resolved_toml, warnings);
      },
      py::arg("path"), py::arg("text"), py::arg("sets"),
      "The scene as arksph reads it: (resolved TOML text, warnings).");

  m.def(
      "erk_table",
      [](const std::string& name) {
        const arksph::ErkTable t = arksph::erk_table(name);
        py::dict d;
        d["A"] = t.A;
        d["b"] = t.b;
        d["c"] = t.c;
        d["d"] = t.d;
        d["order"] = t.order;
        d["embedded_order"] = t.embedded_order;
        return d;
      },
      py::arg("name"), "The coefficients of an ERK table by name (time.integrator's names), as ARKODE holds them.");

  py::class_<ParticleOde>(m, "ParticleOde")
      .def(py::init([](const std::string& path, const std::string& text, const std::vector<std::string>& sets) {
             std::vector<std::string> warnings;
             const arksph::Scene scene = read_scene(path, text, sets, warnings);
             if (!warnings.empty()) {
               py::object warn = py::module_::import("warnings").attr("warn");
               for (const auto& w : warnings) warn(w, py::module_::import("builtins").attr("UserWarning"), 3);
             }
             py::gil_scoped_release free;
             return std::make_unique<ParticleOde>(scene);
           }),
           py::arg("path"), py::arg("text"), py::arg("sets"))
      .def_property_readonly("n", [](const ParticleOde& o) { return o.layout().n; })
      .def_property_readonly("dim", [](const ParticleOde& o) { return o.layout().dim; })
      .def_property_readonly("size", [](const ParticleOde& o) { return o.layout().size(); })
      .def_property_readonly("layout", [](const ParticleOde& o) { return layout_of(o.layout()); })
      .def_property_readonly("ids", [](const ParticleOde& o) { return py::array_t<std::int64_t>(o.ids().size(), o.ids().data()); })
      .def_property_readonly("y0", [](const ParticleOde& o) { return Array(o.initial_state().size(), o.initial_state().data()); })
      .def_property_readonly("h", &ParticleOde::smoothing_length)
      .def_property_readonly("sound_speed", &ParticleOde::sound_speed)
      .def_property_readonly("scheme", [](const ParticleOde& o) { return o.scene().scheme; })
      .def_property_readonly("end_time", [](const ParticleOde& o) { return o.scene().end; })
      .def_property_readonly("scene_toml", [](const ParticleOde& o) { return o.scene().resolved_toml; })
      .def_property_readonly("periods",
                             [](const ParticleOde& o) {
                               py::list periods;
                               const arksph::Scene& s = o.scene();
                               for (int k = 0; k < s.dimension; ++k)
                                 if (s.sides[2 * k].kind == arksph::SideKind::periodic)
                                   periods.append(s.max[k] - s.min[k]);
                                 else
                                   periods.append(py::none());
                               return periods;
                             })
      .def_property_readonly("has_projection", &ParticleOde::has_projection)
      .def_property_readonly("constrained", &ParticleOde::projection_is_constrained)
      .def_property_readonly("evaluations", &ParticleOde::evaluations)
      .def("rhs", [](ParticleOde& o, double t, const Array& y) {
        return evaluate(o, y, [&](const double* in, double* out) { o.rhs(t, in, out); });
      })
      .def("explicit_rhs", [](ParticleOde& o, double t, const Array& y) {
        return evaluate(o, y, [&](const double* in, double* out) { o.explicit_rhs(t, in, out); });
      })
      .def("implicit_rhs", [](ParticleOde& o, double t, const Array& y) {
        return evaluate(o, y, [&](const double* in, double* out) { o.implicit_rhs(t, in, out); });
      })
      .def("implicit_jvp", [](ParticleOde& o, double t, const Array& y, const Array& v) {
        const double* dv = state_of(o, v, "v");
        return evaluate(o, y, [&](const double* in, double* out) { o.implicit_jvp(t, in, dv, out); });
      })
      .def("project", [](ParticleOde& o, double t, const Array& y, double t_start, const Array& y_start) {
        const double* start = state_of(o, y_start, "y_start");
        return evaluate(o, y, [&](const double* in, double* out) {
          std::copy(in, in + o.layout().size(), out);
          o.project(t_start, start, t, out);
        });
      })
      .def("seconds_per_inside_rhs", [](ParticleOde& o, double t, const Array& y, int repeats) {
        const double* in = state_of(o, y, "y");
        py::gil_scoped_release free;
        return o.seconds_per_inside_rhs(t, in, repeats);
      })
      .def("stable_step", [](ParticleOde& o, const Array& y) {
        const double* in = state_of(o, y, "y");
        py::gil_scoped_release free;
        return o.stable_step(in);
      });
}
