// The ride's linear maps: track components onto the track inputs, outputs onto the degrees of
// freedom, and the receptances that join them (one solve per frequency for all inputs).
#include "ride/ride_transfer.hpp"

#include <cmath>
#include <complex>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/analysis_limits.hpp"
#include "model/element_stiffness.hpp"
#include "model/point_motion.hpp"
#include "model/wheelset_dofs.hpp"
#include "railmodal/errors.hpp"
#include "ride/ride_contact.hpp"
#include "ride/track_under_wheels.hpp"
#include "shortest_text.hpp"

namespace railmodal::ride {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
using Complex = std::complex<double>;

using model::body_index;

int element_index(const LinearSystem& system, const std::string& name) {
  const auto& elements = system.vehicle.elements;
  for (size_t k = 0; k < elements.size(); ++k)
    if (elements[k].name == name) return static_cast<int>(k);
  return -1;
}

// "valid: 'a', 'b'": the names an output may give, for its error.
template <typename Items, typename Name>
std::string valid_names(const Items& items, Name name) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "'" : ", '") + name(item) + "'";
  return " (valid: " + (out.empty() ? std::string("none") : out) + ")";
}

std::string body_names(const LinearSystem& s) { return valid_names(s.vehicle.bodies, [](const Body& b) { return b.name; }); }
std::string element_names(const LinearSystem& s) {
  return valid_names(s.vehicle.elements, [](const Element& e) { return e.name; });
}
std::string wheelset_names(const LinearSystem& s) {
  return valid_names(s.vehicle.wheelsets, [](const Wheelset& w) { return w.body; });
}

int input_of(const LinearSystem& system, int element) {
  for (size_t i = 0; i < system.track_inputs.size(); ++i)
    if (system.track_inputs[i].element == element) return static_cast<int>(i);
  return -1;
}

int axis_index(RideAxis axis) { return axis == RideAxis::longitudinal ? 0 : axis == RideAxis::lateral ? 1 : 2; }

bool has_lateral_dofs(const LinearSystem& system) {
  for (const Dof& d : system.dofs)
    if (d.motion == Motion::lateral || d.motion == Motion::roll || d.motion == Motion::yaw) return true;
  return false;
}

// Whether the component moves any input in a direction the DOFs feel (a load, stiff or viscous).
bool reaches_dofs(const LinearSystem& system, const Component& c) {
  for (size_t i = 0; i < system.track_inputs.size(); ++i) {
    const TrackInput& t = system.track_inputs[i];
    if ((t.load_per_displacement * c.displacement[i]).cwiseAbs().maxCoeff() > 0.0 ||
        (t.load_per_velocity * c.displacement[i]).cwiseAbs().maxCoeff() > 0.0)
      return true;
  }
  return false;
}

Component component(const LinearSystem& system, TrackIrregularity slot, const TrackSpectrum& spectrum,
                    double contact_half_spacing, double rolling_radius) {
  if (spectrum.irregularity() != slot)
    throw std::invalid_argument(std::string("ride: the ") + to_string(slot) + " slot holds a " +
                                to_string(spectrum.irregularity()) + " spectrum (" + spectrum.name() + ")");
  // Alignment reaches the wheelsets through the creep forces (the contact's track inputs,
  // ride_contact.hpp), cross-level too (the rails' roll input, kRailRollInput). Without the
  // contact (wheelsets whose lateral motion is not free, among other lateral DOFs) cross-level
  // would reach the lateral motions only partly: refused rather than answered without it.
  const bool wheelsets = !system.vehicle.wheelsets.empty();
  bool rail_roll = false;
  for (const TrackInput& t : system.track_inputs) rail_roll = rail_roll || t.element == kRailRollInput;
  if (wheelsets && slot == TrackIrregularity::cross_level && has_lateral_dofs(system) && !rail_roll)
    throw IrregularityComponentError(
        TrackIrregularity::cross_level,
        "ride: cross-level on a vehicle with wheelsets moves them laterally through the "
        "wheel–rail contact (the rails' roll tilts the normal loads), which the ride models "
        "only when the wheelsets' lateral and yaw motions are free (dofs = \"all\"); leave it "
        "out, free them, or give the vertical degrees of freedom only");
  Component c{slot, spectrum, {}};
  if (slot == TrackIrregularity::cross_level)
    c.displacement = cross_level_directions(system, contact_half_spacing, rolling_radius);
  else
    c.displacement.assign(system.track_inputs.size(), slot == TrackIrregularity::vertical_level
                                                          ? Eigen::Vector3d::UnitZ()
                                                          : Eigen::Vector3d::UnitY());
  // The contact's own inputs take what reaches the wheelset through the contact only.
  for (size_t i = 0; i < system.track_inputs.size(); ++i)
    if (system.track_inputs[i].element < 0) c.displacement[i] = contact_direction(system.track_inputs[i].element, slot);
  if (!reaches_dofs(system, c))
    throw IrregularityComponentError(
        slot, std::string("ride: the ") + to_string(slot) + " component (" + spectrum.name() +
                  ") moves no degree of freedom of this model (" +
                  (slot == TrackIrregularity::vertical_level ? "no vertical" : "no lateral or roll") +
                  " motion reaches the track inputs); its answer would be zero: leave it out, or give "
                  "the degrees of freedom it acts on (dofs = \"all\")");
  return c;
}

