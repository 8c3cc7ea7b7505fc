/// @file ShapeFunctions.cpp
/// @brief Linear Lagrange shape functions and the isoparametric gradient map.
#include "coulomb/fem/ShapeFunctions.hpp"

#include "coulomb/core/Error.hpp"

namespace coulomb::fem {
namespace {

// Corner signs of the tensor-product elements (Exodus order).
constexpr double kQuadSign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double kHexSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

}  // namespace

template <ReferenceShape S>
std::array<double, ShapeTraits<S>::dim> referenceNode(int a) {
  COULOMB_REQUIRE(a >= 0 && a < ShapeTraits<S>::nodes, "referenceNode: node index " << a << " out of range");
  std::array<double, ShapeTraits<S>::dim> xi{};
  if constexpr (S == ReferenceShape::Line2) {
    xi[0] = a == 0 ? -1.0 : 1.0;
  } else if constexpr (S == ReferenceShape::Quad4) {
    xi = {kQuadSign[a][0], kQuadSign[a][1]};
  } else if constexpr (S == ReferenceShape::Hex8) {
    xi = {kHexSign[a][0], kHexSign[a][1], kHexSign[a][2]};
  } else {  // simplices: node 0 at the origin, node k at the k-th unit vector
    if (a > 0) xi[a - 1] = 1.0;
  }
  return xi;
}

// N_a = 1/2 (1 + xi_a xi)                          (Line2)
// N_0 = 1 - xi - eta [- zeta], N_k = xi_k          (Tri3, Tet4)
// N_a = 1/4 (1 + xi_a xi)(1 + eta_a eta)            (Quad4)
// N_a = 1/8 (1 + xi_a xi)(1 + eta_a eta)(1 + zeta_a zeta)  (Hex8)
template <ReferenceShape S>
void shapeValues(const std::array<double, ShapeTraits<S>::dim>& xi, std::array<double, ShapeTraits<S>::nodes>& N) {
  if constexpr (S == ReferenceShape::Line2) {
    N[0] = 0.5 * (1.0 - xi[0]);
    N[1] = 0.5 * (1.0 + xi[0]);
  } else if constexpr (S == ReferenceShape::Tri3) {
    N[0] = 1.0 - xi[0] - xi[1];
    N[1] = xi[0];
    N[2] = xi[1];
  } else if constexpr (S == ReferenceShape::Tet4) {
    N[0] = 1.0 - xi[0] - xi[1] - xi[2];
    N[1] = xi[0];
    N[2] = xi[1];
    N[3] = xi[2];
  } else if constexpr (S == ReferenceShape::Quad4) {
    for (int a = 0; a < 4; ++a)
      N[a] = 0.25 * (1.0 + kQuadSign[a][0] * xi[0]) * (1.0 + kQuadSign[a][1] * xi[1]);
  } else {
    for (int a = 0; a < 8; ++a)
      N[a] = 0.125 * (1.0 + kHexSign[a][0] * xi[0]) * (1.0 + kHexSign[a][1] * xi[1]) *
             (1.0 + kHexSign[a][2] * xi[2]);
  }
}

template <ReferenceShape S>
void shapeGradients(const std::array<double, ShapeTraits<S>::dim>& xi,
                    std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& dNdxi) {
  if constexpr (S == ReferenceShape::Line2) {
    (void)xi;
    dNdxi = {-0.5, 0.5};
  } else if constexpr (S == ReferenceShape::Tri3) {
    (void)xi;
    dNdxi = {-1, -1, 1, 0, 0, 1};
  } else if constexpr (S == ReferenceShape::Tet4) {
    (void)xi;
    dNdxi = {-1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  } else if constexpr (S == ReferenceShape::Quad4) {
    for (int a = 0; a < 4; ++a) {
      const double sx = kQuadSign[a][0], sy = kQuadSign[a][1];
      dNdxi[a * 2 + 0] = 0.25 * sx * (1.0 + sy * xi[1]);
      dNdxi[a * 2 + 1] = 0.25 * sy * (1.0 + sx * xi[0]);
    }
  } else {
    for (int a = 0; a < 8; ++a) {
      const double sx = kHexSign[a][0], sy = kHexSign[a][1], sz = kHexSign[a][2];
      const double fx = 1.0 + sx * xi[0], fy = 1.0 + sy * xi[1], fz = 1.0 + sz * xi[2];
      dNdxi[a * 3 + 0] = 0.125 * sx * fy * fz;
      dNdxi[a * 3 + 1] = 0.125 * sy * fx * fz;
      dNdxi[a * 3 + 2] = 0.125 * sz * fx * fy;
    }
  }
}

template <ReferenceShape S>
double physicalGradients(const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& X,
                         const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& dNdxi,
                         std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& dNdX) {
  constexpr int n = ShapeTraits<S>::nodes;
  constexpr int d = ShapeTraits<S>::dim;
  static_assert(d == 2 || d == 3, "physicalGradients: cells are 2D or 3D");
  double J[d][d] = {};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) J[i][j] += X[a * d + i] * dNdxi[a * d + j];
  double inv[d][d];  // inverse of J
  double det;
  if constexpr (d == 2) {
    det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (!(det > 0.0)) return det;
    const double r = 1.0 / det;
    inv[0][0] = J[1][1] * r;
    inv[0][1] = -J[0][1] * r;
    inv[1][0] = -J[1][0] * r;
    inv[1][1] = J[0][0] * r;
  } else {
    const double c00 = J[1][1] * J[2][2] - J[1][2] * J[2][1];
    const double c01 = J[1][2] * J[2][0] - J[1][0] * J[2][2];
    const double c02 = J[1][0] * J[2][1] - J[1][1] * J[2][0];
    det = J[0][0] * c00 + J[0][1] * c01 + J[0][2] * c02;
    if (!(det > 0.0)) return det;
    const double r = 1.0 / det;
    inv[0][0] = c00 * r;
    inv[1][0] = c01 * r;
    inv[2][0] = c02 * r;
    inv[0][1] = (J[0][2] * J[2][1] - J[0][1] * J[2][2]) * r;
    inv[1][1] = (J[0][0] * J[2][2] - J[0][2] * J[2][0]) * r;
    inv[2][1] = (J[0][1] * J[2][0] - J[0][0] * J[2][1]) * r;
    inv[0][2] = (J[0][1] * J[1][2] - J[0][2] * J[1][1]) * r;
    inv[1][2] = (J[0][2] * J[1][0] - J[0][0] * J[1][2]) * r;
    inv[2][2] = (J[0][0] * J[1][1] - J[0][1] * J[1][0]) * r;
  }
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < d; ++i) {
      double s = 0.0;
      for (int j = 0; j < d; ++j) s += dNdxi[a * d + j] * inv[j][i];
      dNdX[a * d + i] = s;
    }
  return det;
}

#define COULOMB_INSTANTIATE_SHAPE(S)                                                                    \
  template std::array<double, ShapeTraits<S>::dim> referenceNode<S>(int);                             \
  template void shapeValues<S>(const std::array<double, ShapeTraits<S>::dim>&,                         \
                               std::array<double, ShapeTraits<S>::nodes>&);                            \
  template void shapeGradients<S>(const std::array<double, ShapeTraits<S>::dim>&,                      \
                                  std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&);
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Line2)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Tri3)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Quad4)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Tet4)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Hex8)
#undef COULOMB_INSTANTIATE_SHAPE

#define COULOMB_INSTANTIATE_GRADIENTS(S)                                                               \
  template double physicalGradients<S>(const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&, \
                                       const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&, \
                                       std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&);
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Tri3)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Quad4)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Tet4)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Hex8)
#undef COULOMB_INSTANTIATE_GRADIENTS

}  // namespace coulomb::fem
