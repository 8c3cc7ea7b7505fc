// Averaged nodal normals of contact surfaces: exact on flat faces, O(h²) on
// smoothly faceted circles, cylinders and spheres, Sacado derivatives against
// central finite differences on distorted Line2 / Tri3 / Quad4 patches.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "coulomb/contact/interface/NodalNormals.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using V3 = std::array<double, 3>;
constexpr double kPi = 3.14159265358979323846;

/// A faceted surface: nodes, faces of one type (node numbers in outward order).
struct Surface {
  int dim = 3;
  FaceType type = FaceType::Quad4;
  std::vector<V3> x;
  std::vector<std::array<long long, 4>> faces;

  long long addNode(const V3& p) {
    x.push_back(p);
    return static_cast<long long>(x.size()) - 1;
  }
  int faceNodes() const { return mesh::numNodes(type); }

  std::vector<FaceAtNode> facesAt(long long node) const {
    std::vector<FaceAtNode> around;
    for (const auto& f : faces)
      for (int a = 0; a < faceNodes(); ++a)
        if (f[a] == node) {
          FaceAtNode& face = around.emplace_back();
          face.type = type;
          face.corner = a;
          for (int b = 0; b < faceNodes(); ++b) face.nodes[b] = f[b];
          for (int b = 0; b < faceNodes(); ++b) face.x[b] = x[f[b]];
        }
    return around;
  }
  NodalNormal normal(long long node, bool derivative = false) const {
    return averagedNormal(dim, facesAt(node), derivative);
  }
};

double angleBetween(const V3& a, const V3& b) {
  const V3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double s = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::atan2(s, d);
}

V3 unitV(V3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& c : v) c /= n;
  return v;
}

// ---------------------------------------------------------------- flat faces

// A structured nx x ny grid on the plane through c spanned by e1, e2 (normal e1 × e2),
// nodes moved in-plane by a deterministic distortion; Quad4 or Tri3 faces.
Surface planeGrid(FaceType type, int nx, int ny, const V3& c, const V3& e1, const V3& e2, double distortion) {
  Surface s;
  s.type = type;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool inner = i > 0 && i < nx && j > 0 && j < ny;
      const double a = i + (inner ? distortion * std::sin(3.1 * i + 1.7 * j) : 0.0);
      const double b = j + (inner ? distortion * std::cos(2.3 * i - 0.9 * j) : 0.0);
      s.addNode({c[0] + a * e1[0] + b * e2[0], c[1] + a * e1[1] + b * e2[1], c[2] + a * e1[2] + b * e2[2]});
    }
  auto n = [&](int i, int j) { return static_cast<long long>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (type == FaceType::Quad4) {
        s.faces.push_back({n(i, j), n(i + 1, j), n(i + 1, j + 1), n(i, j + 1)});
      } else {
        s.faces.push_back({n(i, j), n(i + 1, j), n(i + 1, j + 1), -1});
        s.faces.push_back({n(i, j), n(i + 1, j + 1), n(i, j + 1), -1});
      }
    }
  return s;
}

TEST(ContactNormals, FlatQuadAndTriFacesGiveThePlaneNormal) {
  const V3 e1{0.3, 0.1, -0.2}, e2{-0.05, 0.25, 0.15};
  const V3 expected = unitV({e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]});
  for (FaceType type : {FaceType::Quad4, FaceType::Tri3}) {
    const Surface s = planeGrid(type, 4, 3, {1.0, -2.0, 0.5}, e1, e2, 0.25);
    for (long long node = 0; node < static_cast<long long>(s.x.size()); ++node) {
      const V3 n = s.normal(node).n;
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(n[i], expected[i], 1e-13) << "node " << node;
    }
  }
}