// The element's stretch along `axis` (upper relative to lower) per unit of each DOF; the
// vertical one is the assembly's own row (LinearSystem::element_vertical_map).
Eigen::RowVectorXd stretch_row(const LinearSystem& system, int k, int axis) {
  if (axis == 2) return system.element_vertical_map.row(k);
  const Element& e = system.vehicle.elements[k];
  Eigen::RowVectorXd row = model::point_displacement_map(system, body_index(system, e.upper), e.point).row(axis);
  const int lower = body_index(system, e.lower);
  if (lower >= 0) row -= model::point_displacement_map(system, lower, e.point).row(axis);
  return row;
}

// Whether the track's displacement along `axis` reaches element k's lower end directly: a track
// element, or (longitudinal and vertical) one standing on a wheelset, whose held motions follow
// the rail; the rail's lateral motion reaches a wheelset through the contact only.
bool track_moves_lower_end(const LinearSystem& system, int k, int axis) {
  const Element& e = system.vehicle.elements[k];
  if (model::stands_on_wheelset(system.vehicle, e)) return axis != 1;
  return e.lower.empty();
}

void add_track_term(OutputMap* map, int input, const Eigen::Vector3d& t0, const Eigen::Vector3d& t1,
                    const Eigen::Vector3d& t2) {
  map->inputs.push_back(input);
  map->t0.push_back(t0);
  map->t1.push_back(t1);
  map->t2.push_back(t2);
}

