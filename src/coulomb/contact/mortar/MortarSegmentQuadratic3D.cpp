/// @file MortarSegmentQuadratic3D.cpp
/// @brief Sub-facet mortar integration of 3D pairs with a quadratic face (see the header).
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"

#include "coulomb/contact/mortar/MortarScalarTypes.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "coulomb/contact/mortar/AuxiliaryPlane.hpp"
#include "coulomb/contact/mortar/PolygonClipping.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using namespace plane;

/// A linear piece of a face: its type (Tri3 or Quad4), the parent nodes at
/// its corners and the parent coordinates of those corners.
struct SubFacet {
  FaceType type = FaceType::Quad4;
  int count = 4;
  std::array<int, 4> node{};
  std::array<std::array<double, 2>, 4> corner{};
};

/// The linear piece of quadratic face F on its nodes `nodes` (3: a
/// triangle, 4: a quadrilateral).
template <FaceType F, std::size_t N>
SubFacet pieceOf(const std::array<int, N>& nodes) {
  SubFacet f;
  f.type = N == 3 ? FaceType::Tri3 : FaceType::Quad4;
  f.count = static_cast<int>(N);
  f.node = {-1, -1, -1, -1};
  for (std::size_t c = 0; c < N; ++c) {
    f.node[c] = nodes[c];
    f.corner[c] = quadraticFaceNode<F>(nodes[c]);
  }
  return f;
}

template <FaceType F>
std::vector<SubFacet> subFacets() {
  if constexpr (F == FaceType::Tri3) {
    return {SubFacet{FaceType::Tri3, 3, {0, 1, 2, -1}, {{{0, 0}, {1, 0}, {0, 1}, {0, 0}}}}};
  } else if constexpr (F == FaceType::Quad4) {
    return {SubFacet{FaceType::Quad4, 4, {0, 1, 2, 3}, {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}}};
  } else if constexpr (F == FaceType::Tri6) {
    // The four triangles between the corners and the mid-sides.
    std::vector<SubFacet> out;
    for (const std::array<int, 3> t : {std::array<int, 3>{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}})
      out.push_back(pieceOf<F>(t));
    return out;
  } else if constexpr (F == FaceType::Quad8) {
    // No centre node: a triangle at each corner (corner, its two
    // mid-sides) and the quadrilateral of the four mid-sides.
    std::vector<SubFacet> out;
    for (const std::array<int, 3> t : {std::array<int, 3>{0, 4, 7}, {1, 5, 4}, {2, 6, 5}, {3, 7, 6}})
      out.push_back(pieceOf<F>(t));
    out.push_back(pieceOf<F>(std::array<int, 4>{4, 5, 6, 7}));
    return out;
  } else {
    static_assert(F == FaceType::Quad9, "sub-facets of Tri3, Quad4, Tri6, Quad8 and Quad9 faces");
    std::vector<SubFacet> out;
    for (const std::array<int, 4> q : {std::array<int, 4>{0, 4, 8, 7}, {4, 1, 5, 8}, {8, 5, 2, 6}, {7, 8, 6, 3}})
      out.push_back(pieceOf<F>(q));
    return out;
  }
}

/// A sub-facet projected on the plane and its inverse map: the coordinates
/// of the plane point q in the parent face, and det(d xi_parent / d q).
template <typename T>
struct PlanePiece {
  const SubFacet* facet = nullptr;
  std::array<Point2<T>, 4> p{};
  Polygon2<T> polygon;

