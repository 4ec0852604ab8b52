#include "implicitizer/groebner/modular_groebner.hpp"

#include <algorithm>
#include <atomic>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "buchberger_engine.hpp"
#include "f4_engine.hpp"
#include "f4_trace.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/memory_account.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/groebner/reduced_basis.hpp"
#include "implicitizer/modular/crt_lift.hpp"
#include "implicitizer/modular/one_per_thread.hpp"
#include "implicitizer/modular/prime_sequence.hpp"
#include "implicitizer/modular/random_prime.hpp"
#include "int_polynomial.hpp"
#include "mod_polynomial.hpp"
#include "rational_proof.hpp"
#include "trace_followers.hpp"

namespace implicitizer {

namespace {

using detail::IntPolynomial;
using detail::ModPolynomial;

// More primes than this and the coefficients would have over 120 000 bits: no input
// this service accepts gets there, so it means a bug (a reconstruction that never
// settles), reported as a size limit rather than a loop.
constexpr std::size_t kMaxPrimes = 2000;

// Primes after which a batch runs in full although a trace could replay it (the
// driver's run() says why); the next such point is four times further.
constexpr std::size_t kFirstAudit = 16;

// A prime is worth a thread of its own when it takes longer than this.
constexpr double kThreadWorthMs = 20;

// The primes a follower may replay behind the learning run (trace_followers.hpp):
// cyclic-7 and katsura-8 need ten besides the learned one, and a prime more than the
// lift needs costs its replay's last steps and interreduction after the learning run
// (docs/algorithms.md, "F4 modulo primes", item 9).
constexpr std::size_t kFollowedPrimes = 8;

// A basis over ℚ of this many terms is worth interreducing on several threads
// (docs/algorithms.md, item 4 of the multi-modular route, has what cyclic-7's took):
// below it, starting a thread may cost more than the work.
constexpr std::size_t kThreadWorthTerms = 5'000;

// ---------------------------------------------------------------- the runs modulo p

// What is lifted of each prime's reduced basis. By default the basis itself. With
// `affine`, the runs are on homogenized generators and the basis is taken to h = 1
// and reduced modulo p in the affine ring (a Gröbner basis of the affine ideal
// modulo p, IVA §8.4 Thm 4, so its reduction is the affine reduced basis); with
// `free_of_first` = k, only the elements whose leading monomial involves none of the
// first k variables are kept (for an elimination order, the elimination ideal's
// reduced basis): their coefficients are often far smaller than the rest's, so
// fewer primes lift them.
struct Projection {
  const Ring* affine = nullptr;
  std::size_t free_of_first = 0;
};

// The reduced basis of ⟨H mod p⟩ (projected), or `bad` when p divides a leading
// coefficient of H (reduction would drop that leading term: the prime is skipped,
// not counted unlucky).
struct PrimeRun {
  std::uint64_t prime = 0;
  bool bad = false;
  bool replayed = false;       // by the trace
  bool replay_failed = false;  // the trace was left: run in full

