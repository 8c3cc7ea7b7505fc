#pragma once
/// @file Formulations.hpp
/// @brief The constructors of the formulations, one per file of this folder
/// (FormulationFactory.cpp chooses). Each is a class template on the
/// dimension; its constructor here takes the dimension (2 or 3).
#include <memory>

#include "coulomb/contact/formulation/Formulation.hpp"

namespace coulomb::contact {

/// ALM and MPC, with friction or without, condensed (AlmFrictional.cpp).
std::unique_ptr<Formulation> makeAlmFrictional(int dim, const PairConstants& constants);
/// Penalty, with or without friction (Penalty.cpp).
std::unique_ptr<Formulation> makePenalty(int dim, const PairConstants& constants);
/// Lagrange multipliers with the NCP functions (4.79), frictionless and
/// frictional, multipliers as unknowns; also ALM frictionless pairs in the
/// saddle-point form (LagrangeNcp.cpp).
std::unique_ptr<Formulation> makeLagrangeNcp(int dim, const PairConstants& constants);

/// The first `dim` components of a 3-wide array.
template <int dim, class T>
std::array<T, dim> first(const std::array<T, 3>& v) {
  std::array<T, dim> out{};
  for (int c = 0; c < dim; ++c) out[c] = v[c];
  return out;
}

}  // namespace coulomb::contact