  template <FaceType F>
  FacePoint<F, T> parentPoint(const Point2<T>& q, T* jacobian = nullptr) const {
    std::array<T, 4> weight{};
    std::array<std::array<T, 2>, 4> grad{};
    if (facet->type == FaceType::Tri3) {
      const PlaneNodes<FaceType::Tri3, T> nodes{p[0], p[1], p[2]};
      const auto xi = invertPlaneMap<FaceType::Tri3, T>(nodes, q);
      weight = {T(1.0 - xi[0] - xi[1]), xi[0], xi[1], T(0.0)};
      grad = {{{T(-1.0), T(-1.0)}, {T(1.0), T(0.0)}, {T(0.0), T(1.0)}, {T(0.0), T(0.0)}}};
    } else {
      const PlaneNodes<FaceType::Quad4, T> nodes{p[0], p[1], p[2], p[3]};
      const auto xi = invertPlaneMap<FaceType::Quad4, T>(nodes, q);
      weight = faceShapeValues<FaceType::Quad4, T>(xi);
      grad = faceShapeGradients<FaceType::Quad4, T>(xi);
    }
    std::array<T, 2> local{T(0.0), T(0.0)};
    std::array<std::array<T, 2>, 2> toParent{}, toPlane{};  // d xi_parent / d xi, d q / d xi
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k) toParent[i][k] = toPlane[i][k] = 0.0;
    for (int c = 0; c < facet->count; ++c)
      for (int i = 0; i < 2; ++i) {
        local[i] += weight[c] * facet->corner[c][i];
        for (int k = 0; k < 2; ++k) {
          toParent[i][k] += facet->corner[c][i] * grad[c][k];
          toPlane[i][k] += p[c][i] * grad[c][k];
        }
      }
    if (jacobian)
      *jacobian = (toParent[0][0] * toParent[1][1] - toParent[0][1] * toParent[1][0]) /
                  (toPlane[0][0] * toPlane[1][1] - toPlane[0][1] * toPlane[1][0]);
    return {local[0], local[1]};
  }
};

/// The convex pieces of a master sub-facet on the plane (`plane`: its
/// corners there): itself, or, a Quad4 that is not convex there (seen
/// edge-on, or distorted by a large predictor), the two triangles either
/// side of the diagonal through its reflex vertex, as the linear kernel
/// does. A quadrilateral twisted over itself that reaches the slave piece is
/// a geometry failure of the iterate (the step is cut back); one that does
/// not is no contact.
template <typename T>
std::vector<SubFacet> convexPieces(const SubFacet& f, const std::array<Point2<T>, 4>& plane,
                                   const Polygon2<T>& slave, double areaTolerance, double tolerance) {
  if (f.type != FaceType::Quad4) return {f};
  const PlaneNodes<FaceType::Quad4, T> quad{plane[0], plane[1], plane[2], plane[3]};
  const int reflex = reflexVertex(quad, areaTolerance);
  if (reflex == -1) return {f};
  auto triangle = [&](int a, int b, int c) {
    SubFacet t;
    t.type = FaceType::Tri3;
    t.count = 3;
    t.node = {f.node[a], f.node[b], f.node[c], -1};
    t.corner = {f.corner[a], f.corner[b], f.corner[c], f.corner[a]};
    return t;
  };
  if (reflex >= 0)
    return {triangle(reflex, (reflex + 1) % 4, (reflex + 2) % 4), triangle((reflex + 2) % 4, (reflex + 3) % 4, reflex)};
  for (int first : {0, 2}) {
    Polygon2<T> half;
    for (int a = 0; a < 3; ++a) half.push(plane[(first + a) % 4]);
    if (!(std::abs(valueOf(signedArea(half))) > areaTolerance)) continue;
    makeCounterClockwise(half);
    const Polygon2<T> part = clipConvexPolygon(half, slave, tolerance);
    COULOMB_REQUIRE(!(part.size >= 3 && valueOf(signedArea(part)) > areaTolerance),
                    "mortar integration: a master face is twisted over itself when projected onto a slave face's "
                    "auxiliary plane (a bow-tie)");
  }
  return {};
}

}  // namespace