  std::vector<ModPolynomial> basis;
  BuchbergerStats stats;
};

// f modulo p with h = 1 (h the last variable of `from`), in `to`, terms re-sorted for
// to's order and equal monomials combined.
ModPolynomial dehomogenize_modulo(const ModPolynomial& f, const Ring& from, const Ring& to, const nmod_t& modulus) {
  const std::size_t wf = from.monomial_size(), wt = to.monomial_size();
  std::vector<std::pair<std::vector<std::int32_t>, std::uint64_t>> terms(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    terms[i].first.resize(wt);
    to.encode(from.exponents(f.monomials.data() + i * wf), terms[i].first.data());
    terms[i].second = f.coefficients[i];
  }
  std::sort(terms.begin(), terms.end(),
            [&](const auto& a, const auto& b) { return to.compare(a.first.data(), b.first.data()) > 0; });
  ModPolynomial out;
  for (std::size_t i = 0; i < terms.size();) {
    std::uint64_t c = 0;
    std::size_t j = i;
    for (; j < terms.size() && to.equal(terms[j].first.data(), terms[i].first.data()); ++j) {
      c = nmod_add(c, terms[j].second, modulus);
    }
    if (c != 0) {
      out.coefficients.push_back(c);
      out.monomials.insert(out.monomials.end(), terms[i].first.begin(), terms[i].first.end());
    }
    i = j;
  }
  return out;
}

// The generators modulo p, monic, or nullopt when p divides a leading coefficient.
std::optional<std::vector<ModPolynomial>> generators_modulo(const std::vector<IntPolynomial>& generators,
                                                            const detail::ModularArithmetic& arithmetic) {
  std::vector<ModPolynomial> reduced;
  for (const auto& g : generators) {
    if (mpz_fdiv_ui(g.coefficients.front().get_mpz_t(), arithmetic.prime()) == 0) return std::nullopt;
    reduced.push_back(arithmetic.reduce_coefficients(g));
  }
  return reduced;
}

// The reduced basis modulo `prime`: by replaying `trace` when there is one (going on
// with `begun` when a follower began the replay, trace_followers.hpp), recording into
// `learn` when asked (F4 only); a run in full shares F4's echelon steps among
// `threads` threads.
PrimeRun run_prime(const Ring& ring, const std::vector<IntPolynomial>& generators, std::uint64_t prime,
                   const ModularGroebnerParams& params, const Projection& projection, const detail::F4Trace* trace,
                   detail::F4Trace* learn, std::size_t threads, detail::F4Trace::Replay* begun = nullptr) {
  PrimeRun run;
  run.prime = prime;
  const detail::ModularArithmetic arithmetic(ring, prime);
  // A follower's replay began from these already (and its prime is not bad).
  std::optional<std::vector<ModPolynomial>> reduced;
  if (begun == nullptr) {
    reduced = generators_modulo(generators, arithmetic);
    if (!reduced) {
      run.bad = true;
      return run;
    }
  }
  std::optional<detail::F4Outcome> replayed;
  if (trace != nullptr) {
    const Budget& budget = params.buchberger.budget;
    replayed = begun != nullptr ? trace->replay(ring, *begun, budget, run.stats)
                                : trace->replay(ring, arithmetic, *reduced, budget, run.stats);
    run.replayed = replayed.has_value();
    run.replay_failed = !run.replayed;
  }
  if (!replayed && !reduced) reduced = generators_modulo(generators, arithmetic);  // run in full
  detail::F4Outcome outcome =
      replayed ? std::move(*replayed)
      : learn != nullptr
          ? detail::run_f4(ring, arithmetic, std::move(*reduced), params.buchberger, run.stats, learn, threads)
          : detail::run_modular_algorithm(ring, arithmetic, std::move(*reduced), params.algorithm, params.buchberger,
                                          run.stats, threads);
  const Ring& lift_ring = projection.affine != nullptr ? *projection.affine : ring;
  // The final interreduction is part of the path: recorded by the learning prime,
  // replayed by the others (by any prime whose basis has the recorded supports).
  const detail::InterreductionPlan* replayed_plan = trace != nullptr ? &trace->interreduction() : nullptr;
  detail::InterreductionPlan* recorded_plan = learn != nullptr ? &learn->interreduction() : nullptr;
  if (outcome.unit) {
    ModPolynomial one;
    one.coefficients.push_back(1);
    one.monomials.assign(lift_ring.monomial_size(), 0);
    run.basis.push_back(std::move(one));
  } else if (projection.affine != nullptr) {
    const detail::ModularArithmetic affine(lift_ring, prime);
    std::vector<ModPolynomial> dehomogenized;
    for (const auto& g : outcome.basis) {
      dehomogenized.push_back(dehomogenize_modulo(g, ring, lift_ring, arithmetic.modulus()));
    }
    run.basis = detail::reduce_modular_basis(lift_ring, affine, std::move(dehomogenized), params.algorithm,
                                             params.buchberger.budget, replayed_plan, recorded_plan);
  } else {
    run.basis = detail::reduce_modular_basis(ring, arithmetic, std::move(outcome.basis), params.algorithm,
                                             params.buchberger.budget, replayed_plan, recorded_plan);
  }
  if (projection.free_of_first > 0) {
    std::erase_if(run.basis, [&](const ModPolynomial& g) {
      const std::int32_t* e = lift_ring.exponents(g.monomials.data());
      return std::any_of(e, e + projection.free_of_first, [](std::int32_t x) { return x != 0; });
    });
  }
  return run;
}

// The leading monomials of a reduced basis modulo p, or of a lifted candidate,
// concatenated: the key that tells lucky primes from unlucky ones (Arnold 2003: for
// all but finitely many primes the reduced basis modulo p has the leading monomials
// of the rational one).
template <class P>
std::vector<std::int32_t> leading_key(const Ring& ring, const std::vector<P>& basis) {
  const std::size_t w = ring.monomial_size();
  std::vector<std::int32_t> key;
  for (const auto& g : basis) key.insert(key.end(), g.monomials.begin(), g.monomials.begin() + static_cast<long>(w));
  return key;
}

// ---------------------------------------------------------------- lifting

// The coefficients of one basis element, lifted by monomial (the union of the
// images' supports: a coefficient that vanished modulo one prime is 0 there, not
// absent). Wang's bound without margin: the driver confirms the candidate on
// further primes (confirms()).
struct LiftedElement {
  std::vector<std::int32_t> monomials;  // decreasing
  CrtLift lift{0};