TEST(ContactNormals, StraightLineGivesTheLineNormal) {
  Surface s;
  s.dim = 2;
  s.type = FaceType::Line2;
  const double t[] = {0.0, 0.3, 0.45, 1.1, 1.2};
  const V3 d = unitV({2.0, 1.0, 0.0});
  for (double ti : t) s.addNode({1.0 + ti * d[0], -1.0 + ti * d[1], 0.0});
  for (long long k = 0; k + 1 < 5; ++k) s.faces.push_back({k, k + 1, -1, -1});
  for (long long node = 0; node < 5; ++node) {
    const V3 n = s.normal(node).n;
    EXPECT_NEAR(n[0], d[1], 1e-14);  // (dy, -dx): outward to the right of the direction of travel
    EXPECT_NEAR(n[1], -d[0], 1e-14);
    EXPECT_EQ(n[2], 0.0);
  }
}

TEST(ContactNormals, CancellingFacesAreAnErrorNamingTheNode) {
  // Two segments folded back onto each other: (dy,-dx) of a->b and b->a' cancel at b.
  Surface s;
  s.dim = 2;
  s.type = FaceType::Line2;
  s.addNode({0.0, 0.0, 0.0});
  s.addNode({1.0, 0.0, 0.0});
  s.addNode({0.0, 0.0, 0.0});
  s.faces = {{0, 1, -1, -1}, {1, 2, -1, -1}};
  try {
    s.normal(1);
    FAIL() << "expected coulomb::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("node 2"), std::string::npos) << e.what();
  }
  // A zero-length edge.
  s.faces = {{0, 2, -1, -1}};
  EXPECT_THROW(s.normal(0), Error);
}

// ------------------------------------------------- curved surfaces, O(h²)

// Smooth, non-uniform periodic grading of [0, 2 pi) (monotone): h_i - h_{i-1} = O(h²).
double gradedAngle(int i, int n) {
  const double s = static_cast<double>(i) / n;
  return 2.0 * kPi * s + 0.3 * std::sin(2.0 * kPi * s);
}

// Circle of radius R (2D, Line2, counter-clockwise: outward normal is radial).
double circleError(int n) {
  Surface s;
  s.dim = 2;
  s.type = FaceType::Line2;
  const double R = 1.7;
  for (int i = 0; i < n; ++i) s.addNode({R * std::cos(gradedAngle(i, n)), R * std::sin(gradedAngle(i, n)), 0.0});
  for (long long i = 0; i < n; ++i) s.faces.push_back({i, (i + 1) % n, -1, -1});
  double error = 0.0;
  for (long long i = 0; i < n; ++i) error = std::max(error, angleBetween(s.normal(i).n, unitV(s.x[i])));
  return error;
}

// Cylinder x² + y² = R² (Quad4 faces, outward), graded in the angle, non-uniform in z.
double cylinderError(int n) {
  Surface s;
  s.type = FaceType::Quad4;
  const double R = 0.8;
  const int nz = n / 4;
  for (int k = 0; k <= nz; ++k) {
    const double t = static_cast<double>(k) / nz;
    const double z = 2.0 * (t + 0.1 * std::sin(kPi * t));
    for (int i = 0; i < n; ++i) s.addNode({R * std::cos(gradedAngle(i, n)), R * std::sin(gradedAngle(i, n)), z});
  }
  auto node = [&](int i, int k) { return static_cast<long long>(k * n + (i % n)); };
  for (int k = 0; k < nz; ++k)
    for (int i = 0; i < n; ++i) s.faces.push_back({node(i, k), node(i + 1, k), node(i + 1, k + 1), node(i, k + 1)});
  double error = 0.0;
  for (long long m = 0; m < static_cast<long long>(s.x.size()); ++m)
    error = std::max(error, angleBetween(s.normal(m).n, unitV({s.x[m][0], s.x[m][1], 0.0})));
  return error;
}

