#pragma once
/// \file
/// The three ways a computation can refuse to answer. Each maps to one exit status
/// of the command line and one HTTP status of the server (see docs/api.md).

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace implicitizer {

/// The input is wrong: a parse error, an unknown variable, a zero denominator.
/// `code` is stable (documented in docs/cli.md); `position` is the 0-based character
/// offset in the offending input, when there is one; `field` names which input
/// ("x", "polynomials[2]", ...) when the caller knows it.
class InputError : public std::runtime_error {
 public:
  InputError(std::string code, const std::string& message, std::optional<std::size_t> position = std::nullopt)
      : std::runtime_error(message), code_(std::move(code)), position_(position) {}

  /// The stable machine-readable code, e.g. `unexpected_character`.
  const std::string& code() const { return code_; }
  /// The 0-based character position the error applies to, if any.
  std::optional<std::size_t> position() const { return position_; }
  /// Which input field the error belongs to ("" when unknown).
  const std::string& field() const { return field_; }
  /// Returns a copy that names the input field the error came from.
  InputError in_field(std::string field) const {
    InputError copy = *this;
    copy.field_ = std::move(field);
    return copy;
  }

 private:
  std::string code_;
  std::optional<std::size_t> position_;
  std::string field_;
};

/// Which limit of a Budget stopped a computation.
enum class Limit {
  time,       ///< the wall-time deadline
  size,       ///< the term limit, or a count stated up front (variables, polynomials)
  memory,     ///< the bytes the computation's threads hold (MemoryAccount)
  work,       ///< the work allowance of one try (auto's head starts); callers that set
              ///< one catch it, so it never reaches a user
  cancelled,  ///< Budget::cancel(): a client left, or the server shuts down
};

/// Returns "time", "size", "memory", "work" or "cancelled".
const char* to_string(Limit limit);

/// A computation stopped because its Budget ran out. `where` names the loop
/// (e.g. "buchberger") so that the user learns what was running.
class LimitExceeded : public std::runtime_error {
 public:
  LimitExceeded(Limit limit, const std::string& message) : std::runtime_error(message), limit_(limit) {}
  /// The limit that was hit.
  Limit limit() const { return limit_; }

 private:
  Limit limit_;
};

/// No single implicit equation can be given: the image of the parametrization is
/// not a surface (code `no_single_equation`; `generators` holds the printed
/// generators of the elimination ideal, empty when the ideal is zero, i.e. the
/// image is dense in space), or the route asked for does not apply (code
/// `base_points`: the auxiliary resultant vanishes identically).
class NoSingleEquation : public std::runtime_error {
 public:
  NoSingleEquation(const std::string& message, std::vector<std::string> generators,
                   std::string code = "no_single_equation")
      : std::runtime_error(message), generators_(std::move(generators)), code_(std::move(code)) {}
  /// The generators of the elimination ideal, printed.
  const std::vector<std::string>& generators() const { return generators_; }
  /// The stable code: `no_single_equation` or `base_points`.
  const std::string& code() const { return code_; }

 private:
  std::vector<std::string> generators_;
  std::string code_;
};

}  // namespace implicitizer
