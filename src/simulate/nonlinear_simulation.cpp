// The nonlinear path: leaf-spring friction with sticking, and progressive springs, on top of
// the linear model, integrated between located events by Dormand–Prince 5(4).
//
// Between events every element keeps its regime (sliding down, sliding up, stuck; the segment
// of a progressive curve), so the equations of motion are smooth and the adaptive Runge–Kutta
// error control holds; at an event the step is cut exactly there (to event_tolerance) and the
// regime changes. Friction follows the book's law R = c(1 ± φ)(f ± z) (springs digest §2.3,
// eqs. (40)–(59)): a force φ·R_el against the sliding, R_el the element's current elastic
// reaction; a stuck element is a constraint whose holding force must stay within ±φ·R_el, so
// a free decay stops in the dead band −φf/(1 + φ) ≤ z ≤ φf/(1 − φ). A leaf in series with
// elastic stages is not a constraint: it carries its own deflection s as a state of the model,
// held while stuck and following the pair's compression while sliding (nonlinear_elements.cpp).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/analysis_limits.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/simulation.hpp"
#include "require_valid.hpp"
#include "shortest_text.hpp"
#include "simulate/dormand_prince.hpp"
#include "simulate/history_summary.hpp"
#include "simulate/nonlinear_elements.hpp"
#include "simulate/sampled_track.hpp"
#include "simulate/sample_count.hpp"
#include "summary/stage_clock.hpp"

namespace railmodal {

const char* to_string(SimulationEvent::Kind kind) {
  switch (kind) {
    case SimulationEvent::Kind::stick: return "stick";
    case SimulationEvent::Kind::slip: return "slip";
    case SimulationEvent::Kind::reversal: return "reversal";
    case SimulationEvent::Kind::kink: return "kink";
  }
  return "?";
}

std::optional<SimulationEvent::Kind> simulation_event_kind_from_string(const std::string& word) {
  using Kind = SimulationEvent::Kind;
  for (Kind k : {Kind::stick, Kind::slip, Kind::reversal, Kind::kink})
    if (word == to_string(k)) return k;
  return std::nullopt;
}

namespace {

using simulate::NonlinearElement;
constexpr double kTwoPi = 6.28318530717958647692;

SimulationEvent event(double t, int element, SimulationEvent::Kind kind) {
  SimulationEvent e;
  e.time = t;
  e.element = element;
  e.kind = kind;
  return e;
}

// One harmonic of one source: Q(t) = Re(Q(ω(t))·e^{iκx(t)}), ω = κV(t) (at constant speed
// κx = ωt and Q is fixed). Under a ramp Q(ω) = s(ω)(Q_K + iωQ_C): exact for every source (the
// phases between wheels do not depend on the speed; excitation.hpp, SeparableLoad).
struct Harmonic {
  Eigen::VectorXcd load;       ///< Q at the initial speed
  double wavenumber = 0.0;     ///< κ, rad/m
  SeparableLoad parts;         ///< for a ramp
  const ExcitationSource* source = nullptr;
};

// What an event function watches.
struct Slot {
  enum class Kind { sliding, stuck, kink } kind;
  int element;      // index into the model's elements
  double kink = 0;  // deflection of the kink (kink slots)
};

class Model {
 public:
  Model(const LinearSystem& s, std::vector<Harmonic> harmonics, std::vector<NonlinearElement> elements,
        const simulate::SpeedProfile& profile)
      : n_(s.size()),
        M_(s.mass),
        C_(s.damping),
        K_(s.stiffness),
        profile_(profile),
        harmonics_(std::move(harmonics)),
        elements_(std::move(elements)),
        state_(elements_.size(), 0),
        leaf_(elements_.size(), 0.0) {
    const Eigen::LLT<Eigen::MatrixXd> llt(M_);
    if (llt.info() != Eigen::Success) throw NumericalError("the mass matrix is not positive definite");
    Minv_ = llt.solve(Eigen::MatrixXd::Identity(n_, n_));
    for (size_t i = 0; i < elements_.size(); ++i)
      if (elements_[i].friction > 0.0) state_[i] = 1;  // sliding until the first resolve says otherwise
    set_stuck();
  }

  int size() const { return n_; }
  const std::vector<NonlinearElement>& elements() const { return elements_; }
  int state(int i) const { return state_[i]; }

  // A sampled track (simulate_nonlinear_sampled): its loads Bd·w + Bv·ẇ join the forces and
  // each element standing on it follows its track input's vertical motion.
  void use_sampled_track(const LinearSystem& s, const simulate::SampledTrack* track) {
    sampled_ = track;
    const Eigen::Index m = 3 * static_cast<Eigen::Index>(s.track_inputs.size());
    Bd_ = Eigen::MatrixXd::Zero(n_, m);
    Bv_ = Eigen::MatrixXd::Zero(n_, m);
    for (size_t i = 0; i < s.track_inputs.size(); ++i) {
      Bd_.middleCols(3 * static_cast<Eigen::Index>(i), 3) = s.track_inputs[i].load_per_displacement;
      Bv_.middleCols(3 * static_cast<Eigen::Index>(i), 3) = s.track_inputs[i].load_per_velocity;
    }
    track_input_.assign(elements_.size(), -1);
    for (size_t e = 0; e < elements_.size(); ++e)
      for (size_t i = 0; i < s.track_inputs.size(); ++i)
        if (s.track_inputs[i].element == elements_[e].element) track_input_[e] = static_cast<int>(i);
  }
  // The time whose smooth piece of the sampled track the next evaluations use.
  void set_piece(double piece) const { piece_ = piece; }