  void add(const ModPolynomial& g, std::uint64_t prime, const Ring& ring) {
    // The usual case: the same support as the primes before (no coefficient vanished).
    if (lift.size() == g.size() && monomials == g.monomials) {
      lift.add(g.coefficients, prime);
      return;
    }
    const std::size_t w = ring.monomial_size();
    std::vector<std::int32_t> merged;
    std::vector<std::size_t> old_positions;  // where each lifted coefficient goes
    std::vector<mp_limb_t> residues;         // g on the merged monomials
    std::size_t i = 0, j = 0;
    while (i < lift.size() || j < g.size()) {
      int cmp;
      if (i == lift.size()) {
        cmp = -1;
      } else if (j == g.size()) {
        cmp = 1;
      } else {
        cmp = ring.compare(monomials.data() + i * w, g.monomials.data() + j * w);
      }
      const std::int32_t* m = cmp >= 0 ? monomials.data() + i * w : g.monomials.data() + j * w;
      if (cmp >= 0) old_positions.push_back(residues.size());
      residues.push_back(cmp <= 0 ? g.coefficients[j] : 0);
      merged.insert(merged.end(), m, m + w);
      if (cmp >= 0) ++i;
      if (cmp <= 0) ++j;
    }
    if (residues.size() != lift.size()) lift.spread(old_positions, residues.size());
    monomials = std::move(merged);
    lift.add(residues, prime);
  }
};

// Chinese remaindering of the reduced bases of the primes that share one set of
// leading monomials. The elements are independent, so the remaindering and the
// reconstruction are shared by `threads` threads (the driver's batch size: more than
// one only once a prime was worth a thread), which would otherwise wait for them:
// element e goes to thread e mod threads. Handing each element to whichever thread
// was free instead made the remaindering slower than on one thread, the elements'
// integers then changing threads (and allocator arenas) from prime to prime.
class BasisLift {
 public:
  explicit BasisLift(const Ring& ring) : ring_(ring) {}

  std::size_t primes() const { return primes_; }
  std::size_t first_seen() const { return first_seen_; }
  void set_first_seen(std::size_t order) { first_seen_ = order; }

  void add(const std::vector<ModPolynomial>& basis, std::uint64_t prime, std::size_t threads) {
    if (elements_.empty()) elements_.resize(basis.size());
    threads = std::max<std::size_t>(threads, 1);
    run_one_per_thread(std::min(threads, basis.size()), [&](std::size_t t) {
      for (std::size_t e = t; e < basis.size(); e += threads) elements_[e].add(basis[e], prime, ring_);
    });
    ++primes_;
  }

  // Rational reconstruction of every coefficient; the candidate basis as primitive
  // integer polynomials (the reconstructed values times their common denominator,
  // divided by their gcd), or nullopt when a coefficient has none (each thread stops
  // at its first failure, and at the next element once another thread failed).
  std::optional<std::vector<IntPolynomial>> reconstruct(std::size_t threads) {
    std::atomic<bool> failed = false;
    threads = std::min(std::max<std::size_t>(threads, 1), elements_.size());
    run_one_per_thread(threads, [&](std::size_t t) {
      for (std::size_t e = t; e < elements_.size() && !failed.load(std::memory_order_relaxed); e += threads) {
        if (!elements_[e].lift.reconstruct()) failed = true;
      }
    });
    if (failed) return std::nullopt;
    // Made only once every element has values: most attempts fail.
    std::vector<IntPolynomial> out(elements_.size());
    const std::size_t w = ring_.monomial_size();
    run_one_per_thread(threads, [&](std::size_t t) {
      for (std::size_t e = t; e < elements_.size(); e += threads) {
        const LiftedElement& element = elements_[e];
        std::vector<Integer> values = element.lift.integer_values();
        IntPolynomial& g = out[e];
        for (std::size_t i = 0; i < values.size(); ++i) {
          if (values[i] == 0) continue;
          g.coefficients.push_back(std::move(values[i]));
          g.monomials.insert(g.monomials.end(), element.monomials.begin() + static_cast<long>(i * w),
                             element.monomials.begin() + static_cast<long>((i + 1) * w));
        }
        detail::make_primitive(g);
      }
    });
    return out;
  }

