#pragma once
/// @file ParameterValidation.hpp
/// @brief Reads an XML deck and checks a user ParameterList against a
/// valid-parameter list, with one-line errors that name the sublist path.
///
/// Conventions of a valid list (built by each component's validParameters()):
/// - an entry's type is the type the user must give (Teuchos' own types);
/// - an entry's validator (Teuchos StringValidator, EnhancedNumberValidator…)
///   checks enumerations and ranges;
/// - a doc string starting with "[required]" marks a required entry;
/// - a sublist named "*" is the template for user-named sublists (one per
///   material, block, boundary condition…);
/// - a sublist whose doc string starts with "[passthrough]" is handed to a
///   Trilinos package untouched (NOX, Stratimikos) and not checked here.
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace coulomb::io {

/// Marker prefixes for doc strings (see file comment).
inline constexpr const char* kRequired = "[required] ";
inline constexpr const char* kPassthrough = "[passthrough] ";

/// @brief Parses an XML file into a ParameterList; malformed XML or a missing
/// file raise coulomb::Error naming the file (and the parser's reason, on one line).
Teuchos::RCP<Teuchos::ParameterList> readXmlDeck(const std::string& path);

/// @brief Checks `user` against `valid`: unknown names, wrong types, values
/// out of range or not in an enumeration, missing required entries. Throws
/// coulomb::Error whose message names the parameter and its sublist path,
/// e.g. "deck: 'Load Stepping/Number of Steps' must be >= 1, got 0".
void validateParameters(const Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                        const std::string& path = "");

/// @brief The value of `name` in `user`, or the default stored in `valid`.
template <typename T>
T valueOrDefault(const Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
                 const std::string& name) {
  return user.isParameter(name) ? user.get<T>(name) : valid.get<T>(name);
}

/// @brief Joins a sublist path and a name with '/'.
std::string joinPath(const std::string& path, const std::string& name);

}  // namespace coulomb::io
