#pragma once
/// @file Formulations.hpp
/// @brief The constructors of the formulations, one per file of this folder
/// (FormulationFactory.cpp chooses). Each is a class template on the
/// dimension, instantiated for 2 and 3 in its file.
#include <memory>

#include "coulomb/contact/formulation/Formulation.hpp"

namespace coulomb::contact {

/// ALM and MPC, frictionless, condensed (AlmFrictionless.cpp).
template <int dim>
std::unique_ptr<Formulation> makeAlmFrictionless(const PairConstants& constants);
/// ALM and MPC with friction, condensed (AlmFrictional.cpp).
template <int dim>
std::unique_ptr<Formulation> makeAlmFrictional(const PairConstants& constants);
/// Penalty, with or without friction (Penalty.cpp).
template <int dim>
std::unique_ptr<Formulation> makePenalty(const PairConstants& constants);
/// Lagrange multipliers with the NCP functions (4.79), frictionless and
/// frictional, multipliers as unknowns; also ALM frictionless pairs in the
/// saddle-point form (LagrangeNcp.cpp).
template <int dim>
std::unique_ptr<Formulation> makeLagrangeNcp(const PairConstants& constants);

/// The first `dim` components of a 3-wide array.
template <int dim, class T>
std::array<T, dim> first(const std::array<T, 3>& v) {
  std::array<T, dim> out{};
  for (int c = 0; c < dim; ++c) out[c] = v[c];
  return out;
}

}  // namespace coulomb::contact