  // Track displacement, velocity and acceleration under element i.
  void track_motion(int i, double t, double* u, double* du, double* ddu) const {
    if (!sampled_ || track_input_[i] < 0) {
      elements_[i].track_motion(t, u, du, ddu);
      return;
    }
    sampled_->motion(t, piece_, &w_, &dw_, &ddw_);
    const Eigen::Index k = 3 * track_input_[i] + 2;
    *u = w_(k), *du = dw_(k), *ddu = ddw_(k);
  }

  // A breakpoint of the sampled track at t: a leaf standing on the track whose velocity jumps
  // there slides the way the jump drives it (a stuck one slips: its upper end keeps its
  // velocity, as no finite force changes it at once; a sliding one turns if it must).
  std::vector<SimulationEvent> cross_break(double t, const Eigen::VectorXd& y, double before, double after) {
    std::vector<SimulationEvent> events;
    const auto v = y.tail(n_);
    for (size_t e = 0; e < elements_.size(); ++e) {
      const int i = static_cast<int>(e);
      if (!(elements_[e].friction > 0.0) || elements_[e].in_series() || track_input_[e] < 0) continue;
      double u, du_before, du_after, ddu;
      set_piece(before);
      track_motion(i, t, &u, &du_before, &ddu);
      set_piece(after);
      track_motion(i, t, &u, &du_after, &ddu);
      if (du_after == du_before) continue;  // no kink under this wheel here
      const double rate = compression_rate(i, t, v);
      const int direction = rate > 0.0 ? 1 : rate < 0.0 ? -1 : 0;
      if (direction == 0 || direction == state_[e]) continue;
      events.push_back(event(t, elements_[e].element,
                             state_[e] == 0 ? SimulationEvent::Kind::slip : SimulationEvent::Kind::reversal));
      state_[e] = direction;
    }
    set_stuck();
    return events;
  }

  double compression(int i, double t, const Eigen::VectorXd& x) const {
    double u, du, ddu;
    track_motion(i, t, &u, &du, &ddu);
    return -(elements_[i].stretch.dot(x) - u);
  }
  double compression_rate(int i, double t, const Eigen::VectorXd& v) const {
    double u, du, ddu;
    track_motion(i, t, &u, &du, &ddu);
    return -(elements_[i].stretch.dot(v) - du);
  }
  // φ·R_el, the friction force a sliding element feels and a stuck one can hold.
  double friction_limit(int i, double t, const Eigen::VectorXd& x) const {
    return elements_[i].friction_force(elements_[i].reaction(compression(i, t, x)));
  }
  // A series element's leaf deflection: held while stuck, on its sliding edge otherwise.
  double leaf_deflection(int i, double delta) const {
    return state_[i] == 0 ? leaf_[i] : elements_[i].sliding_leaf_deflection(delta, state_[i]);
  }
  // A stuck series element: how far the force through it is from the edges of its band.
  double band_margin(int i, double t, const Eigen::VectorXd& x) const {
    const NonlinearElement& e = elements_[i];
    const double reaction = e.leaf_reaction(leaf_[i]);
    return e.friction_force(reaction) - std::abs(e.series_force(compression(i, t, x), leaf_[i]) - reaction);
  }

  // Every generalised force but the holding forces of stuck elements.
  void force(double t, const Eigen::VectorXd& x, const Eigen::VectorXd& v, Eigen::VectorXd* f) const {
    f->noalias() = -K_ * x - C_ * v;
    const double x_track = profile_.distance(t), speed = profile_.speed(t);
    for (const Harmonic& h : harmonics_) {
      const std::complex<double> phase = std::exp(std::complex<double>(0.0, h.wavenumber * x_track));
      if (profile_.acceleration == 0.0) {
        *f += (h.load * phase).real();
      } else {
        const double w = h.wavenumber * speed;
        const double scale = h.source->load_scale(w, h.parts.reference_omega);
        *f += (scale * (h.parts.stiffness_part + std::complex<double>(0.0, w) * h.parts.damping_part) * phase).real();
      }
    }
    if (sampled_) {
      sampled_->motion(t, piece_, &w_, &dw_, &ddw_);
      f->noalias() += Bd_ * w_ + Bv_ * dw_;
    }
    for (size_t i = 0; i < elements_.size(); ++i) {
      const NonlinearElement& e = elements_[i];
      const double delta = compression(static_cast<int>(i), t, x);
      const double reaction = e.reaction(delta);
      double up = 0.0;  // force on the upper end, up positive, beyond the linear model
      if (e.curve) up += reaction - e.static_load - e.tangent * delta;
      if (e.in_series())
        up += e.series_force(delta, leaf_deflection(static_cast<int>(i), delta)) - e.static_load - e.tangent * delta;
      else if (e.friction > 0.0 && state_[i] != 0)
        up += e.friction_force(reaction) * state_[i];
      if (up != 0.0) f->noalias() += e.stretch.transpose() * up;
    }
  }