OutputMap deflection_map(const LinearSystem& system, int k, int axis) {
  const int n = system.size();
  OutputMap m;
  m.a0 = stretch_row(system, k, axis);
  m.a1 = Eigen::RowVectorXd::Zero(n);
  const int input = input_of(system, k);
  if (input >= 0 && track_moves_lower_end(system, k, axis))
    add_track_term(&m, input, -Eigen::Vector3d::Unit(axis), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  return m;
}

// The force element k exerts on its upper body along `axis`: −(k + iωc)·stretch, and the
// Maxwell force −k_s(ω)·s of its series dampers in that direction.
OutputMap force_map(const LinearSystem& system, int k, int axis, double friction_damping) {
  const Element& e = system.vehicle.elements[k];
  const double load = k < static_cast<int>(system.element_loads.size()) ? system.element_loads[k] : 0.0;
  const double stiffness = axis == 0   ? series_stiffness(e.longitudinal_stages)
                           : axis == 1 ? model::lateral_stiffness(e, load)
                                       : series_stiffness(e.vertical_stages);
  const double damping = axis == 0   ? e.longitudinal_damping
                         : axis == 1 ? e.lateral_damping
                                     : e.vertical_damping + friction_damping;
  OutputMap m = deflection_map(system, k, axis);  // stretch, and −u of the track where it enters
  m.a1 = -damping * m.a0;
  m.a0 *= -stiffness;
  for (size_t t = 0; t < m.inputs.size(); ++t) {
    m.t1[t] = -damping * m.t0[t];
    m.t0[t] *= -stiffness;
  }
  const Motion direction = axis == 0 ? Motion::longitudinal : axis == 1 ? Motion::lateral : Motion::bounce;
  for (const SeriesDamperRow& row : system.series_dampers)
    if (row.element == k && row.direction == direction) m.series.push_back(row);
  return m;
}

void add(OutputMap* sum, const OutputMap& part) {
  sum->a0 += part.a0;
  sum->a1 += part.a1;
  sum->series.insert(sum->series.end(), part.series.begin(), part.series.end());
  for (size_t t = 0; t < part.inputs.size(); ++t) add_track_term(sum, part.inputs[t], part.t0[t], part.t1[t], part.t2[t]);
}

// The lateral force of the rails on wheelset i (both wheels, in the inertial frame): the contact
// row of its lateral DOF, which is the axle's (T = [1 lever; 0 1] leaves the lateral row of
// Tᵀ·F the axle's lateral force): −K_c·q − (C_c/V + V·G)·q̇ and the contact's own inputs' loads
// on that row (the alignment's; the rails' roll, contact part only: creep, the leaning normal
// loads −W·θ), docs/ride.md "The wheel–rail force across the track".
OutputMap lateral_contact_map(const LinearSystem& system, const CreepContact& contact, std::size_t i, double speed) {
  const ContactMatrices& c = contact.matrices;
  const int j = contact.lateral[i];
  OutputMap m;
  m.a0 = -c.stiffness.row(j);
  m.a1 = -(c.creep_damping.row(j) / speed + speed * c.gyroscopic.row(j));
  std::size_t alignment = 0, roll = 0;
  for (size_t t = 0; t < system.track_inputs.size(); ++t) {
    const TrackInput& input = system.track_inputs[t];
    if (input.element == kAlignmentInput && alignment++ == i)
      add_track_term(&m, static_cast<int>(t), input.load_per_displacement.row(j).transpose(),
                     input.load_per_velocity.row(j).transpose(), Eigen::Vector3d::Zero());
    if (input.element == kRailRollInput && roll++ == i) {
      const RollLoad load = rail_roll_load(contact, i, speed, true);
      add_track_term(&m, static_cast<int>(t), Eigen::Vector3d(load.stiff(j), 0.0, 0.0),
                     Eigen::Vector3d(load.viscous(j), 0.0, 0.0), Eigen::Vector3d::Zero());
    }
  }
  return m;
}

// The vertical force of the rails on a wheelset (both wheels), its dynamic part: what the
// elements standing on it push down with, plus the wheelset's mass times its vertical
// acceleration, which is the rails' (its bounce is held), the mean of its inputs' vertical
// track displacement (the rails' roll turns it about its centre). The lateral one is the
// contact's (lateral_contact_map); the longitudinal one is zero in the linear contact.
OutputMap wheel_rail_map(const LinearSystem& system, const RideOutput& o, const std::vector<double>& friction,
                         const CreepContact* contact, double speed) {
  const Vehicle& v = system.vehicle;
  const int body = body_index(system, o.element);
  if (body < 0 || !model::wheelset_of(v, o.element))
    throw std::invalid_argument("ride: output '" + o.name + "': no wheelset '" + o.element + "'" +
                                wheelset_names(system));
  if (o.axis == RideAxis::longitudinal)
    throw std::invalid_argument("ride: output '" + o.name + "': the longitudinal wheel–rail force of the linear "
                                "contact is zero on the wheelset: its two wheels' longitudinal creep forces are equal "
                                "and opposite (they make its yaw moment); only the lateral and vertical ones are given");
  if (o.axis == RideAxis::lateral) {
    if (!contact)
      throw std::invalid_argument("ride: output '" + o.name + "': the lateral wheel–rail force is the creep contact's, "
                                  "which the ride assembles only when the wheelsets' lateral and yaw motions are free "
                                  "(dofs = \"all\")");
    for (size_t i = 0; i < v.wheelsets.size(); ++i)
      if (v.wheelsets[i].body == o.element) return lateral_contact_map(system, *contact, i, speed);
  }
  const int n = system.size();
  OutputMap m;
  m.a0 = Eigen::RowVectorXd::Zero(n);
  m.a1 = Eigen::RowVectorXd::Zero(n);
  std::vector<int> inputs;
  for (size_t k = 0; k < v.elements.size(); ++k) {
    if (v.elements[k].lower != o.element) continue;
    add(&m, force_map(system, static_cast<int>(k), 2, k < friction.size() ? friction[k] : 0.0));
    const int input = input_of(system, static_cast<int>(k));
    if (input >= 0) inputs.push_back(input);
  }
  for (int input : inputs)
    add_track_term(&m, input, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                   Eigen::Vector3d::UnitZ() * v.bodies[body].mass / static_cast<double>(inputs.size()));
  return m;
}

OutputMap output_map(const LinearSystem& system, const RideOutput& o, const std::vector<double>& friction,
                     const CreepContact* contact, double speed) {
  const int axis = axis_index(o.axis);
  switch (o.kind) {
    case RideOutput::Kind::point: {
      const int body = body_index(system, o.body);
      if (body < 0)
        throw std::invalid_argument("ride: output '" + o.name + "': no body '" + o.body + "'" + body_names(system));
      OutputMap m;
      m.order = o.quantity == ResponseQuantity::displacement ? 0 : o.quantity == ResponseQuantity::velocity ? 1 : 2;
      m.a0 = model::point_displacement_map(system, body, o.point).row(axis);
      m.a1 = Eigen::RowVectorXd::Zero(system.size());
      m.gravity = gravity_row(system, o);
      return m;
    }
    case RideOutput::Kind::element_deflection:
    case RideOutput::Kind::element_force: {
      const int k = element_index(system, o.element);
      if (k < 0)
        throw std::invalid_argument("ride: output '" + o.name + "': no element '" + o.element + "'" +
                                    element_names(system));
      if (o.kind == RideOutput::Kind::element_deflection) return deflection_map(system, k, axis);
      return force_map(system, k, axis, k < static_cast<int>(friction.size()) ? friction[k] : 0.0);
    }
    case RideOutput::Kind::wheel_rail_force:
      return wheel_rail_map(system, o, friction, contact, speed);
  }
  throw std::invalid_argument("ride: output '" + o.name + "': unknown kind");
}

// At least `columns` columns of `rows` rows, keeping the storage when it already holds them: a
// kept Receptances is rewritten in place (column-major, so column k lies where it would in an
// exact-size matrix), and glibc has nothing to return to the system and fault in again at the
// next solve (docs/ride.md, "Performance", the ninth round).
template <typename Matrix>
void keep_columns(Matrix* a, Eigen::Index rows, Eigen::Index columns) {
  if (a->rows() != rows || a->cols() < columns) a->resize(rows, columns);
}

Complex power_of_i_omega(int order, double omega) {
  Complex p = 1.0;
  for (int k = 0; k < order; ++k) p *= Complex(0.0, omega);
  return p;
}

}  // namespace

