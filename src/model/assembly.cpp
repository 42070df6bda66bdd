// Assembly of M, C and K from bodies and elements (see linear_system.hpp for the model).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <utility>
#include <stdexcept>

#include "model/analysis_limits.hpp"
#include "model/assembly.hpp"
#include "model/body_bending.hpp"
#include "model/element_stiffness.hpp"
#include "model/rigid_body.hpp"
#include "model/spring_stages.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/linear_system.hpp"

namespace railmodal {

const char* to_string(Motion motion) {
  switch (motion) {
    case Motion::lateral: return "lateral";
    case Motion::bounce: return "bounce";
    case Motion::roll: return "roll";
    case Motion::pitch: return "pitch";
    case Motion::yaw: return "yaw";
    case Motion::longitudinal: return "longitudinal";
    case Motion::bending: return "bending";
  }
  return "?";
}

std::optional<Motion> motion_from_string(const std::string& word) {
  for (Motion m : {Motion::lateral, Motion::bounce, Motion::roll, Motion::pitch, Motion::yaw, Motion::longitudinal,
                   Motion::bending})
    if (word == to_string(m)) return m;
  return std::nullopt;
}

const char* to_string(DofSet set) {
  switch (set) {
    case DofSet::vertical: return "vertical";
    case DofSet::lateral: return "lateral";
    case DofSet::all: return "all";
  }
  return "?";
}

std::optional<DofSet> dof_set_from_string(const std::string& word) {
  for (DofSet s : {DofSet::vertical, DofSet::lateral, DofSet::all})
    if (word == to_string(s)) return s;
  return std::nullopt;
}

double series_stiffness(const std::vector<SpringStage>& stages) {
  if (stages.empty()) return 0.0;
  double flexibility = 0.0;
  for (const auto& stage : stages) flexibility += 1.0 / (stage.stiffness * stage.count);
  return 1.0 / flexibility;
}

int LinearSystem::index_of(const std::string& label) const {
  for (size_t i = 0; i < dofs.size(); ++i)
    if (dofs[i].label == label) return static_cast<int>(i);
  return -1;
}

namespace {

using model::kMotionsPerBody;
constexpr double kHalfPi = 1.57079632679489661923;

bool in_set(Motion motion, DofSet set) {
  // Longitudinal motion belongs with bounce and pitch: a CG above the reference point and a
  // spring below it couple surge with pitch, not with the lateral motions. Vertical bending
  // moves points vertically only: it couples with bounce and pitch.
  const bool vertical = motion == Motion::bounce || motion == Motion::pitch || motion == Motion::longitudinal ||
                        motion == Motion::bending;
  switch (set) {
    case DofSet::vertical: return vertical;
    case DofSet::lateral: return !vertical;
    case DofSet::all: return true;
  }
  return true;
}

bool holds(const Body& body, Motion m) { return std::find(body.held.begin(), body.held.end(), m) != body.held.end(); }

// A wheelset's bounce, roll and pitch follow the rails and it rolls with the track (longitudinal
// held); its lateral and yaw motions are what the wheel–rail contact acts on.
void check_wheelsets(const Vehicle& vehicle, const std::map<std::string, int>& index) {
  std::set<std::string> seen;
  for (const Wheelset& w : vehicle.wheelsets) {
    const std::string who = "wheelset '" + w.body + "': ";
    const auto found = index.find(w.body);
    if (found == index.end()) throw std::invalid_argument(who + "no body of that name");
    if (!seen.insert(w.body).second) throw std::invalid_argument(who + "listed twice as a wheelset");
    if (!(w.spin_inertia >= 0.0) || !std::isfinite(w.spin_inertia))
      throw std::invalid_argument(who + "spin inertia must be non-negative and finite");
    const Body& body = vehicle.bodies[found->second];
    for (Motion m : {Motion::bounce, Motion::roll, Motion::pitch})
      if (!holds(body, m))
        throw std::invalid_argument(who + "its " + to_string(m) +
                                    " must be held (a wheelset's bounce, roll and pitch follow the rails)");
    if (body.longitudinal_free)
      throw std::invalid_argument(who + "its longitudinal motion must be held (it rolls with the track)");
    if (body.bending) throw std::invalid_argument(who + "a wheelset is rigid: it carries no bending mode");
    for (Motion m : {Motion::lateral, Motion::yaw})
      if (holds(body, m))
        throw std::invalid_argument(who + "its lateral and yaw motions must be free (the wheel–rail contact acts on " +
                                    "them), and its body holds its " + to_string(m));
  }
}

// What is wrong with an element's spring and damper coefficients, or nullptr. One function for
// check_vehicle (which throws it) and a study's coefficient deltas (coefficients_valid), so the
// two cannot drift apart.
const char* coefficient_error(const Element& e) {
  bool stiffness_valid = true;
  model::each_spring_stage(e, [&](const SpringStage& s) {
    stiffness_valid = stiffness_valid && s.stiffness > 0.0 && std::isfinite(s.stiffness) && s.count >= 1;
  });
  if (!stiffness_valid) return "spring stiffness must be positive and finite";
  if (!(e.longitudinal_damping >= 0.0) || !std::isfinite(e.longitudinal_damping))
    return "longitudinal damping must be non-negative and finite";
  if (!(e.rotational_stiffness.array() >= 0.0).all() || !e.rotational_stiffness.allFinite())
    return "rotational stiffness must be non-negative and finite";
  return nullptr;
}

void check_vehicle(const Vehicle& vehicle, std::map<std::string, int>* index) {
  if (vehicle.bodies.empty()) throw std::invalid_argument("the vehicle has no bodies");
  if (!(vehicle.gravity > 0.0) || !std::isfinite(vehicle.gravity))
    throw std::invalid_argument("gravity must be positive and finite");
  for (size_t b = 0; b < vehicle.bodies.size(); ++b) {
    const Body& body = vehicle.bodies[b];
    if (body.name.empty()) throw std::invalid_argument("a body has no name");
    if (!index->emplace(body.name, static_cast<int>(b)).second)
      throw std::invalid_argument("two bodies are named '" + body.name + "'");
    if (!(body.mass > 0.0) || !std::isfinite(body.mass))
      throw std::invalid_argument("body '" + body.name + "': mass must be positive and finite");
    if (!(body.inertia.array() >= 0.0).all() || !body.inertia.allFinite())
      throw std::invalid_argument("body '" + body.name +
                                  "': moments of inertia must be non-negative and finite");
    if (body.longitudinal_free &&
        std::find(body.held.begin(), body.held.end(), Motion::longitudinal) != body.held.end())
      throw std::invalid_argument("body '" + body.name + "': longitudinal motion is both free and held");
    if (holds(body, Motion::bending))
      throw std::invalid_argument("body '" + body.name + "': bending is not a motion that can be held (a body " +
                                  "without a bending mode is rigid)");
    if (body.bending) model::bending_mode(body);  // checks the mode's data
  }
  for (const Element& e : vehicle.elements) {
    for (const std::string* end : {&e.lower, &e.upper}) {
      if (!end->empty() && !index->count(*end))
        throw std::invalid_argument("element '" + e.name + "' names unknown body '" + *end + "'");
    }
    if (e.upper.empty()) throw std::invalid_argument("element '" + e.name + "' has no upper body");
    if (e.upper == e.lower)
      throw std::invalid_argument("element '" + e.name + "' connects '" + e.upper + "' to itself");
    if (const char* error = coefficient_error(e)) throw std::invalid_argument("element '" + e.name + "': " + error);
    if (e.hanger && (!(e.hanger->length > 0.0) || std::abs(e.hanger->inclination) >= kHalfPi))
      throw std::invalid_argument("element '" + e.name +
                                  "': hanger length must be positive, inclination below 90°");
    for (const SeriesDamper& d : e.series_dampers) {
      if (d.direction != Motion::longitudinal && d.direction != Motion::lateral && d.direction != Motion::bounce)
        throw std::invalid_argument("element '" + e.name + "': a series damper acts longitudinally, laterally or " +
                                    "vertically (bounce), not in " + to_string(d.direction));
      if (!(d.damping > 0.0) || !std::isfinite(d.damping) || !(d.stiffness > 0.0) || !std::isfinite(d.stiffness))
        throw std::invalid_argument("element '" + e.name +
                                    "': a series damper's damping and series stiffness must be positive and finite");
    }
  }
  check_wheelsets(vehicle, *index);
}

// Full coordinates: six rigid motions per body, body-major, then one bending coordinate per
// body that carries a bending mode (none: the layout is the rigid one, index for index).
struct Layout {
  int bodies = 0;
  std::vector<int> bending;                 // each body's bending coordinate, or -1
  std::vector<int> bent;                    // the body of each bending coordinate
  std::vector<model::BendingMode> modes;    // and its mode
  explicit Layout(const Vehicle& v) : bodies(static_cast<int>(v.bodies.size())), bending(v.bodies.size(), -1) {
    for (int b = 0; b < bodies; ++b)
      if (v.bodies[b].bending) {
        bending[b] = rigid() + static_cast<int>(bent.size());
        bent.push_back(b);
        modes.push_back(model::bending_mode(v.bodies[b]));
      }
  }
  int rigid() const { return bodies * kMotionsPerBody; }
  int size() const { return rigid() + static_cast<int>(bent.size()); }
  static int index(int body, Motion m) { return body * kMotionsPerBody + static_cast<int>(m); }
  int body_of(int c) const { return c < rigid() ? c / kMotionsPerBody : bent[c - rigid()]; }
  Motion motion_of(int c) const { return c < rigid() ? static_cast<Motion>(c % kMotionsPerBody) : Motion::bending; }
};

// How an element's point moves with the two bodies it joins: relative displacement
// upper − lower = up · q_upper − low · q_lower (lower = −1: the track), plus, on a body with
// a bending mode, φ(x) times its bending coordinate, vertically (up_bending, low_bending: φ at
// the point, 0 on a rigid body).
struct ElementMap {
  int upper = 0, lower = -1;
  model::PointMap up, low;
  double up_bending = 0.0, low_bending = 0.0;
  bool finite = false;  // up and (where there is a lower body) low hold finite numbers only

