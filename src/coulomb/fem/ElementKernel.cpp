/// @file ElementKernel.cpp
/// @brief Cell residual/tangent: plain-double linear elasticity, neo-Hookean with
/// a Sacado forward-AD material tangent.
#include "coulomb/fem/ElementKernel.hpp"

#include <Sacado.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/Quadrature.hpp"

namespace coulomb::fem {

const char* toString(KernelStatus status) {
  switch (status) {
    case KernelStatus::Ok: return "ok";
    case KernelStatus::InvertedReference: return "inverted reference cell (det J <= 0)";
    case KernelStatus::InvertedCurrent: return "inverted deformed cell (det F <= 0)";
  }
  return "unknown kernel status";
}

namespace {

template <mesh::CellType T>
KernelStatus fail(KernelStatus status, std::array<double, CellTraits<T>::dofs>& residual,
                  std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>* tangent) {
  residual.fill(0.0);
  if (tangent) tangent->fill(0.0);
  return status;
}

/// Displacement gradient H_ij = sum_a u_{a i} G_{a j} (row-major dim x dim).
template <int N, int D>
std::array<double, D * D> displacementGradient(const std::array<double, N * D>& u, const std::array<double, N * D>& G) {
  std::array<double, D * D> H{};
  for (int a = 0; a < N; ++a)
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) H[i * D + j] += u[a * D + i] * G[a * D + j];
  return H;
}

template <mesh::CellType T>
KernelStatus linearElastic(const MaterialParameters& material, const std::array<double, CellTraits<T>::dofs>& X,
                           const std::array<double, CellTraits<T>::dofs>& u,
                           const std::array<double, CellTraits<T>::dim>& b,
                           std::array<double, CellTraits<T>::dofs>& residual,
                           std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>* tangent) {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim, nd = CellTraits<T>::dofs;
  constexpr ReferenceShape S = CellTraits<T>::shape;
  const TabulatedShape<S>& tab = tabulatedShape<S>();
  const double mu = lameParameters(material).mu;
  const double lam = inPlaneLambda(material, d);
  const bool axisymmetric = isAxisymmetric(material, d);
  for (int q = 0; q < tab.points; ++q) {
    std::array<double, nd> G;
    const double detJ = physicalGradients<S>(X, tab.dNdxi[q], G);
    if (!(detJ > 0.0)) return fail<T>(KernelStatus::InvertedReference, residual, tangent);
    // Axisymmetric: the hoop strain u_r / r, whose variation N_a / r acts
    // on the radial DoFs (R[a] below; zero otherwise).
    double r = 0.0, hoop = 0.0;
    std::array<double, n> R{};
    if (axisymmetric) {
      for (int a = 0; a < n; ++a) r += tab.N[q][a] * X[a * d];
      if (!(r > 0.0)) return fail<T>(KernelStatus::InvertedReference, residual, tangent);
      for (int a = 0; a < n; ++a) R[a] = tab.N[q][a] / r, hoop += R[a] * u[a * d];
    }
    const double wdV = tab.weight[q] * detJ * outOfPlaneMeasure(material, d, r);
    const std::array<double, d * d> H = displacementGradient<n, d>(u, G);
    double tr = hoop;
    for (int i = 0; i < d; ++i) tr += H[i * d + i];
    double sigma[d][d];
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) sigma[i][j] = mu * (H[i * d + j] + H[j * d + i]) + (i == j ? lam * tr : 0.0);
    const double sigmaHoop = lam * tr + 2.0 * mu * hoop;
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i) {
        double s = -tab.N[q][a] * b[i] + (i == 0 ? sigmaHoop * R[a] : 0.0);
        for (int j = 0; j < d; ++j) s += sigma[i][j] * G[a * d + j];
        residual[a * d + i] += wdV * s;
      }
    if (!tangent) continue;
    auto& K = *tangent;
    for (int a = 0; a < n; ++a)
      for (int bb = a; bb < n; ++bb) {  // upper block triangle; mirrored below
        const double* Ga = &G[a * d];
        const double* Gb = &G[bb * d];
        double dot = 0.0;
        for (int j = 0; j < d; ++j) dot += Ga[j] * Gb[j];
        for (int i = 0; i < d; ++i) {
          double* row = &K[(a * d + i) * nd + bb * d];
          for (int k = 0; k < d; ++k)
            row[k] += wdV * (lam * Ga[i] * Gb[k] + mu * Ga[k] * Gb[i] + (i == k ? mu * dot : 0.0));
        }
        if (!axisymmetric) continue;
        // The hoop terms: tr(eps) gains R_b u_br, sigma_tt = lambda tr + 2 mu R_b u_br
        // acts on the radial rows through R_a.
        for (int i = 0; i < d; ++i)
          for (int k = 0; k < d; ++k) {
            double h = (k == 0 ? lam * Ga[i] * R[bb] : 0.0) + (i == 0 ? lam * R[a] * Gb[k] : 0.0);
            if (i == 0 && k == 0) h += (lam + 2.0 * mu) * R[a] * R[bb];
            K[(a * d + i) * nd + bb * d + k] += wdV * h;
          }
      }
  }
  if (tangent) {  // K is symmetric: block (b, a) = block (a, b)^T
    auto& K = *tangent;
    for (int a = 0; a < n; ++a)
      for (int bb = a + 1; bb < n; ++bb)
        for (int i = 0; i < d; ++i)
          for (int k = 0; k < d; ++k) K[(bb * d + k) * nd + a * d + i] = K[(a * d + i) * nd + bb * d + k];
  }
  return KernelStatus::Ok;
}