  // Holding forces of the elements in `set` (up positive on the upper end) that keep their
  // relative acceleration equal to the track's; minimum norm when constraints repeat (left and
  // right springs of a wagon seen in bounce and pitch only).
  Eigen::VectorXd holding(const std::vector<int>& set, double t, const Eigen::VectorXd& f) const {
    if (set.empty()) return {};
    const Eigen::Index k = static_cast<Eigen::Index>(set.size());
    Eigen::MatrixXd G(k, n_);
    Eigen::VectorXd target(k);
    for (Eigen::Index r = 0; r < k; ++r) {
      G.row(r) = elements_[set[r]].stretch;
      double u, du, ddu;
      track_motion(set[r], t, &u, &du, &ddu);
      target(r) = ddu;
    }
    const Eigen::MatrixXd MinvGt = Minv_ * G.transpose();
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> W(G * MinvGt);
    return W.solve(target - G * (Minv_ * f));
  }

  void rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd* dy) const {
    const auto x = y.head(n_), v = y.tail(n_);
    Eigen::VectorXd f(n_);
    force(t, x, v, &f);
    dy->head(n_) = v;
    if (stuck_.empty()) {
      dy->tail(n_).noalias() = Minv_ * f;
      return;
    }
    Eigen::VectorXd target(stuck_.size());
    for (size_t r = 0; r < stuck_.size(); ++r) {
      double u, du, ddu;
      track_motion(stuck_[r], t, &u, &du, &ddu);
      target(r) = ddu;
    }
    const Eigen::VectorXd lambda = W_.solve(target - G_ * (Minv_ * f));
    dy->tail(n_).noalias() = Minv_ * (f + G_.transpose() * lambda);
  }

  // The event functions of the current regime, in a fixed order for a regime.
  std::vector<Slot> slots() const {
    std::vector<Slot> out;
    for (size_t i = 0; i < elements_.size(); ++i) {
      const int e = static_cast<int>(i);
      if (elements_[i].friction > 0.0) out.push_back({state_[i] == 0 ? Slot::Kind::stuck : Slot::Kind::sliding, e, 0.0});
      if (elements_[i].curve)
        for (size_t p = 1; p + 1 < elements_[i].curve->deflection.size(); ++p)
          out.push_back({Slot::Kind::kink, e, elements_[i].curve->deflection[p]});
    }
    return out;
  }

  std::vector<double> slot_values(const std::vector<Slot>& slots, double t, const Eigen::VectorXd& y) const {
    const auto x = y.head(n_), v = y.tail(n_);
    std::vector<double> out(slots.size());
    Eigen::VectorXd lambda;
    bool have_lambda = false;
    for (size_t s = 0; s < slots.size(); ++s) {
      const int i = slots[s].element;
      switch (slots[s].kind) {
        case Slot::Kind::sliding: out[s] = state_[i] * compression_rate(i, t, v); break;
        case Slot::Kind::kink: out[s] = elements_[i].static_deflection + compression(i, t, x) - slots[s].kink; break;
        case Slot::Kind::stuck: {
          if (elements_[i].in_series()) {
            out[s] = band_margin(i, t, x);
            break;
          }
          if (!have_lambda) {
            Eigen::VectorXd f(n_);
            force(t, x, v, &f);
            lambda = holding(stuck_, t, f);
            have_lambda = true;
          }
          const auto at = std::find(stuck_.begin(), stuck_.end(), i) - stuck_.begin();
          out[s] = friction_limit(i, t, x) - std::abs(lambda(at));
          break;
        }
      }
    }
    return out;
  }