  // The displacement (longitudinal, lateral, vertical) of the point on the upper (lower) body
  // per unit of full coordinate c; zero for another body's coordinate.
  Eigen::Vector3d column(const Layout& layout, bool upper_end, int c) const {
    const int body = upper_end ? upper : lower;
    if (body < 0 || layout.body_of(c) != body) return Eigen::Vector3d::Zero();
    if (c >= layout.rigid()) return {0.0, 0.0, upper_end ? up_bending : low_bending};
    return (upper_end ? up : low).col(c % kMotionsPerBody);
  }
};

ElementMap element_map(const Vehicle& v, const Layout& layout, const std::map<std::string, int>& index,
                       const Element& e) {
  ElementMap m;
  m.upper = index.at(e.upper);
  m.up = model::point_map(v.bodies[m.upper], e.point);
  // The message names the element only for a body that bends (no string built per element
  // of a rigid vehicle: a study assembles one per variant).
  auto what = [&e](const std::string& body) { return "element '" + e.name + "' on body '" + body + "'"; };
  if (layout.bending[m.upper] >= 0)
    m.up_bending = layout.modes[layout.bending[m.upper] - layout.rigid()].shape_at(e.point.x(), what(e.upper));
  if (!e.lower.empty()) {
    m.lower = index.at(e.lower);
    m.low = model::point_map(v.bodies[m.lower], e.point);
    if (layout.bending[m.lower] >= 0)
      m.low_bending = layout.modes[layout.bending[m.lower] - layout.rigid()].shape_at(e.point.x(), what(e.lower));
  }
  m.finite = m.up.allFinite() && (m.lower < 0 || m.low.allFinite());
  return m;
}

// add_element where at most two of the stiffnesses are nonzero (`stiff`, `count` of them, in
// order), all finite, and so are the maps: each entry of a pair's 6 × 6 block gains the terms
// (s a_d,i k_d) b_d,j of those directions only, as one product or the sum of two. add_element's
// Eigen products give the same bits: its factor (s Aᵀ) kd has the entry (s a_d,i) k_d plus exact
// zeros, and a direction whose k_d is zero adds only exact zeros (a finite number times zero) to
// the entry's sum; x + ±0 = x, a sum of two terms is the same in either order, and a zero sum
// added to K leaves it as it was (K is summed from +0 and holds no −0: +0 + −0 = +0). The
// resort car's springs and dampers act in one direction each (vertical), so this is one
// multiply a term instead of three products of 3 × 5 maps per pair.
void add_element_sparse(const ElementMap& m, const Eigen::Vector3d& k, const int* stiff, int count,
                        Eigen::MatrixXd* K) {
  struct Side { int body; const model::PointMap* map; double sign; };
  const Side sides[2] = {{m.upper, &m.up, 1.0}, {m.lower, &m.low, -1.0}};
  for (const Side& a : sides)
    for (const Side& b : sides) {
      if (a.body < 0 || b.body < 0) continue;
      const double s = a.sign * b.sign;
      Eigen::Map<Eigen::Matrix<double, kMotionsPerBody, kMotionsPerBody>, Eigen::Unaligned, Eigen::OuterStride<>> block(
          K->data() + b.body * kMotionsPerBody * K->rows() + a.body * kMotionsPerBody, Eigen::OuterStride<>(K->rows()));
      // (s a_d,i) k_d, the factor add_element forms.
      const Eigen::Matrix<double, kMotionsPerBody, 1> u0 = (s * a.map->row(stiff[0]).transpose()) * k(stiff[0]);
      if (count == 1) {
        for (int j = 0; j < kMotionsPerBody; ++j) block.col(j) += u0 * (*b.map)(stiff[0], j);
      } else {
        const Eigen::Matrix<double, kMotionsPerBody, 1> u1 = (s * a.map->row(stiff[1]).transpose()) * k(stiff[1]);
        for (int j = 0; j < kMotionsPerBody; ++j)
          block.col(j) += u0 * (*b.map)(stiff[0], j) + u1 * (*b.map)(stiff[1], j);
      }
    }
}

// k = diag(longitudinal, lateral, vertical) at the point: K += Bᵀ k B, scattered into the
// blocks of the two bodies only (a dense Bᵀ k B would cost O(n²) per element).
void add_element(const ElementMap& m, const Eigen::Vector3d& k, Eigen::MatrixXd* K) {
  int stiff[3];
  int count = 0;
  for (int d = 0; d < 3; ++d)
    if (k(d) != 0.0) stiff[count++] = d;
  if (count == 0 && k.allFinite() && m.finite) return;  // only exact zeros to add
  if (count <= 2 && k.allFinite() && m.finite) return add_element_sparse(m, k, stiff, count, K);
  struct Side { int body; const model::PointMap* map; double sign; };
  const Side sides[2] = {{m.upper, &m.up, 1.0}, {m.lower, &m.low, -1.0}};
  const Eigen::Matrix3d kd = k.asDiagonal();
  constexpr int kFive = kMotionsPerBody - 1;  // the motions before longitudinal
  constexpr int kAlong = kFive;               // the longitudinal motion's index
  for (const Side& a : sides)
    for (const Side& b : sides) {
      if (a.body < 0 || b.body < 0) continue;
      const int ra = a.body * kMotionsPerBody, cb = b.body * kMotionsPerBody;
      // The five motions by themselves, as they were assembled before longitudinal motion was
      // a degree of freedom: the same products of 3 × 5 maps, so a vehicle that frees no surge
      // gets its matrices bit for bit as before (a 3 × 6 product sums in another order).
      // (s Aᵀ) kd once for the three products, whose left factors are its rows: kd is diagonal,
      // so each entry sums one term that may be nonzero and exact zeros, which gives the same
      // bits in any order (x + ±0 = x; a sum of zeros is −0 only when every term is), hence
      // the products' bits are those of (s A5ᵀ) kd B5 and the rest evaluated apart, without
      // computing the 5 × 3 and 1 × 3 factors again.
      const Eigen::Matrix<double, kMotionsPerBody, 3> sak = a.sign * b.sign * a.map->transpose() * kd;
      const Eigen::Matrix<double, kFive, 3> sak5 = sak.topRows<kFive>();
      const Eigen::Matrix<double, 1, 3> sak_along = sak.row(kAlong);
      const Eigen::Matrix<double, 3, kFive> b5 = b.map->leftCols<kFive>();
      K->block<kFive, kFive>(ra, cb) += sak5 * b5;
      K->block<kMotionsPerBody, 1>(ra, cb + kAlong) += sak * b.map->col(kAlong);
      K->block<1, kFive>(ra + kAlong, cb) += sak_along * b5;
    }
}

// The vertical stiffness (or damping) k_z of an element on a body with a bending mode: the
// point's vertical displacement gains φ(x)·q_b, so K += Bᵀ k B gains the rows and columns of
// the bending coordinates. Only these are added here (add_element has the rigid blocks, as
// before bending existed): a vehicle without bending gets nothing from this.
void add_bending_coupling(const Layout& layout, const ElementMap& m, double kz, Eigen::MatrixXd* K) {
  struct Side { int body; const model::PointMap* map; double phi; double sign; };
  const Side sides[2] = {{m.upper, &m.up, m.up_bending, 1.0}, {m.lower, &m.low, m.low_bending, -1.0}};
  for (const Side& a : sides) {
    if (a.body < 0 || layout.bending[a.body] < 0 || kz == 0.0) continue;
    const int qa = layout.bending[a.body];
    for (const Side& b : sides) {
      if (b.body < 0) continue;
      const double s = a.sign * b.sign * kz * a.phi;
      // Bending of a against the rigid motions of b, both ways (K stays symmetric).
      const Eigen::Matrix<double, 1, kMotionsPerBody> row = s * b.map->row(2);
      K->block<1, kMotionsPerBody>(qa, b.body * kMotionsPerBody) += row;
      K->block<kMotionsPerBody, 1>(b.body * kMotionsPerBody, qa) += row.transpose();
      if (layout.bending[b.body] >= 0) (*K)(qa, layout.bending[b.body]) += s * b.phi;
    }
  }
}

// Stiffness against the relative rotation (roll, pitch, yaw) of the two bodies.
void add_rotational(const ElementMap& m, const Eigen::Vector3d& k, Eigen::MatrixXd* K) {
  for (int a : {m.upper, m.lower})
    for (int b : {m.upper, m.lower}) {
      if (a < 0 || b < 0) continue;
      const double sign = (a == m.upper) == (b == m.upper) ? 1.0 : -1.0;
      for (int r = 0; r < 3; ++r)  // roll, pitch, yaw are motions 2, 3, 4
        (*K)(a * kMotionsPerBody + 2 + r, b * kMotionsPerBody + 2 + r) += sign * k(r);
    }
}

// Vertical relative displacement of the element's point for full coordinates q.
// Longitudinal motion moves no point vertically: the five motions before it, summed as 3 × 5
// maps were before it existed (bit for bit the same loads).
double vertical_stretch(const Layout& layout, const ElementMap& m, const Eigen::VectorXd& q) {
  constexpr int kFive = kMotionsPerBody - 1;
  const Eigen::Matrix<double, 3, kFive> up = m.up.leftCols<kFive>();
  double dz = up.row(2).dot(q.segment<kFive>(m.upper * kMotionsPerBody));
  if (m.lower >= 0) {
    const Eigen::Matrix<double, 3, kFive> low = m.low.leftCols<kFive>();
    dz -= low.row(2).dot(q.segment<kFive>(m.lower * kMotionsPerBody));
  }
  // The bodies' bending, where they have it (after the rigid sum, which stays as it was).
  if (layout.bending[m.upper] >= 0) dz += m.up_bending * q(layout.bending[m.upper]);
  if (m.lower >= 0 && layout.bending[m.lower] >= 0) dz -= m.low_bending * q(layout.bending[m.lower]);
  return dz;
}

// Keep the motions that are not held; longitudinal motion only where the body frees it; a
// body's bending coordinate (never held) after its rigid motions.
std::vector<int> free_coordinates(const Vehicle& v, const Layout& layout) {
  std::vector<int> free;
  free.reserve(static_cast<size_t>(layout.size()));
  for (int b = 0; b < layout.bodies; ++b) {
    for (int m = 0; m < kMotionsPerBody; ++m) {
      const Body& body = v.bodies[b];
      const auto motion = static_cast<Motion>(m);
      if (motion == Motion::longitudinal && !body.longitudinal_free) continue;
      if (std::find(body.held.begin(), body.held.end(), motion) == body.held.end())
        free.push_back(Layout::index(b, motion));
    }
    if (layout.bending[b] >= 0) free.push_back(layout.bending[b]);
  }
  return free;
}

// Static vertical load of each element (compression positive) under gravity, from the
// springs alone: K q = Q on the free coordinates, minimum-norm where K is singular. A bending
// coordinate takes no load from the body's weight, taken as spread uniformly along the beam
// (∫ m' φ ds = 0), and its stiffness ω²m_b: the springs bend the body (it sags between
// supports), which moves load between supports only where they are more than statics fixes.
// The generalised weights Q in full coordinates: each body's weight at its CG.
Eigen::VectorXd generalised_weights(const Vehicle& v, const Layout& layout) {
  Eigen::VectorXd Q = Eigen::VectorXd::Zero(layout.size());
  for (int b = 0; b < layout.bodies; ++b) {
    const Body& body = v.bodies[b];
    const Eigen::Vector3d weight(0.0, 0.0, -body.mass * v.gravity);
    Q.segment(b * kMotionsPerBody, kMotionsPerBody) =
        model::point_map(body, body.centre_of_gravity).transpose() * weight;
  }
  return Q;
}

// K's rows and columns `keep` into *Kk and Q's rows `keep` into *Qk: the static problem on
// those coordinates.
void pick_system(const Eigen::MatrixXd& K, const Eigen::VectorXd& Q, const std::vector<int>& keep,
                 Eigen::MatrixXd* Kk, Eigen::VectorXd* Qk) {
  const int n = static_cast<int>(keep.size());
  Kk->resize(n, n);
  Qk->resize(n);
  for (int i = 0; i < n; ++i) {
    (*Qk)(i) = Q(keep[i]);
    for (int j = 0; j < n; ++j) (*Kk)(i, j) = K(keep[i], keep[j]);
  }
}

std::vector<double> static_loads(const Vehicle& v, const Layout& layout, const std::vector<int>& free,
                                 const std::vector<ElementMap>& maps, const Eigen::MatrixXd& K_springs,
                                 const Eigen::VectorXd& Q) {
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd Kf;
  Eigen::VectorXd Qf;
  pick_system(K_springs, Q, free, &Kf, &Qf);
  // Usually K is positive definite on the free coordinates (blocked Cholesky, the cheap
  // path); where a direction has no stiffness (a rigid-body mode gravity does not excite)
  // the minimum-norm solution.
  Eigen::LLT<Eigen::MatrixXd> llt(Kf);
  Eigen::VectorXd qf;
  if (llt.info() == Eigen::Success) qf = llt.solve(Qf);
  if (llt.info() != Eigen::Success || !qf.allFinite() || !((Kf * qf - Qf).norm() <= 1e-10 * Qf.norm())) {
    // This thread's decomposition, its storage kept between calls: every variant of a study
    // whose vehicle has a rigid-body mode comes here. The same factorisation of the same matrix.
    thread_local Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
    cod.compute(Kf);
    qf = cod.solve(Qf);
  }
  const double mismatch = (Kf * qf - Qf).norm();
  if (!(mismatch <= 1e-8 * Qf.norm())) {
    // Name the first body whose weight the springs cannot carry.
    for (int i = 0; i < n; ++i) {
      const Eigen::VectorXd r = Kf * qf - Qf;
      if (std::abs(r(i)) > 1e-8 * Qf.norm()) {
        const int b = layout.body_of(free[i]);
        throw NumericalError("no static equilibrium under gravity: nothing holds up body '" +
                             v.bodies[b].name + "' in " + to_string(layout.motion_of(free[i])));
      }
    }
  }
  Eigen::VectorXd q = Eigen::VectorXd::Zero(layout.size());
  for (int i = 0; i < n; ++i) q(free[i]) = qf(i);
  std::vector<double> loads;
  loads.reserve(v.elements.size());
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const double kz = series_stiffness(v.elements[k].vertical_stages);
    loads.push_back(-kz * vertical_stretch(layout, maps[k], q));  // upper sinks: compression
  }
  return loads;
}

// The static loads of static_loads where every direction of K_springs without stiffness is a
// coordinate direction: free coordinates whose rows are exactly zero (a motion no spring
// touches; the benchmark study's resort car has one, and every variant's Cholesky failed on
// it). The minimum-norm solution of K q = Q is then q = 0 on them and the Cholesky solution of
// the remaining block (the pseudo-inverse of a matrix with zero rows and columns and a positive
// definite rest), so one smaller Cholesky replaces a failed Cholesky and the complete
// orthogonal decomposition. It rounds otherwise than the decomposition (a relative change of
// the order of the unit round-off times the block's condition number), so only a study's
// workers take it (VariantAssembly), for every variant whatever the worker's base (which rows
// are zero is found from the variant itself: the results do not depend on the thread count);
// the general assemble keeps static_loads. Returns false, leaving *loads, where the route does
// not apply (no zero row, a weight on one, a block not positive definite or not solved to
// 1e-10): static_loads then decides, with its message.
bool static_loads_on_sprung(const Vehicle& v, const Layout& layout, const std::vector<int>& free,
                            const std::vector<ElementMap>& maps, const Eigen::MatrixXd& K_springs,
                            const Eigen::VectorXd& Q, std::vector<double>* loads) {
  const int n = static_cast<int>(free.size());
  thread_local std::vector<int> sprung;
  sprung.clear();
  for (int i = 0; i < n; ++i) {
    bool zero = true;
    for (int j = 0; j < n && zero; ++j) zero = K_springs(free[i], free[j]) == 0.0;
    if (!zero)
      sprung.push_back(free[i]);
    else if (Q(free[i]) != 0.0)
      return false;
  }
  if (static_cast<int>(sprung.size()) == n) return false;
  const int m = static_cast<int>(sprung.size());
  // This thread's matrices and factorisation, their storage kept between variants (the same
  // operations into kept storage: the same bits).
  thread_local Eigen::MatrixXd Ks;
  thread_local Eigen::VectorXd Qs, qs, Ksqs, q;
  thread_local Eigen::LLT<Eigen::MatrixXd> llt;
  pick_system(K_springs, Q, sprung, &Ks, &Qs);
  llt.compute(Ks);
  if (llt.info() != Eigen::Success) return false;
  qs = llt.solve(Qs);
  Ksqs.noalias() = Ks * qs;
  if (!qs.allFinite() || !((Ksqs - Qs).norm() <= 1e-10 * Qs.norm())) return false;
  q.setZero(layout.size());
  for (int i = 0; i < m; ++i) q(sprung[i]) = qs(i);
  loads->resize(v.elements.size());
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const double kz = series_stiffness(v.elements[k].vertical_stages);
    (*loads)[k] = -kz * vertical_stretch(layout, maps[k], q);  // as static_loads
  }
  return true;
}

