// A body's first vertical bending mode (Body::bending, issue 21 "Also: the first bending mode of
// the car body"): the free–free beam's closed form against the published root and a finite-
// element beam built here, and the assembled mode against the closed form, in the limits where
// the suspension leaves it alone (soft springs; springs at the mode's nodes).
#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

#include "model/body_bending.hpp"
#include "model/point_motion.hpp"
#include "test_support.hpp"

namespace railmodal::test {
namespace {

// Printed: β₁L = 4.730040745 (Blevins 1979 Table 8-1; Thomson and Dahleh 1998 Appendix D
// give 4.7300). Used to form the closed form independently of the code's root.
constexpr double kPrintedBeta1L = 4.730040745;
// A coach-like beam: 24 m, EI 2.5e9 N·m², 1300 kg/m (≈ 8.57 Hz).
constexpr double kLength = 24.0, kEI = 2.5e9, kMassPerLength = 1300.0;

double closed_form_frequency() {
  return kPrintedBeta1L * kPrintedBeta1L / (2.0 * kPi * kLength * kLength) * std::sqrt(kEI / kMassPerLength);
}

// Composite Simpson over [0, 1] with 2000 intervals: for these smooth integrands (|f''''| ≤
// β⁴·cosh β ≈ 3e3) the error bound h⁴/180·max|f''''| ≈ 1e-12.
template <class F>
double simpson(F f) {
  constexpr int kIntervals = 2000;
  const double h = 1.0 / kIntervals;
  double sum = f(0.0) + f(1.0);
  for (int i = 1; i < kIntervals; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  return sum * h / 3.0;
}

// The node of φ between ξ = 0.1 and 0.4, by bisection.
double first_node() {
  double a = 0.1, b = 0.4;
  for (int k = 0; k < 100; ++k) {
    const double m = 0.5 * (a + b);
    (model::free_free_mode_shape(a) * model::free_free_mode_shape(m) <= 0.0 ? b : a) = m;
  }
  return 0.5 * (a + b);
}

TEST(BodyBending, Beta1LIsThePublishedRootOfTheFrequencyEquation) {
  const double beta = model::free_free_beta1_l();
  // Printed to ten digits: agreement within half the last digit.
  EXPECT_NEAR(beta, kPrintedBeta1L, 5e-10);
  // cos β cosh β = 1: the residual is round-off of cosh β ≈ 56.7 (ε·57 ≈ 1e-14).
  EXPECT_NEAR(std::cos(beta) * std::cosh(beta), 1.0, 1e-12);
}

TEST(BodyBending, ModeShapeIsNormalisedAndOrthogonalToTheRigidMotions) {
  using model::free_free_mode_shape;
  // φ = 1 at both ends (the normalisation) — exact at ξ = 0, round-off of cosh β at ξ = 1.
  EXPECT_DOUBLE_EQ(free_free_mode_shape(0.0), 1.0);
  EXPECT_NEAR(free_free_mode_shape(1.0), 1.0, 1e-12);
  // Symmetric about the centre.
  for (double xi : {0.1, 0.27, 0.4}) EXPECT_NEAR(free_free_mode_shape(xi), free_free_mode_shape(1.0 - xi), 1e-12);
  // Orthogonal to the uniform beam's bounce (∫φ = 0) and pitch (∫(ξ − ½)φ = 0); ∫φ² = ¼, so a
  // uniform beam's modal mass is m'L/4. Tolerance: the quadrature's 1e-12, ×10.
  EXPECT_NEAR(simpson([](double x) { return free_free_mode_shape(x); }), 0.0, 1e-11);
  EXPECT_NEAR(simpson([](double x) { return (x - 0.5) * free_free_mode_shape(x); }), 0.0, 1e-11);
  EXPECT_NEAR(simpson([](double x) { return free_free_mode_shape(x) * free_free_mode_shape(x); }), 0.25, 1e-11);
}

TEST(BodyBending, NodesSitWhereTheTablesPrintThem) {
  // Nodes of the free–free beam's first mode at 0.224 L from each end, i.e. 0.276 L either side of
  // the centre (Blevins 1979 Table 8-1 prints 0.224 and 0.776). Printed to three digits.
  const double node = first_node();
  EXPECT_NEAR(node, 0.224, 5e-4);
  EXPECT_NEAR(model::free_free_mode_shape(1.0 - node), 0.0, 1e-12);
  // Between the nodes the centre moves against the ends: φ(½) = −0.6078 (our own quadrature-free
  // value, from the closed form at 30 digits: −0.607822229416).
  EXPECT_NEAR(model::free_free_mode_shape(0.5), -0.607822229416, 1e-11);
}

// An Euler–Bernoulli beam of cubic Hermite elements (consistent mass), free at both ends, set
// up here from the element matrices: its third eigenvalue (after the two rigid modes) is the
// first bending mode, its shape sampled at the element nodes.
struct FiniteElementBeam {
  double frequency = 0.0;
  Eigen::VectorXd deflection;  // at the n + 1 nodes, 1 at the first
};

FiniteElementBeam finite_element_beam(int elements) {
  const double h = kLength / elements;
  const int n = 2 * (elements + 1);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
  Eigen::Matrix4d k, m;
  k << 12, 6 * h, -12, 6 * h, 6 * h, 4 * h * h, -6 * h, 2 * h * h, -12, -6 * h, 12, -6 * h, 6 * h, 2 * h * h, -6 * h,
      4 * h * h;
  m << 156, 22 * h, 54, -13 * h, 22 * h, 4 * h * h, 13 * h, -3 * h * h, 54, 13 * h, 156, -22 * h, -13 * h, -3 * h * h,
      -22 * h, 4 * h * h;
  k *= kEI / (h * h * h);
  m *= kMassPerLength * h / 420.0;
  for (int e = 0; e < elements; ++e) {
    K.block<4, 4>(2 * e, 2 * e) += k;
    M.block<4, 4>(2 * e, 2 * e) += m;
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  FiniteElementBeam beam;
  beam.frequency = std::sqrt(solver.eigenvalues()(2)) / (2.0 * kPi);
  const Eigen::VectorXd v = solver.eigenvectors().col(2);
  beam.deflection.resize(elements + 1);
  for (int i = 0; i <= elements; ++i) beam.deflection(i) = v(2 * i) / v(0);
  return beam;
}

TEST(BodyBending, FrequencyAndShapeAgreeWithAFiniteElementBeam) {
  // 60 elements: the cubic elements' frequency error goes as h⁴ (≈ 1e-9 here); the eigen-
  // solver's round-off on K (entries up to 1e13) against its rigid modes ≈ 1e-9 relative.
  constexpr int kElements = 60;
  const FiniteElementBeam fe = finite_element_beam(kElements);
  const double f = model::free_free_beam_frequency(kEI, kMassPerLength, kLength);
  EXPECT_NEAR(f, closed_form_frequency(), 1e-9 * f);  // the code's root against the printed one
  EXPECT_NEAR(fe.frequency, f, 1e-7 * f);
  for (int i = 0; i <= kElements; ++i)
    EXPECT_NEAR(fe.deflection(i), model::free_free_mode_shape(static_cast<double>(i) / kElements), 1e-6) << i;
}

// A coach body (the Manchester coach's mass and inertia) on four vertical springs, two at each
// of x = ±support, y = ±1 m, with the beam bending mode; rigid if `bending` is false.
Vehicle coach_body(double support, double stiffness, bool bending = true) {
  Vehicle v;
  Body body;
  body.name = "body";
  body.mass = 32000.0;
  body.inertia = {5.68e4, 1.97e6, 1.97e6};
  body.centre_of_gravity = {0.0, 0.0, 1.8};
  body.reference_point = {0.0, 0.0, 0.8};
  if (bending) {
    BodyBending b;
    b.length = kLength;
    b.beam = BodyBending::Beam{kEI, kMassPerLength};
    b.damping_ratio = 0.02;
    body.bending = b;
  }
  v.bodies.push_back(body);
  for (double x : {support, -support})
    for (double y : {1.0, -1.0}) {
      Element e;
      e.name = "spring";
      e.upper = "body";
      e.point = {x, y, 0.8};
      e.vertical_stages = {{"air", stiffness, 1}};
      e.vertical_damping = 2e4;
      v.elements.push_back(e);
    }
  return v;
}

TEST(BodyBendingAssembly, AlonePerfectlyHeldTheBodyBendsAtTheClosedForm) {
  Vehicle v = coach_body(9.5, 4.3e5);
  v.elements.clear();
  v.bodies[0].held = {Motion::lateral, Motion::bounce, Motion::roll, Motion::pitch, Motion::yaw};
  const LinearSystem s = assemble(v, DofSet::all);
  ASSERT_EQ(s.size(), 1);
  EXPECT_EQ(s.dofs[0].label, "body.bending");
  EXPECT_EQ(s.dofs[0].motion, Motion::bending);
  // Modal mass m'L/4; stiffness ω²m_b; damping 2ζω m_b.
  const double mb = kMassPerLength * kLength / 4.0, omega = 2.0 * kPi * closed_form_frequency();
  EXPECT_NEAR(s.mass(0, 0), mb, 1e-12 * mb);
  EXPECT_NEAR(s.stiffness(0, 0), omega * omega * mb, 1e-9 * omega * omega * mb);
  EXPECT_NEAR(s.damping(0, 0), 2.0 * 0.02 * omega * mb, 1e-9 * omega * mb);
  const ModalResult r = solve_modes(s);
  ASSERT_EQ(r.modes.size(), 1u);
  EXPECT_EQ(r.modes[0].name, "body first vertical bending");
  EXPECT_NEAR(r.modes[0].frequency_hz, closed_form_frequency(), 1e-9 * closed_form_frequency());
}

TEST(BodyBendingAssembly, TheModeGivenDirectlyIsTakenAsGiven) {
  Vehicle v = coach_body(9.5, 4.3e5);
  v.bodies[0].bending->beam.reset();
  v.bodies[0].bending->mode = BodyBending::Mode{9.0, 8000.0};
  const LinearSystem s = assemble(v, DofSet::vertical);
  const int q = s.index_of("body.bending");
  ASSERT_GE(q, 0);
  EXPECT_EQ(s.mass(q, q), 8000.0);
  EXPECT_NEAR(s.stiffness(q, q) - 4.0 * 4.3e5 * std::pow(model::free_free_mode_shape((9.5 + 12.0) / 24.0), 2),
              std::pow(2.0 * kPi * 9.0, 2) * 8000.0, 1e-9 * s.stiffness(q, q));
}

double bending_frequency(const Vehicle& v) {
  return mode_named(solve_modes(assemble(v, DofSet::vertical)), "body first vertical bending").frequency_hz;
}

TEST(BodyBendingAssembly, SoftSuspensionTendsToTheFreeFreeFrequency) {
  // Springs k at the four points add k·Σφ² to the mode's stiffness; the rigid modes sit far
  // below it, so to first order in k the frequency rises by f_b·kΣφ²/(2 m_b ω_b²) (first-order
  // perturbation of a simple eigenvalue), and the rest is O(k²). As k falls the excess goes to
  // zero and its ratio to the first-order term to 1: the free–free beam is the limit. f_b here
  // is the code's (its root against the printed one is the first test's business: their 5e-10 Hz
  // would blur a 1e-5 Hz excess).
  const double f = model::free_free_beam_frequency(kEI, kMassPerLength, kLength);
  const double omega = 2.0 * kPi * f, mb = kMassPerLength * kLength / 4.0;
  const double phi = model::free_free_mode_shape(21.5 / 24.0);  // at x = ±9.5 m
  double previous_error = 1.0;
  for (double k : {4.3e5, 4.3e3, 4.3e1}) {
    const double excess = bending_frequency(coach_body(9.5, k)) - f;
    const double first_order = f * 4.0 * k * phi * phi / (2.0 * mb * omega * omega);
    const double error = std::abs(excess / first_order - 1.0);
    EXPECT_GT(excess, 0.0) << k;  // springs only stiffen it
    // The O(k²) rest falls as k: measured 1.3e-2, 1.3e-4, 1.3e-6 of the first-order term.
    EXPECT_LT(error, 0.02 * previous_error) << k;
    previous_error = error;
  }
  // At 43 N/m (1e-4 of the coach's air springs) the excess is 1e-6 of f_b, first order to 1.3e-6.
  EXPECT_LT(previous_error, 1e-5);
}

TEST(BodyBendingAssembly, SupportsAtTheNodesDoNotCoupleBounceAndBending) {
  const double node = (0.5 - first_node()) * kLength;  // 0.2758 L either side of the centre
  for (double k : {4.3e5, 4.3e9}) {  // soft or stiff: the nodes do not move
    const LinearSystem s = assemble(coach_body(node, k), DofSet::vertical);
    const int bounce = s.index_of("body.bounce"), pitch = s.index_of("body.pitch"), q = s.index_of("body.bending");
    // φ(node) is round-off (1e-12 of the bisection's ξ ~ 1e-16, times k): relative to K(bounce, bounce).
    EXPECT_NEAR(s.stiffness(bounce, q), 0.0, 1e-12 * s.stiffness(bounce, bounce));
    EXPECT_NEAR(s.stiffness(pitch, q), 0.0, 1e-12 * s.stiffness(bounce, bounce));
    EXPECT_NEAR(s.stiffness(q, q), s.mass(q, q) * std::pow(2.0 * kPi * closed_form_frequency(), 2),
                1e-9 * s.stiffness(q, q));
    EXPECT_NEAR(bending_frequency(coach_body(node, k)), closed_form_frequency(), 1e-9 * closed_form_frequency());
  }
  // Off the nodes (the coach's bogie centres at ±9.5 m) the springs do couple them.
  const LinearSystem off = assemble(coach_body(9.5, 4.3e5), DofSet::vertical);
  const int bounce = off.index_of("body.bounce"), q = off.index_of("body.bending");
  EXPECT_NEAR(off.stiffness(bounce, q), 4.0 * 4.3e5 * model::free_free_mode_shape(21.5 / 24.0), 1e-9 * 4.3e5);
  EXPECT_EQ(off.stiffness(q, bounce), off.stiffness(bounce, q));
}

TEST(BodyBendingAssembly, RigidMotionsAreAssembledAsWithoutTheMode) {
  // The same body, rigid: every rigid entry of M and C is the same double; those of K and the
  // gravity stiffness are the same to round-off only, since the static solve for the element
  // loads now includes the bending coordinate (1e-12 of the largest entry: a few ε of the loads'
  // Cholesky solve). The bending DOF comes after the body's rigid motions, in the vertical set.
  const LinearSystem rigid = assemble(coach_body(9.5, 4.3e5, false), DofSet::all);
  const LinearSystem flexible = assemble(coach_body(9.5, 4.3e5), DofSet::all);
  ASSERT_EQ(flexible.size(), rigid.size() + 1);
  EXPECT_EQ(flexible.dofs.back().label, "body.bending");
  const int n = rigid.size();
  EXPECT_TRUE(flexible.mass.topLeftCorner(n, n) == rigid.mass);
  EXPECT_TRUE(flexible.damping.topLeftCorner(n, n) == rigid.damping);
  const double scale = rigid.stiffness.cwiseAbs().maxCoeff();
  EXPECT_LE((flexible.stiffness.topLeftCorner(n, n) - rigid.stiffness).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LE((flexible.gravity_stiffness.topLeftCorner(n, n) - rigid.gravity_stiffness).cwiseAbs().maxCoeff(),
            1e-12 * scale);
  EXPECT_TRUE(flexible.gravity_stiffness.col(n).isZero(0.0));
  // The weight does not bend a body on symmetric supports: the loads are the rigid body's (to
  // round-off of the static solve, 1e-12 of the load).
  for (size_t k = 0; k < rigid.element_loads.size(); ++k)
    EXPECT_NEAR(flexible.element_loads[k], rigid.element_loads[k], 1e-12 * rigid.element_loads[k]);
  // The element's stretch (upper end over lower) sees the bending: φ(x) per unit of it.
  EXPECT_EQ(flexible.element_vertical_map(0, n), model::free_free_mode_shape(21.5 / 24.0));
  // The track input pushes the bending coordinate through k·φ(x), vertically only.
  EXPECT_EQ(flexible.track_inputs[0].load_per_displacement(n, 2), 4.3e5 * model::free_free_mode_shape(21.5 / 24.0));
  EXPECT_EQ(flexible.track_inputs[0].load_per_displacement(n, 1), 0.0);
  const LinearSystem lateral = assemble(coach_body(9.5, 4.3e5), DofSet::lateral);
  EXPECT_LT(lateral.index_of("body.bending"), 0);
  EXPECT_GE(assemble(coach_body(9.5, 4.3e5), DofSet::vertical).index_of("body.bending"), 0);
}

TEST(BodyBendingAssembly, PointsAndPointForcesSeeTheMode) {
  const LinearSystem s = assemble(coach_body(9.5, 4.3e5), DofSet::vertical);
  const int q = s.index_of("body.bending"), bounce = s.index_of("body.bounce");
  // The ends move with q (φ = 1), the centre against it.
  const Eigen::MatrixXd end = model::point_displacement_map(s, 0, {-12.0, 0.0, 1.2});
  EXPECT_DOUBLE_EQ(end(2, q), 1.0);
  EXPECT_EQ(end(0, q), 0.0);
  EXPECT_EQ(end(1, q), 0.0);
  EXPECT_EQ(end(2, bounce), 1.0);
  const Eigen::MatrixXd centre = model::point_displacement_map(s, 0, {0.0, 0.5, 1.2});
  EXPECT_NEAR(centre(2, q), -0.607822229416, 1e-11);
  EXPECT_THROW(model::point_displacement_map(s, 0, {12.5, 0.0, 1.2}), std::invalid_argument);
  // A vertical force F at x does the work φ(x)·F on the bending coordinate.
  HarmonicLoad load;
  load.frequency_hz = 5.0;
  load.forces.push_back({0, {-6.0, 0.0, 1.2}, {0.0, 0.0, 1000.0}});
  const Eigen::VectorXcd Q = generalized_load(s, load);
  EXPECT_NEAR(Q(q).real(), 1000.0 * model::free_free_mode_shape(6.0 / 24.0), 1e-12);
  EXPECT_EQ(Q(bounce).real(), 1000.0);
}

TEST(BodyBendingAssembly, BadBendingDataIsRefusedNamingTheBody) {
  auto refused = [](Vehicle v, const std::string& part) {
    try {
      assemble(v, DofSet::all);
      ADD_FAILURE() << "no error: " << part;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  Vehicle both = coach_body(9.5, 4.3e5);
  both.bodies[0].bending->mode = BodyBending::Mode{9.0, 8000.0};
  refused(both, "body 'body': bending: give exactly one");
  Vehicle damped = coach_body(9.5, 4.3e5);
  damped.bodies[0].bending->damping_ratio = 1.0;
  refused(damped, "damping ratio");
  Vehicle short_beam = coach_body(9.5, 4.3e5);
  short_beam.bodies[0].bending->length = 18.0;
  refused(short_beam, "element 'spring' on body 'body' at x = 9.5");
  Vehicle held = coach_body(9.5, 4.3e5);
  held.bodies[0].held.push_back(Motion::bending);
  refused(held, "not a motion that can be held");
}

}  // namespace
}  // namespace railmodal::test