// Eigen's blocked LU and triangular solves cost more in their dispatch than in arithmetic at
// this size, and divide by each pivot in complex arithmetic (libgcc's __divdc3, a call per
// element): here each pivot is inverted once, 1/p = p̄/|p|², and rows are scaled by products.
// In real arithmetic on the columns' interleaved parts (std::complex's layout): the products
// (ac − bd, ad + bc) are std::complex's own, without its NaN and infinity checks (C99 Annex G,
// a branch per product), so the same bits for finite values; none other reaches here (a zero
// pivot stops the elimination). `inverse` holds n values.
void solve_in_place(int n, int r, std::complex<double>* D, std::complex<double>* B, double* pivots,
                    std::complex<double>* inverse) {
  double* a = reinterpret_cast<double*>(D);  // a(i, q) at 2(q·n + i), its imaginary part next
  double* b = reinterpret_cast<double*>(B);
  const auto at = [n](int i, int q) { return 2 * (static_cast<std::ptrdiff_t>(q) * n + i); };
  for (int p = 0; p < n; ++p) pivots[p] = 0.0;
  for (int p = 0; p < n; ++p) {
    int best = p;
    double largest = a[at(p, p)] * a[at(p, p)] + a[at(p, p) + 1] * a[at(p, p) + 1];
    for (int i = p + 1; i < n; ++i) {
      const double norm = a[at(i, p)] * a[at(i, p)] + a[at(i, p) + 1] * a[at(i, p) + 1];
      if (norm > largest) {
        largest = norm;
        best = i;
      }
    }
    pivots[p] = std::sqrt(largest);
    if (!(largest > 0.0)) return;  // singular: the caller throws
    if (best != p) {
      for (int q = 0; q < n; ++q) std::swap(D[static_cast<std::ptrdiff_t>(q) * n + p], D[static_cast<std::ptrdiff_t>(q) * n + best]);
      for (int q = 0; q < r; ++q) std::swap(B[static_cast<std::ptrdiff_t>(q) * n + p], B[static_cast<std::ptrdiff_t>(q) * n + best]);
    }
    const double vr = a[at(p, p)] / largest, vi = -a[at(p, p) + 1] / largest;  // conj(pivot)/|pivot|²
    inverse[p] = Complex(vr, vi);
    for (int i = p + 1; i < n; ++i) {
      const double xr = a[at(i, p)], xi = a[at(i, p) + 1];
      const double lr = xr * vr - xi * vi, li = xr * vi + xi * vr;
      if (lr == 0.0 && li == 0.0) continue;
      for (int q = p + 1; q < n; ++q) {
        const double yr = a[at(p, q)], yi = a[at(p, q) + 1];
        a[at(i, q)] -= lr * yr - li * yi;
        a[at(i, q) + 1] -= lr * yi + li * yr;
      }
      for (int q = 0; q < r; ++q) {
        const double yr = b[at(p, q)], yi = b[at(p, q) + 1];
        b[at(i, q)] -= lr * yr - li * yi;
        b[at(i, q) + 1] -= lr * yi + li * yr;
      }
    }
  }
  for (int p = n - 1; p >= 0; --p) {
    const double vr = inverse[p].real(), vi = inverse[p].imag();
    for (int q = 0; q < r; ++q) {
      double sr = b[at(p, q)], si = b[at(p, q) + 1];
      for (int j = p + 1; j < n; ++j) {
        const double ur = a[at(p, j)], ui = a[at(p, j) + 1], yr = b[at(j, q)], yi = b[at(j, q) + 1];
        sr -= ur * yr - ui * yi;
        si -= ur * yi + ui * yr;
      }
      b[at(p, q)] = sr * vr - si * vi;
      b[at(p, q) + 1] = sr * vi + si * vr;
    }
  }
}