// The matrices in full coordinates before the static loads are known: M, C, and K of the
// springs (hangers' lateral stiffness left out), with each element's point map.
struct FullModel {
  Eigen::MatrixXd M, C, K_springs;
  std::vector<ElementMap> maps;  // one per element
};

// The pairs of bodies whose 6 × 6 blocks add_element and add_rotational write for `maps` (each
// element's two bodies, both ways, and each by itself), without repeats.
std::vector<std::pair<int, int>> joined_blocks(const std::vector<ElementMap>& maps) {
  std::set<std::pair<int, int>> blocks;
  for (const ElementMap& m : maps)
    for (int a : {m.upper, m.lower})
      for (int b : {m.upper, m.lower})
        if (a >= 0 && b >= 0) blocks.insert({a, b});
  return {blocks.begin(), blocks.end()};
}

// The coefficients of the springs and bending modes summed into K_springs, zeroed first: what
// changes when only the elements' stiffnesses do (a study's variants on one base,
// VariantAssembly). The same sums in the same order whichever path calls it.
// `joined`, when given, is joined_blocks(f->maps), and K_springs was summed before with the
// same maps: add_stiffnesses writes only those blocks and the bending coordinates' rows and
// columns, so the rest still holds +0 and only these are zeroed (the same matrix).
void add_stiffnesses(const Vehicle& vehicle, const Layout& layout, FullModel* f,
                     const std::vector<std::pair<int, int>>* joined = nullptr) {
  if (joined) {
    for (const auto& [a, b] : *joined)
      f->K_springs.block<kMotionsPerBody, kMotionsPerBody>(a * kMotionsPerBody, b * kMotionsPerBody).setZero();
    const int bent = layout.size() - layout.rigid();
    f->K_springs.bottomRows(bent).setZero();
    f->K_springs.rightCols(bent).setZero();
  } else {
    f->K_springs.setZero();
  }
  // The bending mode by itself: modal mass m_b, stiffness ω²m_b (damping 2ζω m_b in
  // add_dampings). Its mass is not coupled to the rigid motions: for a uniform beam the mode
  // is orthogonal to them (∫ m' φ ds = ∫ m' (x − centre) φ ds = 0), which we take for the body.
  for (size_t j = 0; j < layout.bent.size(); ++j) {
    const model::BendingMode& mode = layout.modes[j];
    const int q = layout.rigid() + static_cast<int>(j);
    f->K_springs(q, q) = mode.omega * mode.omega * mode.modal_mass;
  }
  for (size_t k = 0; k < vehicle.elements.size(); ++k) {
    const Element& e = vehicle.elements[k];
    const ElementMap& map = f->maps[k];
    // A hanger's lateral stiffness needs the static load: it is added later.
    const double lateral = e.hanger ? 0.0 : series_stiffness(e.lateral_stages);
    add_element(map, {series_stiffness(e.longitudinal_stages), lateral, series_stiffness(e.vertical_stages)},
                &f->K_springs);
    add_rotational(map, e.rotational_stiffness, &f->K_springs);
    add_bending_coupling(layout, map, series_stiffness(e.vertical_stages), &f->K_springs);
  }
}

