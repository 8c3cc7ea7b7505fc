/// @file StressKernel.cpp
/// @brief Nodal stress recovery and von Mises stress.
#include "coulomb/fem/StressKernel.hpp"

#include <cmath>

#include "coulomb/fem/Quadrature.hpp"

namespace coulomb::fem {

template <mesh::CellType T>
KernelStatus cellNodalStress(const MaterialParameters& material, const std::array<double, CellTraits<T>::dofs>& X,
                             const std::array<double, CellTraits<T>::dofs>& u,
                             std::array<double, CellTraits<T>::nodes * 6>& weightedStress,
                             std::array<double, CellTraits<T>::nodes>& weight) {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim, nd = CellTraits<T>::dofs;
  constexpr ReferenceShape S = CellTraits<T>::shape;
  const TabulatedShape<S>& tab = tabulatedShape<S>();
  weightedStress.fill(0.0);
  weight.fill(0.0);
  for (int q = 0; q < tab.points; ++q) {
    std::array<double, nd> G;
    const double detJ = physicalGradients<S>(X, tab.dNdxi[q], G);
    KernelStatus status = KernelStatus::Ok;
    std::array<double, 6> sigma{};
    double r = 0.0;  // x: the radius of an axisymmetric cell
    for (int a = 0; a < n; ++a) r += tab.N[q][a] * X[a * d];
    if (!(detJ > 0.0)) {
      status = KernelStatus::InvertedReference;
    } else {
      std::array<double, d * d> H{};  // H_ij = sum_a u_{a i} G_{a j}
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < d; ++i)
          for (int j = 0; j < d; ++j) H[i * d + j] += u[a * d + i] * G[a * d + j];
      if (material.model == MaterialModel::LinearElastic) {
        double hoop = 0.0;  // axisymmetric: u_r / r
        if (isAxisymmetric(material, d) && r > 0.0)
          for (int a = 0; a < n; ++a) hoop += tab.N[q][a] * u[a * d] / r;
        sigma = linearElasticStress<d>(material, H, hoop);
      } else {
        for (int i = 0; i < d; ++i) H[i * d + i] += 1.0;  // now F
        const double detF = d == 2 ? H[0] * H[3] - H[1] * H[2]
                                   : H[0] * (H[4] * H[8] - H[5] * H[7]) - H[1] * (H[3] * H[8] - H[5] * H[6]) +
                                         H[2] * (H[3] * H[7] - H[4] * H[6]);
        double hoop = 1.0;  // axisymmetric: F_tt = 1 + u_r / R
        if constexpr (d == 2)
          if (isAxisymmetric(material, d) && r > 0.0)
            for (int a = 0; a < n; ++a) hoop += tab.N[q][a] * u[a * d] / r;
        if (!(detF * hoop > 0.0)) {
          status = KernelStatus::InvertedCurrent;
        } else if constexpr (d == 2) {
          if (isAxisymmetric(material, d)) {
            MaterialParameters solid = material;
            solid.plane = PlaneAssumption::PlaneStrain;  // the 3D law: no plane assumption left
            sigma = neoHookeanCauchyStress<3>(solid, {H[0], H[1], 0.0, H[2], H[3], 0.0, 0.0, 0.0, hoop});
          } else {
            sigma = neoHookeanCauchyStress<d>(material, H);
          }
        } else {
          sigma = neoHookeanCauchyStress<d>(material, H);
        }
      }
    }
    if (status != KernelStatus::Ok) {
      weightedStress.fill(0.0);
      weight.fill(0.0);
      return status;
    }
    const double wdV = tab.weight[q] * detJ * outOfPlaneMeasure(material, d, r);
    for (int a = 0; a < n; ++a) {
      // Quadratic cells: N_a^2 (see the header: \int N_a is zero or negative at their corners).
      const double w = wdV * (mesh::isQuadratic(T) ? tab.N[q][a] * tab.N[q][a] : tab.N[q][a]);
      weight[a] += w;
      for (int k = 0; k < 6; ++k) weightedStress[a * 6 + k] += w * sigma[k];
    }
  }
  return KernelStatus::Ok;
}

double vonMises(const std::array<double, 6>& s) {
  const double dxy = s[0] - s[1], dyz = s[1] - s[2], dzx = s[2] - s[0];
  const double shear = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) + 3.0 * shear);
}

#define COULOMB_INSTANTIATE_STRESS(T)                                                                          \
  template KernelStatus cellNodalStress<T>(const MaterialParameters&, const std::array<double, CellTraits<T>::dofs>&, \
                                           const std::array<double, CellTraits<T>::dofs>&,                      \
                                           std::array<double, CellTraits<T>::nodes * 6>&,                       \
                                           std::array<double, CellTraits<T>::nodes>&);
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Quad4)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Tri3)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Hex8)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Tet4)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Quad8)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Quad9)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Tri6)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Hex20)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Hex27)
COULOMB_INSTANTIATE_STRESS(mesh::CellType::Tet10)
#undef COULOMB_INSTANTIATE_STRESS

}  // namespace coulomb::fem