std::complex<double> maxwell_stiffness(double stiffness, double damping, double omega) {
  const Complex ic(0.0, omega * damping);
  return ic * stiffness / (stiffness + ic);
}

Eigen::RowVectorXcd OutputMap::row(double omega) const {
  Eigen::RowVectorXcd r = a0.cast<Complex>() + Complex(0.0, omega) * a1.cast<Complex>();
  for (const SeriesDamperRow& s : series)
    r -= maxwell_stiffness(s.stiffness, s.damping, omega) * s.stretch.cast<Complex>();
  r *= power_of_i_omega(order, omega);
  if (gravity.size()) r += gravity.cast<Complex>();
  return r;
}

// The specific force f = a − g_vec (g_vec = (0, 0, −g)) along a body axis e turned by the small
// rotation θ: f·(e + θ × e) = a·e + g·e_z·(θ × e) + O(θ²) = a·e + g·θ·(e × e_z); e_y × e_z = e_x
// gives +g·θx = +g·φ, e_x × e_z = −e_y gives −g·θy. EN 12299 and ISO 2631-1 evaluate accelerations
// measured by transducers on the floor along the body's axes, as the public sources cited in
// docs/ride.md ("Lateral acceleration's frame") describe them; the standards' own text was not
// at hand.
Eigen::RowVectorXd gravity_row(const LinearSystem& system, const RideOutput& output) {
  if (!reads_gravity(output)) return {};
  const int body = body_index(system, output.body);
  const Motion tilt = output.axis == RideAxis::lateral ? Motion::roll : Motion::pitch;
  const double g = output.axis == RideAxis::lateral ? system.vehicle.gravity : -system.vehicle.gravity;
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(system.size());
  bool any = false;
  for (int d = 0; d < system.size(); ++d)
    if (system.dofs[d].body == body && system.dofs[d].motion == tilt) {
      row(d) = g;
      any = true;
    }
  if (!any) return {};
  return row;
}

