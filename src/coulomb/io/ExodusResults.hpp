#pragma once
/// @file ExodusResults.hpp
/// @brief Reads the time steps, nodal and global variables of an Exodus II
/// result back with the exodusII library (tests and result comparison).
#include <string>
#include <vector>

namespace coulomb::io {

/// @brief Every step of every nodal and global variable of a result file.
struct ExodusResults {
  std::vector<double> times;
  std::vector<std::string> nodalNames;
  std::vector<std::string> globalNames;
  /// nodal[step][variable][node]
  std::vector<std::vector<std::vector<double>>> nodal;
  /// global[step][variable]
  std::vector<std::vector<double>> global;

  /// Index of a nodal variable; throws coulomb::Error naming it if absent.
  std::size_t nodalIndex(const std::string& name) const;
  std::size_t globalIndex(const std::string& name) const;
};

/// @brief Reads `path`; coulomb::Error naming the file on failure.
ExodusResults readExodusResults(const std::string& path);

}  // namespace coulomb::io
