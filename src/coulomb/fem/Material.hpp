#pragma once
/// @file Material.hpp
/// @brief Material parameters and the pointwise constitutive laws
/// (small-strain isotropic linear elasticity, compressible neo-Hookean).
///
/// Tensors are row-major Dim x Dim arrays: H_iJ = du_i/dX_J, F = I + H.
/// Voigt order for stresses is always 6 entries: xx yy zz xy yz xz.
/// 2D cells live in the x-y plane; plane strain means F_zz = 1 (eps_zz = 0),
/// plane stress means sigma_zz = 0 (linear elastic only). Axisymmetric: x is
/// the radius r >= 0 and y the axis z of a body of revolution (seed's Axisym
/// conditions), the out-of-plane strain is the hoop strain eps_tt = u_r / r,
/// the "zz" stress entry the hoop stress sigma_tt, and volume and surface
/// integrals take 2 pi r (forces and reactions are those of the whole ring).
#include <array>
#include <cmath>

namespace coulomb::fem {

/// @brief Constitutive model of a block.
enum class MaterialModel { LinearElastic, NeoHookean };

/// @brief Out-of-plane assumption of 2D cells (ignored for 3D cells).
enum class PlaneAssumption { PlaneStrain, PlaneStress, Axisymmetric };

/// @brief Everything the element kernels need to know about a block's material.
struct MaterialParameters {
  MaterialModel model = MaterialModel::LinearElastic;
  double youngsModulus = 0, poissonRatio = 0;
  PlaneAssumption plane = PlaneAssumption::PlaneStrain;
  double thickness = 1.0;  ///< 2D only: volume integrals are multiplied by it (not axisymmetric ones)
};

/// @brief A 2D block's axisymmetric (PlaneAssumption::Axisymmetric).
inline bool isAxisymmetric(const MaterialParameters& material, int dim) {
  return dim == 2 && material.plane == PlaneAssumption::Axisymmetric;
}

/// @brief What a 2D integral over a cell or face is multiplied by at a point
/// of radius `r` (its x): 2 pi r when axisymmetric, else the thickness; 1 in 3D.
inline double outOfPlaneMeasure(const MaterialParameters& material, int dim, double r) {
  if (dim != 2) return 1.0;
  constexpr double kTwoPi = 6.283185307179586;
  return material.plane == PlaneAssumption::Axisymmetric ? kTwoPi * r : material.thickness;
}

/// @brief Lame parameters mu = E/(2(1+nu)), lambda = E nu/((1+nu)(1-2nu)).
struct LameParameters {
  double mu = 0, lambda = 0;
};

/// @brief The 3D Lame parameters of a material.
LameParameters lameParameters(const MaterialParameters& material);

/// @brief The lambda acting in the in-plane relation sigma = lambda tr(eps) I + 2 mu eps:
/// lambda itself in 3D and plane strain, 2 lambda mu/(lambda + 2 mu) in plane stress.
double inPlaneLambda(const MaterialParameters& material, int dim);

/// @brief Small-strain Cauchy stress (Voigt, 6 entries) from the displacement gradient H
/// (and, axisymmetric, the hoop strain u_r / r).
///
/// eps = (H + H^T)/2, sigma = lambda' tr(eps) I + 2 mu eps in the plane (lambda' from
/// inPlaneLambda); 2D: sigma_zz = lambda (eps_xx + eps_yy) = nu (sigma_xx + sigma_yy) for plane
/// strain, 0 for plane stress, lambda tr(eps) + 2 mu eps_tt with tr(eps) including the hoop
/// strain eps_tt when axisymmetric; sigma_yz = sigma_xz = 0.
template <int Dim>
std::array<double, 6> linearElasticStress(const MaterialParameters& material, const std::array<double, Dim * Dim>& H,
                                          double hoopStrain = 0.0);

/// @brief Neo-Hookean Cauchy stress sigma = P F^T / J (Voigt, 6 entries) for det F > 0.
///
/// 2D is plane strain (F_zz = 1): sigma_zz = lambda ln(J) / J.
template <int Dim>
std::array<double, 6> neoHookeanCauchyStress(const MaterialParameters& material, const std::array<double, Dim * Dim>& F);

/// @brief Compressible neo-Hookean first Piola stress, generic in the scalar type (double or
/// Sacado Fad): P = mu (F - F^{-T}) + lambda ln(J) F^{-T}, J = det F. Returns J.
///
/// From the strain energy W = mu/2 (tr(F^T F) - 3) - mu ln J + lambda/2 (ln J)^2. In 2D the
/// Dim x Dim block is exact for plane strain (F_zz = 1). The caller must ensure J > 0.
template <typename Scalar, int Dim>
Scalar neoHookeanFirstPiola(double mu, double lambda, const std::array<Scalar, Dim * Dim>& F,
                            std::array<Scalar, Dim * Dim>& P) {
  using std::log;
  static_assert(Dim == 2 || Dim == 3, "neoHookeanFirstPiola: Dim must be 2 or 3");
  // cof = cofactor matrix of F, so F^{-T} = cof / J.
  std::array<Scalar, Dim * Dim> cof;
  if constexpr (Dim == 2) {
    cof[0] = F[3];
    cof[1] = -F[2];
    cof[2] = -F[1];
    cof[3] = F[0];
  } else {
    cof[0] = F[4] * F[8] - F[5] * F[7];
    cof[1] = F[5] * F[6] - F[3] * F[8];
    cof[2] = F[3] * F[7] - F[4] * F[6];
    cof[3] = F[2] * F[7] - F[1] * F[8];
    cof[4] = F[0] * F[8] - F[2] * F[6];
    cof[5] = F[1] * F[6] - F[0] * F[7];
    cof[6] = F[1] * F[5] - F[2] * F[4];
    cof[7] = F[2] * F[3] - F[0] * F[5];
    cof[8] = F[0] * F[4] - F[1] * F[3];
  }
  Scalar J = F[0] * cof[0] + F[1] * cof[1];
  if constexpr (Dim == 3) J += F[2] * cof[2];
  const Scalar c = (lambda * log(J) - mu) / J;  // coefficient of F^{-T} = cof / J
  for (int k = 0; k < Dim * Dim; ++k) P[k] = mu * F[k] + c * cof[k];
  return J;
}

}  // namespace coulomb::fem