/// Neo-Hookean on an axisymmetric 2D cell (x = R, y = Z): the deformation
/// gradient is 3 x 3 with the in-plane block F and the hoop stretch
/// F_tt = 1 + u_r / R; the 3D first Piola P (Sacado over the five entries)
/// gives the in-plane rows through the gradients G and the hoop entry P_tt
/// through N_a / R; dV = 2 pi R dA (the reference configuration).
template <mesh::CellType T>
KernelStatus neoHookeanAxisymmetric(const MaterialParameters& material,
                                    const std::array<double, CellTraits<T>::dofs>& X,
                                    const std::array<double, CellTraits<T>::dofs>& u,
                                    const std::array<double, CellTraits<T>::dim>& b,
                                    std::array<double, CellTraits<T>::dofs>& residual,
                                    std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>* tangent) {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim, nd = CellTraits<T>::dofs;
  static_assert(d == 2, "axisymmetric cells are 2D");
  constexpr ReferenceShape S = CellTraits<T>::shape;
  constexpr int kVars = 5;  // F_rr, F_rz, F_zr, F_zz, F_tt
  using Fad = Sacado::Fad::SFad<double, kVars>;
  const TabulatedShape<S>& tab = tabulatedShape<S>();
  const LameParameters lame = lameParameters(material);
  for (int q = 0; q < tab.points; ++q) {
    std::array<double, nd> G;
    const double detJ = physicalGradients<S>(X, tab.dNdxi[q], G);
    double R = 0.0;
    for (int a = 0; a < n; ++a) R += tab.N[q][a] * X[a * d];
    if (!(detJ > 0.0) || !(R > 0.0)) return fail<T>(KernelStatus::InvertedReference, residual, tangent);
    std::array<double, n> NR{};  // N_a / R
    double hoop = 1.0;
    for (int a = 0; a < n; ++a) NR[a] = tab.N[q][a] / R, hoop += NR[a] * u[a * d];
    const double wdV = tab.weight[q] * detJ * outOfPlaneMeasure(material, d, R);
    std::array<double, d * d> F = displacementGradient<n, d>(u, G);
    for (int i = 0; i < d; ++i) F[i * d + i] += 1.0;
    if (!((F[0] * F[3] - F[1] * F[2]) * hoop > 0.0)) return fail<T>(KernelStatus::InvertedCurrent, residual, tangent);
    const double values[kVars] = {F[0], F[1], F[2], F[3], hoop};
    std::array<Fad, kVars> v;
    for (int k = 0; k < kVars; ++k) v[k] = Fad(kVars, k, values[k]);
    const std::array<Fad, 9> F3 = {v[0], v[1], Fad(0.0), v[2], v[3], Fad(0.0), Fad(0.0), Fad(0.0), v[4]};
    std::array<Fad, 9> P3;
    neoHookeanFirstPiola<Fad, 3>(lame.mu, lame.lambda, F3, P3);
    // The five stresses conjugate to the five entries, and their derivatives.
    const Fad* P[kVars] = {&P3[0], &P3[1], &P3[3], &P3[4], &P3[8]};
    // The variation of entry k by the DoF (a, i): in-plane F_iJ by G_aJ, F_tt by N_a / R (i = r).
    auto dEntry = [&](int k, int a, int i) {
      if (k == 4) return i == 0 ? NR[a] : 0.0;
      const int row = k / 2, column = k % 2;
      return row == i ? G[a * d + column] : 0.0;
    };
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i) {
        double s = -tab.N[q][a] * b[i];
        for (int k = 0; k < kVars; ++k) s += P[k]->val() * dEntry(k, a, i);
        residual[a * d + i] += wdV * s;
      }
    if (!tangent) continue;
    auto& K = *tangent;
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i)
        for (int bb = 0; bb < n; ++bb)
          for (int kk = 0; kk < d; ++kk) {
            double s = 0.0;
            for (int k = 0; k < kVars; ++k) {
              const double left = dEntry(k, a, i);
              if (left == 0.0) continue;
              for (int m = 0; m < kVars; ++m) s += left * P[k]->dx(m) * dEntry(m, bb, kk);
            }
            K[(a * d + i) * nd + bb * d + kk] += wdV * s;
          }
  }
  return KernelStatus::Ok;
}

