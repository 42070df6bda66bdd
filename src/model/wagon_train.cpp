// A generated large model: a train of bogie wagons joined by couplers, assembled sparse.
#include <cmath>
#include <stdexcept>

#include "railmodal/sparse_system.hpp"

namespace railmodal {
namespace {

// One wagon's five DOFs, in this order.
enum Local { kLongitudinal, kBounce, kPitch, kBogie1, kBogie2, kPerWagon };

// Parameters of docs in sparse_system.hpp, SI.
constexpr double kBodyEmpty = 22e3, kLoadMax = 58e3;  // kg
constexpr double kBodyLength = 14.0;                  // m, for the pitch inertia m·L²/12
constexpr double kBogieMass = 4.8e3;                  // kg
constexpr double kBogieX = 4.5;                       // m, bogie centres at ±kBogieX
constexpr double kPrimary = 12e6, kSecondary = 4e6;   // N/m per bogie
constexpr double kSecondaryDamping = 30e3;            // N·s/m per bogie
constexpr double kEndX = 7.5;                         // m, coupler points at ±kEndX
constexpr double kCouplerAlong = 20e6, kCouplerVertical = 0.2e6;  // N/m

using Triplets = std::vector<Eigen::Triplet<double>>;

// A spring of rate k whose elongation is Σ aᵢ qᵢ adds k a aᵀ.
void add_spring(Triplets& t, double k, std::initializer_list<std::pair<int, double>> a) {
  for (const auto& [i, ai] : a)
    for (const auto& [j, aj] : a) t.emplace_back(i, j, k * ai * aj);
}

}  // namespace

SparseSystem wagon_train(int wagons) {
  if (wagons < 1) throw std::invalid_argument("wagon_train: wagons must be at least 1, got " + std::to_string(wagons));
  const int n = kPerWagon * wagons;
  SparseSystem s;
  s.name = "train of " + std::to_string(wagons) + " wagons";
  const char* names[kPerWagon] = {"body.longitudinal", "body.bounce", "body.pitch", "bogie1.bounce", "bogie2.bounce"};
  Triplets m, c, k;
  for (int w = 0; w < wagons; ++w) {
    const int o = kPerWagon * w;
    for (int d = 0; d < kPerWagon; ++d) {
      Dof dof;  // no bodies: the label says what moves, Dof::motion is unused
      dof.label = "wagon" + std::to_string(w + 1) + "." + names[d];
      dof.body = -1;
      s.dofs.push_back(dof);
    }
    // Loads from the golden-ratio sequence: every wagon different, none far from the mean.
    const double load = kLoadMax * std::fmod(0.6180339887498949 * (w + 1), 1.0);
    const double body = kBodyEmpty + load;
    m.emplace_back(o + kLongitudinal, o + kLongitudinal, body);
    m.emplace_back(o + kBounce, o + kBounce, body);
    m.emplace_back(o + kPitch, o + kPitch, body * kBodyLength * kBodyLength / 12.0);
    m.emplace_back(o + kBogie1, o + kBogie1, kBogieMass);
    m.emplace_back(o + kBogie2, o + kBogie2, kBogieMass);
    // Vertical motion of a body point at x: z − x·θ (the pitch convention of the vehicles).
    for (const auto& [bogie, x] : {std::pair{kBogie1, kBogieX}, std::pair{kBogie2, -kBogieX}}) {
      add_spring(k, kPrimary, {{o + bogie, 1.0}});
      add_spring(k, kSecondary, {{o + kBounce, 1.0}, {o + kPitch, -x}, {o + bogie, -1.0}});
      add_spring(c, kSecondaryDamping, {{o + kBounce, 1.0}, {o + kPitch, -x}, {o + bogie, -1.0}});
    }
    if (w + 1 < wagons) {  // coupler: rear of this wagon (x = −kEndX) to the front of the next
      const int p = o + kPerWagon;
      add_spring(k, kCouplerAlong, {{o + kLongitudinal, 1.0}, {p + kLongitudinal, -1.0}});
      add_spring(k, kCouplerVertical,
                 {{o + kBounce, 1.0}, {o + kPitch, kEndX}, {p + kBounce, -1.0}, {p + kPitch, -kEndX}});
    }
  }
  s.mass.resize(n, n);
  s.damping.resize(n, n);
  s.stiffness.resize(n, n);
  s.mass.setFromTriplets(m.begin(), m.end());  // duplicates summed
  s.damping.setFromTriplets(c.begin(), c.end());
  s.stiffness.setFromTriplets(k.begin(), k.end());
  return s;
}

}  // namespace railmodal
