#pragma once
/// \file
/// Reduced Gröbner bases over ℚ computed modulo word-size primes (Arnold 2003,
/// "Modular algorithms for computing Gröbner bases"; Idrees, Pfister, Steidel 2011,
/// "Parallelization of modular algorithms"): the reduced basis modulo several primes,
/// the primes whose leading monomials disagree with the majority dropped as
/// unlucky, the coefficients lifted by Chinese remaindering and rational
/// reconstruction, and the candidate proven over ℚ.
///
/// The proof (`ModularGroebnerParams::prove`). Let H be homogeneous generators,
/// K = ⟨H⟩, G the lifted candidate and p one of the primes lifted, whose reduced
/// basis G_p of K_p = ⟨H mod p⟩ has the leading monomials of G. Checked over ℚ:
/// (a) every h ∈ H reduces to zero modulo G, so K ⊆ J = ⟨G⟩; (b) G is a Gröbner
/// basis (Buchberger's criterion on the pairs Gebauer–Möller's update leaves). Then
/// K = J: in each degree d, dim (K_p)_d ≤ dim K_d (the multiples of H of degree d
/// span K_d, and their rank can only drop modulo p), so
///   HF(R/J)(d) = #standard monomials of lm(G) = HF(R/K_p)(d) ≥ HF(R/K)(d) ≥ HF(R/J)(d)
/// (the first equality because both G and G_p are Gröbner bases with those leading
/// monomials, the last because K ⊆ J); equal Hilbert functions and K ⊆ J give K = J.
/// This is Arnold's Theorem 7.1; no prime needs to be "lucky" for it, and (a), (b)
/// are exact: a wrong candidate is never returned. For generators that are not
/// homogeneous the argument fails (reduction modulo p can drop degrees), so they are
/// homogenized with a new variable h under the order >_h (total degree, then the
/// given order on the old variables), the proof is made there, and h = 1 gives a
/// Gröbner basis of the original ideal (Cox–Little–O'Shea, IVA §8.4 Thm 4), which is
/// then reduced. The homogenized basis can be larger than the affine one: that is
/// the price of a proof (docs/algorithms.md has the measurements).
///
/// Without the proof (`prove = false`) the reduced basis modulo each prime is still
/// computed on homogenized generators (faster, measured), taken to h = 1 and reduced
/// modulo p, and the affine candidate is returned after a consistency check on one
/// more prime: for callers that prove what they use by other means (implicitization
/// verifies its equation by substitution and minimality), or, with `random_checks`,
/// as a labelled unproven answer. Then the candidate, fixed before they are drawn,
/// must agree with the reduced basis modulo that many primes drawn at random
/// (random_prime.hpp). A wrong candidate agrees modulo p only when p divides one
/// nonzero integer N fixed by the ideal and the candidate (a difference of a true and
/// a lifted coefficient, or the product of the primes where the leading monomials
/// change, Arnold 2003), so all k checks pass with probability at most
/// (log2(N)/3.3·10^18)^k: 10^-19 for k = 2 even if N had 10^9 bits. N is not known;
/// that bound is the whole guarantee (docs/algorithms.md, "The unproven mode").

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/f4.hpp"

