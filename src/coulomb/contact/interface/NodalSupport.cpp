/// @file NodalSupport.cpp
/// @brief S_j, the D_j of a slave node under a covering master (see the header).
#include "coulomb/contact/interface/NodalSupport.hpp"

#include <cmath>

#include "coulomb/contact/mortar/AuxiliaryPlane.hpp"
#include "coulomb/contact/mortar/DualBasis.hpp"
#include "coulomb/contact/mortar/MortarSegment2D.hpp"
#include "coulomb/contact/mortar/MortarSegment3D.hpp"
#include "coulomb/contact/mortar/MortarSegmentCurved2D.hpp"
#include "coulomb/contact/mortar/MortarScalarTypes.hpp"
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

namespace {

using mesh::FaceType;

/// A face's coordinates and unit normals (the normals only enter the gap,
/// which S_j does not use: the line's or the corners' plane normal).
template <FaceType F>
struct SelfFace {
  FaceNodes<F, double> x{}, n{};
  SelfFace(const ContactFace& f, const InterfaceConfiguration& configuration) {
    constexpr int dim = FaceTraits<F>::spaceDim;
    for (int a = 0; a < FaceTraits<F>::nodes; ++a)
      for (int c = 0; c < dim; ++c) x[a][c] = configuration.point(f.interfaceIndex[a])[c];
    std::array<double, 3> normal{};
    if constexpr (dim == 2) {
      normal = {-(x[1][1] - x[0][1]), x[1][0] - x[0][0], 0.0};
    } else {
      // Triangle: (x1 - x0) x (x2 - x0); quadrilateral: the diagonals (x2 - x0) x (x3 - x1).
      const bool triangle = F == FaceType::Tri3 || F == FaceType::Tri6;
      normal = plane::cross(plane::sub(x[triangle ? 1 : 2], x[0]),
                            plane::sub(x[triangle ? 2 : 3], x[triangle ? 0 : 1]));
    }
    const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    for (auto& node : n)
      for (int c = 0; c < dim; ++c) node[c] = length > 0.0 ? normal[c] / length : 0.0;
  }
};

/// The face paired with itself by the mortar pass' kernel for its type:
/// its D (values) or, with `row`, adds d D_corner / d x to it (the slave and
/// master coordinates are the same DoFs; D does not depend on the normals).
template <FaceType F>
void selfKernel(const ContactFace& f, const SelfFace<F>& face, bool axisymmetric, double tolerance,
                std::array<double, mesh::kMaxFaceNodes>* D, int corner, DerivativeRow* row) {
  const auto& x = face.x;
  const auto& n = face.n;
  auto values = [&]() {
    if constexpr (F == FaceType::Line2)
      return integrateSegment2D<double>(x, n, x, tolerance, axisymmetric);
    else if constexpr (F == FaceType::Line3)
      return integrateCurvedSegment2D<F, F, double>(x, n, x, tolerance, axisymmetric);
    else if constexpr (F == FaceType::Tri3 || F == FaceType::Quad4)
      return integrateSegment3D<F, F, double>(x, n, x, tolerance);
    else
      return integrateQuadraticSegment3D<F, F, double>(x, n, x, tolerance);
  };
  if (D) {
    const auto segment = values();
    for (int j = 0; j < FaceTraits<F>::nodes; ++j) (*D)[j] = segment.D[j];
    return;
  }
  auto linearization = [&]() {
    if constexpr (F == FaceType::Line2)
      return linearizeSegment2D(x, n, x, tolerance, axisymmetric);
    else if constexpr (F == FaceType::Line3)
      return linearizeCurvedSegment2D<F, F>(x, n, x, tolerance, axisymmetric);
    else if constexpr (F == FaceType::Tri3 || F == FaceType::Quad4)
      return linearizeSegment3D<F, F>(x, n, x, tolerance);
    else
      return linearizeQuadraticSegment3D<F, F>(x, n, x, tolerance);
  };
  // Inputs: slave coordinates [0, dim n), slave normals, master coordinates [2 dim n, 3 dim n).
  const auto lin = linearization();
  constexpr int dim = FaceTraits<F>::spaceDim, nodes = FaceTraits<F>::nodes;
  for (int a = 0; a < nodes; ++a)
    for (int c = 0; c < dim; ++c) {
      const double d = lin.dD[corner][a * dim + c] + lin.dD[corner][2 * dim * nodes + a * dim + c];
      if (d != 0.0) (*row)[{f.nodes[a], c}] += d;
    }
}

/// The inputs of the Sacado type faceMass is instantiated for with a 3D
/// face of type F: those of its own pair's kernel (MortarScalarTypes.hpp,
/// SegmentFad3D for Tri3 / Quad4, SubFacetFad3D for the quadratic faces).
template <FaceType F>
constexpr int kSelfInputs =
    F == FaceType::Tri3 || F == FaceType::Quad4 ? segment3DInputs<F, F> : 6 * FaceTraits<F>::nodes;

/// A 3D face's int N~_j dA on the curved face itself (faceMass), the
/// fallback of selfIntegral: its D (values) or, with `row`, adds
/// d D_corner / d x to it.
template <FaceType F>
void curvedIntegral(const ContactFace& f, const FaceNodes<F, double>& x, std::array<double, mesh::kMaxFaceNodes>* D,
                    int corner, DerivativeRow* row) {
  constexpr int nodes = FaceTraits<F>::nodes;
  if (D) {
    const auto mass = faceMass<F, double>(x);
    for (int j = 0; j < nodes; ++j) (*D)[j] = mass.De[j];
    return;
  }
  using Fad = Sacado::Fad::SFad<double, kSelfInputs<F>>;
  FaceNodes<F, Fad> fx;
  for (int a = 0; a < nodes; ++a)
    for (int c = 0; c < 3; ++c) fx[a][c] = Fad(kSelfInputs<F>, 3 * a + c, x[a][c]);
  const auto mass = faceMass<F, Fad>(fx);
  for (int a = 0; a < nodes; ++a)
    for (int c = 0; c < 3; ++c) {
      const double d = mass.De[corner].dx(3 * a + c);
      if (d != 0.0) (*row)[{f.nodes[a], c}] += d;
    }
}

/// selfKernel, or for a 3D face so curved or warped that the kernel cannot
/// project it onto the plane of one of its own pieces (a bow-tie or a
/// non-convex piece: the kernel's geometry error), its curved int N~_j dA.
/// A real master, flatter, may still pair with such a face: S_j only
/// scales its contact-node test and objective weight, which must not end
/// the run (neo_hookean_shear_3d on HEX27 with the block's sides in the
/// slave surface stopped with this error instead of cutting back).
template <FaceType F>
void selfIntegral(const ContactFace& f, const InterfaceConfiguration& configuration, bool axisymmetric,
                  double tolerance, std::array<double, mesh::kMaxFaceNodes>* D, int corner, DerivativeRow* row) {
  const SelfFace<F> face(f, configuration);
  if constexpr (FaceTraits<F>::spaceDim == 3) {
    DerivativeRow own;  // this face's terms: kept only if its kernel succeeds
    try {
      selfKernel<F>(f, face, axisymmetric, tolerance, D, corner, row ? &own : nullptr);
    } catch (const Error&) {
      own.clear();
      curvedIntegral<F>(f, face.x, D, corner, row ? &own : nullptr);
    }
    if (row)
      for (const auto& [key, value] : own) (*row)[key] += value;
  } else {
    selfKernel<F>(f, face, axisymmetric, tolerance, D, corner, row);
  }
}

void selfIntegralOfType(const ContactFace& f, const InterfaceConfiguration& x, bool axisymmetric, double tolerance,
                        std::array<double, mesh::kMaxFaceNodes>* D, int corner, DerivativeRow* row) {
  switch (f.type) {
    case FaceType::Line2: return selfIntegral<FaceType::Line2>(f, x, axisymmetric, tolerance, D, corner, row);
    case FaceType::Line3: return selfIntegral<FaceType::Line3>(f, x, axisymmetric, tolerance, D, corner, row);
    case FaceType::Tri3: return selfIntegral<FaceType::Tri3>(f, x, axisymmetric, tolerance, D, corner, row);
    case FaceType::Quad4: return selfIntegral<FaceType::Quad4>(f, x, axisymmetric, tolerance, D, corner, row);
    case FaceType::Tri6: return selfIntegral<FaceType::Tri6>(f, x, axisymmetric, tolerance, D, corner, row);
    case FaceType::Quad8: return selfIntegral<FaceType::Quad8>(f, x, axisymmetric, tolerance, D, corner, row);
    case FaceType::Quad9: return selfIntegral<FaceType::Quad9>(f, x, axisymmetric, tolerance, D, corner, row);
  }
}

}  // namespace