std::complex<double> OutputMap::track(std::size_t term, const Eigen::Vector3d& u, double omega) const {
  const Complex s(0.0, omega);
  return power_of_i_omega(order, omega) * (t0[term].dot(u) + s * t1[term].dot(u) + s * s * t2[term].dot(u));
}

std::vector<std::string> frame_notes(const LinearSystem& system, const std::vector<RideOutput>& outputs) {
  bool body = false, track = false;
  std::vector<std::string> untilted;  // frame = body on a body that cannot tilt about that axis
  for (const RideOutput& o : outputs) {
    if (o.kind == RideOutput::Kind::point && o.quantity == ResponseQuantity::acceleration && o.axis != RideAxis::vertical)
      (o.frame == RideOutput::Frame::body ? body : track) = true;
    if (reads_gravity(o) && gravity_row(system, o).size() == 0) {
      const bool lateral = o.axis == RideAxis::lateral;
      untilted.push_back("output '" + o.name + "' asks for frame = body, but body '" + o.body + "' has no " +
                         (lateral ? "roll" : "pitch") + " freedom in this model: it cannot tilt, so the accelerometer "
                         "reads " + (lateral ? "ÿ" : "ẍ") + " alone, with no " + (lateral ? "g·φ" : "g·θ") +
                         " term (the same as frame = track); give the body its " + (lateral ? "roll" : "pitch") +
                         " (dofs, held) for the tilted-axis reading");
    }
  }
  std::vector<std::string> notes;
  if (body)
    notes.push_back("lateral and longitudinal accelerations with frame = body are what an accelerometer fixed to the "
                    "body reads (EN 12299, ISO 2631-1): the specific force along the body's tilted axes, ÿ + g·φ and "
                    "ẍ − g·θ (φ the body's roll, θ its pitch, nose down)");
  if (track)
    notes.push_back("lateral and longitudinal accelerations with frame = track are inertial, in the track's frame: an "
                    "accelerometer fixed to a rolling body also reads g·φ (φ its roll)");
  notes.insert(notes.end(), untilted.begin(), untilted.end());
  return notes;
}

std::vector<Component> track_components(const LinearSystem& system, const TrackIrregularitySpectra& track,
                                        double contact_half_spacing, double rolling_radius) {
  if (system.track_inputs.empty())
    throw std::invalid_argument("ride: the vehicle has no element standing on the track (no track input)");
  std::vector<Component> out;
  if (track.vertical_level)
    out.push_back(component(system, TrackIrregularity::vertical_level, *track.vertical_level, contact_half_spacing, rolling_radius));
  if (track.alignment)
    out.push_back(component(system, TrackIrregularity::alignment, *track.alignment, contact_half_spacing, rolling_radius));
  if (track.cross_level)
    out.push_back(component(system, TrackIrregularity::cross_level, *track.cross_level, contact_half_spacing, rolling_radius));
  if (out.empty()) throw std::invalid_argument("ride: the track has no irregularity component");
  refuse_series_dampers_on_track(system, "ride");
  return out;
}

void refuse_series_dampers_on_track(const LinearSystem& system, const char* analysis) {
  for (const SeriesDamperRow& row : system.series_dampers)
    if (input_of(system, row.element) >= 0)
      throw std::invalid_argument(std::string(analysis) + ": element '" + system.vehicle.elements[row.element].name +
                                  "' stands on the track with a series damper, whose track input the ride does "
                                  "not model yet");
}

