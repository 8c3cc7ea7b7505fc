#pragma once
/// @file FrictionLaw.hpp
/// @brief The frictional threshold Θ of a slave node (seed eq. 4.1, 4.70c,
/// 4.76): the largest tangential traction the contact can carry before it
/// slips, as a function of the augmented normal multiplier lambdā_n (a
/// traction, <= 0 in compression, ActiveSet.hpp).
///
///   None    : Θ = 0 (frictionless; every active node slides)
///   Coulomb : Θ = mu <-lambdā_n>      (4.76, ALM: mu (k n.lambda + eps_n g~/D))
///   Tresca  : Θ = g                   (constant threshold, independent of pressure)
///
/// Adding a law = one more enumerator, one line in frictionThreshold, and its
/// name in the deck validator (ContactSettings.cpp). The function is a
/// template on the scalar so the nodal kernel differentiates it with Sacado.
#include <algorithm>
#include <type_traits>

namespace coulomb::contact {

enum class FrictionLawType { None, Coulomb, Tresca };

/// @brief A pair's friction law and its parameters.
struct FrictionLaw {
  FrictionLawType type = FrictionLawType::None;
  double coefficient = 0.0;  ///< mu >= 0 (Coulomb)
  double threshold = 0.0;    ///< Tresca threshold g > 0 [traction]
  /// No tangential traction at all (no law, or Coulomb with mu = 0): the
  /// pair runs frictionless, the seed's automatic FrictionalPureSlip when
  /// every mu is zero (ContactPairSettings::frictional).
  bool frictionless() const {
    return type == FrictionLawType::None || (type == FrictionLawType::Coulomb && coefficient == 0.0);
  }
};

const char* toString(FrictionLawType type);

/// @brief Θ(lambdā_n) >= 0 [traction].
template <class Scalar>
Scalar frictionThreshold(const FrictionLaw& law, const Scalar& augmentedNormal) {
  switch (law.type) {
    case FrictionLawType::Coulomb: {
      const Scalar pressure = -augmentedNormal;
      double value;
      if constexpr (std::is_same_v<Scalar, double>) value = pressure;
      else value = pressure.val();
      return value > 0.0 ? Scalar(law.coefficient * pressure) : Scalar(0.0);
    }
    case FrictionLawType::Tresca:
      return Scalar(law.threshold);
    case FrictionLawType::None:
      break;
  }
  return Scalar(0.0);
}

}  // namespace coulomb::contact
