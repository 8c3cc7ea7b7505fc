#include "coulomb/io/ExodusError.hpp"

#include <exodusII.h>

namespace coulomb::io {

std::string lastExodusError() {
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  std::string text;
  if (function && *function) text += std::string(function) + ": ";
  if (message && *message) text += message;
  return text;
}

}  // namespace coulomb::io
