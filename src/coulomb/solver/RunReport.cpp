#include "coulomb/solver/RunReport.hpp"

#include <sstream>

#include "coulomb/solver/Progress.hpp"

namespace coulomb::solver {

namespace {

std::string number(double value, int digits = 4) {
  std::ostringstream out;
  out.precision(digits);
  out << value;
  return out.str();
}

std::string kind(const ProblemSize& size) {
  bool anyFrictional = false;
  for (const auto& p : size.pairs) anyFrictional = anyFrictional || p.frictional;
  if (size.pairs.empty()) return "elasticity without contact";
  return anyFrictional ? "frictional contact" : "frictionless contact";
}

}  // namespace

std::string slidingState(double ratio, double mu) {
  if (ratio >= 0.99 * mu) return "Q/P = mu: the pair slides (gross slip)";
  return "Q/P < mu: the pair holds (stick or partial slip)";
}

void printProblemSize(std::ostream& out, const ProblemSize& size) {
  out << "  mesh " << size.meshFile << ": " << size.dimension << "D, " << size.nodes << " nodes, " << size.elements
      << " elements in " << size.blocks.size() << " block(s) (";
  for (std::size_t b = 0; b < size.blocks.size(); ++b) out << (b ? ", " : "") << size.blocks[b];
  out << "), " << size.dofs << " DoFs\n";
  out << "  contact pairs: " << size.pairs.size() << "\n";
  for (const auto& p : size.pairs)
    out << "    '" << p.name << "': slave '" << p.slave << "' " << p.slaveFaces << " faces (" << p.slaveNodes
        << " nodes), master '" << p.master << "' " << p.masterFaces << " faces; " << p.formulation << ", " << p.law
        << "\n";
  out << "  load stepping: " << size.numberOfSteps << " steps to t = " << size.finalTime << "\n";
  out << "  result (not written by --check): " << size.outputFile << "\n";
}

void printRunSummary(std::ostream& out, const ProblemSize& size, const std::vector<PairRecord>& pairs, int steps,
                     int cutbacks, double finalTime, double wallSeconds) {
  out << "\nSummary: " << kind(size) << ", " << size.dimension << "D, " << size.nodes << " nodes, " << size.dofs
      << " DoFs; " << steps << " load steps to t = " << number(finalTime) << " (" << cutbacks << " cutbacks) in "
      << formatDuration(wallSeconds) << "\n";
  for (std::size_t p = 0; p < size.pairs.size() && p < pairs.size(); ++p) {
    const auto& d = size.pairs[p];
    const auto& r = pairs[p];
    out << "  contact '" << d.name << "' (" << d.law << "): peak contact pressure " << number(r.peakPressure)
        << " at t = " << number(r.peakTime) << "\n";
    out << "    last step: " << r.active << " of " << d.slaveNodes << " slave nodes in contact";
    if (d.frictional) out << " (" << r.stick << " stick, " << r.active - r.stick << " slip)";
    out << ", normal force P = " << number(r.normalForce);
    if (d.frictional) {
      out << ", tangential Q = " << number(r.tangentialForce);
      if (r.normalForce > 0) {
        const double ratio = r.tangentialForce / r.normalForce;
        out << ", Q/P = " << number(ratio, 3);
        if (d.mu > 0) out << " against mu = " << number(d.mu, 3) << ": " << slidingState(ratio, d.mu);
      }
    }
    out << "\n";
  }
  out << "  result: " << size.outputFile << " (open it in ParaView; pictures: scripts/render " << size.outputFile
      << ")\n";
}

}  // namespace coulomb::solver