 private:
  const Ring& ring_;
  std::vector<LiftedElement> elements_;
  std::size_t primes_ = 0;
  std::size_t first_seen_ = 0;
};

// Whether the candidate, as primitive integer polynomials, reduced modulo
// `run.prime` is `run.basis`.
bool agrees_modulo(const std::vector<IntPolynomial>& candidate, const PrimeRun& run, const Ring& ring) {
  if (candidate.size() != run.basis.size()) return false;
  const detail::ModularArithmetic arithmetic(ring, run.prime);
  for (std::size_t e = 0; e < candidate.size(); ++e) {
    const IntPolynomial& c = candidate[e];
    // The lead is D for a monic element D·g: p divides a denominator of the candidate.
    if (mpz_fdiv_ui(c.coefficients.front().get_mpz_t(), run.prime) == 0) return false;
    const ModPolynomial reduced = arithmetic.reduce_coefficients(c);
    const ModPolynomial& g = run.basis[e];
    if (reduced.coefficients != g.coefficients || reduced.monomials != g.monomials) return false;
  }
  return true;
}

// ---------------------------------------------------------------- homogenization

bool is_homogeneous(const Polynomial& p) {
  const std::int32_t d = p.total_degree();
  const Ring& ring = *p.ring();
  for (std::size_t i = 0; i < p.num_terms(); ++i) {
    if (ring.total_degree(p.monomial(i)) != d) return false;
  }
  return true;
}

// The ring with one more variable h, last, ordered by >_h: total degree, then the
// ring's order on the old variables (h only breaks the ties that leaves, which
// are none: the old order is total on the old variables).
RingPtr homogenized_ring(const Ring& ring) {
  std::vector<std::string> names = ring.variables();
  std::string h = "h";
  while (ring.index_of(h)) h += "_";
  names.push_back(h);
  const std::size_t n = ring.num_variables();
  return Ring::make(names, MonomialOrder::weighted(std::vector<int>(n + 1, 1),
                                                   MonomialOrder::block(n, ring.order(), MonomialOrder::lex())));
}

// p with h = 1, in `ring` (h is the last variable of p's ring).
Polynomial dehomogenize(const IntPolynomial& p, const Ring& from, const RingPtr& ring) {
  const std::size_t wf = from.monomial_size(), w = ring->monomial_size();
  std::vector<std::int32_t> monomials(p.size() * w);
  for (std::size_t i = 0; i < p.size(); ++i)
    ring->encode(from.exponents(p.monomials.data() + i * wf), monomials.data() + i * w);
  // Monic: >_h and the original order rank the terms of a homogeneous p alike.
  return Polynomial::from_terms(ring, Rational(1) / to_rational(p.coefficients.front()), p.coefficients,
                                std::move(monomials));
}

// ---------------------------------------------------------------- the driver

class ModularDriver {
 public:
  // The runs are in `run_ring`, the lifting in `lift_ring` (the same ring unless the
  // projection dehomogenizes).
  ModularDriver(RingPtr run_ring, RingPtr lift_ring, std::vector<IntPolynomial> generators,
                const ModularGroebnerParams& params, const Projection& projection, ModularGroebnerStats& stats)
      : run_ring_(std::move(run_ring)),
        ring_(std::move(lift_ring)),
        generators_(std::move(generators)),
        params_(params),
        projection_(projection),
        stats_(stats),
        primes_(params.first_prime == 0 ? PrimeSequence() : PrimeSequence::from(params.first_prime)) {
    threads_ = params.threads != 0 ? params.threads : std::max(1u, std::thread::hardware_concurrency());
    stats_.threads = threads_;
  }