// The viscous dampers and the bending modes' damping summed into C, zeroed first (when C is
// not empty: an assembly of the stiffness alone has none).
void add_dampings(const Vehicle& vehicle, const Layout& layout, FullModel* f) {
  if (f->C.size() == 0) return;
  f->C.setZero();
  for (size_t j = 0; j < layout.bent.size(); ++j) {
    const model::BendingMode& mode = layout.modes[j];
    const int q = layout.rigid() + static_cast<int>(j);
    f->C(q, q) = 2.0 * mode.damping_ratio * mode.omega * mode.modal_mass;
  }
  for (size_t k = 0; k < vehicle.elements.size(); ++k) {
    const Element& e = vehicle.elements[k];
    add_element(f->maps[k], {e.longitudinal_damping, e.lateral_damping, e.vertical_damping}, &f->C);
    add_bending_coupling(layout, f->maps[k], e.vertical_damping, &f->C);
  }
}

// Without `damping`, C is left empty (the stiffness alone: M and K as with it).
FullModel springs_and_masses(const Vehicle& vehicle, const std::map<std::string, int>& index, const Layout& layout,
                             bool damping) {
  const int N = layout.size();
  FullModel f{Eigen::MatrixXd::Zero(N, N), damping ? Eigen::MatrixXd::Zero(N, N) : Eigen::MatrixXd(),
              Eigen::MatrixXd::Zero(N, N), {}};
  for (int b = 0; b < layout.bodies; ++b)
    f.M.block(b * kMotionsPerBody, b * kMotionsPerBody, kMotionsPerBody, kMotionsPerBody) =
        model::body_mass(vehicle.bodies[b]);
  for (size_t j = 0; j < layout.bent.size(); ++j) {
    const int q = layout.rigid() + static_cast<int>(j);
    f.M(q, q) = layout.modes[j].modal_mass;
  }
  f.maps.reserve(vehicle.elements.size());
  for (const Element& e : vehicle.elements) f.maps.push_back(element_map(vehicle, layout, index, e));
  add_stiffnesses(vehicle, layout, &f);
  add_dampings(vehicle, layout, &f);
  return f;
}

