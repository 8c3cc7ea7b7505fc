#include "coulomb/solver/LinearTolerance.hpp"

#include <algorithm>

#include <Teuchos_ParameterList.hpp>

namespace coulomb::solver {

double linearTolerance(const LinearToleranceSettings& s, double normF, double normFPrevious, double target) {
  if (!(normF > 0)) return s.minimum;
  const double loosest = std::max(s.maximum, s.minimum);
  const double first = s.looseFirstIteration ? loosest : s.minimum;
  const double quadratic =
      normFPrevious > 0 ? s.quadraticFactor * (normF / normFPrevious) * (normF / normFPrevious) : first;
  const double lastStep = s.targetFraction * target / normF;
  return std::clamp(std::max(quadratic, lastStep), s.minimum, loosest);
}

bool noxSetsLinearTolerance(const Teuchos::ParameterList& nox) {
  const auto* direction = nox.getPtr<Teuchos::ParameterList>("Direction");
  const auto* newton = direction ? direction->getPtr<Teuchos::ParameterList>("Newton") : nullptr;
  if (!newton) return false;
  const auto* linear = newton->getPtr<Teuchos::ParameterList>("Linear Solver");
  return newton->isParameter("Forcing Term Method") || (linear && linear->isParameter("Tolerance"));
}

}  // namespace coulomb::solver
