/// @file NodalNormals.cpp
/// @brief Averaged nodal normals and their Sacado derivatives (see the header).
#include "coulomb/contact/interface/NodalNormals.hpp"

#include <Sacado.hpp>
#include <algorithm>
#include <cmath>
#include <string>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;

template <typename T>
double valueOf(const T& x) {
  return Sacado::ScalarValue<T>::eval(x);
}

template <typename T>
std::array<T, 3> difference(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {T(a[0] - b[0]), T(a[1] - b[1]), T(a[2] - b[2])};
}

template <typename T>
std::array<T, 3> cross(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {T(a[1] * b[2] - a[2] * b[1]), T(a[2] * b[0] - a[0] * b[2]), T(a[0] * b[1] - a[1] * b[0])};
}

/// v / |v|; throws coulomb::Error if |v| is zero or not finite (decided on the values).
template <typename T, std::size_t D>
std::array<T, D> unit(const std::array<T, D>& v) {
  T length2 = 0.0;
  for (std::size_t i = 0; i < D; ++i) length2 += v[i] * v[i];
  const double check = valueOf(length2);
  COULOMB_REQUIRE(check > 0.0 && std::isfinite(check), "degenerate face (zero edge length or area)");
  using std::sqrt;
  const T length = sqrt(length2);
  std::array<T, D> u{};
  for (std::size_t i = 0; i < D; ++i) u[i] = v[i] / length;
  return u;
}

/// s_j and ds_j/dx of one face (derivative entries appended unmerged).
template <FaceType F>
void addFace(const FaceAtNode& face, std::array<double, 3>& s, std::vector<NormalDerivative>* ds) {
  constexpr int nn = FaceTraits<F>::nodes;
  constexpr int sd = FaceTraits<F>::spaceDim;
  if (!ds) {
    FaceNodes<F, double> x{};
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < sd; ++i) x[a][i] = face.x[a][i];
    const FaceNodes<F, double> m = faceCornerNormals<F, double>(x);
    for (int i = 0; i < sd; ++i) s[i] += m[face.corner][i];
    return;
  }
  constexpr int inputs = nn * sd;
  using Fad = Sacado::Fad::SFad<double, inputs>;
  FaceNodes<F, Fad> x{};
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < sd; ++i) x[a][i] = Fad(inputs, a * sd + i, face.x[a][i]);
  const FaceNodes<F, Fad> m = faceCornerNormals<F, Fad>(x);
  const auto& mj = m[face.corner];
  for (int i = 0; i < sd; ++i) s[i] += mj[i].val();
  for (int a = 0; a < nn; ++a)
    for (int c = 0; c < sd; ++c) {
      NormalDerivative entry;
      entry.node = face.nodes[a];
      entry.component = c;
      for (int i = 0; i < sd; ++i) entry.dn[i] = mj[i].dx(a * sd + c);
      ds->push_back(entry);
    }
}

/// Sorts by (node, component) and sums entries with the same key.
void mergeEntries(std::vector<NormalDerivative>& entries) {
  std::sort(entries.begin(), entries.end(), [](const NormalDerivative& a, const NormalDerivative& b) {
    return a.node != b.node ? a.node < b.node : a.component < b.component;
  });
  std::size_t out = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (out > 0 && entries[out - 1].node == entries[k].node && entries[out - 1].component == entries[k].component) {
      for (int i = 0; i < 3; ++i) entries[out - 1].dn[i] += entries[k].dn[i];
    } else {
      entries[out++] = entries[k];
    }
  }
  entries.resize(out);
}

/// n = s/|s| and J = dn/ds (Sacado over the D components of s).
template <int D>
void normalizeWithJacobian(const std::array<double, 3>& s, std::array<double, 3>& n,
                           std::array<std::array<double, 3>, 3>& J) {
  using Fad = Sacado::Fad::SFad<double, D>;
  std::array<Fad, D> sF{};
  for (int k = 0; k < D; ++k) sF[k] = Fad(D, k, s[k]);
  const std::array<Fad, D> nF = unit(sF);
  for (int i = 0; i < D; ++i) {
    n[i] = nF[i].val();
    for (int k = 0; k < D; ++k) J[i][k] = nF[i].dx(k);
  }
}

}  // namespace