  // The lifted basis, checked on one more prime and, with `prove`, proven.
  std::vector<IntPolynomial> run() {
    std::optional<std::vector<IntPolynomial>> candidate;
    bool rejected = false;  // the last batch's candidate
    for (;;) {
      // A candidate is confirmed on further primes before the proof (with the proof,
      // on the last prime of the batch it was lifted in, below). Without the proof
      // they run in full: a replay follows the learned prime's path and cannot see a
      // row that does not reduce to zero modulo its own prime, so it could confirm what
      // it was built from. With the proof they are replays when the candidate has the
      // learned prime's leading monomials (a replay costs about an eighth of a full run
      // on cyclic-7): the proof's Hilbert-function argument needs one prime whose
      // reduced basis, computed in full, has the candidate's leading monomials, and the
      // learned prime is one; the confirmation only filters out a spurious
      // reconstruction, which an independent prime refutes as well replayed as in full.
      // The batch after a rejected candidate runs in full: replays of a path learned on
      // an unlucky prime never fail, and only a full run shows that the path is wrong
      // (leaves_trace). So does one batch each time the primes pass 16·4^k: the lift
      // then mixes the learned prime's basis with replays of another object, and may
      // never give a candidate to reject (a test learns on such a prime).
      const bool audit = trace_ != nullptr && stats_.primes >= next_audit_;
      if (audit) next_audit_ *= 4;
      const bool replay = !rejected && !audit && (!candidate || (params_.prove && has_learned_leads(*candidate)));
      // The labelled unproven answer is checked on random primes (the header says why).
      const bool random = candidate && !params_.prove && params_.random_checks > 0;
      std::vector<PrimeRun> batch = next_batch(replay, random);
      rejected = false;
      if (trace_ != nullptr && leaves_trace(batch)) {
        drop_trace();
        candidate.reset();
      }
      std::vector<const PrimeRun*> runs;
      for (const PrimeRun& run : batch) runs.push_back(&run);
      if (candidate) {
        if (accepts(*candidate, runs, random)) return *candidate;
        reject(candidate, rejected);
      }
      const Stopwatch timer;
      std::vector<PrimeRun*> trusted;  // replays of a dropped trace are not
      for (PrimeRun& run : batch) {
        if (!run.replayed || trace_ != nullptr) trusted.push_back(&run);
      }
      // With the proof, the batch's last prime joins the lift after the
      // reconstruction: the candidate was not lifted from it, so it confirms the
      // candidate as a checking batch would, and with batches of several primes that
      // batch is saved (with one prime a batch, the reconstruction only comes one
      // prime later, where the checking prime would have come).
      const PrimeRun* held = params_.prove && !trusted.empty() ? trusted.back() : nullptr;
      for (PrimeRun* run : trusted) {
        if (run == held) continue;
        absorb(*run);
        // Lifted, its basis is not needed: freed at once, its memory serves the lift's
        // next allocations (freed with the batch, a first batch of several primes
        // made the lift's first steps slower, docs/algorithms.md, "F4 modulo primes").
        std::vector<ModPolynomial>().swap(run->basis);
      }
      BasisLift* majority = majority_lift();
      // Reconstruction costs about as much as one prime's Chinese remaindering of the
      // whole basis, and fails until the modulus passes the coefficients' size: try
      // it when the lifted primes have grown by a quarter since the last failure, so
      // its total cost stays a constant factor of the lifting's.
      if (majority != nullptr && majority->primes() >= next_reconstruction_) {
        ++stats_.reconstructions;
        candidate = majority->reconstruct(batch_size_);
        if (!candidate) next_reconstruction_ = majority->primes() + std::max<std::size_t>(1, majority->primes() / 4);
      }
      if (held != nullptr) absorb(*held);
      stats_.lift_ms += timer.elapsed_ms();
      // A replayed prime confirms only a candidate with the learned prime's leading
      // monomials (the proof needs a prime run in full with them); another candidate
      // waits for a batch run in full, as before.
      if (candidate && held != nullptr && (!held->replayed || has_learned_leads(*candidate))) {
        if (accepts(*candidate, {held}, false)) return *candidate;
        reject(candidate, rejected);
      }
    }
  }

 private:
  // After a candidate was rejected: the next batch runs in full (run() says why).
  void reject(std::optional<std::vector<IntPolynomial>>& candidate, bool& rejected) {
    ++stats_.rejected_candidates;
    stats_.checking_primes = 0;  // they join the lift
    candidate.reset();
    rejected = true;
  }

  // Whether `candidate` is the answer: confirmed by `batch` (every prime of it when
  // `random`) and, with `prove`, proven over ℚ.
  bool accepts(const std::vector<IntPolynomial>& candidate, const std::vector<const PrimeRun*>& batch, bool random) {
    const Stopwatch check_timer;
    const bool confirmed = confirms(candidate, batch, random);
    stats_.lift_ms += check_timer.elapsed_ms();
    if (!confirmed) return false;
    stats_.checking_primes = batch.size();
    if (random) {
      for (const PrimeRun* run : batch) stats_.random_primes.push_back(run->prime);
    }
    if (!params_.prove) return true;
    const Stopwatch timer;
    // The pairs computed while the primes ran, when they are this candidate's.
    std::optional<std::vector<detail::SPair>> pairs;
    if (learned_pairs_.valid() && has_learned_leads(candidate)) pairs = learned_pairs_.get();
    const detail::ProofOutcome proof =
        detail::prove_groebner_basis(*run_ring_, generators_, candidate, params_.buchberger, threads_,
                                     detail::ProofRows::by_coefficient_size, pairs ? &*pairs : nullptr);
    stats_.verification_pairs += proof.pairs;
    stats_.proof_content_divisions += proof.content_divisions;
    stats_.verify_ms += timer.elapsed_ms();
    if (proof.proven) {
      stats_.proven = true;
      return true;
    }
    // Confirmed yet not a Gröbner basis: replays or the learned prime misled the lift;
    // start again without replays.
    if (trace_ != nullptr) drop_trace();
    return false;
  }