template <mesh::CellType T>
KernelStatus neoHookean(const MaterialParameters& material, const std::array<double, CellTraits<T>::dofs>& X,
                        const std::array<double, CellTraits<T>::dofs>& u, const std::array<double, CellTraits<T>::dim>& b,
                        std::array<double, CellTraits<T>::dofs>& residual,
                        std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>* tangent) {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim, nd = CellTraits<T>::dofs;
  constexpr ReferenceShape S = CellTraits<T>::shape;
  using Fad = Sacado::Fad::SFad<double, d * d>;
  COULOMB_REQUIRE(d == 3 || material.plane == PlaneAssumption::PlaneStrain,
                  "the neo-Hookean model supports plane strain and axisymmetric 2D cells, not plane stress");
  const TabulatedShape<S>& tab = tabulatedShape<S>();
  const LameParameters lame = lameParameters(material);
  const double scale = outOfPlaneMeasure(material, d, 0.0);  // plane strain or 3D: no radius
  for (int q = 0; q < tab.points; ++q) {
    std::array<double, nd> G;
    const double detJ = physicalGradients<S>(X, tab.dNdxi[q], G);
    if (!(detJ > 0.0)) return fail<T>(KernelStatus::InvertedReference, residual, tangent);
    const double wdV = tab.weight[q] * detJ * scale;
    std::array<double, d * d> F = displacementGradient<n, d>(u, G);
    for (int i = 0; i < d; ++i) F[i * d + i] += 1.0;
    const double detF = d == 2 ? F[0] * F[3] - F[1] * F[2]
                               : F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                                     F[2] * (F[3] * F[7] - F[4] * F[6]);
    if (!(detF > 0.0)) return fail<T>(KernelStatus::InvertedCurrent, residual, tangent);

    std::array<double, d * d> P;
    double A[d * d][d * d] = {};  // A[iJ][kL] = dP_iJ / dF_kL (filled only with a tangent)
    if (tangent) {
      std::array<Fad, d * d> Ff, Pf;
      for (int k = 0; k < d * d; ++k) Ff[k] = Fad(d * d, k, F[k]);
      neoHookeanFirstPiola<Fad, d>(lame.mu, lame.lambda, Ff, Pf);
      for (int k = 0; k < d * d; ++k) {
        P[k] = Pf[k].val();
        for (int m = 0; m < d * d; ++m) A[k][m] = Pf[k].dx(m);
      }
    } else {
      neoHookeanFirstPiola<double, d>(lame.mu, lame.lambda, F, P);
    }

    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i) {
        double s = -tab.N[q][a] * b[i];
        for (int J = 0; J < d; ++J) s += P[i * d + J] * G[a * d + J];
        residual[a * d + i] += wdV * s;
      }
    if (!tangent) continue;
    auto& K = *tangent;
    for (int a = 0; a < n; ++a) {
      // AG[i][k][L] = sum_J G_aJ A[iJ][kL]
      double AG[d][d][d] = {};
      for (int i = 0; i < d; ++i)
        for (int J = 0; J < d; ++J) {
          const double g = G[a * d + J];
          for (int k = 0; k < d; ++k)
            for (int L = 0; L < d; ++L) AG[i][k][L] += g * A[i * d + J][k * d + L];
        }
      for (int bb = 0; bb < n; ++bb)
        for (int i = 0; i < d; ++i) {
          double* row = &K[(a * d + i) * nd + bb * d];
          for (int k = 0; k < d; ++k) {
            double s = 0.0;
            for (int L = 0; L < d; ++L) s += AG[i][k][L] * G[bb * d + L];
            row[k] += wdV * s;
          }
        }
    }
  }
  return KernelStatus::Ok;
}

}  // namespace

template <mesh::CellType T>
KernelStatus cellResidualTangent(const MaterialParameters& material, const std::array<double, CellTraits<T>::dofs>& X,
                                 const std::array<double, CellTraits<T>::dofs>& u,
                                 const std::array<double, CellTraits<T>::dim>& bodyForce,
                                 std::array<double, CellTraits<T>::dofs>& residual,
                                 std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>* tangent) {
  residual.fill(0.0);
  if (tangent) tangent->fill(0.0);
  if (material.model == MaterialModel::NeoHookean) {
    if constexpr (CellTraits<T>::dim == 2)
      if (isAxisymmetric(material, 2)) return neoHookeanAxisymmetric<T>(material, X, u, bodyForce, residual, tangent);
    return neoHookean<T>(material, X, u, bodyForce, residual, tangent);
  }
  return linearElastic<T>(material, X, u, bodyForce, residual, tangent);
}

#define COULOMB_INSTANTIATE_CELL(T)                                                                            \
  template KernelStatus cellResidualTangent<T>(                                                                \
      const MaterialParameters&, const std::array<double, CellTraits<T>::dofs>&,                               \
      const std::array<double, CellTraits<T>::dofs>&, const std::array<double, CellTraits<T>::dim>&,            \
      std::array<double, CellTraits<T>::dofs>&, std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>*);
COULOMB_INSTANTIATE_CELL(mesh::CellType::Quad4)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Tri3)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Hex8)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Tet4)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Quad8)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Quad9)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Tri6)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Hex20)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Hex27)
COULOMB_INSTANTIATE_CELL(mesh::CellType::Tet10)
#undef COULOMB_INSTANTIATE_CELL

}  // namespace coulomb::fem