  // Decides which friction elements stick at time t: `candidates` (the stuck ones and those
  // whose sliding just stopped) stay stuck unless their holding force leaves ±φR_el; the worst
  // offender slides first, in the direction of its holding force, and the rest are re-checked.
  // `releasing` are stuck elements whose holding force has just reached ±φR_el: at the located
  // zero the ratio is 1 to rounding, so they are told to slide rather than tested (testing
  // would keep them stuck and the same zero would fire again forever).
  // Stuck elements get exactly zero relative velocity. Returns the events.
  std::vector<SimulationEvent> resolve(double t, Eigen::VectorXd* y, std::vector<int> candidates,
                                       const std::vector<int>& releasing = {}) {
    std::vector<SimulationEvent> events;
    for (int i : candidates)
      if (elements_[i].in_series()) events.push_back(settle_series(i, t, y->head(n_), releasing));
    candidates.erase(
        std::remove_if(candidates.begin(), candidates.end(), [this](int i) { return elements_[i].in_series(); }),
        candidates.end());
    for (size_t i = 0; i < elements_.size(); ++i)
      if (elements_[i].friction > 0.0 && !elements_[i].in_series() && state_[i] == 0 &&
          std::find(candidates.begin(), candidates.end(), static_cast<int>(i)) == candidates.end())
        candidates.push_back(static_cast<int>(i));
    std::sort(candidates.begin(), candidates.end());
    const auto x = y->head(n_), v = y->tail(n_);
    const std::vector<int> before = state_;
    std::vector<int> set = candidates;
    // The forces with the candidates' own friction taken out (they are held, not sliding).
    for (int i : set) state_[i] = 0;
    bool first_pass = true;
    while (!set.empty()) {
      Eigen::VectorXd f(n_);
      force(t, x, v, &f);
      const Eigen::VectorXd lambda = holding(set, t, f);
      if (first_pass && !releasing.empty()) {
        first_pass = false;
        std::vector<int> kept;
        for (size_t r = 0; r < set.size(); ++r) {
          if (std::find(releasing.begin(), releasing.end(), set[r]) == releasing.end()) kept.push_back(set[r]);
          else state_[set[r]] = lambda(static_cast<Eigen::Index>(r)) > 0.0 ? 1 : -1;
        }
        set = kept;
        continue;
      }
      int worst = -1;
      double worst_ratio = 1.0 + 1e-9;
      for (size_t r = 0; r < set.size(); ++r) {
        const double limit = friction_limit(set[r], t, x);
        const double ratio = limit > 0.0 ? std::abs(lambda(r)) / limit : (lambda(r) != 0.0 ? INFINITY : 0.0);
        if (ratio > worst_ratio) worst_ratio = ratio, worst = static_cast<int>(r);
      }
      if (worst < 0) break;
      state_[set[worst]] = lambda(worst) > 0.0 ? 1 : -1;  // slides the way its holding force pushed
      set.erase(set.begin() + worst);
    }
    set_stuck();
    if (!stuck_.empty()) {  // exactly zero relative velocity for the stuck ones
      Eigen::VectorXd mismatch(stuck_.size());
      for (size_t r = 0; r < stuck_.size(); ++r) {
        double u, du, ddu;
        track_motion(stuck_[r], t, &u, &du, &ddu);
        mismatch(r) = G_.row(r).dot(v) - du;
      }
      y->tail(n_) -= Minv_ * G_.transpose() * W_.solve(mismatch);
    }
    for (int i : candidates) {
      const int element = elements_[i].element;
      if (state_[i] == 0 && before[i] != 0) events.push_back(event(t, element, SimulationEvent::Kind::stick));
      else if (state_[i] != 0 && before[i] == 0) events.push_back(event(t, element, SimulationEvent::Kind::slip));
      else if (state_[i] != 0 && before[i] != 0) events.push_back(event(t, element, SimulationEvent::Kind::reversal));
    }
    return events;
  }

  // At t = 0 a leaf in series with springs starts at its frictionless share of the pair's
  // deflection. A pair released from an initial condition (its stretch or rate from
  // [[simulation.initial]] beyond `tolerance`) starts on the edge of its friction band toward
  // which it moves: its compression rate, or from rest the acceleration the springs give it.
  // This is the book's initial condition (the leaf slides from the release, (192e) in
  // (196a)–(200)). Any other pair (a car standing in equilibrium, also while the track moves
  // under it) starts stuck in the middle of its band, as a single leaf at rest does.
  std::vector<SimulationEvent> place_series_leaves(const Eigen::VectorXd& y, double tolerance) {
    const auto x = y.head(n_), v = y.tail(n_);
    const std::vector<int> before = state_;
    for (size_t i = 0; i < elements_.size(); ++i) {
      state_[i] = 0;  // no friction force while the acceleration is taken
      if (elements_[i].in_series()) leaf_[i] = elements_[i].sliding_leaf_deflection(compression(i, 0.0, x), 0);
    }
    Eigen::VectorXd f(n_);
    force(0.0, x, v, &f);
    const Eigen::VectorXd a = Minv_ * f;
    std::vector<SimulationEvent> events;
    for (size_t i = 0; i < elements_.size(); ++i) {
      state_[i] = before[i];
      if (!elements_[i].in_series()) continue;
      double u, du, ddu;
      track_motion(static_cast<int>(i), 0.0, &u, &du, &ddu);
      const double rate = compression_rate(static_cast<int>(i), 0.0, v),
                   acceleration = -elements_[i].stretch.dot(a) + ddu;
      const bool released =
          std::abs(elements_[i].stretch.dot(x)) > tolerance || std::abs(elements_[i].stretch.dot(v)) > tolerance;
      const double toward = !released ? 0.0 : std::abs(rate) > tolerance ? rate : acceleration;
      state_[i] = toward > 0.0 ? 1 : toward < 0.0 ? -1 : 0;
      if (state_[i] == 0) events.push_back(event(0.0, elements_[i].element, SimulationEvent::Kind::stick));
    }
    return events;
  }

 private:
  // A series element at an event: a stuck one whose force reached an edge of its band slides
  // toward that edge; a sliding one whose compression rate reached 0 holds its deflection
  // there if its band is open (it carries load), and otherwise turns.
  // (Its candidates come from its own fired slot: stuck ones are releasing.)
  SimulationEvent settle_series(int i, double t, const Eigen::VectorXd& x, const std::vector<int>& releasing) {
    const NonlinearElement& e = elements_[i];
    const double delta = compression(i, t, x);
    if (state_[i] == 0) {
      if (std::find(releasing.begin(), releasing.end(), i) == releasing.end())
        throw std::logic_error("a stuck series element was resolved without reaching an edge of its band");
      state_[i] = e.series_force(delta, leaf_[i]) > e.leaf_reaction(leaf_[i]) ? 1 : -1;
      return event(t, e.element, SimulationEvent::Kind::slip);
    }
    // A band narrower than the rounding of the forces it lies between cannot be told from a
    // closed one (nor its edges located): such a leaf turns as if frictionless.
    constexpr double kResolvableBand = 1e-12;
    const double s = e.sliding_leaf_deflection(delta, state_[i]);
    if (e.friction_force(e.leaf_reaction(s)) > kResolvableBand * std::abs(e.static_load)) {
      leaf_[i] = s;
      state_[i] = 0;
      return event(t, e.element, SimulationEvent::Kind::stick);
    }
    state_[i] = -state_[i];
    return event(t, e.element, SimulationEvent::Kind::reversal);
  }

