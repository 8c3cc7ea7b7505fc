#include "coulomb/contact/laws/FrictionlessNode.hpp"

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

template <int dim>
FrictionlessNodeState<dim> frictionlessState(const FrictionlessNodeInput<dim>& in, ContactState previous,
                                             const FrictionlessParameters& p) {
  COULOMB_CHECK(in.D > 0.0 && p.k > 0.0 && p.epsN > 0.0 && p.thickness > 0.0,
                "frictionless node: D " << in.D << ", k " << p.k << ", eps_n " << p.epsN << ", t " << p.thickness);
  FrictionlessNodeState<dim> out;
  out.frame = condensationFrame<dim>(in.normal, in.prescribed);
  const auto& frame = out.frame;
  if (!frame.usable) return out;
  double lambdaN = 0;
  if (isActive(previous)) {
    double projected = 0;
    for (int f = 0; f < frame.numFree; ++f) {
      const int c = frame.free[f];
      projected += frame.a[c] * in.residual[c];
    }
    lambdaN = projected / (p.k * p.thickness * in.D * frame.normFree);
  }
  out.state = p.multiPointConstraint ? mpcContactState(isActive(previous), lambdaN, in.gap)
                                     : almContactState(lambdaN, in.gap, in.D, p.k, p.epsN, p.touchingGap);
  out.lambdaN = lambdaN;
  out.augmentedNormal = p.multiPointConstraint ? p.k * lambdaN
                                               : augmentedNormalMultiplier(lambdaN, in.gap, in.D, p.k, p.epsN);
  return out;
}

template FrictionlessNodeState<2> frictionlessState<2>(const FrictionlessNodeInput<2>&, ContactState,
                                                      const FrictionlessParameters&);
template FrictionlessNodeState<3> frictionlessState<3>(const FrictionlessNodeInput<3>&, ContactState,
                                                      const FrictionlessParameters&);

}  // namespace coulomb::contact
