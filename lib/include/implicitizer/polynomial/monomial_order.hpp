#pragma once
/// \file
/// Monomial orders as values (mathicgb's "order is only a description").
/// Every order here is a matrix order: monomials compare as the lexicographic order
/// of M·e, where e is the exponent vector. The Ring turns the description into that
/// matrix once, so that comparing two monomials is comparing short integer keys.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace implicitizer {

/// A monomial order description: lex, grlex, grevlex, weighted (a weight vector
/// with a tie-break order) or block (one order on the first k variables, another on
/// the rest: an elimination order for the first block). Cheap to copy.
class MonomialOrder {
 public:
  enum class Kind { lex, grlex, grevlex, weighted, block };

  /// Pure lexicographic order, x1 > x2 > ... > xn.
  static MonomialOrder lex();
  /// Total degree, ties broken lexicographically.
  static MonomialOrder grlex();
  /// Total degree, ties broken by the reverse lexicographic order (the smallest
  /// last-variable exponent wins). The default of this project, as of Singular's `dp`.
  static MonomialOrder grevlex();
  /// Weighted degree Σ w_i e_i first (weights in [0, 1024]), then `tie_break`.
  /// It is admissible because `tie_break` is and weights are non-negative.
  static MonomialOrder weighted(std::vector<int> weights, const MonomialOrder& tie_break);
  /// `first` on the first `first_block_size` variables, then `rest` on the others.
  /// Any monomial containing a first-block variable is larger than every monomial
  /// without one, which is what elimination needs (Cox–Little–O'Shea, §3.1).
  static MonomialOrder block(std::size_t first_block_size, const MonomialOrder& first, const MonomialOrder& rest);

  /// Parses `lex`, `grlex`, `grevlex` (the contract's names); throws InputError
  /// (`unknown_order`) otherwise.
  static MonomialOrder from_name(const std::string& name);

  /// The kind of order.
  Kind kind() const { return kind_; }
  /// Weights of a weighted order (empty otherwise).
  const std::vector<int>& weights() const { return weights_; }
  /// Size of the first block of a block order (0 otherwise).
  std::size_t first_block_size() const { return first_block_size_; }

  /// The rows of the order's matrix for `num_variables` variables. Throws InputError
  /// (`invalid_order`) when the description does not fit that many variables.
  std::vector<std::vector<std::int32_t>> matrix(std::size_t num_variables) const;

  /// The weights of the degree this order refines first, for `num_variables`
  /// variables: all ones for lex, grlex and grevlex (lex refines no degree; the total
  /// degree is the natural one), the weights of a weighted order (all ones if they
  /// are all zero), and for a block order the first block's degree weights followed
  /// by zeros (the elimination degree). Buchberger's sugar is measured in it.
  std::vector<std::int32_t> degree_weights(std::size_t num_variables) const;

  /// A readable name: `grevlex`, `weighted(1,2,3;grevlex)`, `block(2:grevlex|grevlex)`.
  std::string name() const;

  /// Singular's name of the order for `num_variables` variables (`dp`, `lp`, `Dp`,
  /// `(a(1,2,3),dp)`, `(dp(2),dp(3))`), for reproduce scripts and oracle tests.
  std::string singular_name(std::size_t num_variables) const;

  /// Two descriptions are equal when they describe the same order the same way.
  bool operator==(const MonomialOrder& other) const;

 private:
  Kind kind_ = Kind::grevlex;
  std::vector<int> weights_;
  std::size_t first_block_size_ = 0;
  std::shared_ptr<const MonomialOrder> first_;  // tie-break (weighted) or first block (block)
  std::shared_ptr<const MonomialOrder> rest_;   // second block (block)
};

}  // namespace implicitizer