namespace {

/// d g~_j / d n_a,i (n_a the slave's nodal normals), [j][a][i].
template <FaceType S>
using GapNormalDerivative = std::array<std::array<std::array<double, 3>, FaceTraits<S>::nodes>, FaceTraits<S>::nodes>;

/// The kernel (see the header) with the nodal normals as plain values: they
/// enter g~ alone, through n = sum_a N_a n_a at a Gauss point, so their
/// derivatives are summed here by hand (`dGapNormal`, when not null) and
/// the Sacado type need only carry the coordinates: a third fewer
/// derivatives in every operation. The Gauss-point sums are of the trial
/// functions N~ (D~_k, M~_kl, g~~_k); the dual coefficients A, the same at
/// every point, are applied once at the end (Phi_j = sum_k A_jk N~_k).
template <FaceType S, FaceType Mf, typename T>
MortarSegment3D<S, Mf, T> integrateSubFacets(const FaceNodes<S, T>& xs, const FaceNodes<S, double>& ns,
                                             const FaceNodes<Mf, T>& xm, double relativeTolerance,
                                             GapNormalDerivative<S>* dGapNormal) {
  using std::sqrt;
  constexpr int nS = FaceTraits<S>::nodes;
  constexpr int nM = FaceTraits<Mf>::nodes;
  MortarSegment3D<S, Mf, T> out;  // first the sums of N~_k, then (the end) of Phi_j
  for (int j = 0; j < nS; ++j) {
    out.D[j] = 0.0;
    out.gap[j] = 0.0;
    for (int l = 0; l < nM; ++l) out.M[j][l] = 0.0;
  }
  out.area = 0.0;
  GapNormalDerivative<S> dTrialGap{};  // d (sum N~_k g_n dA) / d n_a,i
  static const std::vector<SubFacet> slaveFacets = subFacets<S>(), masterFacets = subFacets<Mf>();
  const TriangleRule7& rule = triangleRule7();

  for (const SubFacet& fs : slaveFacets) {
    // The auxiliary plane of the slave sub-facet (MortarSegment3D.hpp, step 1).
    Vec3<T> x0{T(0.0), T(0.0), T(0.0)};
    for (int c = 0; c < fs.count; ++c)
      for (int i = 0; i < 3; ++i) x0[i] += xs[fs.node[c]][i] / double(fs.count);
    const auto& q = fs.node;
    const Vec3<T> v = fs.type == FaceType::Tri3 ? cross(sub(xs[q[1]], xs[q[0]]), sub(xs[q[2]], xs[q[0]]))
                                                 : cross(sub(xs[q[2]], xs[q[0]]), sub(xs[q[3]], xs[q[1]]));
    const T vNorm = sqrt(dot(v, v));
    if (!(valueOf(vNorm) > 0.0)) continue;
    const Vec3<T> n0{T(v[0] / vNorm), T(v[1] / vNorm), T(v[2] / vNorm)};
    const Vec3<T> t = sub(xs[q[1]], xs[q[0]]);
    const T tn = dot(t, n0);
    Vec3<T> e1{T(t[0] - tn * n0[0]), T(t[1] - tn * n0[1]), T(t[2] - tn * n0[2])};
    const T e1Norm = sqrt(dot(e1, e1));
    for (int i = 0; i < 3; ++i) e1[i] /= e1Norm;
    const Vec3<T> e2 = cross(n0, e1);
    auto toPlane = [&](const std::array<T, 3>& x) {
      const Vec3<T> r = sub(x, x0);
      return Point2<T>{dot(r, e1), dot(r, e2)};
    };
    PlanePiece<T> slave;
    slave.facet = &fs;
    for (int c = 0; c < fs.count; ++c) {
      slave.p[c] = toPlane(xs[fs.node[c]]);
      slave.polygon.push(slave.p[c]);
    }
    const double slaveArea = valueOf(signedArea(slave.polygon));
    if (!(slaveArea > 0.0)) continue;
    if (fs.type == FaceType::Quad4) {
      const PlaneNodes<FaceType::Quad4, T> quad{slave.p[0], slave.p[1], slave.p[2], slave.p[3]};
      COULOMB_REQUIRE(reflexVertex(quad, relativeTolerance * slaveArea) == -1,
                      "mortar integration: a slave face is not convex on its auxiliary plane (distorted element)");
    }
    const double tolerance = relativeTolerance * std::sqrt(slaveArea);
    // The slave polygon's box on the plane, in doubles: a master sub-facet
    // whose box misses it is skipped before its projection and clipping in
    // T, which with Sacado (tens of derivatives) is most of the kernel's cost
    // and would find no overlap anyway.
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int c = 0; c < fs.count; ++c)
      for (int i = 0; i < 2; ++i) {
        lo[i] = std::min(lo[i], valueOf(slave.p[c][i]));
        hi[i] = std::max(hi[i], valueOf(slave.p[c][i]));
      }
    const double margin = 10.0 * tolerance;
    double origin[3], axis1[3], axis2[3];  // the plane in doubles
    for (int i = 0; i < 3; ++i) {
      origin[i] = valueOf(x0[i]);
      axis1[i] = valueOf(e1[i]);
      axis2[i] = valueOf(e2[i]);
    }
    auto besideSlave = [&](const SubFacet& facet) {
      double mLo[2] = {1e300, 1e300}, mHi[2] = {-1e300, -1e300};
      for (int c = 0; c < facet.count; ++c) {
        double s[2] = {0.0, 0.0};
        for (int i = 0; i < 3; ++i) {
          const double r = valueOf(xm[facet.node[c]][i]) - origin[i];
          s[0] += r * axis1[i];
          s[1] += r * axis2[i];
        }
        for (int i = 0; i < 2; ++i) {
          mLo[i] = std::min(mLo[i], s[i]);
          mHi[i] = std::max(mHi[i], s[i]);
        }
      }
      for (int i = 0; i < 2; ++i)
        if (mLo[i] > hi[i] + margin || lo[i] > mHi[i] + margin) return true;
      return false;
    };
    for (const SubFacet& facet : masterFacets) {
      if (besideSlave(facet)) continue;
      std::array<Point2<T>, 4> corners{};
      Polygon2<T> outline;
      for (int c = 0; c < facet.count; ++c) {
        corners[c] = toPlane(xm[facet.node[c]]);
        outline.push(corners[c]);
      }
      if (!(std::abs(valueOf(signedArea(outline))) > relativeTolerance * slaveArea)) continue;
      for (const SubFacet& fm :
           convexPieces(facet, corners, slave.polygon, relativeTolerance * slaveArea, tolerance)) {
        PlanePiece<T> master;
        master.facet = &fm;
        for (int c = 0; c < fm.count; ++c) {
          master.p[c] = toPlane(xm[fm.node[c]]);
          master.polygon.push(master.p[c]);
        }
        if (!(std::abs(valueOf(signedArea(master.polygon))) > relativeTolerance * slaveArea)) continue;
        Polygon2<T> masterPolygon = master.polygon;
        makeCounterClockwise(masterPolygon);
        const Polygon2<T> clip = clipConvexPolygon(masterPolygon, slave.polygon, tolerance);
        if (clip.size < 3 || !(valueOf(signedArea(clip)) > relativeTolerance * slaveArea)) continue;
        out.contributes = true;
        out.polygonVertices += clip.size;
        const Point2<T> centre = areaCentroid(clip);
        for (int c = 0; c < clip.size; ++c) {
          const Point2<T>& q0 = centre;
          const Point2<T>& q1 = clip.vertex[c];
          const Point2<T>& q2 = clip.vertex[(c + 1) % clip.size];
          const T cellArea = 0.5 * ((q1[0] - q0[0]) * (q2[1] - q0[1]) - (q1[1] - q0[1]) * (q2[0] - q0[0]));
          for (int g = 0; g < 7; ++g) {
            const std::array<double, 3>& L = rule.L[g];
            const Point2<T> p{T(L[0] * q0[0] + L[1] * q1[0] + L[2] * q2[0]),
                              T(L[0] * q0[1] + L[1] * q1[1] + L[2] * q2[1])};
            T toParent{};  // det(d xi1 / d p)
            const FacePoint<S, T> xi1 = slave.template parentPoint<S>(p, &toParent);
            const FacePoint<Mf, T> xi2 = master.template parentPoint<Mf>(p);
            const NodalValues<S, T> N1 = faceShapeValues<S, T>(xi1);
            const NodalValues<S, T> trial = trialFromShapeValues<S, T>(N1);
            const NodalValues<Mf, T> N2 = faceShapeValues<Mf, T>(xi2);
            Vec3<T> x1{T(0.0), T(0.0), T(0.0)}, x2{T(0.0), T(0.0), T(0.0)}, n{T(0.0), T(0.0), T(0.0)};
            for (int a = 0; a < nS; ++a)
              for (int i = 0; i < 3; ++i) {
                x1[i] += N1[a] * xs[a][i];
                n[i] += N1[a] * ns[a][i];
              }
            for (int l = 0; l < nM; ++l)
              for (int i = 0; i < 3; ++i) x2[i] += N2[l] * xm[l][i];
            const Vec3<T> r = sub(x2, x1);
            const T nNorm = sqrt(dot(n, n));
            const T gn = dot(r, n) / nNorm;
            // The parent's surface measure |x_xi × x_eta| dxi1, dxi1 = det(d xi1 / d p) dp:
            // the measure faceMass integrates, so the dual basis stays biorthogonal.
            const Vec3<T> nx = tangentNormal<S, T>(faceShapeGradients<S, T>(xi1), xs);
            const T dA = rule.w[g] * cellArea * sqrt(dot(nx, nx)) * toParent;
            addGaussPoint(out, trial, N2, gn, dA);  // the sums of N~_k (Phi_j applied at the end)
            if (dGapNormal != nullptr) {
              // d g_n / d n = r / |n| - (r . n) n / |n|^3, and d n / d n_a = N_a.
              const double norm = valueOf(nNorm), rn = valueOf(dot(r, n));
              double q[3];
              for (int i = 0; i < 3; ++i)
                q[i] = valueOf(r[i]) / norm - rn * valueOf(n[i]) / (norm * norm * norm);
              for (int k = 0; k < nS; ++k) {
                const double w = valueOf(trial[k]) * valueOf(dA);
                for (int a = 0; a < nS; ++a) {
                  const double wa = w * valueOf(N1[a]);
                  for (int i = 0; i < 3; ++i) dTrialGap[k][a][i] += wa * q[i];
                }
              }
            }
          }
        }
      }
    }
  }
  // Phi_j = sum_k A_jk N~_k: D_j, M_jl, g~_j from the sums of N~_k.
  const NodalMatrix<S, T> A = dualCoefficients<S, T>(xs);
  MortarSegment3D<S, Mf, T> dual = out;
  for (int j = 0; j < nS; ++j) {
    dual.D[j] = 0.0;
    dual.gap[j] = 0.0;
    for (int l = 0; l < nM; ++l) dual.M[j][l] = 0.0;
    for (int k = 0; k < nS; ++k) {
      dual.D[j] += A[j][k] * out.D[k];
      dual.gap[j] += A[j][k] * out.gap[k];
      for (int l = 0; l < nM; ++l) dual.M[j][l] += A[j][k] * out.M[k][l];
    }
  }
  if (dGapNormal != nullptr)
    for (int j = 0; j < nS; ++j)
      for (int a = 0; a < nS; ++a)
        for (int i = 0; i < 3; ++i) {
          double sum = 0.0;
          for (int k = 0; k < nS; ++k) sum += valueOf(A[j][k]) * dTrialGap[k][a][i];
          (*dGapNormal)[j][a][i] = sum;
        }
  return dual;
}

}  // namespace

