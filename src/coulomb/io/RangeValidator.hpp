#pragma once
/// @file RangeValidator.hpp
/// @brief A Teuchos validator for a double in an interval whose ends may be
/// open, e.g. Young's modulus in (0, inf) or Poisson's ratio in (-1, 0.5):
/// Teuchos' EnhancedNumberValidator only knows closed intervals.
#include <limits>
#include <string>

#include <initializer_list>

#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

namespace coulomb::io {

class RangeValidator : public Teuchos::ParameterEntryValidator {
public:
  /// lower/upper may be ±infinity (then the end is unbounded).
  RangeValidator(double lower, bool lowerOpen, double upper, bool upperOpen);

  /// "must be > 0", "must be in (-1, 0.5)", ...
  std::string requirement() const;

  const std::string getXMLTypeName() const override { return "coulombRangeValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override { return Teuchos::null; }
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;

private:
  double lower_, upper_;
  bool lowerOpen_, upperOpen_;
};

/// Shorthands.
inline Teuchos::RCP<RangeValidator> positive() {
  return Teuchos::rcp(new RangeValidator(0.0, true, std::numeric_limits<double>::infinity(), true));
}
inline Teuchos::RCP<RangeValidator> nonNegative() {
  return Teuchos::rcp(new RangeValidator(0.0, false, std::numeric_limits<double>::infinity(), true));
}
// Enumerations of names: io::Choices (Choices.hpp), declared once with their values.

}  // namespace coulomb::io