  // The next primes that are not bad, `batch_size_` of them run in parallel. The
  // first batch is one prime on the calling thread: small ideals take well under a
  // millisecond a prime, less than starting a thread costs (measured 4–5 ms on a busy
  // machine, a scheduler tick), so more threads are used only when a prime took
  // longer than kThreadWorthMs. With `random`, `random_checks` primes drawn at random
  // instead of the sequence's, run in full.
  std::vector<PrimeRun> next_batch(bool replay, bool random) {
    const Stopwatch timer;
    std::vector<PrimeRun> batch;
    const std::size_t wanted = random ? params_.random_checks : stats_.primes == 0 ? 1 : batch_size_;
    while (batch.size() < wanted) {
      if (stats_.primes + stats_.bad_primes >= kMaxPrimes) {
        throw LimitExceeded(Limit::size, "modular Groebner basis: no stable reconstruction after " +
                                             std::to_string(kMaxPrimes) + " primes");
      }
      std::vector<std::uint64_t> primes;
      if (random && !random_primes_) random_primes_.emplace();  // seeded only when needed
      for (std::size_t i = batch.size(); i < wanted; ++i)
        primes.push_back(random ? random_primes_->next() : next_prime());
      // The first prime run with F4 (one, on this thread) records its path.
      const bool learning = params_.trace && params_.algorithm == ModularAlgorithm::f4 && !stats_.trace_dropped &&
                            trace_ == nullptr && primes.size() == 1;
      auto learned = learning ? std::make_unique<detail::F4Trace>() : nullptr;
      std::vector<PrimeRun> runs;
      if (learning) {
        runs = learn(primes.front(), *learned, timer);
      } else {
        // A prime run alone (each while a prime is not worth a thread) shares its
        // matrices' echelon steps among the threads.
        const std::size_t echelon_threads = primes.size() == 1 ? threads_ : 1;
        runs.resize(primes.size());
        run_one_per_thread(primes.size(), [&](std::size_t k) {
          runs[k] = run_prime(*run_ring_, generators_, primes[k], params_, projection_, replay ? trace_.get() : nullptr,
                              nullptr, echelon_threads);
        });
      }
      for (auto& r : runs) {
        if (r.bad) {
          ++stats_.bad_primes;
          continue;
        }
        ++stats_.primes;
        if (r.replayed) ++stats_.replayed_primes;
        if (r.replay_failed) ++stats_.replay_failures;
        if (!r.replayed) stats_.last_prime = r.stats;  // a replay skips most of what is counted
        if (learned != nullptr && learned->complete()) {
          trace_ = std::move(learned);
          trace_key_ = leading_key(*ring_, r.basis);
          if (params_.prove) start_proof_pairs();
        }
        // How many primes the lift needs is known only when reconstruction succeeds.
        params_.buchberger.budget.report_stage("modular Groebner basis (primes)", stats_.primes, 0);
        batch.push_back(std::move(r));
      }
    }
    const double ms = timer.elapsed_ms();
    if (stats_.primes == batch.size() && ms > kThreadWorthMs) batch_size_ = threads_;
    stats_.modular_ms += ms;
    return batch;
  }

  // The first prime's F4 run, recording its path into `learned` (on this thread, its
  // large matrices shared among the threads), then the primes a follower replayed
  // behind it (trace_followers.hpp), started once the run has taken long enough to be
  // worth a thread: the learning run first, the followed primes in their order.
  std::vector<PrimeRun> learn(std::uint64_t prime, detail::F4Trace& learned, const Stopwatch& timer) {
    std::optional<detail::TraceFollowers> followers;
    if (threads_ > 1) {
      learned.set_after_step([&] {
        if (followers || timer.elapsed_ms() < kThreadWorthMs) return;
        std::vector<std::uint64_t> primes;
        for (std::size_t i = 0; i < kFollowedPrimes; ++i) primes.push_back(next_prime());
        followers.emplace(
            *run_ring_, learned, std::move(primes),
            [this](std::uint64_t p) {
              return generators_modulo(generators_, detail::ModularArithmetic(*run_ring_, p));
            },
            params_.buchberger.budget);
      });
    }
    std::vector<PrimeRun> runs;
    {
      // Closed however the run ends, so that a follower waiting for a step stops.
      struct CloseOnExit {
        detail::F4Trace& trace;
        ~CloseOnExit() { trace.close(); }
      } close{learned};
      runs.push_back(run_prime(*run_ring_, generators_, prime, params_, projection_, nullptr, &learned, threads_));
    }
    if (!followers) return runs;
    detail::TraceFollowers::Followed followed = followers->stop();
    for (const std::uint64_t p : followed.bad) {
      PrimeRun bad;
      bad.prime = p;
      bad.bad = true;
      runs.push_back(std::move(bad));
    }
    std::vector<std::uint64_t> unused;  // back to the sequence, in order
    if (!learned.complete()) {
      for (const detail::F4Trace::Replay& r : followed.replays) unused.push_back(r.prime());
      followed.replays.clear();
    }
    unused.insert(unused.end(), followed.untaken.begin(), followed.untaken.end());
    pending_primes_.insert(pending_primes_.begin(), unused.begin(), unused.end());
    // What the follower left of each replay, on every thread, whichever is free.
    std::vector<PrimeRun> finished(followed.replays.size());
    std::atomic<std::size_t> next = 0;
    run_one_per_thread(std::min(threads_, finished.size()), [&](std::size_t) {
      for (std::size_t i; (i = next.fetch_add(1)) < finished.size();) {
        detail::F4Trace::Replay& r = followed.replays[i];
        finished[i] = run_prime(*run_ring_, generators_, r.prime(), params_, projection_, &learned, nullptr, 1, &r);
      }
    });
    for (PrimeRun& r : finished) runs.push_back(std::move(r));
    return runs;
  }

