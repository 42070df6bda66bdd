// What the assembly offers the analyses beside assemble (linear_system.hpp): the stiffness
// alone, for an analysis that needs nothing else (the metacentric height of a study's every
// variant), without the damping, track inputs and copy of the vehicle a LinearSystem holds.
#pragma once

#include <memory>
#include <vector>

#include "railmodal/linear_system.hpp"

namespace railmodal::model {

/// The system of assemble(vehicle, set) with only its dofs, stiffness and gravity_stiffness
/// filled, each bit for bit as assemble gives it (the same sums in the same order); every
/// other member empty. Throws as assemble does.
LinearSystem assemble_stiffness(const Vehicle& vehicle, DofSet set);

/// Each element's static vertical load under gravity, N, compression positive: the
/// element_loads of assemble(vehicle, set) for any set (the statics are solved on every free
/// coordinate), without the damping, track inputs and reduced matrices. Throws as assemble
/// does. What the reader checks a general vehicle's wheels with (a track element in tension).
std::vector<double> element_static_loads(const Vehicle& vehicle);

/// assemble(vehicle, set) and assemble_stiffness(vehicle, stiffness_set), bit for bit, from one
/// assembly of the full matrices (a study's variant: the vertical system it sweeps and the
/// lateral stiffness of its metacentric height).
struct SystemAndStiffness {
  LinearSystem system;
  LinearSystem stiffness;
};
SystemAndStiffness assemble_with_stiffness(const Vehicle& vehicle, DofSet set, DofSet stiffness_set);
/// The same with the vehicle moved into system.vehicle instead of copied (a study's worker
/// owns the variant it reads). Where it throws, `vehicle` is left as it was.
SystemAndStiffness assemble_with_stiffness(Vehicle&& vehicle, DofSet set, DofSet stiffness_set);

/// A study worker's assembly of many variants of one base vehicle (issue 19, item 2: variants as
/// parameter deltas on one assembled base). The first vehicle is assembled in full and what its
/// coefficients do not change is kept: the checks of its bodies and geometry, the coordinates
/// and the free ones, each element's point maps, M, the DOFs and their labels, the element
/// vertical map. A later vehicle that differs from the kept one only in its elements' spring
/// stages' stiffnesses, rotational stiffnesses and viscous dampings (the coefficients that
/// enter C and K linearly) has only these summed again, in the order assemble sums them, and
/// what depends on them (static loads, hangers' lateral stiffness, dead loads, track inputs,
/// series dampers) found again; any other vehicle is assembled in full and kept instead.
/// Either way the result is assemble_with_stiffness's, bit for bit.
class VariantAssembly {
 public:
  VariantAssembly();
  ~VariantAssembly();
  VariantAssembly(const VariantAssembly&) = delete;
  VariantAssembly& operator=(const VariantAssembly&) = delete;

  /// assemble_with_stiffness(std::move(vehicle), set, stiffness_set) into *system and
  /// *stiffness, their storage reused where it has the sizes (a caller that hands back the
  /// same two systems each variant allocates little). Throws as assemble does; `vehicle` is
  /// then left as it was, and so is what is kept.
  void assemble(Vehicle&& vehicle, DofSet set, DofSet stiffness_set, LinearSystem* system, LinearSystem* stiffness);

  /// Whether the last call reused the kept base (for tests).
  bool reused() const { return reused_; }

 private:
  struct Base;
  std::unique_ptr<Base> base_;
  bool reused_ = false;
};

}  // namespace railmodal::model
