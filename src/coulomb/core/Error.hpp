#pragma once
/// @file Error.hpp
/// @brief What a user can fix (coulomb::Error) apart from what is a bug
/// (coulomb::InternalError), and the checking macros.
#include <sstream>
#include <stdexcept>
#include <string>

namespace coulomb {

/// @brief An error the user can act on: the message names the parameter,
/// file, set or block that is wrong. The executable prints it on one line
/// and exits non-zero on every rank.
class Error : public std::runtime_error {
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// @brief The residual or tangent could not be evaluated at one iterate: a
/// projection or inverse map that did not converge, a degenerate contact
/// geometry, a slave node deeper in the master than the search reaches, a
/// non-finite value. Thrown on every rank alike (Parallel.hpp); the model
/// evaluator turns it into a rejected iterate, so the load step fails and is
/// cut back instead of the run ending. The message says what happened.
class EvaluationError : public Error {
public:
  using Error::Error;
};

/// @brief A broken internal invariant: a bug in Coulomb, not in the input.
/// `main` reports it as such, with the rank, and aborts every rank (the
/// other ranks may not have failed). Never caught to retry or to cut back.
class InternalError : public std::logic_error {
public:
  explicit InternalError(const std::string& message) : std::logic_error(message) {}
};

}  // namespace coulomb

/// Always-on check of an internal invariant: throws coulomb::InternalError
/// with the streamed message and the source location.
/// Example: COULOMB_CHECK(z.size() == owned.size(), "one multiplier per owned slave node");
#define COULOMB_CHECK(condition, message)                                                                   \
  do {                                                                                                      \
    if (!(condition)) {                                                                                     \
      std::ostringstream coulomb_check_stream_;                                                             \
      coulomb_check_stream_ << message << " (" << __FILE__ << ":" << __LINE__ << ")";                       \
      throw ::coulomb::InternalError(coulomb_check_stream_.str());                                          \
    }                                                                                                       \
  } while (false)

/// Always-on check: throws coulomb::Error with a streamed message.
/// Example: COULOMB_REQUIRE(E > 0, "Materials/steel: Young's Modulus must be > 0, got " << E);
#define COULOMB_REQUIRE(condition, message)                 \
  do {                                                      \
    if (!(condition)) {                                     \
      std::ostringstream coulomb_require_stream_;           \
      coulomb_require_stream_ << message;                   \
      throw ::coulomb::Error(coulomb_require_stream_.str()); \
    }                                                       \
  } while (false)

/// Debug-only check of a programmer invariant (compiled out in Release).
#ifndef NDEBUG
#define COULOMB_ASSERT(condition)                                                    \
  do {                                                                               \
    if (!(condition))                                                                \
      throw ::coulomb::InternalError(std::string(#condition) + " at " + __FILE__ + ":" + \
                                     std::to_string(__LINE__));                     \
  } while (false)
#else
#define COULOMB_ASSERT(condition) \
  do {                            \
  } while (false)
#endif
