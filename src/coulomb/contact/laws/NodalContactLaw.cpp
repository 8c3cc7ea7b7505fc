/// @file NodalContactLaw.cpp
/// @brief Nodal frictionless ALM and penalty kernels (seed 4.71a, 4.72a/b,
/// 4.74 with mu = 0); formulas in NodalContactLaw.hpp.
#include "coulomb/contact/laws/NodalContactLaw.hpp"

#include <algorithm>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

void checkParameters(const AlmParameters& p) {
  COULOMB_CHECK(p.k > 0.0, "contact ALM: scale factor k must be > 0, got " << p.k);
  COULOMB_CHECK(p.epsN > 0.0, "contact ALM: normal penalty must be > 0, got " << p.epsN);
  COULOMB_CHECK(p.epsTau > 0.0, "contact ALM: tangential penalty must be > 0, got " << p.epsTau);
}

template <int dim>
double dot(const NVec<dim>& a, const NVec<dim>& b) {
  double s = 0.0;
  for (int i = 0; i < dim; ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

template <int dim>
AlmNodeResidual<dim> almResidual(const AlmNodeInput<dim>& in, const AlmParameters& p, ContactState state) {
  checkParameters(p);
  COULOMB_CHECK(in.D > 0.0, "contact ALM: nodal mortar weight D_j must be > 0, got " << in.D);
  const NVec<dim>& n = in.normal;
  const NVec<dim>& lam = in.lambda;
  const double k2 = p.k * p.k;
  const double cTau = in.D * k2 / p.epsTau;  // tangential coefficient
  const double cN = in.D * k2 / p.epsN;      // inactive normal coefficient
  const double ln = dot<dim>(n, lam);
  AlmNodeResidual<dim> out;
  // Tangential part (both states): -c_tau P lambda = -c_tau (lambda - (n.lambda) n).
  //   d/dlambda = -c_tau (I - n n^T);  d/dn = c_tau ((n.lambda) I + n lambda^T);  d/dD = -(k^2/eps_tau) P lambda.
  for (int i = 0; i < dim; ++i) {
    const double pl = lam[i] - ln * n[i];
    out.r[i] = -cTau * pl;
    out.dD[i] = -(k2 / p.epsTau) * pl;
    for (int c = 0; c < dim; ++c) {
      out.dLambda[i][c] = -cTau * ((i == c ? 1.0 : 0.0) - n[i] * n[c]);
      out.dNormal[i][c] = cTau * ((i == c ? ln : 0.0) + n[i] * lam[c]);
    }
  }
  if (state == ContactState::Slip) {
    // Normal part k g~ n: d/dg~ = k n, d/dn = k g~ I.
    for (int i = 0; i < dim; ++i) {
      out.r[i] += p.k * in.gap * n[i];
      out.dGap[i] = p.k * n[i];
      out.dNormal[i][i] += p.k * in.gap;
    }
  } else {
    // Normal part -c_n (n.lambda) n: d/dlambda = -c_n n n^T, d/dn = -c_n ((n.lambda) I + n lambda^T),
    // d/dD = -(k^2/eps_n)(n.lambda) n.
    for (int i = 0; i < dim; ++i) {
      out.r[i] += -cN * ln * n[i];
      out.dD[i] += -(k2 / p.epsN) * ln * n[i];
      for (int c = 0; c < dim; ++c) {
        out.dLambda[i][c] += -cN * n[i] * n[c];
        out.dNormal[i][c] += -cN * ((i == c ? ln : 0.0) + n[i] * lam[c]);
      }
    }
  }
  return out;
}

double defaultPenalty(double E, double h, double factor) {
  COULOMB_CHECK(E > 0.0, "contact penalty: Young's modulus must be > 0, got " << E);
  COULOMB_CHECK(h > 0.0, "contact penalty: element size must be > 0, got " << h);
  COULOMB_CHECK(factor > 0.0, "contact penalty: penalty factor must be > 0, got " << factor);
  return factor * E / h;
}

#define COULOMB_NODAL_LAW_INSTANTIATE(DIM)                                                                      \
  template AlmNodeResidual<DIM> almResidual<DIM>(const AlmNodeInput<DIM>&, const AlmParameters&, ContactState);
COULOMB_NODAL_LAW_INSTANTIATE(2)
COULOMB_NODAL_LAW_INSTANTIATE(3)
#undef COULOMB_NODAL_LAW_INSTANTIATE

}  // namespace coulomb::contact
