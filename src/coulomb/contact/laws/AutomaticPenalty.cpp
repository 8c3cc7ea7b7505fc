#include "coulomb/contact/laws/AutomaticPenalty.hpp"

#include <algorithm>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

double defaultPenalty(double E, double h, double factor) {
  COULOMB_CHECK(E > 0.0, "contact penalty: Young's modulus must be > 0, got " << E);
  COULOMB_CHECK(h > 0.0, "contact penalty: element size must be > 0, got " << h);
  COULOMB_CHECK(factor > 0.0, "contact penalty: penalty factor must be > 0, got " << factor);
  return factor * E / h;
}

double meanFaceDiameter(const std::vector<PenaltyFace>& faces) {
  double sum = 0;
  for (const auto& face : faces) sum += face.diameter;
  return faces.empty() ? 0.0 : sum / static_cast<double>(faces.size());
}

std::vector<double> automaticNodalPenalty(const std::vector<PenaltyFace>& faces, int numNodes, double masterModulus,
                                          double factor, PenaltySize size) {
  COULOMB_CHECK(numNodes >= 0, "automatic penalty: negative node count");
  std::vector<double> diameterSum(numNodes, 0.0), modulus(numNodes, 0.0);
  std::vector<int> count(numNodes, 0);
  const double meanSize = meanFaceDiameter(faces);
  for (const auto& face : faces)
    for (int a = 0; a < face.numNodes; ++a) {
      const int j = face.nodes[a];
      COULOMB_CHECK(j >= 0 && j < numNodes, "automatic penalty: face node " << j << " out of range");
      COULOMB_REQUIRE(face.diameter > 0.0, "automatic penalty: a slave face of zero size (its nodes coincide)");
      diameterSum[j] += face.diameter;
      modulus[j] = std::max(modulus[j], face.modulus);
      ++count[j];
    }
  std::vector<double> penalty(numNodes, 0.0);
  for (int j = 0; j < numNodes; ++j) {
    if (count[j] == 0) continue;
    const double E = masterModulus > 0 && modulus[j] > 0 ? std::min(modulus[j], masterModulus)
                                                         : std::max(modulus[j], masterModulus);
    penalty[j] = defaultPenalty(E, size == PenaltySize::PairMean ? meanSize : diameterSum[j] / count[j], factor);
  }
  return penalty;
}

}  // namespace coulomb::contact
