/// @file ShapeFunctions.cpp
/// @brief Linear and quadratic Lagrange shape functions and the isoparametric gradient map.
#include "coulomb/fem/ShapeFunctions.hpp"

#include "coulomb/core/Error.hpp"

namespace coulomb::fem {
namespace {

// Corner signs of the tensor-product elements (Exodus order).
constexpr double kQuadSign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double kHexSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// Reference coordinates of the quadratic tensor-product nodes (Exodus order,
// see mesh::nodeCorners): Quad8 is the first 8 of Quad9, Hex20 the first 20 of Hex27.
constexpr double kQuad9Node[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
constexpr double kHex27Node[27][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1},  // corners
    {0, -1, -1},  {1, 0, -1},  {0, 1, -1}, {-1, 0, -1},                                                  // bottom edges
    {-1, -1, 0},  {1, -1, 0},  {1, 1, 0},  {-1, 1, 0},                                                   // vertical edges
    {0, -1, 1},   {1, 0, 1},   {0, 1, 1},  {-1, 0, 1},                                                   // top edges
    {0, 0, 0},    {0, 0, -1},  {0, 0, 1},  {-1, 0, 0},  {1, 0, 0},  {0, -1, 0}, {0, 1, 0}};            // centres
// Edges of the quadratic simplices, in the order of their edge nodes.
constexpr int kTri6Edge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kTet10Edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

/// 1D quadratic Lagrange function of the node at c in {-1, 0, 1} on {-1, 0, 1}, and its derivative.
double lagrange2(double c, double x) { return c == 0.0 ? 1.0 - x * x : 0.5 * x * (x + c); }
double lagrange2Derivative(double c, double x) { return c == 0.0 ? -2.0 * x : x + 0.5 * c; }

/// Full tensor-product quadratic Lagrange (Line3, Quad9, Hex27): N_a = prod_i L(c_ai, xi_i).
template <int D, int N>
void tensorValues(const double (&node)[N][D], const double* xi, double* values, double* gradients) {
  for (int a = 0; a < N; ++a) {
    double l[D], dl[D];
    for (int i = 0; i < D; ++i) {
      l[i] = lagrange2(node[a][i], xi[i]);
      dl[i] = lagrange2Derivative(node[a][i], xi[i]);
    }
    if (values) {
      double v = 1.0;
      for (int i = 0; i < D; ++i) v *= l[i];
      values[a] = v;
    }
    if (gradients)
      for (int j = 0; j < D; ++j) {
        double g = dl[j];
        for (int i = 0; i < D; ++i)
          if (i != j) g *= l[i];
        gradients[a * D + j] = g;
      }
  }
}

/// Serendipity quadratics (Quad8, Hex20) on the first N nodes of `node`:
///   corner:    N_a = 2^-D prod_i (1 + c_i x_i) (sum_i c_i x_i - (D - 1))
///   mid-edge:  N_a = 2^-(D-1) (1 - x_k^2) prod_{i != k} (1 + c_i x_i), c_k = 0
template <int D, int N, int M>
void serendipityValues(const double (&node)[M][D], const double* xi, double* values, double* gradients) {
  static_assert(N <= M, "serendipity nodes are the leading nodes of the Lagrange table");
  for (int a = 0; a < N; ++a) {
    const double* c = node[a];
    int zero = -1;
    for (int i = 0; i < D; ++i)
      if (c[i] == 0.0) zero = i;
    double f[D];  // f_i = 1 + c_i x_i
    for (int i = 0; i < D; ++i) f[i] = 1.0 + c[i] * xi[i];
    if (zero < 0) {
      const double scale = 1.0 / (1 << D);
      double s = -(D - 1), p = scale;
      for (int i = 0; i < D; ++i) s += c[i] * xi[i], p *= f[i];
      if (values) values[a] = p * s;
      if (gradients)
        for (int j = 0; j < D; ++j) {
          // d/dx_j [f_j s] = c_j s + f_j c_j
          double g = scale * c[j] * (s + f[j]);
          for (int i = 0; i < D; ++i)
            if (i != j) g *= f[i];
          gradients[a * D + j] = g;
        }
    } else {
      const double scale = 1.0 / (1 << (D - 1));
      const double bubble = 1.0 - xi[zero] * xi[zero];
      double p = scale * bubble;
      for (int i = 0; i < D; ++i)
        if (i != zero) p *= f[i];
      if (values) values[a] = p;
      if (gradients)
        for (int j = 0; j < D; ++j) {
          double g = scale * (j == zero ? -2.0 * xi[zero] : bubble * c[j]);
          for (int i = 0; i < D; ++i)
            if (i != j && i != zero) g *= f[i];
          gradients[a * D + j] = g;
        }
    }
  }
}

/// Quadratic simplices (Tri6, Tet10) in barycentric coordinates L_0 = 1 - sum xi, L_k = xi_{k-1}:
/// corner N_a = L_a (2 L_a - 1), edge (a, b) N = 4 L_a L_b.
template <int D, int E>
void simplexValues(const int (&edges)[E][2], const double* xi, double* values, double* gradients) {
  double L[D + 1];
  L[0] = 1.0;
  for (int i = 0; i < D; ++i) L[i + 1] = xi[i], L[0] -= xi[i];
  auto dL = [](int k, int j) { return k == 0 ? -1.0 : (k == j + 1 ? 1.0 : 0.0); };  // dL_k / dxi_j
  for (int a = 0; a <= D; ++a) {
    if (values) values[a] = L[a] * (2.0 * L[a] - 1.0);
    if (gradients)
      for (int j = 0; j < D; ++j) gradients[a * D + j] = (4.0 * L[a] - 1.0) * dL(a, j);
  }
  for (int e = 0; e < E; ++e) {
    const int a = edges[e][0], b = edges[e][1], node = D + 1 + e;
    if (values) values[node] = 4.0 * L[a] * L[b];
    if (gradients)
      for (int j = 0; j < D; ++j) gradients[node * D + j] = 4.0 * (dL(a, j) * L[b] + L[a] * dL(b, j));
  }
}

/// Values and/or parametric gradients of the quadratic shapes (null pointers skip a part).
template <ReferenceShape S>
void quadraticShape(const double* xi, double* values, double* gradients) {
  static constexpr double kLine3Node[3][1] = {{-1}, {1}, {0}};
  if constexpr (S == ReferenceShape::Line3) {
    tensorValues<1, 3>(kLine3Node, xi, values, gradients);
  } else if constexpr (S == ReferenceShape::Quad9) {
    tensorValues<2, 9>(kQuad9Node, xi, values, gradients);
  } else if constexpr (S == ReferenceShape::Hex27) {
    tensorValues<3, 27>(kHex27Node, xi, values, gradients);
  } else if constexpr (S == ReferenceShape::Quad8) {
    serendipityValues<2, 8>(kQuad9Node, xi, values, gradients);
  } else if constexpr (S == ReferenceShape::Hex20) {
    serendipityValues<3, 20>(kHex27Node, xi, values, gradients);
  } else if constexpr (S == ReferenceShape::Tri6) {
    simplexValues<2>(kTri6Edge, xi, values, gradients);
  } else {
    static_assert(S == ReferenceShape::Tet10, "quadraticShape: not a quadratic shape");
    simplexValues<3>(kTet10Edge, xi, values, gradients);
  }
}

constexpr bool isQuadratic(ReferenceShape s) { return numNodes(s) > 8 || s == ReferenceShape::Line3 ||
                                                      s == ReferenceShape::Tri6 || s == ReferenceShape::Quad8; }

}  // namespace

template <ReferenceShape S>
std::array<double, ShapeTraits<S>::dim> referenceNode(int a) {
  COULOMB_REQUIRE(a >= 0 && a < ShapeTraits<S>::nodes, "referenceNode: node index " << a << " out of range");
  std::array<double, ShapeTraits<S>::dim> xi{};
  if constexpr (S == ReferenceShape::Line2) {
    xi[0] = a == 0 ? -1.0 : 1.0;
  } else if constexpr (S == ReferenceShape::Line3) {
    xi[0] = a == 0 ? -1.0 : a == 1 ? 1.0 : 0.0;
  } else if constexpr (S == ReferenceShape::Quad8 || S == ReferenceShape::Quad9) {
    xi = {kQuad9Node[a][0], kQuad9Node[a][1]};
  } else if constexpr (S == ReferenceShape::Hex20 || S == ReferenceShape::Hex27) {
    xi = {kHex27Node[a][0], kHex27Node[a][1], kHex27Node[a][2]};
  } else if constexpr (S == ReferenceShape::Tri6 || S == ReferenceShape::Tet10) {
    // corners as the linear simplex; an edge node at the mean of its ends
    constexpr int d = ShapeTraits<S>::dim;
    auto corner = [](int c) {
      std::array<double, d> x{};
      if (c > 0) x[c - 1] = 1.0;
      return x;
    };
    if (a <= d) return corner(a);
    const int* e = S == ReferenceShape::Tri6 ? kTri6Edge[a - 3] : kTet10Edge[a - 4];
    const auto p = corner(e[0]), q = corner(e[1]);
    for (int i = 0; i < d; ++i) xi[i] = 0.5 * (p[i] + q[i]);
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
  if constexpr (isQuadratic(S)) {
    quadraticShape<S>(xi.data(), N.data(), nullptr);
  } else if constexpr (S == ReferenceShape::Line2) {
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
  if constexpr (isQuadratic(S)) {
    quadraticShape<S>(xi.data(), nullptr, dNdxi.data());
  } else if constexpr (S == ReferenceShape::Line2) {
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
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Line3)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Tri6)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Quad8)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Quad9)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Tet10)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Hex20)
COULOMB_INSTANTIATE_SHAPE(ReferenceShape::Hex27)
#undef COULOMB_INSTANTIATE_SHAPE

#define COULOMB_INSTANTIATE_GRADIENTS(S)                                                               \
  template double physicalGradients<S>(const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&, \
                                       const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&, \
                                       std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>&);
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Tri3)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Quad4)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Tet4)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Hex8)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Tri6)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Quad8)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Quad9)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Tet10)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Hex20)
COULOMB_INSTANTIATE_GRADIENTS(ReferenceShape::Hex27)
#undef COULOMB_INSTANTIATE_GRADIENTS

}  // namespace coulomb::fem
