/// @file UserMessage.cpp
/// @brief userMessage (UserMessage.hpp).
#include "coulomb/core/UserMessage.hpp"

#include <regex>

namespace coulomb {

std::string userMessage(const std::string& message) {
  // TEUCHOS_TEST_FOR_EXCEPTION's banner: "file:line:\n\nThrow number = N\n\n
  // Throw test that evaluated to true: expression\n\n" before the text.
  static const std::regex banner(
      R"([^\s:]+:[0-9]+:\s*Throw number = [0-9]+\s*Throw test that evaluated to true: [^\n]*\n?)");
  const std::string text = std::regex_replace(message, banner, "");
  std::string line;
  for (char c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    if (c == ' ' && (line.empty() || line.back() == ' ')) continue;
    line += c;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

}  // namespace coulomb
