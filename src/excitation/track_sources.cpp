// Displacement sources: rail joints, wheel eccentricity and flats, kinematic hunting.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "excitation/wheelsets.hpp"
#include "railmodal/excitation.hpp"
#include "require_valid.hpp"
#include "shortest_text.hpp"

namespace railmodal {

namespace {

constexpr double kPi = 3.14159265358979323846;
const std::complex<double> kI(0.0, 1.0);

std::string mm(double metres) {
  std::ostringstream out;
  out << metres * 1e3 << " mm";
  return out.str();
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

// Multiplies harmonic k of an input by e^{−i·2πk·ahead/Λ}: the input's feature (a joint, a
// flat) lies `ahead` of the leading wheelset at t = 0, along the track (docs/scenes.md, "Where
// the track starts"). Nothing is done at ahead = 0, so that the default start leaves every
// amplitude, down to the sign of its zero imaginary part, as it was.
void shift_start(std::complex<double>* amplitude, double ahead, double wavelength, int harmonic) {
  if (ahead != 0.0) *amplitude *= std::polar(1.0, -2.0 * kPi * harmonic * ahead / wavelength);
}

// Delay of a wheelset behind the leading one at speed V.
double delay(const std::vector<excitation::Wheelset>& sets, double x, double speed) {
  return (sets.front().x - x) / speed;
}

class RailJointSource final : public ExcitationSource {
 public:
  explicit RailJointSource(const RailJoints& p) : p_(p) {}
  std::string kind() const override { return "rail_joints"; }
  std::string description() const override {
    std::ostringstream out;
    out << "rail joints, L = " << p_.rail_length << " m, " << (p_.staggered ? "staggered" : "opposite")
        << ", dip 2a = " << mm(p_.dip_depth) << " (" << to_string(p_.shape) << " over "
        << dip_length() << " m)";
    if (p_.track_stiffness > 0.0)
      out << ", on track of K = " << p_.track_stiffness / 1e6 << " MN/m (wheelset on track ρ = "
          << std::sqrt(p_.track_stiffness / p_.half_wheelset_mass) << " 1/s)";
    return out.str();
  }
  double wavelength() const override { return p_.rail_length; }
  void load_scales(const double* omega, int count, double reference_omega, double* out) const override {
    if (!(p_.track_stiffness > 0.0)) {  // a rigid track: the wheel follows the dip as it is
      std::fill_n(out, count, 1.0);
      return;
    }
    const double reference = track_factor(reference_omega);
    for (int i = 0; i < count; ++i) out[i] = track_factor(omega[i]) / reference;
  }
  int harmonic_count() const override { return p_.harmonics; }

  HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const override {
    HarmonicLoad out;
    out.frequency_hz = frequency_hz(speed, harmonic);
    const double A = dip_harmonic(p_.shape, p_.dip_depth, dip_length(), p_.rail_length, harmonic) *
                     track_factor(2.0 * kPi * out.frequency_hz);
    // Staggered: the right rail's joints lie half a rail on, a factor e^{−iπk} = (−1)^k.
    const double right = p_.staggered && harmonic % 2 == 1 ? -1.0 : 1.0;
    // This thread's list, kept between loads (a study builds several loads per variant).
    const std::vector<excitation::Wheelset>& sets = excitation::kept_wheelsets(system);
    out.wheels.reserve(system.track_inputs.size());  // every input is a wheel: one allocation
    for (const auto& set : sets)
      for (int index : set.inputs) {
        const int side = excitation::rail_side(system.track_inputs[index]);
        const double factor = side > 0 ? 1.0 : side < 0 ? right : 0.5 * (1.0 + right);
        WheelInput w;
        w.track_input = index;
        w.amplitude(2) = A * factor;
        shift_start(&w.amplitude(2), p_.first_joint_at, p_.rail_length, harmonic);
        w.delay_s = delay(sets, set.x, speed);
        out.wheels.push_back(w);
      }
    return out;
  }

 private:
  double dip_length() const { return p_.dip_length > 0.0 ? p_.dip_length : p_.rail_length; }
  // The wheel on the elastic rail follows the dip amplified by ρ²/(ρ² − n²), Filonenko-
  // Borodich's path (162) without its free term; the book drops it as n² ≪ ρ² (≈ 1 %).
  double track_factor(double n) const {
    if (!(p_.track_stiffness > 0.0)) return 1.0;
    const double rho2 = p_.track_stiffness / p_.half_wheelset_mass;
    if (std::abs(rho2 - n * n) <= 1e-12 * rho2)
      throw std::invalid_argument("rail joints: this speed meets the wheelset-on-track resonance ρ = " +
                                  shortest_text(std::sqrt(rho2), 4) + " 1/s");
    return rho2 / (rho2 - n * n);
  }
  RailJoints p_;
};

class EccentricitySource final : public ExcitationSource {
 public:
  explicit EccentricitySource(const WheelEccentricity& p) : p_(p) {}
  std::string kind() const override { return "wheel_eccentricity"; }
  std::string description() const override {
    std::ostringstream out;
    out << (p_.lobes == 1 ? "wheel eccentricity e = " : "out-of-round wheels, " + std::to_string(p_.lobes) + " lobes of e = ")
        << mm(p_.eccentricity) << ", D = " << p_.wheel_diameter << " m"
        << (p_.phases.empty() ? ", all wheelsets in phase" : ", wheelset phases given");
    return out.str();
  }
  double wavelength() const override { return kPi * p_.wheel_diameter / p_.lobes; }
  int harmonic_count() const override { return 1; }
  std::optional<Misfit> misfit(const LinearSystem& system) const override {
    const size_t wheelsets = excitation::wheelsets(system).size();
    if (p_.phases.empty() || p_.phases.size() == wheelsets) return std::nullopt;
    return Misfit{"phases",
                  std::to_string(p_.phases.size()) + " phases given for " + std::to_string(wheelsets) + " wheelsets"};
  }

  HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const override {
    HarmonicLoad out;
    out.frequency_hz = frequency_hz(speed, harmonic);
    if (harmonic != 1) return out;  // a pure sinusoid of the wheel's turn
    if (const auto m = misfit(system)) throw std::invalid_argument("wheel eccentricity: " + m->reason);
    const auto sets = excitation::wheelsets(system);
    for (size_t j = 0; j < sets.size(); ++j)
      for (int index : sets[j].inputs) {
        // The wheels turn together: no delay; e sin(ωt + ψ) = Re(−i e e^{iψ} e^{iωt}).
        WheelInput w;
        w.track_input = index;
        w.amplitude(2) = -kI * p_.eccentricity * std::exp(kI * (p_.phases.empty() ? 0.0 : p_.phases[j]));
        out.wheels.push_back(w);
      }
    return out;
  }

 private:
  WheelEccentricity p_;
};

class FlatSource final : public ExcitationSource {
 public:
  explicit FlatSource(const WheelFlat& p) : p_(p) {}
  std::string kind() const override { return "wheel_flat"; }
  std::string description() const override {
    std::ostringstream out;
    out << "wheel flats a1 = " << mm(p_.depth) << " over " << p_.length << " m (" << to_string(p_.shape)
        << "), D = " << p_.wheel_diameter << " m, every wheel in phase";
    return out.str();
  }
  double wavelength() const override { return kPi * p_.wheel_diameter; }
  int harmonic_count() const override { return p_.harmonics; }

  HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const override {
    HarmonicLoad out;
    out.frequency_hz = frequency_hz(speed, harmonic);
    // The flat is on the wheel: every wheel meets its own flat at the same moment (the book's
    // worst case, all in phase), no delay between axles.
    const double A = dip_harmonic(p_.shape, p_.depth, std::min(p_.length, wavelength()), wavelength(), harmonic);
    for (int index = 0; index < static_cast<int>(system.track_inputs.size()); ++index) {
      WheelInput w;
      w.track_input = index;
      w.amplitude(2) = A;
      // A flat θ ahead meets the rail once the wheel has rolled θD/2.
      shift_start(&w.amplitude(2), p_.flat_angle * p_.wheel_diameter / 2.0, wavelength(), harmonic);
      out.wheels.push_back(w);
    }
    return out;
  }

 private:
  WheelFlat p_;
};

class HuntingSource final : public ExcitationSource {
 public:
  explicit HuntingSource(const Hunting& p) : p_(p) {
    require(p.amplitude >= 0.0, "hunting: amplitude must not be negative");
    require(wavelength() > 0.0 && std::isfinite(wavelength()), "hunting: the wavelength must be positive");
    require(p.phase >= 0.0 && p.phase < 2.0 * kPi, "hunting: phase must lie in [0, 2π)");
  }
  std::string kind() const override { return "hunting"; }
  std::string description() const override {
    std::ostringstream out;
    out << "kinematic hunting, ";
    switch (p_.model) {
      case Hunting::Model::free_wheelset: out << "free wheelset (Klingel), conicity " << p_.conicity; break;
      case Hunting::Model::rigid_bogie:
        out << "rigid bogie, wheelbase " << p_.bogie_wheelbase << " m (Rocard), conicity " << p_.conicity;
        break;
      case Hunting::Model::given: out << "given wavelength"; break;
    }
    out << ", λ = " << wavelength() << " m, y0 = " << mm(p_.amplitude);
    if (p_.meineke) {
      const auto& m = *p_.meineke;
      out << "; Meineke's hunting-limit speed (267): " << std::setprecision(4)
          << meineke_hunting_speed_kmh(m.wheelbase, m.diagonal, m.clearance, m.wheels, m.k) << " km/h";
    }
    return out.str();
  }
  double wavelength() const override {
    switch (p_.model) {
      case Hunting::Model::free_wheelset:
        return klingel_wavelength(p_.conicity, p_.rolling_circle_spacing, p_.rolling_radius);
      case Hunting::Model::rigid_bogie:
        return rigid_bogie_wavelength(p_.conicity, p_.rolling_circle_spacing, p_.rolling_radius,
                                      p_.bogie_wheelbase);
      case Hunting::Model::given: return p_.given_wavelength;
    }
    return 0.0;
  }
  int harmonic_count() const override { return 1; }

  HarmonicLoad load_at(const LinearSystem& system, double speed, int harmonic) const override {
    HarmonicLoad out;
    out.frequency_hz = frequency_hz(speed, harmonic);
    if (harmonic != 1) return out;
    const std::vector<excitation::Wheelset>& sets = excitation::kept_wheelsets(system);  // as the rail joints'
    for (const auto& set : sets)
      for (int index : set.inputs) {
        // Each wheelset follows the same sinuous path, y0 sin(2πs/λ + φ), reached later by the
        // wheelsets behind: Re(−i y0 e^{iφ} e^{iωt}) at the leading one.
        WheelInput w;
        w.track_input = index;
        w.amplitude(1) = -kI * p_.amplitude;
        shift_start(&w.amplitude(1), -p_.phase / (2.0 * kPi) * wavelength(), wavelength(), 1);
        w.delay_s = delay(sets, set.x, speed);
        out.wheels.push_back(w);
      }
    return out;
  }

 private:
  Hunting p_;
};

}  // namespace

const char* to_string(Hunting::Model model) {
  switch (model) {
    case Hunting::Model::free_wheelset: return "free_wheelset";
    case Hunting::Model::rigid_bogie: return "rigid_bogie";
    case Hunting::Model::given: return "given";
  }
  return "?";
}

std::optional<Hunting::Model> hunting_model_from_string(const std::string& word) {
  for (Hunting::Model m : {Hunting::Model::free_wheelset, Hunting::Model::rigid_bogie, Hunting::Model::given})
    if (word == to_string(m)) return m;
  return std::nullopt;
}

double klingel_wavelength(double conicity, double rolling_circle_spacing, double rolling_radius) {
  require(conicity > 0.0 && rolling_circle_spacing > 0.0 && rolling_radius > 0.0,
          "hunting: conicity, rolling-circle spacing and rolling radius must be positive");
  return 2.0 * kPi * std::sqrt(rolling_circle_spacing * rolling_radius / (2.0 * conicity));  // (264b)
}

double rigid_bogie_wavelength(double conicity, double rolling_circle_spacing, double rolling_radius,
                              double wheelbase) {
  require(wheelbase > 0.0, "hunting: the bogie wheelbase must be positive");
  const double ratio = wheelbase / rolling_circle_spacing;
  return klingel_wavelength(conicity, rolling_circle_spacing, rolling_radius) * std::sqrt(1.0 + ratio * ratio);
}

double meineke_hunting_speed_kmh(double wheelbase, double diagonal, double clearance, int wheels, double k) {
  require(wheelbase > 0.0 && diagonal > 0.0 && clearance > 0.0 && wheels > 0 && k > 0.0,
          "Meineke: all inputs must be positive");
  return (1.33 * wheelbase / diagonal + 0.67) * wheelbase * k / (clearance * std::sqrt(wheels));  // (267)
}

// The rules of the track and wheel sources. Each `why` begins with the field's name, which is
// also the scene file's key: the scene reader fails at that key with the rest of the text.
bool RailJoints::is_valid(std::string* why) const {
  if (!(rail_length > 0.0) || !std::isfinite(rail_length))
    return invalid(why, "rail_length must be positive and finite");
  if (!(dip_depth >= 0.0) || !std::isfinite(dip_depth)) return invalid(why, "dip_depth must be finite and not negative");
  if (!(dip_length >= 0.0)) return invalid(why, "dip_length must not be negative (0: the whole rail)");
  if (dip_length > rail_length) return invalid(why, "dip_length cannot exceed the rail length");
  if (harmonics < 1) return invalid(why, "harmonics must be at least 1");
  if (!(track_stiffness >= 0.0) || !std::isfinite(track_stiffness))
    return invalid(why, "track_stiffness must be finite and not negative (0: a rigid track)");
  if (!(half_wheelset_mass >= 0.0) || !std::isfinite(half_wheelset_mass))
    return invalid(why, "half_wheelset_mass must be finite and not negative (0: a rigid track)");
  if ((track_stiffness > 0.0) != (half_wheelset_mass > 0.0))
    return invalid(why, std::string(track_stiffness > 0.0 ? "half_wheelset_mass" : "track_stiffness") +
                            " missing: the track's dynamics need both track_stiffness and half_wheelset_mass");
  if (!(first_joint_at >= 0.0)) return invalid(why, "first_joint_at must not be negative");
  if (!(first_joint_at < rail_length))
    return invalid(why, "first_joint_at must be shorter than the rail length (the next joint is the first)");
  return true;
}

bool WheelEccentricity::is_valid(std::string* why) const {
  if (!(wheel_diameter > 0.0) || !std::isfinite(wheel_diameter))
    return invalid(why, "wheel_diameter must be positive and finite");
  if (!(eccentricity >= 0.0) || !std::isfinite(eccentricity))
    return invalid(why, "eccentricity must be finite and not negative");
  for (double phase : phases)
    if (!std::isfinite(phase)) return invalid(why, "phases must be finite angles");
  if (lobes < 1) return invalid(why, "lobes must be at least 1");
  return true;
}

bool WheelFlat::is_valid(std::string* why) const {
  if (!(wheel_diameter > 0.0) || !std::isfinite(wheel_diameter))
    return invalid(why, "wheel_diameter must be positive and finite");
  if (!(depth >= 0.0) || !std::isfinite(depth)) return invalid(why, "depth must be finite and not negative");
  if (!(length > 0.0)) return invalid(why, "length must be positive");
  // A relative 1e-9 lets a length written as πD to a file's precision be the whole revolution.
  if (length > kPi * wheel_diameter * (1.0 + 1e-9)) return invalid(why, "length cannot exceed the wheel circumference πD");
  if (harmonics < 1) return invalid(why, "harmonics must be at least 1");
  if (!(flat_angle >= 0.0 && flat_angle < 2.0 * kPi)) return invalid(why, "flat_angle must lie in [0, 2π)");
  return true;
}

std::unique_ptr<ExcitationSource> make_source(const RailJoints& joints) {
  require_valid(joints, "rail joints: ");
  return std::make_unique<RailJointSource>(joints);
}
std::unique_ptr<ExcitationSource> make_source(const WheelEccentricity& eccentricity) {
  require_valid(eccentricity, "wheel eccentricity: ");
  return std::make_unique<EccentricitySource>(eccentricity);
}
std::unique_ptr<ExcitationSource> make_source(const WheelFlat& flat) {
  require_valid(flat, "wheel flat: ");
  return std::make_unique<FlatSource>(flat);
}
std::unique_ptr<ExcitationSource> make_source(const Hunting& hunting) {
  return std::make_unique<HuntingSource>(hunting);
}

}  // namespace railmodal