// Band |latitude| <= 60° of a sphere, graded in longitude and latitude; Quad4
// faces or Tri3 (each quad split along one diagonal). Error at interior nodes
// (the band's edge rows see faces on one side only).
double sphereError(FaceType type, int n) {
  Surface s;
  s.type = type;
  const double R = 1.3;
  const int nl = n / 2;
  for (int k = 0; k <= nl; ++k) {
    const double t = static_cast<double>(k) / nl;
    const double lat = kPi / 3.0 * (2.0 * t - 1.0 + 0.15 * std::sin(kPi * t));
    for (int i = 0; i < n; ++i) {
      const double lon = gradedAngle(i, n);
      s.addNode({R * std::cos(lat) * std::cos(lon), R * std::cos(lat) * std::sin(lon), R * std::sin(lat)});
    }
  }
  auto node = [&](int i, int k) { return static_cast<long long>(k * n + (i % n)); };
  for (int k = 0; k < nl; ++k)
    for (int i = 0; i < n; ++i) {
      // counter-clockwise seen from outside: east then north
      const long long a = node(i, k), b = node(i + 1, k), c = node(i + 1, k + 1), d = node(i, k + 1);
      if (type == FaceType::Quad4) {
        s.faces.push_back({a, b, c, d});
      } else {
        s.faces.push_back({a, b, c, -1});
        s.faces.push_back({a, c, d, -1});
      }
    }
  double error = 0.0;
  for (int k = 1; k < nl; ++k)
    for (int i = 0; i < n; ++i) error = std::max(error, angleBetween(s.normal(node(i, k)).n, unitV(s.x[node(i, k)])));
  return error;
}

void expectSecondOrder(const std::function<double(int)>& error, const char* what) {
  const double e1 = error(16), e2 = error(32), e3 = error(64);
  const double rate1 = std::log2(e1 / e2), rate2 = std::log2(e2 / e3);
  EXPECT_GT(e1, 1e-6) << what << ": error suspiciously small (symmetric grid?)";
  EXPECT_LT(e1, 0.05) << what;
  EXPECT_NEAR(rate1, 2.0, 0.3) << what << ": errors " << e1 << " " << e2 << " " << e3;
  EXPECT_NEAR(rate2, 2.0, 0.2) << what << ": errors " << e1 << " " << e2 << " " << e3;
}

TEST(ContactNormals, CircleLine2IsSecondOrder) { expectSecondOrder(circleError, "circle, Line2"); }
TEST(ContactNormals, CylinderQuad4IsSecondOrder) { expectSecondOrder(cylinderError, "cylinder, Quad4"); }
TEST(ContactNormals, SphereQuad4IsSecondOrder) {
  expectSecondOrder([](int n) { return sphereError(FaceType::Quad4, n); }, "sphere, Quad4");
}
TEST(ContactNormals, SphereTri3IsSecondOrder) {
  expectSecondOrder([](int n) { return sphereError(FaceType::Tri3, n); }, "sphere, Tri3");
}

// ------------------------------------------------------------ derivatives

// d n / d x of the normal at `node` against central differences over every
// coordinate of every node of the surface (nodes outside the faces around the
// node must have zero derivative, and must be absent from the sparse list).
void checkDerivative(Surface s, long long node) {
  const NodalNormal exact = s.normal(node, true);
  std::map<std::pair<long long, int>, V3> ad;
  for (const auto& entry : exact.derivative) {
    const bool inserted = ad.emplace(std::make_pair(entry.node, entry.component), entry.dn).second;
    EXPECT_TRUE(inserted) << "duplicate derivative entry";
  }
  double scale = 0.0;
  for (const auto& [key, dn] : ad)
    for (double v : dn) scale = std::max(scale, std::abs(v));
  ASSERT_GT(scale, 0.0);
  const double h = 1e-6;
  double worst = 0.0;
  int nonzeroColumns = 0;
  for (long long m = 0; m < static_cast<long long>(s.x.size()); ++m)
    for (int c = 0; c < s.dim; ++c) {
      const double x0 = s.x[m][c];
      s.x[m][c] = x0 + h;
      const V3 plus = s.normal(node).n;
      s.x[m][c] = x0 - h;
      const V3 minus = s.normal(node).n;
      s.x[m][c] = x0;
      const auto it = ad.find({m, c});
      const V3 analytic = it == ad.end() ? V3{0.0, 0.0, 0.0} : it->second;
      double columnNorm = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double fd = (plus[i] - minus[i]) / (2.0 * h);
        worst = std::max(worst, std::abs(fd - analytic[i]) / scale);
        columnNorm += std::abs(fd);
      }
      if (columnNorm > 1e-8 * scale) {
        ++nonzeroColumns;
        EXPECT_NE(it, ad.end()) << "node " << m << " component " << c << " missing from the derivative";
      }
    }
  EXPECT_LT(worst, 1e-6) << "normal at node " << node;
  EXPECT_GT(nonzeroColumns, s.dim);  // the derivative couples several nodes
}

