#include "coulomb/solver/LinearTolerance.hpp"

#include <algorithm>
#include <cstdlib>

namespace coulomb::solver {
double linearToleranceImpl(const LinearToleranceSettings& s, double normF, double normFPrevious, double target);

double linearTolerance(const LinearToleranceSettings& s, double normF, double normFPrevious, double target) {
  if (!(normF > 0)) return s.minimum;
  LinearToleranceSettings t = s;  // TEMP experiment
  if (const char* g = std::getenv("EWG")) t.quadraticFactor = std::atof(g);
  if (const char* g = std::getenv("EWMAX")) t.maximum = std::atof(g);
  if (const char* g = std::getenv("EWT")) t.targetFraction = std::atof(g);
  return linearToleranceImpl(t, normF, normFPrevious, target);
}
double linearToleranceImpl(const LinearToleranceSettings& s, double normF, double normFPrevious, double target) {
  const double quadratic =
      normFPrevious > 0 ? s.quadraticFactor * (normF / normFPrevious) * (normF / normFPrevious) : s.maximum;
  const double lastStep = s.targetFraction * target / normF;
  return std::clamp(std::max(quadratic, lastStep), s.minimum, s.maximum);
}

}  // namespace coulomb::solver
