#pragma once
#include <array>
/// @file DirichletConstraints.hpp
/// @brief Prescribed displacement DoFs and their values in time.
///
/// Constrained DoFs stay in the system: their residual rows are u − ū and
/// their matrix rows and columns are those of the identity, which keeps the
/// tangent symmetric for CG. Newton starts each step from the prescribed
/// values, or (Load Stepping/Boundary Increment = Tangent: Simulation.cpp)
/// from the predictor's: an iterate whose prescribed DoFs lag behind ū gets
/// the coupling K_fp (ū − u_p) of that lag added to its free rows by the
/// assembler, so the first Newton step takes the boundary increment
/// through the tangent instead of the dropped columns. Where two conditions
/// constrain the same DoF, the later one in the deck wins.
#include <vector>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::fem {

class DirichletConstraints {
public:
  DirichletConstraints(const mesh::Mesh& mesh, const DofMap& dofs, const std::vector<DirichletCondition>& conditions);

  /// Is overlap-local DoF `dof` prescribed?
  bool isConstrained(int overlapLocalDof) const { return constrained_[overlapLocalDof] != 0; }
  /// Writes ū(t) into the prescribed entries of an owned vector.
  void setPrescribedValues(double time, Vector& ownedU) const;
  /// Replaces the prescribed rows of an owned residual by u − ū(t).
  void setResidualRows(double time, const Vector& ownedU, Vector& ownedResidual) const;
  /// Owned-local indices of prescribed DoFs.
  std::vector<int> ownedConstrainedDofs() const;
  /// Writes ū(t) − u into the prescribed entries of an owned vector and zero
  /// elsewhere (the boundary increment still to be taken by an iterate that
  /// does not carry the prescribed values); whether any entry of this rank is
  /// not zero.
  bool pendingIncrements(double time, const Vector& ownedU, Vector& ownedPending) const;

private:
  /// A node turned rigidly by a condition with a Rotation Angle.
  struct NodeRotation {
    std::array<double, 3> X{};           ///< reference position
    std::array<double, 3> offset{};      ///< displacement prescribed before, per component: offset × base(t)
    std::array<const TimeFunction*, 3> base{};
    const DirichletCondition* rotation = nullptr;
  };
  struct Prescribed {
    int ownedLocalDof;
    double offset;  ///< Value + c · X
    const TimeFunction* function;
    int component = 0;
    int rotation = -1;  ///< index in rotations_, or -1
  };
  double prescribed(const Prescribed& p, double time) const;

  std::vector<DirichletCondition> conditions_;  // owns the TimeFunctions pointed to
  std::vector<char> constrained_;
  std::vector<Prescribed> owned_;
  std::vector<NodeRotation> rotations_;
  int dim_ = 3;
};

}  // namespace coulomb::fem