std::vector<OutputMap> output_maps(const LinearSystem& system, const std::vector<RideOutput>& outputs,
                                   const std::vector<double>& friction_damping, const CreepContact* contact,
                                   double speed) {
  if (outputs.empty()) throw std::invalid_argument("ride: no outputs requested");
  std::set<std::string> names;
  std::vector<OutputMap> maps;
  for (const RideOutput& o : outputs) {
    if (o.name.empty()) throw std::invalid_argument("ride: an output has no name");
    if (!names.insert(o.name).second) throw std::invalid_argument("ride: output name '" + o.name + "' is repeated");
    maps.push_back(output_map(system, o, friction_damping, contact, speed));
    const OutputMap& m = maps.back();
    // An accelerometer's gravity row moves it too (a longitudinal reading −g·θ with the
    // longitudinal motion held and pitch free).
    const bool gravity_moves_it = m.gravity.size() && m.gravity.cwiseAbs().maxCoeff() > 0.0;
    if (m.a0.cwiseAbs().maxCoeff() == 0.0 && m.a1.cwiseAbs().maxCoeff() == 0.0 && m.series.empty() && m.inputs.empty() &&
        !gravity_moves_it)
      throw std::invalid_argument("ride: output '" + o.name + "': no degree of freedom of this model moves it (the " +
                                  to_string(o.axis) + " axis is not among the model's motions); its answer would be "
                                  "zero: leave it out, or give the degrees of freedom it needs (dofs = \"all\")");
  }
  return maps;
}

OutputMap stretch_rate_map(const LinearSystem& system, int element) {
  OutputMap m = deflection_map(system, element, 2);
  m.order = 1;
  return m;
}