TEST(ContactNormals, Line2DerivativeMatchesFiniteDifferences) {
  Surface s;
  s.dim = 2;
  s.type = FaceType::Line2;
  s.addNode({0.0, 0.1, 0.0});
  s.addNode({0.9, -0.2, 0.0});
  s.addNode({1.7, 0.35, 0.0});
  s.addNode({2.5, 0.4, 0.0});  // not adjacent to node 1
  s.faces = {{0, 1, -1, -1}, {1, 2, -1, -1}, {2, 3, -1, -1}};
  checkDerivative(s, 1);
  checkDerivative(s, 0);  // end node: one face
}

// A warped, distorted 3x3-node patch around node 4 (4 Quad4 or 8 Tri3 faces),
// plus one extra row of faces not touching node 4.
Surface warpedPatch(FaceType type) {
  Surface s = planeGrid(type, 2, 3, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0.0);
  for (std::size_t m = 0; m < s.x.size(); ++m) {
    V3& p = s.x[m];
    const double a = p[0], b = p[1];
    p = {a + 0.13 * std::sin(1.3 * m), b + 0.11 * std::cos(2.1 * m), 0.2 * a * a - 0.15 * a * b + 0.1 * std::sin(3.0 * m)};
  }
  return s;
}

TEST(ContactNormals, Quad4DerivativeMatchesFiniteDifferences) {
  const Surface s = warpedPatch(FaceType::Quad4);
  checkDerivative(s, 4);   // interior: 4 faces
  checkDerivative(s, 0);   // corner: 1 face
  checkDerivative(s, 3);   // edge: 2 faces
}

TEST(ContactNormals, Tri3DerivativeMatchesFiniteDifferences) {
  const Surface s = warpedPatch(FaceType::Tri3);
  checkDerivative(s, 4);  // interior: 6 faces
  checkDerivative(s, 2);  // corner with one face
  checkDerivative(s, 3);  // edge
}

TEST(ContactNormals, DerivativeDoesNotChangeTheValue) {
  const Surface s = warpedPatch(FaceType::Quad4);
  const V3 a = s.normal(4, false).n, b = s.normal(4, true).n;
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(a[i], b[i]);
  EXPECT_NEAR(std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), 1.0, 1e-15);
}

TEST(ContactNormals, QuadCornerNormalIsTheBilinearSurfaceNormal) {
  // Warped quad: x_xi × x_eta at corner (-1,-1) is (x1 - x0)/2 × (x3 - x0)/2.
  const FaceNodes<FaceType::Quad4, double> x{{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.2}, {1.1, 0.9, -0.1}, {0.0, 1.0, 0.3}}};
  const auto m = faceCornerNormals<FaceType::Quad4, double>(x);
  // corner 2 (1,1): x_xi = (x2 - x3)/2, x_eta = (x2 - x1)/2
  const V3 xi{x[2][0] - x[3][0], x[2][1] - x[3][1], x[2][2] - x[3][2]};
  const V3 eta{x[2][0] - x[1][0], x[2][1] - x[1][1], x[2][2] - x[1][2]};
  const V3 expected = unitV({xi[1] * eta[2] - xi[2] * eta[1], xi[2] * eta[0] - xi[0] * eta[2], xi[0] * eta[1] - xi[1] * eta[0]});
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m[2][i], expected[i], 1e-15);
  EXPECT_GT(angleBetween(m[0], m[2]), 0.1);  // warped: corners differ
}

}  // namespace
}  // namespace coulomb::contact
