#pragma once
/// @file ModelSettings.hpp
/// @brief The physical model a deck describes (materials per block, loads,
/// boundary conditions) as typed values, and the valid-parameter lists of
/// the deck sublists that describe it.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coulomb/fem/Material.hpp"
#include "coulomb/fem/TimeFunction.hpp"

namespace Teuchos {
class ParameterList;
}

namespace coulomb::fem {

/// @brief u_c(X, t) = (value + coefficients · X) f(t) on every node of a node set.
struct DirichletCondition {
  std::string name;                        ///< the deck sublist name (for messages)
  std::string nodeSet;                     ///< node set name as in the mesh
  std::vector<int> components;             ///< 0 = x, 1 = y, 2 = z
  double value = 0.0;                      ///< constant part [length]
  std::vector<double> linearCoefficients;  ///< optional gradient part (empty = none)
  TimeFunction function = TimeFunction::ramp();
  /// Rigid rotation (the deck gives a Rotation Angle, even 0: all components): the node set turns
  /// by rotationAngle × f(t) about rotationCenter (axis rotationAxis in 3D,
  /// z in 2D), carrying the displacement the conditions listed before this
  /// one prescribe on its nodes: u = R (X + v - C) + C - X.
  bool rotation = false;
  double rotationAngle = 0.0;
  std::array<double, 3> rotationCenter{};
  std::array<double, 3> rotationAxis{0.0, 0.0, 1.0};
};

/// @brief A dead load on a side set of the reference configuration.
struct NeumannCondition {
  enum class Kind { Pressure, Traction };
  std::string name;
  std::string sideSet;
  Kind kind = Kind::Pressure;
  double pressure = 0.0;                ///< [force/area], > 0 pushes into the body
  std::array<double, 3> traction{};     ///< [force/area]
  TimeFunction function = TimeFunction::ramp();
};

/// @brief A body force per reference volume on one block (or all blocks).
struct BodyForce {
  std::string name;
  std::optional<std::string> block;     ///< empty: every block
  std::array<double, 3> force{};        ///< [force/volume]
  TimeFunction function = TimeFunction::ramp();
};

/// @brief Everything the bulk model needs from the deck.
struct ModelSettings {
  std::map<std::string, MaterialParameters> blockMaterials;  ///< by block name
  std::vector<DirichletCondition> dirichlet;
  std::vector<NeumannCondition> neumann;
  std::vector<BodyForce> bodyForces;
  /// The blocks are axisymmetric sections ('Problem/Plane Assumption' is one for all blocks).
  bool axisymmetric(int dimension) const {
    return !blockMaterials.empty() && isAxisymmetric(blockMaterials.begin()->second, dimension);
  }
};

/// @brief Valid parameters of "Materials", "Element Blocks", "Functions",
/// "Dirichlet Conditions", "Neumann Conditions", "Body Forces", "Problem".
void addValidModelParameters(Teuchos::ParameterList& valid);

/// @brief Typed model from a validated deck. `dimension` is the mesh's
/// (components and vectors are checked against it).
ModelSettings parseModelSettings(const Teuchos::ParameterList& deck, int dimension);

}  // namespace coulomb::fem