// Dead loads: each weight at its CG, each element's static load at its point. A bending
// coordinate gets none: its second-order terms (the slope φ' turning a load's lever, the
// drop of a point off the neutral axis) are left out, as the rotation of the beam's sections
// is (docs/ride.md, "Car-body bending").
// The bodies' weights' part, summed first (what the springs' coefficients do not change).
Eigen::MatrixXd weights_gravity_stiffness(const Vehicle& vehicle, const Layout& layout) {
  Eigen::MatrixXd K_gravity = Eigen::MatrixXd::Zero(layout.size(), layout.size());
  for (int b = 0; b < layout.bodies; ++b) {
    const Body& body = vehicle.bodies[b];
    K_gravity.block(b * kMotionsPerBody, b * kMotionsPerBody, kMotionsPerBody, kMotionsPerBody) +=
        model::dead_load_stiffness(body, body.centre_of_gravity, Eigen::Vector3d(0.0, 0.0, -body.mass * vehicle.gravity));
  }
  return K_gravity;
}

// K_weights: weights_gravity_stiffness's, to which the elements' static loads are added.
Eigen::MatrixXd gravity_stiffness(const Vehicle& vehicle, const std::vector<ElementMap>& maps,
                                  const std::vector<double>& loads, const Eigen::MatrixXd& K_weights) {
  Eigen::MatrixXd K_gravity = K_weights;
  auto block = [&](int body) {
    return K_gravity.block(body * kMotionsPerBody, body * kMotionsPerBody, kMotionsPerBody, kMotionsPerBody);
  };
  for (size_t k = 0; k < vehicle.elements.size(); ++k) {
    const Element& e = vehicle.elements[k];
    const Eigen::Vector3d on_upper(0.0, 0.0, loads[k]);
    const int up = maps[k].upper;  // the bodies element_map looked up by name
    block(up) += model::dead_load_stiffness(vehicle.bodies[up], e.point, on_upper);
    if (maps[k].lower >= 0) {
      const int low = maps[k].lower;
      block(low) += model::dead_load_stiffness(vehicle.bodies[low], e.point, -on_upper);
    }
  }
  return K_gravity;
}

// The motions of the requested set among the free coordinates (`free`), and their DOFs.
std::vector<int> kept_coordinates(const Vehicle& vehicle, const Layout& layout, const std::vector<int>& free, DofSet set,
                                  std::vector<Dof>* dofs) {
  std::vector<int> keep;
  keep.reserve(free.size());
  dofs->reserve(dofs->size() + free.size());
  for (int c : free) {
    const Motion motion = layout.motion_of(c);
    if (!in_set(motion, set)) continue;
    const int b = layout.body_of(c);
    keep.push_back(c);
    dofs->push_back({vehicle.bodies[b].name + "." + to_string(motion), b, motion});
  }
  return keep;
}

// A's rows and columns `keep` into *out (its storage reused when it has the size already).
void pick_into(const Eigen::MatrixXd& A, const std::vector<int>& keep, Eigen::MatrixXd* out) {
  const int n = static_cast<int>(keep.size());
  out->resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) (*out)(i, j) = A(keep[i], keep[j]);
}

Eigen::MatrixXd pick(const Eigen::MatrixXd& A, const std::vector<int>& keep) {
  Eigen::MatrixXd out;
  pick_into(A, keep, &out);
  return out;
}

// Row k: the vertical stretch of element k per kept coordinate.
Eigen::MatrixXd element_vertical_map(const Layout& layout, const std::vector<ElementMap>& maps,
                                     const std::vector<int>& keep) {
  const int n = static_cast<int>(keep.size());
  Eigen::MatrixXd map = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(maps.size()), n);
  for (size_t k = 0; k < maps.size(); ++k)
    for (int i = 0; i < n; ++i) {
      const int body = layout.body_of(keep[i]);
      if (body == maps[k].upper) map(k, i) += maps[k].column(layout, true, keep[i])(2);
      if (body == maps[k].lower) map(k, i) -= maps[k].column(layout, false, keep[i])(2);
    }
  return map;
}

// An element on the ground that resists only longitudinal motion (draw gear to the rest of the
// train, a traction rod) is no wheel: the track's displacement does not reach it.
bool pulls_only_along(const Element& e) {
  return (!e.longitudinal_stages.empty() || e.longitudinal_damping > 0.0) && e.vertical_stages.empty() &&
         e.lateral_stages.empty() && !e.hanger && e.vertical_damping == 0.0 && e.lateral_damping == 0.0 &&
         e.rotational_stiffness.isZero(0.0);
}

// Each element's upper-body columns among the kept coordinates (position, ElementMap::column),
// which depend only on the geometry: a study's workers find them once per base (upper_columns).
struct KeptColumn {
  int position;
  Eigen::Vector3d column;
};
using UpperColumns = std::vector<std::vector<KeptColumn>>;  // per element

UpperColumns upper_columns(const Layout& layout, const std::vector<ElementMap>& maps, const std::vector<int>& keep) {
  UpperColumns columns(maps.size());
  for (size_t k = 0; k < maps.size(); ++k)
    for (int i = 0; i < static_cast<int>(keep.size()); ++i)
      if (layout.body_of(keep[i]) == maps[k].upper) columns[k].push_back({i, maps[k].column(layout, true, keep[i])});
  return columns;
}

