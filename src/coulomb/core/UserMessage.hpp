#pragma once
/// @file UserMessage.hpp
/// @brief An error message as a user reads it: one line, without the throw
/// banner Teuchos puts in front of its exceptions' texts ("<source file of
/// Trilinos>:<line>: Throw number = N Throw test that evaluated to true:
/// <expression>"), which names Trilinos' code instead of the user's input.
#include <string>

namespace coulomb {

/// `message` on one line (newlines and runs of spaces become one space),
/// every Teuchos throw banner removed.
std::string userMessage(const std::string& message);

}  // namespace coulomb
