#include "coulomb/io/RangeValidator.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Teuchos_ParameterEntry.hpp>

namespace coulomb::io {

RangeValidator::RangeValidator(double lower, bool lowerOpen, double upper, bool upperOpen)
    : lower_(lower), upper_(upper), lowerOpen_(lowerOpen), upperOpen_(upperOpen) {}

std::string RangeValidator::requirement() const {
  std::ostringstream out;
  const bool hasLower = std::isfinite(lower_), hasUpper = std::isfinite(upper_);
  if (hasLower && !hasUpper) out << "must be " << (lowerOpen_ ? "> " : ">= ") << lower_;
  else if (!hasLower && hasUpper) out << "must be " << (upperOpen_ ? "< " : "<= ") << upper_;
  else if (hasLower && hasUpper)
    out << "must be in " << (lowerOpen_ ? "(" : "[") << lower_ << ", " << upper_ << (upperOpen_ ? ")" : "]");
  else out << "any number";
  return out.str();
}

void RangeValidator::printDoc(const std::string& docString, std::ostream& out) const {
  out << "# " << docString << " (" << requirement() << ")\n";
}

void RangeValidator::validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                              const std::string& sublistName) const {
  const double value = Teuchos::any_cast<double>(entry.getAny(false));
  const bool aboveLower = lowerOpen_ ? value > lower_ : value >= lower_;
  const bool belowUpper = upperOpen_ ? value < upper_ : value <= upper_;
  if (!(aboveLower && belowUpper) || std::isnan(value))
    throw std::invalid_argument("'" + sublistName + "/" + paramName + "' " + requirement());
}

}  // namespace coulomb::io