std::array<double, mesh::kMaxFaceNodes> faceSupportMeasures(const ContactFace& f, const InterfaceConfiguration& x,
                                                            bool axisymmetric, double relativeTolerance) {
  std::array<double, mesh::kMaxFaceNodes> D{};
  selfIntegralOfType(f, x, axisymmetric, relativeTolerance, &D, 0, nullptr);
  return D;
}

void addFaceSupportMeasureDerivative(const ContactFace& f, const InterfaceConfiguration& x, bool axisymmetric,
                                     int corner, DerivativeRow& row, double relativeTolerance) {
  selfIntegralOfType(f, x, axisymmetric, relativeTolerance, nullptr, corner, &row);
}

std::vector<double> nodalSupportMeasures(const ContactInterface& contact, const InterfaceConfiguration& x,
                                         const std::vector<NodalMortarEntry>& entries, double relativeTolerance) {
  const auto& offset = contact.slaveNodeFaceOffsets();
  std::vector<std::array<double, mesh::kMaxFaceNodes>> faceD;  // per integrated face
  std::vector<int> faceIndex(contact.slaveFaces().size(), -1);
  std::vector<double> measures;
  measures.reserve(entries.size());
  for (const auto& entry : entries) {
    const int slaveNode = contact.slaveNodeIndex(entry.node);
    double measure = 0.0;
    for (int k = offset[slaveNode]; k < offset[slaveNode + 1]; ++k) {
      const int face = contact.slaveNodeFaces()[k];
      if (faceIndex[face] < 0) {
        faceIndex[face] = static_cast<int>(faceD.size());
        faceD.push_back(faceSupportMeasures(contact.slaveFaces()[face], x, contact.axisymmetric(), relativeTolerance));
      }
      measure += faceD[faceIndex[face]][contact.slaveNodeFaceCorners()[k]];
    }
    measures.push_back(measure);
  }
  return measures;
}

DerivativeRow nodalSupportMeasureDerivative(const ContactInterface& contact, const InterfaceConfiguration& x,
                                            long long node, double relativeTolerance) {
  const auto& offset = contact.slaveNodeFaceOffsets();
  const int slaveNode = contact.slaveNodeIndex(node);
  DerivativeRow row;
  for (int k = offset[slaveNode]; k < offset[slaveNode + 1]; ++k)
    addFaceSupportMeasureDerivative(contact.slaveFaces()[contact.slaveNodeFaces()[k]], x, contact.axisymmetric(),
                                    contact.slaveNodeFaceCorners()[k], row, relativeTolerance);
  return row;
}

}  // namespace coulomb::contact
