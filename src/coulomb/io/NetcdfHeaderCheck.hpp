#pragma once
/// @file NetcdfHeaderCheck.hpp
/// @brief A bounds check of the header of a classic netCDF file (CDF-1,
/// CDF-2 "64-bit offset", CDF-5), the container of most Exodus II meshes,
/// before netCDF reads it: netCDF allocates each list of the header (the
/// dimensions, attributes, variables, a variable's dimension ids, an
/// attribute's values) at the length the header declares, so one corrupted
/// count made it ask for gigabytes (found by tests/fuzz/fuzz_exodus) and a
/// damaged mesh ended in an out-of-memory kill instead of a message. Every
/// declared count is checked against the bytes the file has left. Other
/// containers (netCDF-4/HDF5) are left to their library.
#include <cstdint>
#include <string>
#include <vector>

namespace coulomb::io {

/// What is wrong with the classic netCDF header at the start of `bytes`
/// (the file's first bytes; `fileSize` its length), or "" when every count
/// fits in the file or `bytes` is not a classic netCDF file.
std::string classicNetcdfHeaderProblem(const std::vector<unsigned char>& bytes, std::uint64_t fileSize);

/// The same for the file at `path` (reads at most the header's extent).
std::string classicNetcdfHeaderProblem(const std::string& path);

}  // namespace coulomb::io