void receptances(const LinearSystem& system, const std::vector<Component>& components,
                 const std::vector<OutputMap>& maps, const Eigen::VectorXd& grid, const Eigen::MatrixXd* basis,
                 const ModalBasis* split, Receptances* into) {
  Receptances& r = *into;
  const int n = system.size();
  // The input groups: the inputs at one x (within round-off) share their delay at every speed.
  std::vector<double> xs;
  std::vector<int> group_of;
  for (const TrackInput& t : system.track_inputs) {
    size_t g = 0;
    while (g < xs.size() && std::abs(xs[g] - t.point.x()) > 1e-12 * (1.0 + std::abs(t.point.x()))) ++g;
    if (g == xs.size()) xs.push_back(t.point.x());
    group_of.push_back(static_cast<int>(g));
  }
  const int m = static_cast<int>(xs.size());
  const int C = static_cast<int>(components.size());
  const int O = static_cast<int>(maps.size());
  const Eigen::Index K = grid.size();
  // K, M, C and each series damper's stretchᵀ·stretch as complex matrices once; in the basis Φ
  // (modal truncation) ΦᵀKΦ and the rest.
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd& Phi = basis ? *basis : I;
  auto reduced = [&](const Eigen::MatrixXd& A) -> Eigen::MatrixXcd {
    return basis ? Eigen::MatrixXcd((Phi.transpose() * A * Phi).cast<Complex>()) : Eigen::MatrixXcd(A.cast<Complex>());
  };
  const Eigen::MatrixXcd stiffness = reduced(system.stiffness), mass = reduced(system.mass),
                         damping = reduced(system.damping);
  std::vector<Eigen::MatrixXcd> series;
  for (const SeriesDamperRow& sd : system.series_dampers) series.push_back(reduced(sd.stretch.transpose() * sd.stretch));
  const Eigen::MatrixXcd basis_c = Phi.cast<Complex>();
  Eigen::MatrixXcd D(stiffness.rows(), stiffness.cols());
  const int J = split ? static_cast<int>(split->shapes.cols()) : 0;
  r.outputs = O;
  r.components = C;
  r.inputs = m;
  r.x = xs;
  r.modes = J;
  keep_columns(&r.response, static_cast<Eigen::Index>(O) * C * m, K);
  if (J > 0) {  // without modal terms (rms_only) no reader looks at them: a kept pair stays for the next full solve
    keep_columns(&r.modal, static_cast<Eigen::Index>(J) * C * m, K);
    keep_columns(&r.modal_rows, static_cast<Eigen::Index>(O) * J, K);
  }
  Eigen::MatrixXcd Q(n, C * m), X(n, C * m), A(O, n), h(O, C * m), q(J, C * m), seen(O, J);
  const Eigen::MatrixXcd left_c = split ? Eigen::MatrixXcd(split->left.cast<Complex>()) : Eigen::MatrixXcd();
  const Eigen::MatrixXcd shapes_c = split ? Eigen::MatrixXcd(split->shapes.cast<Complex>()) : Eigen::MatrixXcd();
  // Q_{c,g} = Σ_{i∈g}(P_i + iωV_i)u_{c,i}: its two real parts once.
  Eigen::MatrixXd stiff_load = Eigen::MatrixXd::Zero(n, C * m), damper_load = Eigen::MatrixXd::Zero(n, C * m);
  for (size_t i = 0; i < system.track_inputs.size(); ++i)
    for (int c = 0; c < C; ++c) {
      const TrackInput& t = system.track_inputs[i];
      stiff_load.col(c * m + group_of[i]) += t.load_per_displacement * components[c].displacement[i];
      damper_load.col(c * m + group_of[i]) += t.load_per_velocity * components[c].displacement[i];
    }
  Eigen::MatrixXcd Y;  // the solve's right-hand sides, then its solution
  Eigen::VectorXd pivots(D.rows());
  std::vector<Complex> inverse(static_cast<size_t>(D.rows()));
  for (Eigen::Index k = 0; k < K; ++k) {
    const double omega = kTwoPi * grid(k);
    const Complex iw(0.0, omega);
    for (int j = 0; j < C * m; ++j) Q.col(j) = stiff_load.col(j).cast<Complex>() + iw * damper_load.col(j).cast<Complex>();
    D.noalias() = stiffness - omega * omega * mass;
    D.noalias() += iw * damping;
    for (size_t d = 0; d < series.size(); ++d)
      D.noalias() += maxwell_stiffness(system.series_dampers[d].stiffness, system.series_dampers[d].damping, omega) *
                     series[d];
    if (basis) Y.noalias() = basis_c.transpose() * Q;
    else Y = Q;
    // Singular: a pivot of U at round-off of the largest (with partial pivoting the pivots'
    // spread bounds the condition from below; a condition estimate costs more solves than the
    // solve itself on these small systems, and would be paid at every frequency).
    solve_in_place(static_cast<int>(D.rows()), static_cast<int>(Y.cols()), D.data(), Y.data(), pivots.data(),
                   inverse.data());
    if (!(pivots.minCoeff() > 1e-14 * pivots.maxCoeff()))
      throw NumericalError("ride: the dynamic stiffness K − ω²M + iωC is singular at " + shortest_text(grid(k), 8) +
                           " Hz (smallest pivot " + shortest_text(pivots.minCoeff() / pivots.maxCoeff(), 3) +
                           " of the largest), which is not an undamped mode's frequency");
    if (basis) X.noalias() = basis_c * Y;
    else X = Y;
    h.setZero();
    for (int o = 0; o < O; ++o) {
      // maps[o].row(omega) written in place (no temporaries at every frequency), the same operations.
      const OutputMap& map = maps[o];
      for (int j = 0; j < n; ++j) A(o, j) = Complex(map.a0(j), omega * map.a1(j));
      for (const SeriesDamperRow& sd : map.series) {
        const Complex ks = maxwell_stiffness(sd.stiffness, sd.damping, omega);
        for (int j = 0; j < n; ++j) A(o, j) -= ks * sd.stretch(j);
      }
      const Complex power = power_of_i_omega(map.order, omega);
      for (int j = 0; j < n; ++j) A(o, j) *= power;
      if (map.gravity.size())
        for (int j = 0; j < n; ++j) A(o, j) += map.gravity(j);
      for (size_t t = 0; t < maps[o].inputs.size(); ++t)
        for (int c = 0; c < C; ++c) {
          const int i = maps[o].inputs[t];
          h(o, c * m + group_of[i]) += maps[o].track(t, components[c].displacement[i], omega);
        }
    }
    h.noalias() += A * X;
    // Column k, row (o·C + c)·m + g = h(o, c·m + g): the output's index runs slowest.
    for (int o = 0; o < O; ++o) r.response.col(k).segment(static_cast<Eigen::Index>(o) * C * m, C * m) = h.row(o).transpose();
    if (!split) continue;
    q.noalias() = left_c * X;  // J × C·m
    for (int j = 0; j < J; ++j) r.modal.col(k).segment(static_cast<Eigen::Index>(j) * C * m, C * m) = q.row(j).transpose();
    seen.noalias() = A * shapes_c;  // O × J
    for (int o = 0; o < O; ++o)
      for (int j = 0; j < J; ++j) r.modal_rows(static_cast<Eigen::Index>(o) * J + j, k) = std::norm(seen(o, j));
  }
}

}  // namespace railmodal::ride
