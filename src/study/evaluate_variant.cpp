// One variant of a study: what the designer compares (docs/studies.md, "What is computed").
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "railmodal/critical_speed_report.hpp"
#include "railmodal/errors.hpp"
#include "railmodal/stability.hpp"
#include "railmodal/study.hpp"
#include "study/permissible_deflection.hpp"

namespace railmodal {
namespace {

void summarise_modes(const ModalResult& modes, VariantResult* r) {
  for (const Mode& m : modes.modes)
    r->modes.push_back({m.name, to_string(m.kind), m.frequency_hz, m.period_s, m.divergence_rate});
}

// Static deflection of each body's reference point: K_el q = M u g, with u the upward unit
// translation of every body, is the elastic response to the weights turned upward (M u g is
// the generalised weight, moments of off-centre CGs included); gravity stiffness is left
// out because the deflection is measured from the unloaded springs, as the book's f_st.
void static_deflections(const Vehicle& vehicle, const LinearSystem& any, VariantResult* r) {
  const LinearSystem s = any.size() > 0 && std::all_of(any.dofs.begin(), any.dofs.end(), [](const Dof& d) {
    return d.motion == Motion::bounce || d.motion == Motion::pitch;
  }) ? any : assemble(vehicle, DofSet::vertical);
  if (s.size() == 0) return;
  Eigen::VectorXd up = Eigen::VectorXd::Zero(s.size());
  for (int i = 0; i < s.size(); ++i)
    if (s.dofs[i].motion == Motion::bounce) up(i) = 1.0;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(s.stiffness - s.gravity_stiffness);
  if (!lu.isInvertible()) return;  // a free vertical direction: no static position to report
  const Eigen::VectorXd q = lu.solve(s.mass * up * vehicle.gravity);
  for (int i = 0; i < s.size(); ++i)
    if (s.dofs[i].motion == Motion::bounce) r->static_deflections.push_back({vehicle.bodies[s.dofs[i].body].name, q(i)});
}

void metacentric_height(const Vehicle& vehicle, VariantResult* r) {
  for (const Body& b : vehicle.bodies)
    if (b.name == "body" && std::find(b.held.begin(), b.held.end(), Motion::roll) == b.held.end()) {
      try {
        r->metacentric_height = lateral_stability(vehicle, "body").metacentric_height;
      } catch (const std::invalid_argument&) {
        // no free roll in the lateral set: nothing to report
      }
    }
}

void summarise_response(const CriticalSpeedStudy& study, VariantResult* r) {
  for (const CriticalSpeed& c : study.critical_speeds)
    r->critical_speeds.push_back({c.speed, c.source, c.source_kind, c.harmonic, c.mode_name, c.friction_stops});
  for (size_t k = 0; k < study.curves.size(); ++k) {
    const AmplitudeCurve& curve = study.curves[k];
    VariantResult::PeakSummary p;
    p.source = curve.source;
    p.output = curve.output;
    p.quantity = to_string(curve.quantity);
    for (size_t i = 0; i < curve.speeds.size(); ++i) {
      if (curve.unbounded[i]) p.unbounded = true;
      else if (curve.amplitudes[i] > p.amplitude) p.amplitude = curve.amplitudes[i], p.speed = curve.speeds[i];
    }
    for (const auto& refined : study.peaks)
      if (refined.curve == static_cast<int>(k) && refined.peak.amplitude > p.amplitude)
        p.amplitude = refined.peak.amplitude, p.speed = refined.peak.speed;
    r->peaks.push_back(p);
  }
}

// The largest dynamic deflection of every element or stage the rule limits, over every source
// and the study's speed grid (which holds every critical speed), by the rule of
// docs/studies.md, "Permissible dynamic deflections":
//  1. an undamped resonance in range that leaf friction does not stop (the criterion of the
//     critical speeds, the book's (169a) as Den Hartog's) grows without limit: every element
//     its mode stretches is unbounded;
//  2. otherwise leaf friction is linearised at the element stretch where the element reaches
//     its (first) limit, X_lim, and the response there is compared with the limit. For one
//     mode driven through its own coordinate the response A(X) of friction linearised at X
//     has A(X)/X falling in X, so A(X_lim) ≤ X_lim exactly when the friction-limited
//     amplitude X* ≤ X_lim, and the value reported lies between X* and X_lim. That holds as
//     the book's (169a) holds, with the track's own motion under the spring left out; with
//     it the stretch at resonance is |X_lim/s ± |u_r − u_f|/2| (tests/response/
//     element_deflection_test.cpp), which the check takes as it comes.
// Friction of an element without a limit is linearised at the scene's [friction] amplitude,
// if any, else left out (less damping: the safe side).
void check_deflections(const DeflectionRule& rule, const CriticalSpeedStudy& study, VariantResult* r) {
  r->deflections_checked = true;
  const LinearSystem& system = study.system;
  const std::vector<study::PermissibleDeflection> limits = study::permissible_deflections(rule, system);
  if (limits.empty()) return;
  std::vector<int> elements;
  std::vector<double> reference(system.vehicle.elements.size(), study.scene.friction_reference_amplitude);
  std::vector<bool> limited(reference.size(), false);
  for (const auto& l : limits) {
    if (std::find(elements.begin(), elements.end(), l.element) == elements.end()) elements.push_back(l.element);
    const double stretch = l.permissible / l.share;
    reference[l.element] = limited[l.element] ? std::min(reference[l.element], stretch) : stretch;
    limited[l.element] = true;
  }
  for (const auto& l : limits) {
    VariantResult::DeflectionCheck c;
    const Element& e = system.vehicle.elements[l.element];
    c.element = e.name;
    c.stage = l.stage < 0 ? "" : e.vertical_stages[l.stage].kind;
    c.basis = l.basis;
    c.permissible = l.permissible;
    r->deflections.push_back(c);
  }
  // Rule 1: resonances friction does not stop.
  for (const CriticalSpeed& cs : study.critical_speeds) {
    if (!cs.unbounded || cs.friction_stops) continue;
    const Eigen::VectorXd& shape = study.modes.modes[cs.mode - 1].shape;
    for (size_t i = 0; i < limits.size(); ++i) {
      const Eigen::RowVectorXd row = system.element_vertical_map.row(limits[i].element);
      VariantResult::DeflectionCheck& c = r->deflections[i];
      if (!c.unbounded && std::abs(row.dot(shape)) > 1e-9 * shape.cwiseAbs().maxCoeff() * row.cwiseAbs().sum())
        c.unbounded = true, c.speed = cs.speed, c.source = cs.source;
    }
  }
  const std::vector<double> speeds = study.curves.empty() ? std::vector<double>{} : study.curves.front().speeds;
  for (size_t s = 0; s < study.scene.sources.size() && !speeds.empty(); ++s) {
    const std::vector<DeflectionCurve> curves = element_deflection_curves(
        system, study.modes, *study.scene.sources[s], static_cast<int>(s), elements, speeds, reference);
    for (size_t i = 0; i < limits.size(); ++i) {
      const auto& l = limits[i];
      VariantResult::DeflectionCheck& c = r->deflections[i];
      const DeflectionCurve& curve = *std::find_if(curves.begin(), curves.end(),
                                                   [&](const DeflectionCurve& d) { return d.element == l.element; });
      for (size_t v = 0; v < speeds.size(); ++v) {
        if (curve.unbounded[v]) {
          if (!c.unbounded) c.speed = speeds[v], c.source = static_cast<int>(s);
          c.unbounded = true;
        } else if (!c.unbounded && l.share * curve.amplitudes[v] > c.deflection) {
          c.deflection = l.share * curve.amplitudes[v], c.speed = speeds[v], c.source = static_cast<int>(s);
        }
      }
    }
  }
  for (auto& c : r->deflections)
    if (c.unbounded) c.deflection = 0.0;
}

// The failure of a vehicle with no steady response: its modes (when they can be computed), and
// the unstable one named.
void describe_failure(const StudyVariant& variant, const std::string& why, VariantResult* r) {
  r->failure = "numerical failure: " + why;
  const LinearSystem system = assemble(variant.vehicle, variant.scene.dofs);
  const ModalResult modes = solve_modes(system);
  summarise_modes(modes, r);
  static_deflections(variant.vehicle, system, r);
  metacentric_height(variant.vehicle, r);
  for (const Mode& m : modes.modes)
    if (m.kind == ModeKind::unstable) {
      char rate[32];
      std::snprintf(rate, sizeof rate, "%.4g", m.divergence_rate);
      r->failure = "unstable: mode " + std::to_string(m.index) + ", " + m.name + ", diverges at " + rate + " 1/s";
      return;
    }
}

}  // namespace

VariantResult evaluate_variant(const StudyVariant& variant, int index, const DeflectionRule& rule) {
  VariantResult r;
  r.index = index;
  r.name = variant.name;
  r.parameters = variant.parameters;
  try {
    // One assembly and one modal solve serve everything: the study's own.
    CriticalSpeedStudy study;
    try {
      study = study_critical_speeds(variant.scene, variant.vehicle);
    } catch (const NumericalError& e) {
      describe_failure(variant, e.what(), &r);
      return r;
    }
    summarise_modes(study.modes, &r);
    static_deflections(variant.vehicle, study.system, &r);
    metacentric_height(variant.vehicle, &r);
    summarise_response(study, &r);
    if (rule.active()) check_deflections(rule, study, &r);
  } catch (const NumericalError& e) {
    if (r.failure.empty()) r.failure = std::string("numerical failure: ") + e.what();
  } catch (const InputError& e) {
    r.failure = e.message();  // the scene's outputs do not fit this vehicle
  } catch (const std::invalid_argument& e) {
    r.failure = e.what();
  }
  return r;
}

}  // namespace railmodal