  // The next prime of the sequence: first those drawn for followers and not used.
  std::uint64_t next_prime() {
    if (pending_primes_.empty()) return primes_.next();
    const std::uint64_t p = pending_primes_.front();
    pending_primes_.pop_front();
    return p;
  }

  // The proof's pairs depend only on the candidate's leading monomials, which the
  // learned prime already has (every replay, and so the lift, keeps them): they are
  // computed on a thread of their own while the other primes run, where the proof
  // would compute them while the other threads wait (docs/algorithms.md, "F4 modulo
  // primes", item 7).
  void start_proof_pairs() {
    MemoryAccount* const account = current_memory_account();
    learned_pairs_ = std::async(std::launch::async, [this, account, key = trace_key_] {
      const MemoryScope scope(account);
      return detail::proof_pairs(*run_ring_, key, params_.buchberger);
    });
  }

  // Whether a prime run in full has other leading monomials than the prime the trace
  // was learned on: one of the two is unlucky, and replays would copy the learned
  // prime's path, so the trace is not to be trusted.
  bool leaves_trace(const std::vector<PrimeRun>& batch) const {
    return std::any_of(batch.begin(), batch.end(),
                       [&](const PrimeRun& r) { return !r.replayed && leading_key(*ring_, r.basis) != trace_key_; });
  }

  // Whether `candidate` has the leading monomials of the basis the trace was learned
  // from (false without a trace).
  bool has_learned_leads(const std::vector<IntPolynomial>& candidate) const {
    return trace_ != nullptr && leading_key(*ring_, candidate) == trace_key_;
  }

  // Forgets the trace and every lift (some may hold replays); the primes from here on
  // run in full.
  void drop_trace() {
    trace_.reset();
    stats_.trace_dropped = true;
    lifts_.clear();
    next_reconstruction_ = 1;
  }

  void absorb(const PrimeRun& run) {
    const std::vector<std::int32_t> key = leading_key(*ring_, run.basis);
    auto it = lifts_.find(key);
    if (it == lifts_.end()) {
      it = lifts_.emplace(key, BasisLift(*ring_)).first;
      it->second.set_first_seen(lifts_.size());
    }
    it->second.add(run.basis, run.prime, batch_size_);
  }

  // The lift of the most primes (ties: the set seen first); the others are unlucky.
  BasisLift* majority_lift() {
    BasisLift* best = nullptr;
    std::size_t total = 0;
    for (auto& [key, lift] : lifts_) {
      total += lift.primes();
      if (best == nullptr || lift.primes() > best->primes() ||
          (lift.primes() == best->primes() && lift.first_seen() < best->first_seen())) {
        best = &lift;
      }
    }
    if (best != nullptr) {
      stats_.lifted_primes = best->primes();
      stats_.unlucky_primes = total - best->primes();
    }
    return best;
  }

  // Whether every prime of `batch` whose basis has the candidate's leading monomials
  // agrees with the candidate, and at least one does; with `every`, whether every
  // prime agrees (the random checks: a prime with other leading monomials may be the
  // lucky one that shows the candidate's to be wrong).
  bool confirms(const std::vector<IntPolynomial>& candidate, const std::vector<const PrimeRun*>& batch,
                bool every) const {
    const std::vector<std::int32_t> key = leading_key(*ring_, candidate);
    std::size_t agreeing = 0;
    for (const PrimeRun* run : batch) {
      if (agrees_modulo(candidate, *run, *ring_)) {
        ++agreeing;
        continue;
      }
      // Other leading monomials: an unlucky prime (or the candidate is), no verdict.
      if (every || leading_key(*ring_, run->basis) == key) return false;
    }
    return agreeing > 0;
  }