template <FaceType F, typename T>
FaceNodes<F, T> faceCornerNormals(const FaceNodes<F, T>& x) {
  FaceNodes<F, T> m{};
  if constexpr (F == FaceType::Line2) {
    // edge a -> b has outward normal (dy, -dx) (fem/FaceTopology.hpp)
    const std::array<T, 2> v{T(x[1][1] - x[0][1]), T(x[0][0] - x[1][0])};
    m[0] = m[1] = unit(v);
  } else if constexpr (F == FaceType::Line3) {
    // the tangent dx/dxi at the node (xi = -1, 1, 0), turned like Line2's edge
    static constexpr double kNodeXi[3] = {-1.0, 1.0, 0.0};
    for (int a = 0; a < 3; ++a) {
      const auto g = faceShapeGradients<F, double>(FacePoint<F, double>{kNodeXi[a]});
      std::array<T, 2> t{T(0.0), T(0.0)};
      for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 2; ++i) t[i] += g[b][0] * x[b][i];
      m[a] = unit(std::array<T, 2>{t[1], T(-t[0])});
    }
  } else if constexpr (F == FaceType::Quad9 || F == FaceType::Quad8 || F == FaceType::Tri6) {
    // x_xi × x_eta of the quadratic face at each node (the Quad4 formula's
    // orientation: at a corner it is along (x_next - x_a) × (x_prev - x_a);
    // Tri3's at a Tri6 corner).
    constexpr int n = FaceTraits<F>::nodes;
    for (int a = 0; a < n; ++a) {
      const auto node = quadraticFaceNode<F>(a);
      const FacePoint<F, double> at{node[0], node[1]};
      const auto g = faceShapeGradients<F, double>(at);
      std::array<T, 3> tx{T(0.0), T(0.0), T(0.0)}, ty{T(0.0), T(0.0), T(0.0)};
      for (int b = 0; b < n; ++b)
        for (int i = 0; i < 3; ++i) {
          tx[i] += g[b][0] * x[b][i];
          ty[i] += g[b][1] * x[b][i];
        }
      m[a] = unit(cross(tx, ty));
    }
  } else if constexpr (F == FaceType::Tri3) {
    m[0] = m[1] = m[2] = unit(cross(difference(x[1], x[0]), difference(x[2], x[0])));
  } else {
    for (int a = 0; a < 4; ++a) {
      const int next = (a + 1) % 4, prev = (a + 3) % 4;
      m[a] = unit(cross(difference(x[next], x[a]), difference(x[prev], x[a])));
    }
  }
  return m;
}

NodalNormal averagedNormal(int dimension, const std::vector<FaceAtNode>& faces, bool withDerivative) {
  COULOMB_CHECK(!faces.empty(), "averagedNormal without faces");
  COULOMB_CHECK(dimension == 2 || dimension == 3, "averagedNormal in dimension " << dimension);
  const long long node = faces.front().nodes[faces.front().corner];
  NodalNormal result;
  std::array<double, 3> s{};
  std::vector<NormalDerivative> ds;
  try {
    for (const FaceAtNode& face : faces) {
      COULOMB_CHECK((face.type == FaceType::Line2 || face.type == FaceType::Line3) == (dimension == 2),
                      "face type does not match dimension " << dimension);
      std::vector<NormalDerivative>* target = withDerivative ? &ds : nullptr;
      switch (face.type) {
        case FaceType::Line2: addFace<FaceType::Line2>(face, s, target); break;
        case FaceType::Line3: addFace<FaceType::Line3>(face, s, target); break;
        case FaceType::Tri3: addFace<FaceType::Tri3>(face, s, target); break;
        case FaceType::Quad4: addFace<FaceType::Quad4>(face, s, target); break;
        case FaceType::Quad9: addFace<FaceType::Quad9>(face, s, target); break;
        case FaceType::Quad8: addFace<FaceType::Quad8>(face, s, target); break;
        case FaceType::Tri6: addFace<FaceType::Tri6>(face, s, target); break;
      }
    }
  } catch (const Error& e) {
    throw Error("contact: nodal normal at node " + std::to_string(node + 1) + ": " + e.what());
  }
  double norm = 0.0;
  for (double v : s) norm += v * v;
  norm = std::sqrt(norm);
  COULOMB_REQUIRE(norm > 1e-8 * static_cast<double>(faces.size()),
                  "contact: nodal normal at node " << node + 1 << " is undefined: the normals of its "
                                                   << faces.size() << " slave faces cancel (folded surface?)");
  std::array<std::array<double, 3>, 3> J{};
  if (dimension == 2)
    normalizeWithJacobian<2>(s, result.n, J);
  else
    normalizeWithJacobian<3>(s, result.n, J);
  if (withDerivative) {
    mergeEntries(ds);
    result.derivative.resize(ds.size());
    for (std::size_t k = 0; k < ds.size(); ++k) {
      NormalDerivative& out = result.derivative[k];
      out.node = ds[k].node;
      out.component = ds[k].component;
      for (int i = 0; i < dimension; ++i) {
        out.dn[i] = 0.0;
        for (int j = 0; j < dimension; ++j) out.dn[i] += J[i][j] * ds[k].dn[j];
      }
    }
  }
  return result;
}

