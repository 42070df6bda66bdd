// Vehicles and their matrices: load_vehicle, the Vehicle's fields, assemble → LinearSystem
// (M, C, K as numpy views of the system's own memory), a LinearSystem from numpy M, K (and C),
// Matrix Market in and out, and the sparse models (scipy.sparse). vehicle_from_dict is in
// python/railmodal/vehicle_dict.py: it writes the dict as a vehicle file and reads it here.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <Eigen/SparseCore>
#include <fstream>
#include <string>
#include <vector>

#include "analysis_values.hpp"
#include "arrays.hpp"
#include "bindings.hpp"
#include "dofs.hpp"
#include "number_text.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/input.hpp"
#include "railmodal/linear_system.hpp"
#include "railmodal/matrix_market.hpp"
#include "railmodal/sparse_system.hpp"
#include "railmodal/vehicle.hpp"

namespace py = pybind11;

namespace railmodal::python {

namespace {

DofSet dof_set(const std::string& word) {
  const std::optional<DofSet> set = dof_set_from_string(word);
  if (!set) throw py::value_error("dofs is '" + word + "'; expected one of vertical, lateral, all");
  return *set;
}

std::vector<std::string> motion_words(const std::vector<Motion>& motions) {
  std::vector<std::string> words;
  for (Motion m : motions) words.emplace_back(to_string(m));
  return words;
}

std::vector<Motion> motions_of(const std::vector<std::string>& words) {
  std::vector<Motion> motions;
  for (const std::string& w : words) {
    const std::optional<Motion> m = motion_from_string(w);
    if (!m) throw py::value_error("unknown motion '" + w + "' (lateral, bounce, roll, pitch, yaw, longitudinal)");
    motions.push_back(*m);
  }
  return motions;
}

std::vector<Dof> labelled_dofs(int n, const std::vector<std::string>& labels) {
  if (!labels.empty() && static_cast<int>(labels.size()) != n)
    throw py::value_error(std::to_string(labels.size()) + " DOF labels for " + std::to_string(n) +
                          " degrees of freedom");
  std::vector<Dof> dofs(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    dofs[static_cast<std::size_t>(i)].label = labels.empty() ? "dof" + std::to_string(i + 1) : labels[static_cast<std::size_t>(i)];
    dofs[static_cast<std::size_t>(i)].body = -1;
  }
  return dofs;
}

void require_square(const Eigen::MatrixXd& a, const char* name, Eigen::Index n) {
  if (a.rows() != n || a.cols() != n)
    throw py::value_error(std::string(name) + " is " + std::to_string(a.rows()) + " x " + std::to_string(a.cols()) +
                          "; expected " + std::to_string(n) + " x " + std::to_string(n));
  if (!a.allFinite()) throw py::value_error(std::string(name) + " has an entry that is not a finite number");
}

}  // namespace

LinearSystem system_from_arrays(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness,
                                const std::optional<Eigen::MatrixXd>& damping, const std::vector<std::string>& labels) {
  const Eigen::Index n = mass.rows();
  require_square(mass, "M", n);
  require_square(stiffness, "K", n);
  if (damping) require_square(*damping, "C", n);
  // Through the public SparseSystem → LinearSystem path, so the system is the one a Matrix
  // Market model gives (no bodies, no gravity stiffness, no track inputs).
  SparseSystem sparse;
  sparse.name = "numpy arrays";
  sparse.dofs = labelled_dofs(static_cast<int>(n), labels);
  sparse.mass = mass.sparseView(0.0, 0.0);
  sparse.stiffness = stiffness.sparseView(0.0, 0.0);
  sparse.damping = damping ? Eigen::SparseMatrix<double>(damping->sparseView(0.0, 0.0)) : Eigen::SparseMatrix<double>(n, n);
  LinearSystem system = to_linear_system(sparse);
  // The dense matrices exactly as given (sparseView keeps every nonzero, so this is a no-op
  // but for explicit zeros).
  system.mass = mass;
  system.stiffness = stiffness;
  if (damping) system.damping = *damping;
  return system;
}

// A read-only copy of a 3-vector of a body or element: a view would point into a list's
// storage (vehicle_lists.hpp), and a writeable copy would make `b.inertia[0] *= 2` change
// nothing; assign the whole vector instead (`b.inertia = [...]`).
template <typename Owner>
auto vector3_copy(Eigen::Vector3d Owner::*field) {
  return [field](const Owner& o) {
    py::array_t<double> a(3);
    for (py::ssize_t i = 0; i < 3; ++i) a.mutable_at(i) = (o.*field)(i);
    return read_only(a);
  };
}
template <typename Owner>
auto vector3_setter(Eigen::Vector3d Owner::*field) {
  return [field](Owner& o, const Eigen::Vector3d& v) { o.*field = v; };
}

// The setter of a list field: same length in place, else only while no item is held.
template <typename Owner, typename T>
auto list_setter(std::vector<T> Owner::*field, const char* what) {
  return [field, what](Owner& o, const py::object& values) { assign_list(o.*field, values, what); };
}
template <typename Owner, typename T>
auto list_getter(std::vector<T> Owner::*field) {
  return [field](Owner& o) -> std::vector<T>& { return o.*field; };
}

void bind_model(py::module_& m) {
  py::class_<SpringStage>(m, "SpringStage", "One stage of identical springs in parallel (SI).")
      .def(py::init<>())
      .def("copy", [](const SpringStage& s) { return SpringStage(s); })
      .def_readwrite("kind", &SpringStage::kind)
      .def_readwrite("stiffness", &SpringStage::stiffness, "N/m, of one spring")
      .def_readwrite("count", &SpringStage::count)
      .def_readwrite("relative_friction", &SpringStage::relative_friction)
      .def("__repr__", [](const SpringStage& s) {
        return "SpringStage(kind='" + s.kind + "', stiffness=" + py::repr(py::float_(s.stiffness)).cast<std::string>() +
               ", count=" + std::to_string(s.count) + ")";
      });

  py::class_<Body>(m, "Body", "A rigid body (SI: kg, kg·m², m).")
      .def(py::init<>())
      .def("copy", [](const Body& b) { return Body(b); })
      .def_readwrite("name", &Body::name)
      .def_readwrite("mass", &Body::mass, "kg")
      .def_property("inertia", vector3_copy(&Body::inertia), vector3_setter(&Body::inertia),
                    "roll, pitch, yaw about the CG, kg·m² (a read-only copy: assign all three)")
      .def_property("centre_of_gravity", vector3_copy(&Body::centre_of_gravity),
                    vector3_setter(&Body::centre_of_gravity), "m (a read-only copy: assign all three)")
      .def_property("reference_point", vector3_copy(&Body::reference_point), vector3_setter(&Body::reference_point),
                    "m (a read-only copy: assign all three)")
      .def_property(
          "held", [](const Body& b) { return py::tuple(py::cast(motion_words(b.held))); },
          [](Body& b, const std::vector<std::string>& words) { b.held = motions_of(words); },
          "the motions held, a tuple (b.held.append would change a copy): assign a new list to change them")
      .def_readwrite("longitudinal_free", &Body::longitudinal_free)
      .def_property_readonly("has_bending", [](const Body& b) { return b.bending.has_value(); })
      .def_readwrite("floor_height", &Body::floor_height,
                     "m, z of the floor above the plane of the axles (not the rail), or None: where "
                     "default_ride_outputs puts its floor points (None: at the reference point's height, "
                     "and the ride's notes say so)")
      .def("__repr__", [](const Body& b) { return "Body('" + b.name + "', mass=" + number_text(b.mass) + " kg)"; });

  py::class_<Element>(m, "Element", "A suspension element between two bodies or a body and the track (SI).")
      .def(py::init<>())
      .def("copy", [](const Element& e) { return Element(e); })
      .def_readwrite("name", &Element::name)
      .def_readwrite("lower", &Element::lower, "body name, '' for the track")
      .def_readwrite("upper", &Element::upper)
      .def_property("point", vector3_copy(&Element::point), vector3_setter(&Element::point),
                    "m (a read-only copy: assign all three)")
      .def_property("vertical_stages", list_getter(&Element::vertical_stages),
                    list_setter(&Element::vertical_stages, "the element's vertical_stages"),
                    py::return_value_policy::reference_internal, "in series; items by reference")
      .def_property("lateral_stages", list_getter(&Element::lateral_stages),
                    list_setter(&Element::lateral_stages, "the element's lateral_stages"),
                    py::return_value_policy::reference_internal, "in series; items by reference")
      .def_property("longitudinal_stages", list_getter(&Element::longitudinal_stages),
                    list_setter(&Element::longitudinal_stages, "the element's longitudinal_stages"),
                    py::return_value_policy::reference_internal, "in series; items by reference")
      .def_property("rotational_stiffness", vector3_copy(&Element::rotational_stiffness),
                    vector3_setter(&Element::rotational_stiffness),
                    "roll, pitch, yaw, N·m/rad (a read-only copy: assign all three)")
      .def_readwrite("vertical_damping", &Element::vertical_damping, "N·s/m")
      .def_readwrite("lateral_damping", &Element::lateral_damping, "N·s/m")
      .def_readwrite("longitudinal_damping", &Element::longitudinal_damping, "N·s/m")
      .def_property_readonly("vertical_stiffness", [](const Element& e) { return series_stiffness(e.vertical_stages); },
                             "N/m, the vertical stages in series")
      .def_property_readonly("lateral_stiffness", [](const Element& e) { return series_stiffness(e.lateral_stages); },
                             "N/m, the lateral stages in series")
      .def("__repr__", [](const Element& e) {
        return "Element('" + e.name + "', " + (e.lower.empty() ? "track" : e.lower) + " -> " + e.upper + ")";
      });

  bind_vehicle_lists(m);

  py::class_<Vehicle>(m, "Vehicle", "Rigid bodies joined by suspension elements (SI). load_vehicle, vehicle_from_dict.")
      .def_readwrite("name", &Vehicle::name)
      .def_readwrite("source", &Vehicle::source, "the file it was read from")
      .def_readwrite("gravity", &Vehicle::gravity, "m/s²")
      .def_property("bodies", list_getter(&Vehicle::bodies), list_setter(&Vehicle::bodies, "vehicle.bodies"),
                    py::return_value_policy::reference_internal,
                    "the vehicle's own bodies: car.bodies[0].mass *= 2 changes the car")
      .def_property("elements", list_getter(&Vehicle::elements), list_setter(&Vehicle::elements, "vehicle.elements"),
                    py::return_value_policy::reference_internal,
                    "the vehicle's own elements: car.elements[i].vertical_damping = ... changes the car")
      .def_property_readonly("wheelsets",
                             [](const Vehicle& v) {
                               std::vector<std::string> bodies;
                               for (const Wheelset& w : v.wheelsets) bodies.push_back(w.body);
                               return py::tuple(py::cast(bodies));  // read-only: a tuple, not a list
                             },
                             "the names of the bodies that are wheelsets on the rails")
      .def("copy", [](const Vehicle& v) { return Vehicle(v); })
      .def("__repr__", [](const Vehicle& v) {
        return "Vehicle('" + v.name + "', " + std::to_string(v.bodies.size()) + " bodies, " +
               std::to_string(v.elements.size()) + " elements)";
      });

  m.def(
      "load_vehicle",
      [](const std::string& path) {
        std::vector<std::string> warnings;
        Vehicle vehicle;
        {
          py::gil_scoped_release unlocked;
          vehicle = load_vehicle(path, &warnings);
        }
        warn_input(warnings);
        return vehicle;
      },
      py::arg("path"),
      "Reads a vehicle file (TOML with units). InputError names file, line, column and key; what it accepts "
      "but finds unusual is an InputWarning (Python's warnings module).");

  py::class_<LinearSystem>(m, "LinearSystem",
                           "M q'' + C q' + K q = f over dof_labels (SI). M, C, K, K_gravity are read-only "
                           "numpy views of the system's memory (no copy).")
      .def(py::init([](const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, std::optional<Eigen::MatrixXd> C,
                       std::vector<std::string> dof_labels) { return system_from_arrays(M, K, C, dof_labels); }),
           py::arg("M"), py::arg("K"), py::arg("C") = py::none(), py::arg("dof_labels") = std::vector<std::string>{},
           "A system from numpy M, K (and C); DOFs named dof1, dof2, ... unless labelled.")
      .def_property_readonly("M", [](py::object self) { return matrix_view(self.cast<const LinearSystem&>().mass, self); })
      .def_property_readonly("C", [](py::object self) { return matrix_view(self.cast<const LinearSystem&>().damping, self); })
      .def_property_readonly("K", [](py::object self) { return matrix_view(self.cast<const LinearSystem&>().stiffness, self); })
      .def_property_readonly(
          "K_gravity", [](py::object self) { return matrix_view(self.cast<const LinearSystem&>().gravity_stiffness, self); },
          "the part of K due to gravity and preloads")
      .def_property_readonly("dof_labels", [](const LinearSystem& s) { return dof_labels(s.dofs); })
      .def_property_readonly("vehicle", [](const LinearSystem& s) { return s.vehicle; })
      .def_property_readonly("element_loads_n", [](py::object self) {
        return vector_view(self.cast<const LinearSystem&>().element_loads, self);
      }, "static vertical load of each element, N (+ = compression)")
      .def_property_readonly("size", &LinearSystem::size)
      .def("__len__", &LinearSystem::size)
      .def("index_of", &LinearSystem::index_of, py::arg("label"), "index of the DOF with this label, or -1")
      .def("__repr__", [](const LinearSystem& s) {
        return "LinearSystem(" + std::to_string(s.size()) + " DOFs" + (s.vehicle.name.empty() ? "" : ", '" + s.vehicle.name + "'") + ")";
      });

  m.def(
      "assemble", [](const py::object& vehicle, const std::string& dofs) {
        const DofSet set = dof_set(dofs);
        if (py::isinstance<Vehicle>(vehicle)) {  // referred to, not copied
          const Vehicle& v = vehicle.cast<const Vehicle&>();
          py::gil_scoped_release release;
          return assemble(v, set);
        }
        const Vehicle v = vehicle_argument(vehicle);  // a file, as the other analyses take one
        py::gil_scoped_release release;
        return assemble(v, set);
      },
      py::arg("vehicle"), py::arg("dofs") = "all",
      "M, C, K of a vehicle (a Vehicle or a vehicle file) for the motions 'vertical', 'lateral' or 'all'.");

  py::class_<SparseSystem>(m, "SparseSystem",
                           "M q'' + C q' + K q = f with sparse matrices; M, C, K as scipy.sparse.csc_matrix (copies).")
      .def_readonly("name", &SparseSystem::name)
      .def_property_readonly("M", [](const SparseSystem& s) { return s.mass; })
      .def_property_readonly("C", [](const SparseSystem& s) { return s.damping; })
      .def_property_readonly("K", [](const SparseSystem& s) { return s.stiffness; })
      .def_property_readonly("dof_labels", [](const SparseSystem& s) { return dof_labels(s.dofs); })
      .def_property_readonly("size", &SparseSystem::size)
      .def("__len__", &SparseSystem::size)
      .def("to_dense", [](const SparseSystem& s) { return to_linear_system(s); }, "the dense LinearSystem")
      .def("__repr__", [](const SparseSystem& s) { return "SparseSystem('" + s.name + "', " + std::to_string(s.size()) + " DOFs)"; });

  m.def("wagon_train", &wagon_train, py::arg("wagons"), py::call_guard<py::gil_scoped_release>(),
        "The generated train of bogie wagons, 5 DOFs each (sparse_system.hpp).");

  m.def(
      "read_matrix_market",
      [](const std::string& path, bool require_symmetric) {
        MatrixMarketMatrix read;
        {
          py::gil_scoped_release release;
          read = read_matrix_market(path, require_symmetric);
        }
        return py::make_tuple(read.matrix, read.dof_labels);
      },
      py::arg("path"), py::arg("require_symmetric") = false,
      "One Matrix Market file: (scipy.sparse.csc_matrix, DOF labels its comments name or []).");

  m.def(
      "write_matrix_market",
      [](const std::string& path, const Eigen::SparseMatrix<double>& matrix, bool symmetric,
         const std::vector<std::string>& dof_labels) {
        std::ofstream out(path);
        if (!out) throw py::value_error("cannot write " + path);
        write_matrix_market(out, matrix, symmetric, dof_labels);
        if (!out) throw py::value_error("cannot write " + path);
      },
      py::arg("path"), py::arg("matrix"), py::arg("symmetric") = false, py::arg("dof_labels") = std::vector<std::string>{},
      "Writes a matrix (scipy.sparse or numpy) in Matrix Market coordinate format, 17 digits.");

  m.def(
      "load_matrix_model",
      [](const std::string& mass, const std::string& stiffness, const std::string& damping, bool sparse) -> py::object {
        MatrixModel model;
        {
          py::gil_scoped_release release;
          model = load_matrix_model(mass, stiffness, damping);
        }
        if (sparse) return py::cast(to_sparse_system(model));
        return py::cast(to_linear_system(model));
      },
      py::arg("mass"), py::arg("stiffness"), py::arg("damping") = "", py::arg("sparse") = false,
      "M and K (and C) from Matrix Market files: a LinearSystem, or with sparse=True a SparseSystem.");
}

}  // namespace railmodal::python
