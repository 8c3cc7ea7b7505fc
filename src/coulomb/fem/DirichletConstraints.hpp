#pragma once
/// @file DirichletConstraints.hpp
/// @brief Prescribed displacement DoFs and their values in time.
///
/// Constrained DoFs stay in the system: Newton starts each step from the
/// prescribed values, their residual rows are u − ū and their matrix rows and
/// columns are those of the identity, which keeps the tangent symmetric for
/// CG. Where two conditions constrain the same DoF, the later one in the deck wins.
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

private:
  struct Prescribed {
    int ownedLocalDof;
    double offset;  ///< Value + c · X
    const TimeFunction* function;
  };
  double prescribed(const Prescribed& p, double time) const { return p.offset * (*p.function)(time); }

  std::vector<DirichletCondition> conditions_;  // owns the TimeFunctions pointed to
  std::vector<char> constrained_;
  std::vector<Prescribed> owned_;
};

}  // namespace coulomb::fem
