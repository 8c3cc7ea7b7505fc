#pragma once
/// @file ExodusError.hpp
/// @brief The exodus library's last error, for messages that name a file.
#include <string>

namespace coulomb::io {

/// @brief "function: message" of the exodusII library's last error (empty when it has none).
std::string lastExodusError();

}  // namespace coulomb::io