// Where the track's displacement enters: the final stiffness of each track element
// (hangers included) and its damping, seen from the kept coordinates of its upper body.
// An element standing on a wheelset takes the rail's longitudinal and vertical displacement as
// a track element does (the wheelset's held motions follow the rail); the lateral displacement
// reaches it through the contact, which M, C and K do not hold, so that column stays zero.
// Into *inputs, its entries' storage reused where they have their sizes already (a study's
// worker assembles every variant of one base into the same system).
// `kept`, when given, is upper_columns(layout, maps, keep): the same columns, found once.
void fill_track_inputs(const Vehicle& vehicle, const Layout& layout, const std::vector<ElementMap>& maps,
                       const std::vector<double>& loads, const std::vector<int>& keep, std::vector<TrackInput>* inputs,
                       const UpperColumns* kept = nullptr) {
  const int n = static_cast<int>(keep.size());
  size_t count = 0;
  for (size_t k = 0; k < vehicle.elements.size(); ++k) {
    const Element& e = vehicle.elements[k];
    const bool wheelset = model::stands_on_wheelset(vehicle, e);
    if ((!e.lower.empty() && !wheelset) || pulls_only_along(e)) continue;
    const Eigen::Vector3d stiffness(series_stiffness(e.longitudinal_stages),
                                    wheelset ? 0.0 : model::lateral_stiffness(e, loads[k]),
                                    series_stiffness(e.vertical_stages));
    const Eigen::Vector3d damping(e.longitudinal_damping, wheelset ? 0.0 : e.lateral_damping, e.vertical_damping);
    if (inputs->size() <= count) inputs->emplace_back();
    TrackInput& input = (*inputs)[count++];
    input.element = static_cast<int>(k);
    input.point = e.point;
    input.load_per_displacement.setZero(n, 3);
    input.load_per_velocity.setZero(n, 3);
    if (kept) {
      for (const KeptColumn& c : (*kept)[k])
        for (int d = 0; d < 3; ++d) {
          input.load_per_displacement(c.position, d) = c.column(d) * stiffness(d);
          input.load_per_velocity(c.position, d) = c.column(d) * damping(d);
        }
      continue;
    }
    for (int i = 0; i < n; ++i) {
      if (layout.body_of(keep[i]) != maps[k].upper) continue;
      const Eigen::Vector3d column = maps[k].column(layout, true, keep[i]);
      for (int d = 0; d < 3; ++d) {
        input.load_per_displacement(i, d) = column(d) * stiffness(d);
        input.load_per_velocity(i, d) = column(d) * damping(d);
      }
    }
  }
  inputs->resize(count);
}

// The stretch of each series damper along its direction, per kept coordinate, from the same
// point maps as add_element; a damper whose stretch no kept motion changes (a lateral damper
// among the vertical motions) is left out.
std::vector<SeriesDamperRow> series_damper_rows(const Vehicle& vehicle, const Layout& layout,
                                                const std::vector<ElementMap>& maps, const std::vector<int>& keep) {
  const int n = static_cast<int>(keep.size());
  std::vector<SeriesDamperRow> rows;
  for (size_t k = 0; k < vehicle.elements.size(); ++k)
    for (const SeriesDamper& d : vehicle.elements[k].series_dampers) {
      const int axis = d.direction == Motion::longitudinal ? 0 : d.direction == Motion::lateral ? 1 : 2;
      SeriesDamperRow row;
      row.element = static_cast<int>(k);
      row.direction = d.direction;
      row.damping = d.damping;
      row.stiffness = d.stiffness;
      row.stretch = Eigen::RowVectorXd::Zero(n);
      for (int i = 0; i < n; ++i) {
        const int body = layout.body_of(keep[i]);
        if (body == maps[k].upper) row.stretch(i) += maps[k].column(layout, true, keep[i])(axis);
        if (body == maps[k].lower) row.stretch(i) -= maps[k].column(layout, false, keep[i])(axis);
      }
      if (!row.stretch.isZero(0.0)) rows.push_back(std::move(row));
    }
  return rows;
}

// The matrices in full coordinates, every static load known: K holds the springs, the
// hangers' lateral stiffness and the dead loads (K_gravity).
struct FullAssembly {
  Layout layout;
  std::vector<int> free;  // free_coordinates, found once for the statics and every set kept
  Eigen::VectorXd weights;    // generalised_weights
  Eigen::MatrixXd K_weights;  // weights_gravity_stiffness
  FullModel full;
  std::vector<double> loads;
  Eigen::MatrixXd K, K_gravity;
};

// Each element's dead-load stiffness per unit of its static load, on its upper body and (zero
// where it stands on the ground) its lower one: what a study's workers keep per base, since
// the points and bodies do not change with the springs' coefficients.
// With them, each hanger's lateral stiffness per unit stiffness: the entries of K that
// add_element(map, {0, 1, 0}) changes (row, column, value; its exact zeros left out).
struct DeadLoadPatterns {
  std::vector<model::BodyMatrix> upper, lower;
  struct HangerEntry {
    int element;
    Eigen::Index row, column;
    double value;
  };
  std::vector<HangerEntry> hangers;  // in element order
};

DeadLoadPatterns dead_load_patterns(const Vehicle& vehicle, const std::vector<ElementMap>& maps, int layout_size) {
  DeadLoadPatterns p;
  for (size_t k = 0; k < vehicle.elements.size(); ++k) {
    const Eigen::Vector3d unit(0.0, 0.0, 1.0);
    const Eigen::Vector3d& point = vehicle.elements[k].point;
    p.upper.push_back(model::dead_load_stiffness(vehicle.bodies[maps[k].upper], point, unit));
    p.lower.push_back(maps[k].lower >= 0 ? model::dead_load_stiffness(vehicle.bodies[maps[k].lower], point, -unit)
                                         : model::BodyMatrix::Zero());
    if (!vehicle.elements[k].hanger) continue;
    Eigen::MatrixXd per_unit = Eigen::MatrixXd::Zero(layout_size, layout_size);
    add_element(maps[k], {0.0, 1.0, 0.0}, &per_unit);
    for (Eigen::Index c = 0; c < per_unit.cols(); ++c)
      for (Eigen::Index r = 0; r < per_unit.rows(); ++r)
        if (per_unit(r, c) != 0.0) p.hangers.push_back({static_cast<int>(k), r, c, per_unit(r, c)});
  }
  return p;
}

// Where a set of kept coordinates (`keep`) meets what a study's workers add per variant, found
// once per base: the picked cells inside each body's rigid 6 × 6 block (its dead loads), and
// the picked cells of the hangers' per-unit entries, in DeadLoadPatterns::hangers' order.
struct PickedCells {
  struct Cell {
    int row, column;    // among the kept coordinates
    int motion_row, motion_column;  // in the body's block
  };
  std::vector<std::vector<Cell>> in_block;  // per body
  struct HangerCell {
    int row, column;
    size_t entry;  // in DeadLoadPatterns::hangers
  };
  std::vector<HangerCell> hangers;
};