namespace implicitizer {

/// Parameters of compute_groebner_basis_modular().
struct ModularGroebnerParams {
  /// The selection strategy and criteria of every run modulo a prime (and of the
  /// verification), and the budget of the whole computation.
  BuchbergerParams buchberger;
  /// The algorithm of each run modulo a prime (f4.hpp). Both take the same 62-bit
  /// primes: F4's delayed reduction for primes below 2^31 (f4_row_echelon.hpp) saved
  /// about 15% a prime on cyclic-7, but lifting needed 23 such primes against 13
  /// (docs/algorithms.md, "F4 modulo primes").
  ModularAlgorithm algorithm = ModularAlgorithm::buchberger;
  /// Prove the candidate over ℚ (the file comment). false: the affine candidate
  /// after a consistency check on one more prime, for callers that prove it otherwise.
  bool prove = true;
  /// Without the proof only: the consistency check is made modulo this many primes
  /// drawn at random (each run in full, every one of them must agree) instead of the
  /// next prime of the sequence: the labelled unproven answer of the file comment.
  /// 0: the sequence's next prime(s), for callers that prove the answer themselves.
  std::size_t random_checks = 0;
  /// With F4: the first prime's run is recorded and replayed on the others, which then
  /// skip the pair criteria, symbolic preprocessing and the rows that reduced to zero
  /// (a prime whose replay leaves the recorded path is run in full; the trace is
  /// dropped when a candidate is rejected). false: every prime runs in full.
  bool trace = true;
  /// 0: the primes just above 2^62 (PrimeSequence). Otherwise the primes from just
  /// above this value, which must stay below 2^62 (F4's arithmetic modulo p needs
  /// p < 2^63): tests force small primes, unlucky ones among them.
  std::uint64_t first_prime = 0;
  /// Primes computed at once, one per thread (0: the hardware's cores).
  std::size_t threads = 0;
  /// Without the proof only: lift only the basis elements whose leading monomial
  /// involves none of the first k variables (for an elimination order for them, the
  /// reduced basis of the elimination ideal; its coefficients are often far smaller
  /// than the rest's, so fewer primes lift them). 0: the whole basis.
  std::size_t lift_only_free_of_first = 0;
};

/// What the modular computation did.
struct ModularGroebnerStats {
  std::size_t primes = 0;           ///< primes whose reduced basis was computed
  std::size_t lifted_primes = 0;    ///< of which lifted (their leading monomials were the majority's)
  std::size_t unlucky_primes = 0;   ///< dropped: other leading monomials than the majority's
  std::size_t checking_primes = 0;  ///< the primes that confirmed the candidate, not lifted into it
  /// The random primes the returned candidate was checked on (`random_checks`; empty
  /// with the proof): the answer's whole guarantee when it is not proven.
  std::vector<std::uint64_t> random_primes;
  std::size_t bad_primes = 0;           ///< skipped: dividing a leading coefficient of the generators
  std::size_t replayed_primes = 0;      ///< computed by replaying the first prime's F4 trace
  std::size_t replay_failures = 0;      ///< primes whose replay left the trace (then run in full)
  bool trace_dropped = false;           ///< a full run contradicted the trace: lifts restarted without it
  std::size_t reconstructions = 0;      ///< rational reconstructions attempted
  std::size_t rejected_candidates = 0;  ///< candidates the consistency check or the proof rejected
  bool homogenized = false;             ///< the runs modulo p were on homogenized generators
  bool proven = false;                  ///< the answer was proven over ℚ (file comment)
  std::size_t verification_pairs = 0;   ///< S-pairs reduced over ℚ by the proof
  /// Divisions of a row of the proof by the gcd of its entries, made when they had
  /// outgrown the candidate's coefficients eightfold and again at every doubling
  /// after that (docs/algorithms.md, "F4 modulo primes", item 7).
  std::size_t proof_content_divisions = 0;
  std::size_t threads = 0;     ///< threads used for the primes
  double modular_ms = 0;       ///< wall time of the runs modulo primes
  double lift_ms = 0;          ///< of Chinese remaindering, reconstruction and the check on further primes
  double verify_ms = 0;        ///< of the proof over ℚ
  double dehomogenize_ms = 0;  ///< of h = 1 and the reduction of the affine basis over ℚ
  BuchbergerStats last_prime;  ///< the counters of one run modulo a prime
};

/// The reduced Gröbner basis of the ideal generated by `generators` (one ring) in that
/// ring's order, computed modulo primes and, with `params.prove`, proven exact (the
/// file comment). The basis's stats are those of one run modulo a prime, with
/// elapsed_ms the whole call's. Throws LimitExceeded when the budget runs out (the
/// message says in which phase).
GroebnerResult compute_groebner_basis_modular(std::span<const Polynomial> generators,
                                              const ModularGroebnerParams& params = ModularGroebnerParams(),
                                              ModularGroebnerStats* stats = nullptr);

}  // namespace implicitizer
