#pragma once
/// @file Choices.hpp
/// @brief An enumeration of a deck declared once: its names and values in one
/// table, from which the deck's validator, the parse and the name for
/// messages all come (no validator list, parse chain and toString to keep
/// in step).
///
///   const io::Choices<SlipMeasure> kSlipMeasures{{"Objective", SlipMeasure::Objective},
///                                                {"Non-Objective", SlipMeasure::NonObjective}};
///   list.set("Slip Measure", "Objective", "...", kSlipMeasures.validator());
///   settings.slipMeasure = kSlipMeasures.value(list.get<std::string>("Slip Measure"));
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "coulomb/core/Error.hpp"

namespace coulomb::io {

template <class Enum>
class Choices {
public:
  Choices(std::initializer_list<std::pair<const char*, Enum>> choices) : choices_(choices) {}

  /// The deck's validator: one of the names.
  Teuchos::RCP<Teuchos::StringValidator> validator() const {
    Teuchos::Array<std::string> names;
    for (const auto& [name, value] : choices_) names.push_back(name);
    return Teuchos::rcp(new Teuchos::StringValidator(names));
  }
  /// The value of a name the validator accepted.
  Enum value(const std::string& name) const {
    for (const auto& [n, value] : choices_)
      if (name == n) return value;
    throw InternalError("'" + name + "' is not a choice of this enumeration (the deck was not validated)");
  }
  /// The deck's name of a value.
  const char* name(Enum value) const {
    for (const auto& [n, v] : choices_)
      if (v == value) return n;
    throw InternalError("an enumeration value without a deck name");
  }

private:
  std::vector<std::pair<const char*, Enum>> choices_;
};

}  // namespace coulomb::io
