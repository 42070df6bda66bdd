// Longitudinal motion (surge) of a body, freed by Body::longitudinal_free (issue 17 item 11):
// with it free, the natural frequencies do not depend on where the reference points are;
// held (the default), pitch is about the reference point with the inertia J + m·d².
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace railmodal::test {
namespace {

// Undamped eigenvalues ω², ascending.
Eigen::VectorXd eigenvalues(const LinearSystem& s) {
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(s.stiffness, s.mass, Eigen::EigenvaluesOnly)
      .eigenvalues();
}

// Moves every body's reference point by its own offset; the physics is unchanged.
Vehicle with_reference_points_moved(Vehicle v) {
  const Eigen::Vector3d offsets[] = {{0.7, 0.2, -0.9}, {-0.3, -0.1, 0.45}, {0.25, 0.15, -0.6}};
  for (size_t b = 0; b < v.bodies.size(); ++b) v.bodies[b].reference_point += offsets[b % 3];
  return v;
}

Vehicle manchester_coach(bool longitudinal_free) {
  Vehicle v = load_vehicle(data_file("manchester_benchmark_coach.toml"));
  for (Body& b : v.bodies) b.longitudinal_free = longitudinal_free;
  return v;
}

// With every motion of every body free, a move of the reference points is an invertible
// change of coordinates: the eigenvalues are the same. Gravity stiffness too, since the dead
// loads on each body sum to zero in the static equilibrium. Tolerance: round-off of the
// assembly and of a dense eigensolver on matrices whose eigenvalues span about 4e3 (13 to
// 5e4 s⁻²), ε·4e3 ≈ 1e-12 (measured: 4.3e-13); 1e-9 leaves room and is still 1e6 times below
// the effect of the move with surge held (next test: up to a factor 3).
TEST(LongitudinalMotion, FrequenciesDoNotDependOnTheReferencePointWhenFree) {
  const Vehicle v = manchester_coach(true);
  for (const Body& b : v.bodies) EXPECT_TRUE(b.held.empty()) << b.name;  // every motion free
  for (DofSet set : {DofSet::all, DofSet::vertical}) {
    const Eigen::VectorXd here = eigenvalues(assemble(v, set));
    const Eigen::VectorXd moved = eigenvalues(assemble(with_reference_points_moved(v), set));
    ASSERT_EQ(here.size(), moved.size());
    for (Eigen::Index i = 0; i < here.size(); ++i)
      EXPECT_NEAR(moved(i) / here(i), 1.0, 1e-9) << to_string(set) << " eigenvalue " << i;
  }
}

// Held, the reference point's height is physics: pitch is about it, J + m·d².
TEST(LongitudinalMotion, HeldSurgeMakesTheReferencePointMatter) {
  const Vehicle v = manchester_coach(false);
  const Eigen::VectorXd here = eigenvalues(assemble(v, DofSet::vertical));
  const Eigen::VectorXd moved = eigenvalues(assemble(with_reference_points_moved(v), DofSet::vertical));
  EXPECT_GT((moved.cwiseQuotient(here).array() - 1.0).abs().maxCoeff(), 1e-3);
}

// A longitudinal spring k a height h below the reference point couples surge and pitch:
// the point moves u − h·θ, so K gains k [[1, −h], [−h, h²]] on (longitudinal, pitch).
TEST(LongitudinalMotion, SpringBelowTheReferencePointCouplesSurgeAndPitch) {
  Vehicle v;
  Body b;
  b.name = "frame";
  b.mass = 2000.0;
  b.inertia = {500.0, 1500.0, 1500.0};
  b.centre_of_gravity = {0.0, 0.0, 0.5};
  b.reference_point = {0.0, 0.0, 0.5};
  b.held = {Motion::lateral, Motion::roll, Motion::yaw};
  b.longitudinal_free = true;
  v.bodies.push_back(b);
  for (double x : {-1.0, 1.0}) {
    Element e;
    e.name = "axlebox";
    e.upper = "frame";
    e.point = {x, 0.0, 0.0};
    e.vertical_stages = {{"coil", 1.0e6, 1}};
    e.longitudinal_stages = {{"guide", 3.0e7, 1}};
    e.longitudinal_damping = 5.0e3;
    v.elements.push_back(e);
  }
  const LinearSystem s = assemble(v, DofSet::vertical);
  const int u = s.index_of("frame.longitudinal"), p = s.index_of("frame.pitch");
  ASSERT_GE(u, 0);
  ASSERT_GE(p, 0);
  const double k = 2 * 3.0e7, h = 0.5;
  EXPECT_DOUBLE_EQ(s.stiffness(u, u), k);
  EXPECT_DOUBLE_EQ(s.stiffness(u, p), -k * h);
  EXPECT_DOUBLE_EQ(s.damping(u, u), 2 * 5.0e3);
  EXPECT_DOUBLE_EQ(s.damping(u, p), -2 * 5.0e3 * h);
  EXPECT_EQ(s.dofs[u].motion, Motion::longitudinal);
  EXPECT_EQ(assemble(v, DofSet::lateral).index_of("frame.longitudinal"), -1);  // a vertical-plane motion
  // The track's longitudinal displacement enters through the guides.
  ASSERT_EQ(s.track_inputs.size(), 2u);
  EXPECT_DOUBLE_EQ(s.track_inputs[0].load_per_displacement(u, 0), 3.0e7);
}

TEST(LongitudinalMotion, FreeAndHeldAtOnceIsRefused) {
  Vehicle v = manchester_coach(true);
  v.bodies[0].held.push_back(Motion::longitudinal);
  EXPECT_THROW(assemble(v, DofSet::all), std::invalid_argument);
}

// The Manchester coach's bogie pitch (issue 17 item 11). Held, the frame pitches about the
// axle plane with J + m·h1² (11.50 Hz). Freed, with the benchmark's primary longitudinal
// springs (4 × 31.4 MN/m at the axle plane) to wheelsets taken as rigid track, the axle-plane
// point stays almost fixed and the pitch stays there (11.48 Hz). The published multibody
// models have wheelsets free longitudinally (held by creep forces, a damping, not a
// stiffness): without the primary longitudinal restraint the frame pitches nearly about
// its CG with J, and the frequency rises by up to √((J + m·h1²)/J) = 1.72 %.
double bogie_pitch_hz(const Vehicle& v) {
  for (const Mode& m : solve_modes(assemble(v, DofSet::all)).modes)
    if (m.name.find("pitch") != std::string::npos && m.name.find("bogie") != std::string::npos) return m.frequency_hz;
  ADD_FAILURE() << "no bogie pitch mode";
  return 0.0;
}

TEST(LongitudinalMotion, ManchesterBogiePitchWithSurgeFree) {
  const double held = bogie_pitch_hz(manchester_coach(false));
  const double along_rigid_track = bogie_pitch_hz(manchester_coach(true));
  Vehicle free_wheelsets = manchester_coach(true);
  for (Element& e : free_wheelsets.elements)
    if (e.lower.empty()) e.longitudinal_stages.clear();  // no primary longitudinal restraint
  const double about_cg = bogie_pitch_hz(free_wheelsets);
  const Body& bogie = *body_named(free_wheelsets, "bogie1");
  const double h1 = bogie.centre_of_gravity.z() - bogie.reference_point.z();
  const double limit = std::sqrt((bogie.inertia.y() + bogie.mass * h1 * h1) / bogie.inertia.y());
  // Stiff springs at the axle plane: within 0.5 % of the held model (measured −0.18 %).
  EXPECT_NEAR(along_rigid_track / held, 1.0, 5e-3);
  // No restraint: toward the published value, by most of the inertia ratio (measured +1.55 %
  // of the 1.72 %; the rest is the pitch's coupling with the frame's own surge and the body).
  EXPECT_GT(about_cg / held, 1.0 + 0.8 * (limit - 1.0));
  EXPECT_LT(about_cg / held, limit);
}

}  // namespace
}  // namespace railmodal::test
