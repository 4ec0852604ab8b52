#pragma once
/// \file
/// A polynomial ring over ℚ: variable names plus a monomial order. Every polynomial
/// refers to one. The ring also owns every monomial operation (mathicgb's "monoid"):
/// a monomial is a packed array of int32 laid out as [key | exponents], where the key
/// is M·e for the order matrix M. Because M is linear, multiplying monomials adds the
/// whole array, and comparing them compares keys only.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "implicitizer/polynomial/monomial_order.hpp"

namespace implicitizer {

class Ring;
/// Rings are shared: polynomials keep their ring alive.
using RingPtr = std::shared_ptr<const Ring>;

/// Exponents and keys are int32; the ring refuses total degrees above this so that
/// weighted keys (weights <= 1024) cannot overflow.
inline constexpr std::int32_t kMaxTotalDegree = 1 << 20;

/// The most variables a ring may have. Monomials are dense (a key word per row of the
/// order matrix and an exponent per variable) and encoding one costs a product with
/// the num_variables² order matrix, so a ring of 20 000 variables would take gigabytes
/// and seconds per term; requests are capped far lower (Budget::max_variables).
inline constexpr std::size_t kMaxVariables = 1024;

/// Variable names and a monomial order, with the monomial arithmetic for them.
class Ring {
 public:
  /// Builds a ring. Throws InputError (`invalid_variables`) for duplicate or empty
  /// names, (`invalid_order`) when the order does not fit the variables, and
  /// LimitExceeded (size) for more than kMaxVariables variables.
  static RingPtr make(std::vector<std::string> variables, const MonomialOrder& order = MonomialOrder::grevlex());

  /// The variable names, largest first.
  const std::vector<std::string>& variables() const { return variables_; }
  /// The number of variables.
  std::size_t num_variables() const { return variables_.size(); }
  /// The index of `name`, if it is a variable of this ring.
  std::optional<std::size_t> index_of(const std::string& name) const;
  /// The order description.
  const MonomialOrder& order() const { return order_; }

  /// Number of int32 words in one monomial: key words plus one per variable.
  std::size_t monomial_size() const { return key_size_ + variables_.size(); }
  /// Number of key words.
  std::size_t key_size() const { return key_size_; }

  /// Writes the monomial with exponent vector `exponents` (num_variables entries)
  /// into `out` (monomial_size words).
  void encode(const std::int32_t* exponents, std::int32_t* out) const;
  /// The exponent vector of monomial `m`.
  const std::int32_t* exponents(const std::int32_t* m) const { return m + key_size_; }
  /// Total degree of `m`.
  std::int32_t total_degree(const std::int32_t* m) const;
  /// The degree of `m` in the order's degree weights (MonomialOrder::degree_weights):
  /// the total degree for lex, grlex and grevlex, the weighted degree of a weighted
  /// order, the eliminated variables' degree of an elimination order. Buchberger's
  /// sugar is measured in it, as Singular measures its ecart in the order's first
  /// weight vector: with the total degree instead, an elimination order picks pairs
  /// by their x,y,z degree and the basis blows up (biquadratic_patch: over 100 s
  /// against 42 ms).
  std::int32_t sugar_degree(const std::int32_t* m) const {
    std::int32_t d = 0;
    for (std::size_t i = 0; i < degree_weights_.size(); ++i) d += degree_weights_[i] * m[key_size_ + i];
    return d;
  }
  /// True when some variable has degree weight 0: the order is an elimination order
  /// for the variables of positive weight (a weighted order with zero weights, or a
  /// block order), and its degree says nothing about the other variables.
  bool is_elimination_order() const { return is_elimination_order_; }

  /// -1, 0 or 1 as `a` is smaller than, equal to or larger than `b` in the order.
  int compare(const std::int32_t* a, const std::int32_t* b) const {
    for (std::size_t i = 0; i < key_size_; ++i) {
      if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
  }
  /// Whether `a` and `b` are the same monomial.
  bool equal(const std::int32_t* a, const std::int32_t* b) const { return compare(a, b) == 0; }
  /// out = a·b (out may alias a or b).
  void multiply(const std::int32_t* a, const std::int32_t* b, std::int32_t* out) const {
    const std::size_t n = monomial_size();
    for (std::size_t i = 0; i < n; ++i) out[i] = a[i] + b[i];
  }
  /// Whether `a` divides `b`.
  bool divides(const std::int32_t* a, const std::int32_t* b) const {
    const std::size_t n = monomial_size();
    for (std::size_t i = key_size_; i < n; ++i) {
      if (a[i] > b[i]) return false;
    }
    return true;
  }
  /// out = b / a; precondition: divides(a, b).
  void divide(const std::int32_t* b, const std::int32_t* a, std::int32_t* out) const {
    const std::size_t n = monomial_size();
    for (std::size_t i = 0; i < n; ++i) out[i] = b[i] - a[i];
  }
  /// out = lcm(a, b).
  void lcm(const std::int32_t* a, const std::int32_t* b, std::int32_t* out) const;
  /// Whether gcd(a, b) = 1.
  bool coprime(const std::int32_t* a, const std::int32_t* b) const;
  /// A 64-bit summary such that divides(a, b) implies (mask(a) & ~mask(b)) == 0:
  /// a cheap filter before the exact divisibility test.
  std::uint64_t divisor_mask(const std::int32_t* m) const;

  /// Whether the two rings have the same variables and order.
  bool operator==(const Ring& other) const;

 private:
  Ring(std::vector<std::string> variables, const MonomialOrder& order);

  std::vector<std::string> variables_;
  MonomialOrder order_;
  std::vector<std::vector<std::int32_t>> matrix_;
  std::vector<std::int32_t> degree_weights_;
  bool is_elimination_order_ = false;
  std::size_t key_size_ = 0;
};

}  // namespace implicitizer