  void set_stuck() {
    stuck_.clear();
    for (size_t i = 0; i < elements_.size(); ++i)
      if (elements_[i].friction > 0.0 && !elements_[i].in_series() && state_[i] == 0)
        stuck_.push_back(static_cast<int>(i));
    G_.resize(static_cast<Eigen::Index>(stuck_.size()), n_);
    for (size_t r = 0; r < stuck_.size(); ++r) G_.row(r) = elements_[stuck_[r]].stretch;
    if (!stuck_.empty()) W_.compute(G_ * Minv_ * G_.transpose());
  }

  int n_;
  Eigen::MatrixXd M_, C_, K_, Minv_;
  simulate::SpeedProfile profile_;
  std::vector<Harmonic> harmonics_;
  std::vector<NonlinearElement> elements_;
  std::vector<int> state_;  // friction elements: +1 sliding into compression, −1 out of it, 0 stuck
  std::vector<double> leaf_;  // series elements: the leaf's deflection s while stuck, m
  std::vector<int> stuck_;
  Eigen::MatrixXd G_;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> W_;
  const simulate::SampledTrack* sampled_ = nullptr;  // none: the harmonics are the track
  Eigen::MatrixXd Bd_, Bv_;                          // the sampled track's loads, n × 3·inputs
  std::vector<int> track_input_;                     // per element: its track input, or −1
  mutable double piece_ = 0.0;
  mutable Eigen::VectorXd w_, dw_, ddw_;
};

double error_norm(const Eigen::VectorXd& error, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double tol) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < error.size(); ++i)
    worst = std::max(worst, std::abs(error(i)) / (tol + tol * std::max(std::abs(y0(i)), std::abs(y1(i)))));
  return worst;
}

// The harmonics of every source at the initial speed, and the loads the nonlinear elements
// read their track inputs from (one per harmonic, also where the load is zero).
struct SourceHarmonics {
  std::vector<HarmonicLoad> loads;
  std::vector<const ExcitationSource*> load_sources;
  std::vector<Harmonic> harmonics;  // only those with a load
};

SourceHarmonics source_harmonics(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                                 double speed, const simulate::SpeedProfile& profile) {
  SourceHarmonics out;
  for (const ExcitationSource* source : sources)
    for (int k = 1; k <= source->harmonic_count(); ++k) {
      out.loads.push_back(source->load(system, speed, k));
      out.load_sources.push_back(source);
      const Eigen::VectorXcd Q = generalized_load(system, out.loads.back());
      if (Q.norm() == 0.0) continue;
      Harmonic h;
      h.load = Q;
      h.wavenumber = kTwoPi * out.loads.back().frequency_hz / speed;
      h.source = source;
      if (profile.acceleration != 0.0) h.parts = source->separable_load(system, k);
      out.harmonics.push_back(std::move(h));
    }
  return out;
}

// y = (x, v) at t = 0 from the initial conditions.
Eigen::VectorXd initial_state(const LinearSystem& system, const SimulationOptions& options) {
  const int n = system.size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * n);
  for (const auto& ic : options.initial) {
    const int d = system.index_of(ic.dof);
    if (d < 0) throw std::invalid_argument("simulation: initial condition on unknown DOF '" + ic.dof + "'");
    y(d) = ic.displacement;
    y(n + d) = ic.velocity;
  }
  return y;
}

// The slots whose event fires first in a step (within event_tolerance of each other), and when.
struct FiredSlots {
  double at = INFINITY;  // into the step
  std::vector<int> slots;
};

// The integration: adaptive Dormand–Prince steps, each cut at the first located event, where
// the model resolves the new regime. Writes the outputs, events and step count into `out`.
class Integration {
 public:
  Integration(Model& model, const SimulationOptions& options, Eigen::VectorXd y, TimeHistory& out)
      : model_(model),
        options_(options),
        n_(model.size()),
        y_(std::move(y)),
        h_(options.time_step),
        out_(out),
        time_(1),
        x_(1, n_),
        v_(1, n_) {}

  // At rest at t = 0 every friction element is a candidate for sticking.
  void start_at_rest() {
    for (const auto& e : model_.place_series_leaves(y_, options_.tolerance)) out_.events.push_back(e);
    std::vector<int> resting;
    for (size_t i = 0; i < model_.elements().size(); ++i)
      if (model_.elements()[i].friction > 0.0 && !model_.elements()[i].in_series() &&
          std::abs(model_.compression_rate(static_cast<int>(i), 0.0, y_.tail(n_))) <= options_.tolerance)
        resting.push_back(static_cast<int>(i));
    for (const auto& e : model_.resolve(0.0, &y_, resting))
      if (e.kind != SimulationEvent::Kind::reversal) out_.events.push_back(e);
    stamp(0);
  }