FaceAtNode faceAtNode(const ContactInterface& contact, const InterfaceConfiguration& x, int k) {
  const ContactFace& f = contact.slaveFaces()[contact.slaveNodeFaces()[k]];
  FaceAtNode a;
  a.type = f.type;
  a.corner = contact.slaveNodeFaceCorners()[k];
  a.nodes = f.nodes;
  for (int b = 0; b < f.numNodes; ++b) {
    const double* p = x.point(f.interfaceIndex[b]);
    for (int c = 0; c < x.dimension; ++c) a.x[b][c] = p[c];
  }
  return a;
}

std::vector<NodalNormal> computeNodalNormals(const ContactInterface& contact, const InterfaceConfiguration& x,
                                             bool withDerivatives, const std::vector<int>* slaveNodeIndices,
                                             const SlaveNormalFaces* faces) {
  const int dim = contact.dimension();
  COULOMB_CHECK(x.dimension == dim && x.x.size() == contact.interfaceNodes().size() * dim,
                  "interface configuration does not match the contact interface");
  const std::size_t numSlaveNodes = contact.slaveNodes().size();
  std::vector<NodalNormal> normals(numSlaveNodes);
  const auto& offset = contact.slaveNodeFaceOffsets();
  std::vector<FaceAtNode> around;
  auto compute = [&](int i) {
    around.clear();
    const bool all = !faces || faces->allFaces(i);
    for (int k = offset[i], chosen = 0; k < offset[i + 1]; ++k) {
      if (!all) {
        const auto& use = faces->faces[static_cast<std::size_t>(i)];
        if (chosen == static_cast<int>(use.size()) || use[static_cast<std::size_t>(chosen)] != k - offset[i]) continue;
        ++chosen;
      }
      around.push_back(faceAtNode(contact, x, k));
    }
    try {
      normals[i] = averagedNormal(dim, around, withDerivatives);
    } catch (const Error& e) {
      throw Error("slave side set '" + contact.slaveSetName() + "': " + e.what());
    }
  };
  if (slaveNodeIndices) {
    for (int i : *slaveNodeIndices) {
      COULOMB_CHECK(i >= 0 && static_cast<std::size_t>(i) < numSlaveNodes, "slave node index " << i);
      compute(i);
    }
  } else {
    for (std::size_t i = 0; i < numSlaveNodes; ++i) compute(static_cast<int>(i));
  }
  return normals;
}

#define COULOMB_CONTACT_NORMALS_INSTANTIATE(F, N)                                                                 \
  template FaceNodes<F, double> faceCornerNormals<F, double>(const FaceNodes<F, double>&);                       \
  template FaceNodes<F, Sacado::Fad::SFad<double, N>> faceCornerNormals<F, Sacado::Fad::SFad<double, N>>(        \
      const FaceNodes<F, Sacado::Fad::SFad<double, N>>&);
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Line2, 4)
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Line3, 6)
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Tri3, 9)
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Quad4, 12)
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Quad9, 27)
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Quad8, 24)
COULOMB_CONTACT_NORMALS_INSTANTIATE(FaceType::Tri6, 18)
#undef COULOMB_CONTACT_NORMALS_INSTANTIATE

}  // namespace coulomb::contact
