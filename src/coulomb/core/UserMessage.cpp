/// @file UserMessage.cpp
/// @brief userMessage (UserMessage.hpp).
#include "coulomb/core/UserMessage.hpp"

#include <cctype>

namespace coulomb {
namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// Where the banner whose "Throw number = " is at `mark` starts ("file:line:"
/// before it, white space between), or npos when the text before is no such
/// location.
std::size_t bannerStart(const std::string& s, std::size_t mark) {
  std::size_t i = mark;
  while (i > 0 && isSpace(s[i - 1])) --i;
  if (i == 0 || s[i - 1] != ':') return std::string::npos;
  --i;
  const std::size_t digitsEnd = i;
  while (i > 0 && isDigit(s[i - 1])) --i;
  if (i == digitsEnd || i == 0 || s[i - 1] != ':') return std::string::npos;
  --i;
  const std::size_t fileEnd = i;
  while (i > 0 && !isSpace(s[i - 1]) && s[i - 1] != ':') --i;
  return i == fileEnd ? std::string::npos : i;
}

/// Where the banner whose "Throw number = " is at `mark` ends (past the
/// "Throw test that evaluated to true: ..." line), or npos.
std::size_t bannerEnd(const std::string& s, std::size_t mark) {
  static const std::string number = "Throw number = ", test = "Throw test that evaluated to true: ";
  std::size_t i = mark + number.size();
  const std::size_t digits = i;
  while (i < s.size() && isDigit(s[i])) ++i;
  if (i == digits) return std::string::npos;
  while (i < s.size() && isSpace(s[i])) ++i;
  if (s.compare(i, test.size(), test) != 0) return std::string::npos;
  const std::size_t newline = s.find('\n', i);
  return newline == std::string::npos ? s.size() : newline + 1;
}

}  // namespace

std::string userMessage(const std::string& message) {
  // TEUCHOS_TEST_FOR_EXCEPTION's banner: "file:line:\n\nThrow number = N\n\n
  // Throw test that evaluated to true: expression\n\n" before the text. A
  // linear scan: std::regex backtracked for seconds on a 4 kB message (a
  // fuzzed deck quoted in Teuchos' XML error, tests/fuzz/regressions/deck).
  std::string text;
  std::size_t copied = 0, from = 0;
  for (std::size_t mark; (mark = message.find("Throw number = ", from)) != std::string::npos;) {
    from = mark + 1;
    const std::size_t start = bannerStart(message, mark), end = bannerEnd(message, mark);
    if (start == std::string::npos || end == std::string::npos || start < copied) continue;
    text.append(message, copied, start - copied);
    copied = from = end;
  }
  text.append(message, copied, std::string::npos);
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