  // A sampled track: steps end on its breakpoints up to and including `target`, and at each
  // the leaves standing on the track take the regime the jump of its velocity gives them.
  void use_sampled_track(const simulate::SampledTrack* track) {
    track_ = track;
    nudge_ = 1e-6 * track->shortest_piece();
    model_.set_piece(t_ + nudge_);
  }
  void cross_breaks_to(double target) {
    if (!track_) return;
    for (double b = track_->next_break(t_); b <= target; b = track_->next_break(t_)) {
      advance_to(b);
      t_ = b;
      const size_t first_event = out_.events.size();
      for (const auto& e : model_.cross_break(t_, y_, t_ - nudge_, t_ + nudge_)) out_.events.push_back(e);
      stamp(first_event);
      model_.set_piece(t_ + nudge_);
      just_fired_.clear();
    }
  }
  // The sample at t to `receive`, with the acceleration (on a breakpoint, the mean of both
  // sides: what the Fourier series of the interpolated track converges to); returns whether
  // it is finite.
  bool record(double t, const simulate::SampleReceiver& receive) {
    Eigen::VectorXd before(2 * n_), after(2 * n_);
    model_.set_piece(t - nudge_);
    model_.rhs(t, y_, &before);
    model_.set_piece(t + nudge_);
    model_.rhs(t, y_, &after);
    const Eigen::VectorXd acceleration = 0.5 * (before.tail(n_) + after.tail(n_));
    receive(t, y_, acceleration);
    return y_.allFinite() && acceleration.allFinite();
  }

  // Gives the sample at t to the sink; returns whether it is finite.
  bool record(double t, HistorySink& sink) {
    time_(0) = t;
    x_ = y_.head(n_).transpose();
    v_ = y_.tail(n_).transpose();
    sink.write(time_, x_, v_);
    return y_.allFinite();
  }

  void advance_to(double target) {
    while (t_ < target) {
      const double hh = std::min(h_, target - t_);
      if (hh < 1e-15 * std::max(1.0, target)) {
        t_ = target;
        break;
      }
      const auto step = step_from_here(hh);
      const double err = error_norm(step.error, y_, step.y, options_.tolerance);
      if (!step.y.allFinite()) throw NumericalError("simulation diverged at t = " + shortest_text(t_, 9) + " s");
      ++out_.steps_taken;
      if (err > 1.0) {
        h_ = hh * std::max(0.2, 0.9 * std::pow(err, -0.2));
        if (h_ < 1e-14 * std::max(1.0, t_))
          throw NumericalError("simulation: step size underflow at t = " + shortest_text(t_, 9) + " s");
        continue;
      }
      const std::vector<Slot> slots = model_.slots();
      const FiredSlots fired = first_events(slots, hh, step.y);
      if (fired.slots.empty()) {
        y_ = step.y;
        t_ = (hh == target - t_) ? target : t_ + hh;
        h_ = hh * std::min(5.0, 0.9 * std::pow(std::max(err, 1e-10), -0.2));
        just_fired_.assign(slots.size(), false);
        continue;
      }
      fire(slots, fired);
    }
  }

 private:
  simulate::DormandPrinceStep step_from_here(double length) const {
    if (track_) model_.set_piece(t_ + 0.5 * length);  // the step lies on one smooth piece
    const auto rhs = [this](double t, const Eigen::VectorXd& state, Eigen::VectorXd* dy) { model_.rhs(t, state, dy); };
    return simulate::dormand_prince_step(rhs, t_, y_, length);
  }

  // Events: an event function that changes sign over the step (sliding: the compression
  // rate against the sliding direction reaches zero; stuck: the holding force reaches
  // ±φR_el; kink: the deflection crosses a corner of the curve).
  FiredSlots first_events(const std::vector<Slot>& slots, double hh, const Eigen::VectorXd& y1) {
    const std::vector<double> h0 = model_.slot_values(slots, t_, y_), h1 = model_.slot_values(slots, t_ + hh, y1);
    if (just_fired_.size() != slots.size()) just_fired_.assign(slots.size(), false);
    FiredSlots first;
    for (size_t s = 0; s < slots.size(); ++s) {
      const bool crossed = slots[s].kind == Slot::Kind::kink ? (h0[s] > 0.0) != (h1[s] > 0.0) && !just_fired_[s]
                                                              : h1[s] < 0.0 && (h0[s] >= 0.0 || !just_fired_[s]);
      if (!crossed) continue;
      const double at = locate_zero(slots, s, hh, h0[s], h1[s]);
      if (at < first.at - options_.event_tolerance) {
        first.at = at;
        first.slots.assign(1, static_cast<int>(s));
      } else if (std::abs(at - first.at) <= options_.event_tolerance) {
        first.slots.push_back(static_cast<int>(s));
      }
    }
    return first;
  }

