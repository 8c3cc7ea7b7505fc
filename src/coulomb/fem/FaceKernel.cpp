/// @file FaceKernel.cpp
/// @brief Surface-load integration on Line2/Line3, Tri3/Tri6 and Quad4/Quad8/Quad9 faces.
#include "coulomb/fem/FaceKernel.hpp"

#include <cmath>

#include "coulomb/fem/Quadrature.hpp"

namespace coulomb::fem {
namespace {

/// Area-weighted outward normal n dA / (dxi deta) at quadrature point q:
/// 2D: (dY/dxi, -dX/dxi); 3D: dX/dxi x dX/deta.
template <mesh::FaceType F>
std::array<double, FaceTraits<F>::dim> areaNormal(const std::array<double, FaceTraits<F>::dofs>& X, int q) {
  constexpr int n = FaceTraits<F>::nodes, d = FaceTraits<F>::dim;
  constexpr ReferenceShape S = FaceTraits<F>::shape;
  constexpr int p = ShapeTraits<S>::dim;  // parametric dimension d - 1
  const TabulatedShape<S>& tab = tabulatedShape<S>();
  double t[p][d] = {};  // t[j] = dX/dxi_j
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < p; ++j)
      for (int i = 0; i < d; ++i) t[j][i] += tab.dNdxi[q][a * p + j] * X[a * d + i];
  std::array<double, d> nd;
  if constexpr (d == 2) {
    nd = {t[0][1], -t[0][0]};
  } else {
    nd = {t[0][1] * t[1][2] - t[0][2] * t[1][1], t[0][2] * t[1][0] - t[0][0] * t[1][2],
          t[0][0] * t[1][1] - t[0][1] * t[1][0]};
  }
  return nd;
}

/// The 2D out-of-plane measure at quadrature point q: 2 pi x when
/// axisymmetric, else the thickness (1 for 3D faces).
template <mesh::FaceType F>
double outOfPlane(const std::array<double, FaceTraits<F>::dofs>& X, int q, double thickness, bool axisymmetric) {
  constexpr int n = FaceTraits<F>::nodes, d = FaceTraits<F>::dim;
  if (d != 2) return 1.0;
  if (!axisymmetric) return thickness;
  const TabulatedShape<FaceTraits<F>::shape>& tab = tabulatedShape<FaceTraits<F>::shape>();
  double r = 0.0;
  for (int a = 0; a < n; ++a) r += tab.N[q][a] * X[a * d];
  return 6.283185307179586 * r;
}

template <int D>
double norm(const std::array<double, D>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

}  // namespace

template <mesh::FaceType F>
void faceTractionForces(const std::array<double, FaceTraits<F>::dofs>& X,
                        const std::array<double, FaceTraits<F>::dim>& traction, double thickness,
                        std::array<double, FaceTraits<F>::dofs>& force, bool axisymmetric) {
  constexpr int n = FaceTraits<F>::nodes, d = FaceTraits<F>::dim;
  const TabulatedShape<FaceTraits<F>::shape>& tab = tabulatedShape<FaceTraits<F>::shape>();
  force.fill(0.0);
  for (int q = 0; q < tab.points; ++q) {
    const double dA = tab.weight[q] * norm<d>(areaNormal<F>(X, q)) * outOfPlane<F>(X, q, thickness, axisymmetric);
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i) force[a * d + i] += tab.N[q][a] * traction[i] * dA;
  }
}

template <mesh::FaceType F>
void facePressureForces(const std::array<double, FaceTraits<F>::dofs>& X, double pressure, double thickness,
                        std::array<double, FaceTraits<F>::dofs>& force, bool axisymmetric) {
  constexpr int n = FaceTraits<F>::nodes, d = FaceTraits<F>::dim;
  const TabulatedShape<FaceTraits<F>::shape>& tab = tabulatedShape<FaceTraits<F>::shape>();
  force.fill(0.0);
  for (int q = 0; q < tab.points; ++q) {
    const std::array<double, d> ndA = areaNormal<F>(X, q);
    const double w = -pressure * tab.weight[q] * outOfPlane<F>(X, q, thickness, axisymmetric);
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < d; ++i) force[a * d + i] += w * tab.N[q][a] * ndA[i];
  }
}

template <mesh::FaceType F>
double faceArea(const std::array<double, FaceTraits<F>::dofs>& X) {
  const TabulatedShape<FaceTraits<F>::shape>& tab = tabulatedShape<FaceTraits<F>::shape>();
  double area = 0.0;
  for (int q = 0; q < tab.points; ++q) area += tab.weight[q] * norm<FaceTraits<F>::dim>(areaNormal<F>(X, q));
  return area;
}

template <mesh::FaceType F>
std::array<double, FaceTraits<F>::dim> faceAreaVector(const std::array<double, FaceTraits<F>::dofs>& X) {
  const TabulatedShape<FaceTraits<F>::shape>& tab = tabulatedShape<FaceTraits<F>::shape>();
  std::array<double, FaceTraits<F>::dim> v{};
  for (int q = 0; q < tab.points; ++q) {
    const std::array<double, FaceTraits<F>::dim> ndA = areaNormal<F>(X, q);
    for (int i = 0; i < FaceTraits<F>::dim; ++i) v[i] += tab.weight[q] * ndA[i];
  }
  return v;
}

#define COULOMB_INSTANTIATE_FACE(F)                                                                         \
  template void faceTractionForces<F>(const std::array<double, FaceTraits<F>::dofs>&,                       \
                                      const std::array<double, FaceTraits<F>::dim>&, double,                \
                                      std::array<double, FaceTraits<F>::dofs>&, bool);                      \
  template void facePressureForces<F>(const std::array<double, FaceTraits<F>::dofs>&, double, double,       \
                                      std::array<double, FaceTraits<F>::dofs>&, bool);                      \
  template double faceArea<F>(const std::array<double, FaceTraits<F>::dofs>&);                              \
  template std::array<double, FaceTraits<F>::dim> faceAreaVector<F>(const std::array<double, FaceTraits<F>::dofs>&);
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Line2)
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Tri3)
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Quad4)
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Line3)
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Tri6)
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Quad8)
COULOMB_INSTANTIATE_FACE(mesh::FaceType::Quad9)
#undef COULOMB_INSTANTIATE_FACE

}  // namespace coulomb::fem
