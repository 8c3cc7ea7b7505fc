// coulomb_exodiff A.e B.e [--tolerance T] [--skip PREFIX]...
// Compares two Coulomb results read with the exodusII library: same steps and
// times, and every nodal and global variable of every step equal within
// T × (largest magnitude in A of the variable's family — the name up to its
// first '_', so stress_xy is measured against the largest stress component;
// a family that is identically zero is compared with T absolutely). Global
// forces (reactions, contact forces) are measured against the largest global
// force of the step: a component that is zero by symmetry (a lateral
// reaction) carries the solver's error of the load, not of itself. Other
// globals (node counts) are compared relative to themselves.
// Default T = 1e-6. --skip leaves out the variables whose name starts with
// PREFIX (e.g. contact_multiplier, which scales with 1 / the ALM factor k).
// Used by the regression tests to show that np = 1, 2, 3 give the same answer.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusResults.hpp"

namespace {

double largest(const std::vector<double>& values) {
  double m = 0;
  for (double v : values) m = std::max(m, std::abs(v));
  return m;
}

std::string family(const std::string& name) { return name.substr(0, name.find('_')); }

bool isForce(const std::string& global) {
  for (const char* prefix : {"reaction_", "contact_force_", "contact_normal_force_", "contact_tangential_force_"})
    if (global.rfind(prefix, 0) == 0) return true;
  return false;
}

bool compare(const std::vector<double>& a, const std::vector<double>& b, double tolerance, double scale, double& worst) {
  if (a.size() != b.size()) return false;
  double difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) difference = std::max(difference, std::abs(a[i] - b[i]));
  worst = scale > 0 ? difference / scale : difference;
  return worst <= tolerance;
}

}  // namespace

int main(int argc, char** argv) {
  double tolerance = 1e-6;
  std::vector<std::string> skipped;
  bool usage = argc < 3;
  for (int i = 3; i < argc && !usage; i += 2) {
    const std::string option = argv[i];
    if (i + 1 >= argc) usage = true;
    else if (option == "--tolerance") tolerance = std::atof(argv[i + 1]);
    else if (option == "--skip") skipped.emplace_back(argv[i + 1]);
    else usage = true;
  }
  if (usage) {
    std::cerr << "usage: coulomb_exodiff A.e B.e [--tolerance T] [--skip PREFIX]...\n";
    return 2;
  }
  auto skip = [&skipped](const std::string& name) {
    return std::any_of(skipped.begin(), skipped.end(),
                       [&name](const std::string& prefix) { return name.rfind(prefix, 0) == 0; });
  };
  try {
    const auto a = coulomb::io::readExodusResults(argv[1]);
    const auto b = coulomb::io::readExodusResults(argv[2]);
    COULOMB_REQUIRE(a.times.size() == b.times.size(), "different number of steps: " << a.times.size() << " vs " << b.times.size());
    COULOMB_REQUIRE(a.nodalNames == b.nodalNames, "different nodal variables");
    COULOMB_REQUIRE(a.globalNames == b.globalNames, "different global variables");
    COULOMB_REQUIRE(!a.times.empty(), "no time steps in " << argv[1]);
    int failures = 0;
    for (std::size_t s = 0; s < a.times.size(); ++s) {
      if (std::abs(a.times[s] - b.times[s]) > 1e-12 * std::max(1.0, std::abs(a.times[s]))) {
        std::cerr << "step " << s + 1 << ": time " << a.times[s] << " vs " << b.times[s] << "\n";
        ++failures;
      }
      for (std::size_t v = 0; v < a.nodalNames.size(); ++v) {
        if (skip(a.nodalNames[v])) continue;
        double scale = 0, worst = 0;
        for (std::size_t w = 0; w < a.nodalNames.size(); ++w)
          if (family(a.nodalNames[w]) == family(a.nodalNames[v])) scale = std::max(scale, largest(a.nodal[s][w]));
        if (!compare(a.nodal[s][v], b.nodal[s][v], tolerance, scale, worst)) {
          std::cerr << "step " << s + 1 << ": nodal '" << a.nodalNames[v] << "' differs by " << worst << " (relative)\n";
          ++failures;
        }
      }
      double largestForce = 0;
      for (std::size_t v = 0; v < a.globalNames.size(); ++v)
        if (isForce(a.globalNames[v])) largestForce = std::max(largestForce, std::abs(a.global[s][v]));
      for (std::size_t v = 0; v < a.globalNames.size(); ++v) {
        // iteration counts legitimately differ between rank counts
        if (a.globalNames[v].find("iterations") != std::string::npos || skip(a.globalNames[v])) continue;
        const double scale = isForce(a.globalNames[v]) ? largestForce : std::abs(a.global[s][v]);
        double worst = 0;
        if (!compare({a.global[s][v]}, {b.global[s][v]}, tolerance, scale, worst) &&
            std::abs(a.global[s][v] - b.global[s][v]) > tolerance) {
          std::cerr << "step " << s + 1 << ": global '" << a.globalNames[v] << "' " << a.global[s][v] << " vs "
                    << b.global[s][v] << "\n";
          ++failures;
        }
      }
    }
    if (failures) return 1;
    std::cout << "coulomb_exodiff: " << a.times.size() << " steps, " << a.nodalNames.size() << " nodal and "
              << a.globalNames.size() << " global variables agree within " << tolerance << "\n";
  } catch (const std::exception& e) {
    std::cerr << "coulomb_exodiff: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