  // Illinois false position on the step length for slot s's zero; the root is bracketed by
  // (lo, hi], and hi is returned. It stops at the event tolerance, or where no double lies
  // between lo and hi; the bound on the iterations only guards against a bracket that stops
  // shrinking (Illinois converges superlinearly, and even bisection from a 1 s step reaches
  // 1e-300 s in 1000 halvings: 400 is far beyond what a located zero takes).
  double locate_zero(const std::vector<Slot>& slots, size_t s, double hh, double glo, double ghi) const {
    constexpr int kMaxIterations = 400;
    double lo = 0.0, hi = hh;
    if (slots[s].kind != Slot::Kind::kink && glo < 0.0) glo = 0.0;  // already past: fire at once
    int side = 0;
    for (int iteration = 0; hi - lo > options_.event_tolerance && glo != 0.0; ++iteration) {
      if (iteration == kMaxIterations)
        throw NumericalError("simulation: an event near t = " + shortest_text(t_, 9) + " s was not located to " +
                             shortest_text(options_.event_tolerance, 9) + " s in " + std::to_string(kMaxIterations) +
                             " iterations; try a larger event_tolerance");
      double mid = (lo * ghi - hi * glo) / (ghi - glo);
      if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;  // lo and hi are neighbouring doubles
      const auto trial = step_from_here(mid);
      const double g = model_.slot_values(slots, t_ + mid, trial.y)[s];
      if ((g > 0.0) == (glo > 0.0)) {
        lo = mid, glo = g;
        if (side == -1) ghi *= 0.5;
        side = -1;
      } else {
        hi = mid, ghi = g;
        if (side == 1) glo *= 0.5;
        side = 1;
      }
    }
    return glo == 0.0 ? lo : hi;
  }

  // Moves to the event, records kinks, lets the model resolve the friction elements' new
  // regime, and marks the slots whose zero is now behind.
  void fire(const std::vector<Slot>& slots, const FiredSlots& fired) {
    if (fired.at > 0.0) y_ = step_from_here(fired.at).y;
    t_ += fired.at;
    // A regime that cannot last a step (a zero that fires again at once) would stall time;
    // say so instead of spinning.
    events_here_ = fired.at > 0.0 ? 0 : events_here_ + 1;
    if (events_here_ > 64)
      throw NumericalError("simulation: friction events chatter at t = " + shortest_text(t_, 9) +
                           " s (no consistent stick/slip state); try a larger event_tolerance");
    const size_t first_event = out_.events.size();
    std::vector<int> candidates, releasing;
    for (int s : fired.slots) {
      if (slots[s].kind == Slot::Kind::kink) {
        out_.events.push_back(event(t_, model_.elements()[slots[s].element].element, SimulationEvent::Kind::kink));
        continue;
      }
      candidates.push_back(slots[s].element);
      if (slots[s].kind == Slot::Kind::stuck) releasing.push_back(slots[s].element);
    }
    for (const auto& e : model_.resolve(t_, &y_, candidates, releasing)) out_.events.push_back(e);
    if (out_.events.size() > options_.max_events)
      throw NumericalError("simulation: more than " + std::to_string(options_.max_events) +
                           " stick/slip/kink events by t = " + shortest_text(t_, 9) +
                           " s: each is held with the state after it, and the limit (max_events) bounds their "
                           "memory; simulate a shorter duration");
    stamp(first_event);
    mark_just_fired(slots, fired.slots, candidates);
  }

  // The slots of the new regime whose zero is where the step now starts: the kinks that fired,
  // and every slot of a friction element just resolved (its regime starts at its zero).
  void mark_just_fired(const std::vector<Slot>& slots, const std::vector<int>& fired,
                       const std::vector<int>& candidates) {
    const std::vector<Slot> next = model_.slots();
    just_fired_.assign(next.size(), false);
    for (int s : fired)
      for (size_t q = 0; q < next.size(); ++q)
        if (next[q].element == slots[s].element && next[q].kind == Slot::Kind::kink &&
            slots[s].kind == Slot::Kind::kink && next[q].kink == slots[s].kink)
          just_fired_[q] = true;
    for (size_t q = 0; q < next.size(); ++q)
      if (next[q].kind != Slot::Kind::kink &&
          std::find(candidates.begin(), candidates.end(), next[q].element) != candidates.end())
        just_fired_[q] = true;
  }

  // Events carry the state they leave behind.
  void stamp(size_t from) {
    for (size_t e = from; e < out_.events.size(); ++e) {
      out_.events[e].displacement = y_.head(n_);
      out_.events[e].velocity = y_.tail(n_);
    }
  }

  Model& model_;
  const SimulationOptions& options_;
  const int n_;
  Eigen::VectorXd y_;
  double t_ = 0.0;
  double h_;
  const simulate::SampledTrack* track_ = nullptr;  // none: harmonic sources
  double nudge_ = 0.0;  // s: t ± this picks the sampled track's piece on either side of t
  std::vector<bool> just_fired_;  // slots that fired at the start of this step: their zero is behind us
  int events_here_ = 0;           // events in a row without time moving on
  TimeHistory& out_;
  Eigen::VectorXd time_;  // the sample being recorded, as one row
  Eigen::MatrixXd x_, v_;
};

// What both entry points (sources, sampled track) require before they build the model, in this
// order; check_speed says what each requires of the speed (a sampled track runs at one speed).
template <typename CheckSpeed>
void require_simulable(const LinearSystem& system, const SimulationOptions& options, CheckSpeed check_speed) {
  model::refuse_series_dampers(system, "simulation");
  if (system.size() == 0) throw std::invalid_argument("simulation: the system has no degrees of freedom");
  require_valid(options, "simulation: ");
  if (options.duration / options.time_step > 1e8)
    throw std::invalid_argument("simulation: more than 1e8 output steps; take a longer time step");
  check_speed();
  for (int i = 0; i < system.size(); ++i)
    if (system.mass.row(i).cwiseAbs().maxCoeff() == 0.0)
      throw std::invalid_argument("simulation: '" + system.dofs[i].label +
                                  "' is massless; the nonlinear path needs inertia at every degree of freedom");
}

