#pragma once
/// @file Types.hpp
/// @brief Ordinal and scalar types shared by all layers (what Debian's
/// Trilinos 13.2 instantiates: double, int, long long, serial node).
#include <cstdint>

namespace coulomb {
using Scalar = double;
using LocalOrdinal = int;
using GlobalOrdinal = long long;
}  // namespace coulomb