PickedCells picked_cells(const Layout& layout, const DeadLoadPatterns& p, const std::vector<int>& keep) {
  PickedCells cells;
  cells.in_block.resize(static_cast<size_t>(layout.bodies));
  const int n = static_cast<int>(keep.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (keep[i] < layout.rigid() && keep[j] < layout.rigid() && layout.body_of(keep[i]) == layout.body_of(keep[j]))
        cells.in_block[static_cast<size_t>(layout.body_of(keep[i]))].push_back(
            {i, j, keep[i] % kMotionsPerBody, keep[j] % kMotionsPerBody});
  std::vector<int> position(static_cast<size_t>(layout.size()), -1);
  for (int i = 0; i < n; ++i) position[static_cast<size_t>(keep[i])] = i;
  for (size_t e = 0; e < p.hangers.size(); ++e) {
    const int row = position[static_cast<size_t>(p.hangers[e].row)];
    const int column = position[static_cast<size_t>(p.hangers[e].column)];
    if (row >= 0 && column >= 0) cells.hangers.push_back({row, column, e});
  }
  return cells;
}

// The rows and columns `keep` of a study's workers' K and K_gravity: K_springs plus each
// hanger's per-unit entries times its stiffness (k·(s·a·b) where add_element rounds (s·a·k)·b),
// and K_weights plus each element's load times its unit dead-load pattern (equal to
// gravity_stiffness's terms but for the sign of a zero), then K + K_gravity: study-base2's sums
// (round-off against assemble). Computed on the kept cells only, each entry the same sum in the
// same order as in the full N × N matrices the workers formed before, so the same bits without
// the full copies and sums.
void picked_stiffness(const FullAssembly& a, const DeadLoadPatterns& p, const std::vector<double>& hanger_stiffness,
                      const std::vector<int>& keep, const PickedCells& cells, Eigen::MatrixXd* K,
                      Eigen::MatrixXd* K_gravity) {
  pick_into(a.full.K_springs, keep, K);
  for (const PickedCells::HangerCell& h : cells.hangers)
    (*K)(h.row, h.column) += hanger_stiffness[static_cast<size_t>(p.hangers[h.entry].element)] * p.hangers[h.entry].value;
  pick_into(a.K_weights, keep, K_gravity);
  const std::vector<ElementMap>& maps = a.full.maps;
  for (size_t k = 0; k < maps.size(); ++k) {
    for (const PickedCells::Cell& c : cells.in_block[static_cast<size_t>(maps[k].upper)])
      (*K_gravity)(c.row, c.column) += a.loads[k] * p.upper[k](c.motion_row, c.motion_column);
    if (maps[k].lower >= 0)
      for (const PickedCells::Cell& c : cells.in_block[static_cast<size_t>(maps[k].lower)])
        (*K_gravity)(c.row, c.column) += a.loads[k] * p.lower[k](c.motion_row, c.motion_column);
  }
  *K += *K_gravity;
}

// What follows the springs and masses: the static loads, the hangers' lateral stiffness and the
// dead loads, from a.full (its K_springs summed).
void add_static_loads(const Vehicle& vehicle, FullAssembly* a) {
  a->loads = static_loads(vehicle, a->layout, a->free, a->full.maps, a->full.K_springs, a->weights);
  a->K = a->full.K_springs;
  for (size_t k = 0; k < vehicle.elements.size(); ++k) {
    const Element& e = vehicle.elements[k];
    if (e.hanger) add_element(a->full.maps[k], {0.0, model::lateral_stiffness(e, a->loads[k]), 0.0}, &a->K);
  }
  a->K_gravity = gravity_stiffness(vehicle, a->full.maps, a->loads, a->K_weights);
  a->K += a->K_gravity;
}

// The static loads of a study's workers (static_loads_on_sprung where it applies, otherwise
// static_loads, which decides with its message) and each hanger's lateral stiffness, once per
// hanger (a pure function of the element and its load), into *hanger_stiffness by element.
// K and K_gravity are then picked for each kept set by picked_stiffness.
void workers_static_loads(const Vehicle& vehicle, FullAssembly* a, const DeadLoadPatterns& p,
                          std::vector<double>* hanger_stiffness) {
  if (!static_loads_on_sprung(vehicle, a->layout, a->free, a->full.maps, a->full.K_springs, a->weights, &a->loads))
    a->loads = static_loads(vehicle, a->layout, a->free, a->full.maps, a->full.K_springs, a->weights);
  hanger_stiffness->assign(vehicle.elements.size(), 0.0);
  int hanger = -1;
  for (const DeadLoadPatterns::HangerEntry& h : p.hangers)
    if (h.element != hanger) {
      hanger = h.element;
      (*hanger_stiffness)[static_cast<size_t>(hanger)] = model::lateral_stiffness(vehicle.elements[h.element], a->loads[h.element]);
    }
}

FullAssembly assemble_full(const Vehicle& vehicle, bool damping) {
  std::map<std::string, int> index;
  check_vehicle(vehicle, &index);
  FullAssembly a{Layout(vehicle), {}, {}, {}, {}, {}, {}, {}};
  a.free = free_coordinates(vehicle, a.layout);
  a.weights = generalised_weights(vehicle, a.layout);
  a.K_weights = weights_gravity_stiffness(vehicle, a.layout);
  a.full = springs_and_masses(vehicle, index, a.layout, damping);
  add_static_loads(vehicle, &a);
  return a;
}

}  // namespace

namespace {

// `owned`, when given, is `vehicle` itself, which the caller gives up: it is moved into the
// system last (nothing reads it after), saving the copy of every body and element name.
LinearSystem system_of(const Vehicle& vehicle, const FullAssembly& a, DofSet set, Vehicle* owned = nullptr) {
  LinearSystem system;
  const std::vector<int> keep = kept_coordinates(vehicle, a.layout, a.free, set, &system.dofs);
  system.mass = pick(a.full.M, keep);
  system.damping = pick(a.full.C, keep);
  system.stiffness = pick(a.K, keep);
  system.gravity_stiffness = pick(a.K_gravity, keep);
  system.element_loads = a.loads;
  system.element_vertical_map = element_vertical_map(a.layout, a.full.maps, keep);
  fill_track_inputs(vehicle, a.layout, a.full.maps, a.loads, keep, &system.track_inputs);
  system.series_dampers = series_damper_rows(vehicle, a.layout, a.full.maps, keep);
  if (owned)
    system.vehicle = std::move(*owned);
  else
    system.vehicle = vehicle;
  return system;
}

LinearSystem stiffness_of(const Vehicle& vehicle, const FullAssembly& a, DofSet set) {
  LinearSystem system;
  const std::vector<int> keep = kept_coordinates(vehicle, a.layout, a.free, set, &system.dofs);
  system.stiffness = pick(a.K, keep);
  system.gravity_stiffness = pick(a.K_gravity, keep);
  return system;
}

}  // namespace

LinearSystem assemble(const Vehicle& vehicle, DofSet set) { return system_of(vehicle, assemble_full(vehicle, true), set); }

LinearSystem model::assemble_stiffness(const Vehicle& vehicle, DofSet set) {
  return stiffness_of(vehicle, assemble_full(vehicle, false), set);
}

std::vector<double> model::element_static_loads(const Vehicle& vehicle) {
  return assemble_full(vehicle, false).loads;
}

model::SystemAndStiffness model::assemble_with_stiffness(const Vehicle& vehicle, DofSet set, DofSet stiffness_set) {
  const FullAssembly a = assemble_full(vehicle, true);
  return {system_of(vehicle, a, set), stiffness_of(vehicle, a, stiffness_set)};
}

namespace {

// The geometry a VariantAssembly keeps, compared bit for bit (a -0.0 for a 0.0 is another
// vehicle: its products may carry the sign).
bool bitwise_equal(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool bitwise_equal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return bitwise_equal(a.x(), b.x()) && bitwise_equal(a.y(), b.y()) && bitwise_equal(a.z(), b.z());
}
bool bitwise_equal(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || bitwise_equal(*a, *b));
}

bool same_bending(const std::optional<BodyBending>& a, const std::optional<BodyBending>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  if (!bitwise_equal(a->length, b->length) || !bitwise_equal(a->centre, b->centre) ||
      !bitwise_equal(a->damping_ratio, b->damping_ratio))
    return false;
  if (a->beam.has_value() != b->beam.has_value() || a->mode.has_value() != b->mode.has_value()) return false;
  if (a->beam && (!bitwise_equal(a->beam->bending_stiffness, b->beam->bending_stiffness) ||
                  !bitwise_equal(a->beam->mass_per_length, b->beam->mass_per_length)))
    return false;
  return !a->mode || (bitwise_equal(a->mode->frequency, b->mode->frequency) &&
                      bitwise_equal(a->mode->modal_mass, b->mode->modal_mass));
}

bool same_stage_shape(const std::vector<SpringStage>& a, const std::vector<SpringStage>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].count != b[i].count) return false;
  return true;
}