// The options the integration uses: the event tolerance raised to the resolution of time over
// the run where it was finer, which the summary's checks say.
SimulationOptions with_resolvable_events(const SimulationOptions& options, AnalysisSummary* summary) {
  SimulationOptions used = options;
  if (used.event_tolerance < resolvable_event_tolerance(options.duration)) {
    used.event_tolerance = resolvable_event_tolerance(options.duration);
    summary->checks.push_back({"event tolerance raised to the resolution of time over the run (ε·duration), s",
                               used.event_tolerance, std::numeric_limits<double>::infinity(), true});
  }
  return used;
}

// The integration's counts, reported without a bound.
void add_step_counts(const TimeHistory& out, AnalysisSummary* summary) {
  summary->checks.push_back({"integrator steps", static_cast<double>(out.steps_taken),
                             std::numeric_limits<double>::infinity(), true});
  summary->checks.push_back({"events", static_cast<double>(out.events.size()),
                             std::numeric_limits<double>::infinity(), true});
}

}  // namespace

TimeHistory simulate_nonlinear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                               const SimulationOptions& options, const NonlinearEffects& effects) {
  return simulate::recorded(
      [&](HistorySink& sink) { return simulate_nonlinear(system, sources, options, effects, sink); });
}

TimeHistory simulate_nonlinear(const LinearSystem& system, const std::vector<const ExcitationSource*>& sources,
                               const SimulationOptions& options, const NonlinearEffects& effects, HistorySink& sink) {
  require_simulable(system, options, [&] {
    if (!sources.empty() && !(options.speed > 0.0))
      throw std::invalid_argument("simulation: the speed must be positive");
    if (options.final_speed > 0.0 && sources.empty())
      throw std::invalid_argument("simulation: a final speed must be positive, and needs sources to run over");
  });

  AnalysisSummary summary;
  StageClock clock(&summary);
  const SimulationOptions used = with_resolvable_events(options, &summary);
  const simulate::SpeedProfile profile =
      simulate::speed_profile(options.speed, options.final_speed, options.duration);
  SourceHarmonics excitation = source_harmonics(system, sources, options.speed, profile);
  Model model(system, std::move(excitation.harmonics),
              simulate::nonlinear_elements(system, excitation.loads, effects, excitation.load_sources, profile),
              profile);
  Eigen::VectorXd y = initial_state(system, options);

  const int outputs = static_cast<int>(simulate::sample_count(options.duration, options.time_step) - 1);
  clock.lap("model");
  TimeHistory out;
  for (const auto& d : system.dofs) out.labels.push_back(d.label);
  sink.begin(out.labels, outputs + 1);
  Integration integration(model, used, std::move(y), out);
  integration.start_at_rest();
  bool finite = integration.record(0.0, sink);
  for (int i = 1; i <= outputs; ++i) {
    const double target = i * options.time_step;
    integration.advance_to(target);
    finite = integration.record(target, sink) && finite;
  }
  clock.lap("integrate");
  add_step_counts(out, &summary);
  simulate::summarise_history(&out, outputs + 1, finite, std::move(summary), "time history, nonlinear",
                              "adaptive Dormand–Prince 5(4), events located by Illinois false position");
  return out;
}

namespace simulate {

TimeHistory simulate_nonlinear_sampled(const LinearSystem& system, const SampledTrack& track,
                                       const SimulationOptions& options, const NonlinearEffects& effects,
                                       const SampleReceiver& receive) {
  require_simulable(system, options, [&] {
    if (!(options.speed > 0.0)) throw std::invalid_argument("simulation: the speed must be positive");
    if (options.final_speed > 0.0) throw std::invalid_argument("simulation: a sampled track runs at one speed");
  });

  AnalysisSummary summary;
  StageClock clock(&summary);
  const SimulationOptions used = with_resolvable_events(options, &summary);
  SpeedProfile profile;
  profile.initial = options.speed;
  Model model(system, {}, nonlinear_elements(system, {}, effects, {}, profile), profile);
  model.use_sampled_track(system, &track);
  const int outputs = static_cast<int>(sample_count(options.duration, options.time_step) - 1);
  clock.lap("model");
  TimeHistory out;
  for (const auto& d : system.dofs) out.labels.push_back(d.label);
  Integration integration(model, used, initial_state(system, options), out);
  integration.use_sampled_track(&track);
  integration.start_at_rest();
  bool finite = integration.record(0.0, receive);
  for (int i = 1; i <= outputs; ++i) {
    const double target = i * options.time_step;
    integration.cross_breaks_to(target);
    integration.advance_to(target);
    finite = integration.record(target, receive) && finite;
  }
  clock.lap("integrate");
  add_step_counts(out, &summary);
  summary.checks.push_back({"non-finite samples", finite ? 0.0 : 1.0, 0.0, finite});
  summary.analysis = "time history, nonlinear, sampled track";
  summary.method = "adaptive Dormand–Prince 5(4), steps ending on the track's breakpoints, events located by Illinois "
                   "false position";
  out.summary = std::move(summary);
  return out;
}

}  // namespace simulate
}  // namespace railmodal
