#pragma once
/// \file
/// Determinants of matrices whose entries are affine in a few variables, computed
/// the way FLINT and Macaulay2 compute large symbolic determinants: evaluate at the
/// points of a grid modulo word-size primes, interpolate, and combine the primes by
/// Chinese remaindering. A symbolic expansion of an 18×18 determinant with entries
/// linear in x, y, z would create millions of intermediate terms; this never holds
/// more than one residue per monomial of the answer.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/modular/prime_sequence.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// A square matrix pencil A(u) = A_0 + u_1·A_1 + … + u_k·A_k with integer entries.
class MatrixPencil {
 public:
  /// The zero pencil of `size`×`size` matrices in `num_variables` variables.
  MatrixPencil(std::size_t size, std::size_t num_variables);
  /// Rows (= columns).
  std::size_t size() const { return size_; }
  /// The number k of variables.
  std::size_t num_variables() const { return num_variables_; }
  /// Entry (row, col) of A_part: part 0 is the constant matrix A_0, part i
  /// (1 ≤ i ≤ k) the coefficient matrix of the i-th variable.
  Integer& at(std::size_t part, std::size_t row, std::size_t col) {
    return entries_[(part * size_ + row) * size_ + col];
  }
  /// Read access to at().
  const Integer& at(std::size_t part, std::size_t row, std::size_t col) const {
    return entries_[(part * size_ + row) * size_ + col];
  }
  /// Σ over parts of |entry (row, col)|: the ℓ1 norm of the entry as a polynomial.
  Integer entry_norm(std::size_t row, std::size_t col) const;
  /// A bound B, in bits, with |c| < 2^B for every coefficient c of det A(u): the
  /// ℓ1 norm of the determinant is at most the permanent of the entries' ℓ1 norms,
  /// which is at most the product of the rows' sums (Hadamard's argument with ℓ1).
  std::size_t determinant_coefficient_bits() const;

 private:
  std::size_t size_;
  std::size_t num_variables_;
  std::vector<Integer> entries_;
};

/// How pencil_determinant() works and when it stops.
struct PencilDeterminantParams {
  /// A proven bound on the total degree of the answer in u; it fixes the grid.
  std::int32_t degree_bound = 0;
  /// When non-empty, the answer is det A(u) / det A(u)[minor, minor] (Macaulay's
  /// quotient): indices of the rows and columns of the divisor, increasing. The
  /// quotient must be a polynomial.
  std::vector<std::size_t> divisor_minor;
  /// When > 0, every coefficient of the answer is proven to satisfy |c| < 2^bits:
  /// primes are added until their product exceeds 2^(bits+1), and the answer is
  /// exact by construction. When 0, the reconstruction stops once `stable_primes`
  /// further primes change no coefficient (early termination, as in FLINT's
  /// multi-modular gcd); callers verify the answer.
  std::size_t proven_bits = 0;
  /// See proven_bits.
  std::size_t stable_primes = 2;
  /// A size limit: more primes than this throws LimitExceeded (size).
  std::size_t max_primes = 2000;
  /// Threads for independent primes; 0 means the machine's cores when a prime costs
  /// more than ~3·10⁶ operations, else one (starting a thread costs more).
  unsigned threads = 0;
  /// Seeds the evaluation grid (reproducible runs).
  std::uint64_t seed = 0x1234abcd;
  /// The primes to use (tests force small ones to exercise unlucky primes).
  PrimeSequence primes{};
  /// Time, size and cancellation, checked at every grid line.
  Budget budget;
};

/// What pencil_determinant() did.
struct PencilDeterminantStats {
  std::size_t primes = 0;          ///< primes whose images were combined
  std::size_t unlucky_primes = 0;  ///< primes dropped: the divisor minor vanished on the grid
  std::size_t evaluations = 0;     ///< determinants evaluated modulo a prime
  std::size_t modulus_bits = 0;    ///< bits of the product of the primes used
  bool proven = false;             ///< whether the primes reached the proven bound
};

/// det A(u) (or the quotient, see PencilDeterminantParams::divisor_minor) as a
/// polynomial in `ring`, whose variables are u_1..u_k in order. Throws
/// std::invalid_argument when the ring or the options do not fit the pencil,
/// std::logic_error when the answer exceeds degree_bound (the bound was wrong),
/// LimitExceeded when the budget or max_primes runs out, and before the first
/// evaluation when the evaluations one prime needs would end past the deadline
/// (each is a determinant of the whole pencil, which cannot be interrupted).
Polynomial pencil_determinant(const MatrixPencil& pencil, const RingPtr& ring, const PencilDeterminantParams& options,
                              PencilDeterminantStats* stats = nullptr);

/// Throws LimitExceeded (time) when `evaluations` determinants of a `size` × `size`
/// matrix modulo a word-size prime would end past `budget`'s deadline. FLINT cannot
/// interrupt one, and at size 2000 one takes seconds, so pencil_determinant and
/// probe_pencil_determinant call this before their first; a caller whose pencil is
/// long to build calls it before building it. Nothing without a deadline.
void refuse_determinants_past_deadline(std::size_t size, std::size_t evaluations, const Budget& budget);

/// The outcome of a probe at random points.
enum class PencilProbe {
  nonzero,     ///< the determinant (quotient) is not identically zero: proven
  zero,        ///< it vanished at every probe: identically zero, up to the chance below
  minor_zero,  ///< the divisor minor vanished at every probe: the quotient is unusable
};

/// The cheap test for an identically zero determinant: evaluates at `trials`
/// random points, each modulo a different 62-bit prime. A non-zero value proves
/// the polynomial non-zero; a polynomial of degree d that is not zero vanishes at
/// all trials with probability at most (d / 2^62)^trials (Schwartz–Zippel).
/// Throws LimitExceeded when `budget` runs out, or before the first evaluation when
/// the evaluations would end past its deadline (as pencil_determinant does).
PencilProbe probe_pencil_determinant(const MatrixPencil& pencil, const std::vector<std::size_t>& divisor_minor,
                                     std::uint64_t seed = 0x5eed, int trials = 2, const Budget& budget = Budget());

}  // namespace implicitizer