template <FaceType S, FaceType Mf, typename T>
MortarSegment3D<S, Mf, T> integrateQuadraticSegment3D(const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns,
                                                      const FaceNodes<Mf, T>& xm, double relativeTolerance) {
  static_assert(std::is_same_v<T, double>, "values only: linearizeQuadraticSegment3D differentiates");
  return integrateSubFacets<S, Mf, T>(xs, ns, xm, relativeTolerance, nullptr);
}

template <FaceType S, FaceType Mf>
MortarSegment3DLinearization<S, Mf> linearizeQuadraticSegment3D(const FaceNodes<S, double>& xs,
                                                                const FaceNodes<S, double>& ns,
                                                                const FaceNodes<Mf, double>& xm,
                                                                double relativeTolerance) {
  // Sacado over the coordinates alone ([0, 3 nS) slave, [3 nS, 3 nS + 3 nM)
  // master); the normals' derivatives come from integrateSubFacets.
  constexpr int nS = FaceTraits<S>::nodes;
  constexpr int nM = FaceTraits<Mf>::nodes;
  constexpr int nC = 3 * (nS + nM);
  using Fad = SubFacetFad3D<S, Mf>;
  FaceNodes<S, Fad> fxs;
  FaceNodes<Mf, Fad> fxm;
  for (int a = 0; a < nS; ++a)
    for (int i = 0; i < 3; ++i) fxs[a][i] = Fad(nC, 3 * a + i, xs[a][i]);
  for (int l = 0; l < nM; ++l)
    for (int i = 0; i < 3; ++i) fxm[l][i] = Fad(nC, 3 * nS + 3 * l + i, xm[l][i]);
  GapNormalDerivative<S> dGapNormal{};
  const MortarSegment3D<S, Mf, Fad> r = integrateSubFacets<S, Mf, Fad>(fxs, ns, fxm, relativeTolerance, &dGapNormal);
  // Into the layout of MortarSegment3DLinearization: [0, 3 nS) slave
  // coordinates, [3 nS, 6 nS) normals, [6 nS, 6 nS + 3 nM) master.
  auto input = [](int c) { return c < 3 * nS ? c : c + 3 * nS; };
  MortarSegment3DLinearization<S, Mf> lin;
  lin.value.contributes = r.contributes;
  lin.value.polygonVertices = r.polygonVertices;
  lin.value.area = r.area.val();
  for (int c = 0; c < nC; ++c) lin.dArea[input(c)] = r.area.dx(c);
  for (int j = 0; j < nS; ++j) {
    lin.value.D[j] = r.D[j].val();
    lin.value.gap[j] = r.gap[j].val();
    for (int c = 0; c < nC; ++c) {
      lin.dD[j][input(c)] = r.D[j].dx(c);
      lin.dGap[j][input(c)] = r.gap[j].dx(c);
    }
    for (int a = 0; a < nS; ++a)
      for (int i = 0; i < 3; ++i) lin.dGap[j][3 * nS + 3 * a + i] = dGapNormal[j][a][i];
    for (int l = 0; l < nM; ++l) {
      lin.value.M[j][l] = r.M[j][l].val();
      for (int c = 0; c < nC; ++c) lin.dM[j][l][input(c)] = r.M[j][l].dx(c);
    }
  }
  return lin;
}