// Whether `v` differs from `kept` at most in what add_stiffnesses, add_dampings, the static
// loads and the track inputs read afresh: its spring stages' stiffnesses, rotational
// stiffnesses and viscous dampings (and what the assembly does not read: names of stages, friction, curves, the
// wheel–rail contact). Everything the kept checks, coordinates, point maps, M and DOF labels
// were made from is compared. A field added to Body, Element or Vehicle that the assembly
// reads must be compared here (test VariantAssembly.ComparesEveryFieldTheAssemblyReads).
bool same_but_coefficients(const Vehicle& kept, const Vehicle& v) {
  if (!bitwise_equal(kept.gravity, v.gravity) || kept.bodies.size() != v.bodies.size() ||
      kept.elements.size() != v.elements.size() || kept.wheelsets.size() != v.wheelsets.size())
    return false;
  for (size_t b = 0; b < v.bodies.size(); ++b) {
    const Body &x = kept.bodies[b], &y = v.bodies[b];
    if (x.name != y.name || !bitwise_equal(x.mass, y.mass) || !bitwise_equal(x.inertia, y.inertia) ||
        !bitwise_equal(x.centre_of_gravity, y.centre_of_gravity) ||
        !bitwise_equal(x.reference_point, y.reference_point) || x.held != y.held ||
        x.longitudinal_free != y.longitudinal_free || !same_bending(x.bending, y.bending) ||
        // Not read by the assembly, but by the ride's default floor points, which a study's
        // worker takes from the kept system's vehicle.
        !bitwise_equal(x.floor_height, y.floor_height))
      return false;
  }
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element &x = kept.elements[k], &y = v.elements[k];
    if (x.name != y.name || x.lower != y.lower || x.upper != y.upper || !bitwise_equal(x.point, y.point) ||
        !same_stage_shape(x.vertical_stages, y.vertical_stages) ||
        !same_stage_shape(x.lateral_stages, y.lateral_stages) ||
        !same_stage_shape(x.longitudinal_stages, y.longitudinal_stages) ||
        x.hanger.has_value() != y.hanger.has_value() || x.series_dampers.size() != y.series_dampers.size())
      return false;
    if (x.hanger && (!bitwise_equal(x.hanger->length, y.hanger->length) ||
                     !bitwise_equal(x.hanger->inclination, y.hanger->inclination)))
      return false;
    for (size_t d = 0; d < x.series_dampers.size(); ++d) {
      const SeriesDamper &p = x.series_dampers[d], &q = y.series_dampers[d];
      if (p.direction != q.direction || !bitwise_equal(p.damping, q.damping) ||
          !bitwise_equal(p.stiffness, q.stiffness))
        return false;
    }
  }
  for (size_t w = 0; w < v.wheelsets.size(); ++w)
    if (kept.wheelsets[w].body != v.wheelsets[w].body ||
        !bitwise_equal(kept.wheelsets[w].spin_inertia, v.wheelsets[w].spin_inertia))
      return false;
  return true;
}

// check_vehicle's checks of the coefficients same_but_coefficients lets differ: a vehicle that
// fails one is assembled in full, which throws check_vehicle's message.
bool coefficients_valid(const Vehicle& v) {
  for (const Element& e : v.elements)
    if (coefficient_error(e)) return false;
  return true;
}

// The coefficients add_dampings reads (with the bending modes', part of the kept geometry).
std::vector<double> dampings_of(const Vehicle& v) {
  std::vector<double> d;
  d.reserve(3 * v.elements.size());
  for (const Element& e : v.elements)
    d.insert(d.end(), {e.longitudinal_damping, e.lateral_damping, e.vertical_damping});
  return d;
}

bool same_dampings(const std::vector<double>& damped, const Vehicle& v) {
  for (size_t k = 0; k < v.elements.size(); ++k) {
    const Element& e = v.elements[k];
    if (!bitwise_equal(damped[3 * k], e.longitudinal_damping) || !bitwise_equal(damped[3 * k + 1], e.lateral_damping) ||
        !bitwise_equal(damped[3 * k + 2], e.vertical_damping))
      return false;
  }
  return true;
}

}  // namespace

struct model::VariantAssembly::Base {
  Vehicle kept;                // the geometry the rest was made from (its coefficients are not read)
  std::vector<double> damped;  // the viscous dampings C was summed from (dampings_of)
  FullAssembly a;              // layout, free coordinates, point maps and M kept; the rest each variant's
                               // (its full K and K_gravity, the first vehicle's by assemble, are not
                               // read: each variant's are picked_stiffness's)
  DofSet set, stiffness_set;
  std::vector<int> keep, stiffness_keep;
  std::vector<Dof> dofs, stiffness_dofs;
  Eigen::MatrixXd mass, element_vertical_map;  // picked for `set`
  DeadLoadPatterns dead_loads;                 // dead_load_patterns
  PickedCells cells, stiffness_cells;          // picked_cells of keep and stiffness_keep
  UpperColumns track_columns;                  // upper_columns of keep
  std::vector<std::pair<int, int>> joined;     // joined_blocks of the point maps
  std::vector<double> hanger_stiffness;        // each variant's, by element (workers_static_loads)
};

model::VariantAssembly::VariantAssembly() = default;
model::VariantAssembly::~VariantAssembly() = default;

void model::VariantAssembly::assemble(Vehicle&& vehicle, DofSet set, DofSet stiffness_set, LinearSystem* system,
                                      LinearSystem* stiffness) {
  reused_ = base_ && base_->set == set && base_->stiffness_set == stiffness_set &&
            same_but_coefficients(base_->kept, vehicle) && coefficients_valid(vehicle);
  if (reused_) {
    add_stiffnesses(vehicle, base_->a.layout, &base_->a.full, &base_->joined);
    if (!same_dampings(base_->damped, vehicle)) {
      add_dampings(vehicle, base_->a.layout, &base_->a.full);
      base_->damped = dampings_of(vehicle);
    }
    workers_static_loads(vehicle, &base_->a, base_->dead_loads, &base_->hanger_stiffness);
  } else {
    FullAssembly a = assemble_full(vehicle, true);  // throws before anything is kept
    auto fresh = std::unique_ptr<Base>(
        new Base{vehicle, dampings_of(vehicle), std::move(a), set, stiffness_set, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}});
    const FullAssembly& f = fresh->a;
    fresh->keep = kept_coordinates(vehicle, f.layout, f.free, set, &fresh->dofs);
    fresh->stiffness_keep = kept_coordinates(vehicle, f.layout, f.free, stiffness_set, &fresh->stiffness_dofs);
    pick_into(f.full.M, fresh->keep, &fresh->mass);
    fresh->element_vertical_map = element_vertical_map(f.layout, f.full.maps, fresh->keep);
    fresh->dead_loads = dead_load_patterns(vehicle, f.full.maps, f.layout.size());
    fresh->cells = picked_cells(f.layout, fresh->dead_loads, fresh->keep);
    fresh->stiffness_cells = picked_cells(f.layout, fresh->dead_loads, fresh->stiffness_keep);
    fresh->track_columns = upper_columns(f.layout, f.full.maps, fresh->keep);
    fresh->joined = joined_blocks(f.full.maps);
    // The base's static loads found again as every later variant's are (the results do not
    // depend on which variant a worker took first, hence not on the thread count).
    workers_static_loads(vehicle, &fresh->a, fresh->dead_loads, &fresh->hanger_stiffness);
    base_ = std::move(fresh);
  }
  const Base& b = *base_;
  const FullAssembly& a = b.a;
  stiffness->dofs = b.stiffness_dofs;
  picked_stiffness(a, b.dead_loads, b.hanger_stiffness, b.stiffness_keep, b.stiffness_cells, &stiffness->stiffness,
                   &stiffness->gravity_stiffness);
  system->dofs = b.dofs;
  system->mass = b.mass;
  pick_into(a.full.C, b.keep, &system->damping);
  picked_stiffness(a, b.dead_loads, b.hanger_stiffness, b.keep, b.cells, &system->stiffness,
                   &system->gravity_stiffness);
  system->element_loads = a.loads;
  system->element_vertical_map = b.element_vertical_map;
  fill_track_inputs(vehicle, a.layout, a.full.maps, a.loads, b.keep, &system->track_inputs, &b.track_columns);
  system->series_dampers = series_damper_rows(vehicle, a.layout, a.full.maps, b.keep);
  system->vehicle = std::move(vehicle);
}

model::SystemAndStiffness model::assemble_with_stiffness(Vehicle&& vehicle, DofSet set, DofSet stiffness_set) {
  const FullAssembly a = assemble_full(vehicle, true);
  SystemAndStiffness both;
  both.stiffness = stiffness_of(vehicle, a, stiffness_set);  // before the vehicle moves into the system
  both.system = system_of(vehicle, a, set, &vehicle);
  return both;
}

}  // namespace railmodal
