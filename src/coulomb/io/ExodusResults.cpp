#include "coulomb/io/ExodusResults.hpp"

#include <algorithm>

#include <exodusII.h>

#include "coulomb/core/Error.hpp"

namespace coulomb::io {

namespace {

std::vector<std::string> variableNames(int file, ex_entity_type type, const std::string& path) {
  int count = 0;
  COULOMB_REQUIRE(ex_get_variable_param(file, type, &count) >= 0, "result '" << path << "': cannot read variable count");
  std::vector<std::string> names;
  if (count == 0) return names;
  const int length = static_cast<int>(ex_inquire_int(file, EX_INQ_MAX_READ_NAME_LENGTH));
  std::vector<std::vector<char>> buffers(count, std::vector<char>(length + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  COULOMB_REQUIRE(ex_get_variable_names(file, type, count, pointers.data()) >= 0,
                  "result '" << path << "': cannot read variable names");
  for (auto& b : buffers) names.emplace_back(b.data());
  return names;
}

std::size_t indexOf(const std::vector<std::string>& names, const std::string& name, const char* kind) {
  const auto it = std::find(names.begin(), names.end(), name);
  COULOMB_REQUIRE(it != names.end(), "result has no " << kind << " variable '" << name << "'");
  return static_cast<std::size_t>(it - names.begin());
}

}  // namespace

std::size_t ExodusResults::nodalIndex(const std::string& name) const { return indexOf(nodalNames, name, "nodal"); }
std::size_t ExodusResults::globalIndex(const std::string& name) const { return indexOf(globalNames, name, "global"); }

ExodusResults readExodusResults(const std::string& path) {
  int wordSize = 8, ioWordSize = 0;
  float version = 0;
  ex_opts(0);
  const int file = ex_open(path.c_str(), EX_READ, &wordSize, &ioWordSize, &version);
  COULOMB_REQUIRE(file >= 0, "result '" << path << "' cannot be opened as Exodus II");
  ExodusResults results;
  try {
    const int steps = static_cast<int>(ex_inquire_int(file, EX_INQ_TIME));
    const int64_t numNodes = ex_inquire_int(file, EX_INQ_NODES);
    results.nodalNames = variableNames(file, EX_NODAL, path);
    results.globalNames = variableNames(file, EX_GLOBAL, path);
    results.times.resize(steps);
    for (int s = 0; s < steps; ++s) {
      COULOMB_REQUIRE(ex_get_time(file, s + 1, &results.times[s]) >= 0, "result '" << path << "': cannot read time " << s + 1);
      std::vector<std::vector<double>> nodal(results.nodalNames.size(), std::vector<double>(numNodes));
      for (std::size_t v = 0; v < nodal.size(); ++v)
        COULOMB_REQUIRE(ex_get_var(file, s + 1, EX_NODAL, static_cast<int>(v + 1), 1, numNodes, nodal[v].data()) >= 0,
                        "result '" << path << "': cannot read nodal variable " << results.nodalNames[v]);
      results.nodal.push_back(std::move(nodal));
      std::vector<double> global(results.globalNames.size());
      if (!global.empty())
        COULOMB_REQUIRE(ex_get_var(file, s + 1, EX_GLOBAL, 1, 1, static_cast<int64_t>(global.size()), global.data()) >= 0,
                        "result '" << path << "': cannot read global variables");
      results.global.push_back(std::move(global));
    }
  } catch (...) {
    ex_close(file);
    throw;
  }
  ex_close(file);
  return results;
}

}  // namespace coulomb::io
