/// @file Material.cpp
/// @brief Lame parameters and the double-precision stress evaluations.
#include "coulomb/fem/Material.hpp"

#include "coulomb/core/Error.hpp"

namespace coulomb::fem {

LameParameters lameParameters(const MaterialParameters& material) {
  const double E = material.youngsModulus, nu = material.poissonRatio;
  LameParameters lame;
  lame.mu = E / (2.0 * (1.0 + nu));
  lame.lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  return lame;
}

double inPlaneLambda(const MaterialParameters& material, int dim) {
  const LameParameters lame = lameParameters(material);
  if (dim == 2 && material.plane == PlaneAssumption::PlaneStress)
    return 2.0 * lame.lambda * lame.mu / (lame.lambda + 2.0 * lame.mu);  // = E nu / (1 - nu^2)
  return lame.lambda;
}

template <int Dim>
std::array<double, 6> linearElasticStress(const MaterialParameters& material, const std::array<double, Dim * Dim>& H,
                                          double hoopStrain) {
  const LameParameters lame = lameParameters(material);
  const double lam = inPlaneLambda(material, Dim);
  std::array<double, 6> s{};
  if constexpr (Dim == 2) {
    const double tr = H[0] + H[3] + hoopStrain;
    s[0] = lam * tr + 2.0 * lame.mu * H[0];
    s[1] = lam * tr + 2.0 * lame.mu * H[3];
    s[2] = material.plane == PlaneAssumption::PlaneStress ? 0.0 : lame.lambda * tr + 2.0 * lame.mu * hoopStrain;
    s[3] = lame.mu * (H[1] + H[2]);
  } else {
    const double tr = H[0] + H[4] + H[8];
    s[0] = lam * tr + 2.0 * lame.mu * H[0];
    s[1] = lam * tr + 2.0 * lame.mu * H[4];
    s[2] = lam * tr + 2.0 * lame.mu * H[8];
    s[3] = lame.mu * (H[1] + H[3]);
    s[4] = lame.mu * (H[5] + H[7]);
    s[5] = lame.mu * (H[2] + H[6]);
  }
  return s;
}

template <int Dim>
std::array<double, 6> neoHookeanCauchyStress(const MaterialParameters& material, const std::array<double, Dim * Dim>& F) {
  COULOMB_REQUIRE(Dim == 3 || material.plane == PlaneAssumption::PlaneStrain,
                  "the neo-Hookean model supports plane strain only in 2D");
  const LameParameters lame = lameParameters(material);
  std::array<double, Dim * Dim> P;
  const double J = neoHookeanFirstPiola<double, Dim>(lame.mu, lame.lambda, F, P);
  // sigma_ij = (1/J) sum_K P_iK F_jK
  auto sigma = [&](int i, int j) {
    double v = 0.0;
    for (int k = 0; k < Dim; ++k) v += P[i * Dim + k] * F[j * Dim + k];
    return v / J;
  };
  std::array<double, 6> s{};
  s[0] = sigma(0, 0);
  s[1] = sigma(1, 1);
  s[3] = sigma(0, 1);
  if constexpr (Dim == 3) {
    s[2] = sigma(2, 2);
    s[4] = sigma(1, 2);
    s[5] = sigma(0, 2);
  } else {
    s[2] = lame.lambda * std::log(J) / J;  // P_zz F_zz / J with F_zz = 1
  }
  return s;
}

template std::array<double, 6> linearElasticStress<2>(const MaterialParameters&, const std::array<double, 4>&, double);
template std::array<double, 6> linearElasticStress<3>(const MaterialParameters&, const std::array<double, 9>&, double);
template std::array<double, 6> neoHookeanCauchyStress<2>(const MaterialParameters&, const std::array<double, 4>&);
template std::array<double, 6> neoHookeanCauchyStress<3>(const MaterialParameters&, const std::array<double, 9>&);

}  // namespace coulomb::fem