#define COULOMB_QUADRATIC_3D_INSTANTIATE(S, Mf)                                                                     \
  template MortarSegment3D<S, Mf, double> integrateQuadraticSegment3D<S, Mf, double>(                             \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double);              \
  template MortarSegment3DLinearization<S, Mf> linearizeQuadraticSegment3D<S, Mf>(                                \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double);
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad9, FaceType::Quad9)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad9, FaceType::Quad4)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad9, FaceType::Tri3)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad4, FaceType::Quad9)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri3, FaceType::Quad9)
// Quad8 and Tri6 (transformed slave basis) with each other and the linear faces.
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad8, FaceType::Quad8)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad8, FaceType::Tri6)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad8, FaceType::Quad4)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad8, FaceType::Tri3)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri6, FaceType::Tri6)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri6, FaceType::Quad8)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri6, FaceType::Quad4)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri6, FaceType::Tri3)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad4, FaceType::Quad8)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad4, FaceType::Tri6)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri3, FaceType::Quad8)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri3, FaceType::Tri6)
// Quad9 with Quad8 and Tri6 (a HEX27 body on a HEX20 or TET10 one): the
// master side takes its standard shape functions whatever its type.
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad9, FaceType::Quad8)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad9, FaceType::Tri6)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Quad8, FaceType::Quad9)
COULOMB_QUADRATIC_3D_INSTANTIATE(FaceType::Tri6, FaceType::Quad9)
#undef COULOMB_QUADRATIC_3D_INSTANTIATE

}  // namespace coulomb::contact
