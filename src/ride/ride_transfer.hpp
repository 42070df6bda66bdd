// From the track to the outputs, per frequency: how each irregularity component displaces the
// track inputs, the linear map of each requested output, and the DOF receptances to every
// input (docs/ride.md, "The response to random track").
#pragma once

#include <Eigen/Core>
#include <complex>
#include <string>
#include <vector>

#include "railmodal/ride.hpp"
#include "ride/ride_contact.hpp"

namespace railmodal::ride {

/// One irregularity component of the request.
struct Component {
  TrackIrregularity kind = TrackIrregularity::vertical_level;
  TrackSpectrum spectrum;
  /// Per track input: the displacement (longitudinal, lateral, vertical; m) of the track under
  /// it per metre of the component. Level (0, 0, 1); alignment (0, 1, 0); cross-level Δz rolls
  /// the rails by θ = Δz/(2b) about the rail top, r0 below the axle plane: (0, −θ(z + r0), θy)
  /// per unit Δz (cross_level_directions, the time domain's too).
  std::vector<Eigen::Vector3d> displacement;
};

/// The components of `track` in the order vertical level, alignment, cross-level. Throws
/// std::invalid_argument for none, a spectrum in the wrong slot, no track input, and a lateral
/// input (alignment; cross-level among lateral DOFs) on a vehicle with wheelsets, whose
/// lateral track input acts through the wheel–rail contact that the ride does not model yet,
/// and for a component that loads no degree of freedom (alignment on a vertical model: its
/// answer would be a silent zero).
std::vector<Component> track_components(const LinearSystem& system, const TrackIrregularitySpectra& track,
                                        double contact_half_spacing, double rolling_radius);

/// Throws std::invalid_argument("<analysis>: element '<name>' stands on the track with a series
/// damper, …") for the first series damper on an element with a track input: the track would
/// move one end of its spring, an input neither domain of the ride models yet.
void refuse_series_dampers_on_track(const LinearSystem& system, const char* analysis);

/// One output as a linear map of the DOF response X and the track displacements u_i:
///   y(ω) = (iω)^order · [a(ω)·X + Σ_terms t(ω)·u_input] + g·X,
///   a(ω) = a0 + iω·a1 − Σ_series k_s(ω)·stretch,  t(ω) = t0 + iω·t1 + (iω)²·t2,
/// g the accelerometer's gravity row (gravity_row; empty, no term, in the track frame).
struct OutputMap {
  int order = 0;  ///< 0 displacement (or force), 1 velocity, 2 acceleration
  Eigen::RowVectorXd a0, a1;
  Eigen::RowVectorXd gravity;  ///< empty, or per DOF: g·φ's or −g·θ's coefficient
  std::vector<SeriesDamperRow> series;  ///< Maxwell elements whose force the output carries
  std::vector<int> inputs;              ///< track inputs with a direct term
  std::vector<Eigen::Vector3d> t0, t1, t2;
  /// (iω)^order · a(ω).
  Eigen::RowVectorXcd row(double omega) const;
  /// (iω)^order · t(ω)·u of direct term `term`.
  std::complex<double> track(std::size_t term, const Eigen::Vector3d& u, double omega) const;
};

/// The map of each output. `friction_damping` (per element, N·s/m; may be empty) adds the
/// linearised leaf friction to an element's vertical damping in its force. With `contact` (and
/// `system` its with_creep at `speed`) a wheelset's lateral wheel–rail force is the contact's.
/// Throws std::invalid_argument naming an output whose name is empty or repeated, or whose body,
/// element or wheelset the system does not have, a lateral wheel–rail force without the
/// contact, and a longitudinal one (zero in the linear contact).
std::vector<OutputMap> output_maps(const LinearSystem& system, const std::vector<RideOutput>& outputs,
                                   const std::vector<double>& friction_damping, const CreepContact* contact = nullptr,
                                   double speed = 0.0);

/// The gravity term an accelerometer fixed to the output's body reads along its tilted axis,
/// per DOF: laterally +g on the body's roll (ÿ + g·φ), longitudinally −g on its pitch (ẍ − g·θ;
/// pitch right-handed about y, nose down), g = Vehicle::gravity. Empty where it does not enter
/// (reads_gravity false, or no roll or pitch DOF of that body). A bending mode's local slope is
/// left out (it tilts a longitudinal axis only). Both domains use it: the frequency domain adds
/// g·H_φ to the output's H, the time domain g·φ(t) to its history.
Eigen::RowVectorXd gravity_row(const LinearSystem& system, const RideOutput& output);

/// What a reader must know of the frame of the outputs' lateral and longitudinal point
/// accelerations: one note for those read by an accelerometer on the body (with the gravity
/// component), one for those in the track's frame; none without such outputs. And one for each
/// output that asks for frame = body on a body without the tilt it needs (no roll DOF for a
/// lateral reading, no pitch for a longitudinal one): that body cannot tilt, so the reading is the
/// inertial one, and the note says so rather than leaving out g·φ silently.
std::vector<std::string> frame_notes(const LinearSystem& system, const std::vector<RideOutput>& outputs);

/// The map of element k's vertical stretch rate (upper relative to lower, track subtracted), m/s.
OutputMap stretch_rate_map(const LinearSystem& system, int element);

/// k_s(ω) = iωck/(k + iωc): a damper c with a spring k in series, as one complex stiffness.
std::complex<double> maxwell_stiffness(double stiffness, double damping, double omega);

/// Solves D·Y = B in place (B becomes Y, D its LU factors) by Gaussian elimination with
/// partial pivoting (the row of the largest modulus in the column, as LAPACK's zgetrf) on
/// column-major storage: D n × n, B n × r. `pivots` receives the moduli of U's pivots and
/// `inverse` their reciprocals, n values each, all the caller's (no allocation: it runs at every
/// grid frequency). A zero pivot stops the elimination there (the pivots after it stay zero and
/// B is left unfinished): the caller refuses the singular matrix, and no NaN or infinity is
/// formed. For the ride's small systems.
void solve_in_place(int n, int r, std::complex<double>* D, std::complex<double>* B, double* pivots,
                    std::complex<double>* inverse);

/// The modal basis an output's modal terms are taken in: X = Σ_j φ_j q_j, q_j = φ_jᵀM X.
struct ModalBasis {
  Eigen::MatrixXd shapes;  ///< n × J, mass-normalised
  Eigen::MatrixXd left;    ///< J × n: ΦᵀM
};

/// What does not depend on speed, one column per grid frequency (C components, m input groups,
/// O outputs, J modes of the split). An input group is the track inputs at one x (the two
/// wheels of an axle): at every speed they share their delay, so their loads are summed
/// before the solve and each speed combines m groups, not every input.
///
/// The matrices may have more columns than the grid has points: a Receptances kept across
/// solves (ride::Workspace) keeps its storage when a later grid is shorter, and only the first
/// grid-size columns are the current solve's (every reader indexes them by grid point). Without
/// modal terms (modes = 0) `modal` and `modal_rows` are not read and may hold an earlier solve's.
struct Receptances {
  int outputs = 0, components = 0, inputs = 0, modes = 0;
  std::vector<double> x;  ///< per input group: its position along the vehicle, m (x forward)
  /// Row (o·C + c)·m + g: h_{o,c,g}(f), output o's response to component c entering at group g's
  /// inputs alone: a_o(ω)·X_{c,g} + Σ_{i∈g} t_{o,i}(ω)·u_{c,i}, X_{c,g} = D⁻¹Σ_{i∈g}(P_i + iωV_i)u_{c,i}.
  Eigen::MatrixXcd response;
  /// Row (j·C + c)·m + g: φ_jᵀM X_{c,g}, mode j's coordinate (with a split basis).
  Eigen::MatrixXcd modal;
  /// Row o·J + j: |a_o(ω)·φ_j|², how much of mode j output o sees (squared: all a speed needs).
  Eigen::MatrixXd modal_rows;
};

/// Solves the dynamic stiffness K − ω²M + iωC (+ the series dampers' k_s(ω)) once per grid
/// frequency for every input group at once; with a basis Φ (n × J, not null) in the reduced
/// coordinates X = Φq, (ΦᵀDΦ)q = ΦᵀQ (modal truncation). Throws railmodal::NumericalError naming
/// the frequency where the matrix is singular. With `split` (not null) the modal terms too.
/// Writes into `r`, whose matrices are reallocated only when their rows change or the grid
/// outgrows their columns (the ride's largest arrays: a caller that solves again keeps them).
void receptances(const LinearSystem& system, const std::vector<Component>& components,
                 const std::vector<OutputMap>& maps, const Eigen::VectorXd& grid, const Eigen::MatrixXd* basis,
                 const ModalBasis* split, Receptances* r);

}  // namespace railmodal::ride