  RingPtr run_ring_;
  RingPtr ring_;  // where the bases are lifted
  std::vector<IntPolynomial> generators_;
  const ModularGroebnerParams& params_;
  Projection projection_;
  ModularGroebnerStats& stats_;
  PrimeSequence primes_;
  std::deque<std::uint64_t> pending_primes_;  // drawn for followers, not used: next_prime() takes them first
  std::optional<RandomPrimes> random_primes_;
  std::size_t threads_ = 1;
  std::size_t batch_size_ = 1;            // primes per batch after the first (threads_ once a prime is worth a thread)
  std::size_t next_reconstruction_ = 1;   // lifted primes needed before the next reconstruction
  std::size_t next_audit_ = kFirstAudit;  // primes after which a batch runs in full despite a trace
  std::map<std::vector<std::int32_t>, BasisLift> lifts_;
  std::unique_ptr<const detail::F4Trace> trace_;           // the first prime's F4 run, replayed on the others
  std::vector<std::int32_t> trace_key_;                    // the leading monomials that prime found
  std::future<std::vector<detail::SPair>> learned_pairs_;  // the proof's pairs on trace_key_
};

}  // namespace

GroebnerResult compute_groebner_basis_modular(std::span<const Polynomial> generators,
                                              const ModularGroebnerParams& params, ModularGroebnerStats* stats_out) {
  const Stopwatch timer;
  ModularGroebnerStats stats;
  GroebnerResult result;
  std::vector<const Polynomial*> nonzero;
  for (const auto& g : generators) {
    if (!g.is_zero()) nonzero.push_back(&g);
  }
  if (nonzero.empty()) {
    if (stats_out != nullptr) *stats_out = stats;
    return result;
  }
  const RingPtr ring = nonzero.front()->ring();
  for (const Polynomial* g : nonzero) {
    if (g->ring() != ring && !(*g->ring() == *ring)) throw std::invalid_argument("generators from different rings");
  }
  // Homogenize for the proof (file comment), and also without it: the runs modulo p
  // on homogenized generators, degree by degree, were 2–5 times faster than on the
  // affine ones on the implicitization ideals measured (docs/algorithms.md).
  const bool homogenize =
      !std::all_of(nonzero.begin(), nonzero.end(), [](const Polynomial* g) { return is_homogeneous(*g); });
  const RingPtr work_ring = homogenize ? homogenized_ring(*ring) : ring;
  std::vector<IntPolynomial> work;
  std::vector<std::size_t> identity(ring->num_variables());
  for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = i;
  for (const Polynomial* g : nonzero) {
    const Polynomial p = homogenize ? g->map_to(work_ring, identity).homogenize(ring->num_variables()) : *g;
    work.push_back(detail::to_int_polynomial(p));
  }
  stats.homogenized = homogenize;
  Projection projection;
  if (!params.prove) {
    if (homogenize) projection.affine = ring.get();
    projection.free_of_first = params.lift_only_free_of_first;
  }
  const RingPtr lift_ring = projection.affine != nullptr ? ring : work_ring;
  const std::vector<IntPolynomial> lifted =
      ModularDriver(work_ring, lift_ring, std::move(work), params, projection, stats).run();
  std::vector<Polynomial> basis;
  if (homogenize && params.prove) {
    // h = 1: a Gröbner basis of the original ideal, not reduced (IVA §8.4 Thm 4).
    const Stopwatch dehomogenize_timer;
    std::vector<Polynomial> affine;
    for (const auto& g : lifted) affine.push_back(dehomogenize(g, *work_ring, ring));
    // On the route's threads once the basis is large enough to be worth starting one.
    std::size_t terms = 0;
    for (const auto& g : affine) terms += g.num_terms();
    basis = reduce_basis(affine, params.buchberger.budget, terms >= kThreadWorthTerms ? stats.threads : 1);
    stats.dehomogenize_ms = dehomogenize_timer.elapsed_ms();
  } else {
    for (const auto& g : lifted) basis.push_back(detail::to_monic_polynomial(lift_ring, g));
  }
  result.basis = std::move(basis);
  result.stats = stats.last_prime;
  result.stats.basis_size = result.basis.size();
  result.stats.elapsed_ms = timer.elapsed_ms();
  if (stats_out != nullptr) *stats_out = stats;
  return result;
}

}  // namespace implicitizer
