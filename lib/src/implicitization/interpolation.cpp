#include "implicitizer/implicitization/interpolation.hpp"

#include <flint/nmod_mat.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/implicitization/implicit_support.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/sparse_interpolation.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/modular/crt_lift.hpp"
#include "implicitizer/modular/flint_handles.hpp"
#include "implicitizer/modular/one_per_thread.hpp"
#include "interpolation_kernel.hpp"

namespace implicitizer {

namespace {

// The most primes computed at once (see batch_threads).
constexpr unsigned kMaxThreads = 4;

// A bound whose matrix has at most this many columns (degree 4 in space, 7 in the
// plane) is taken at once, without the upward search: a 39×35 kernel costs about as
// much as the setup of the smaller ones below it, and it reads the degree from its
// nullity (tp_11_rational: one kernel instead of two; tri_quadratic: one instead of
// three).
constexpr double kDirectColumns = 36;

// Kernels of at least this many columns time the row reduction for the deadline's
// prediction (refuse_kernel_past_deadline); smaller ones are mostly evaluation and
// set-up, whose cost does not grow as the cube.
constexpr double kTimedColumns = 200;

// ---------------------------------------------------------------- the driver

// The search for the degree and the Chinese remaindering, prime by prime.
class InterpolationDriver {
 public:
  InterpolationDriver(const Parametrization& p, const InterpolationParams& options)
      : parametrization_(p), options_(options), forms_(map_forms(p, options.budget)), primes_(options.primes) {}

  // The equation, or nullopt when its degree is proven above `max_degree` (only
  // when that is below the degree bound: at the bound there is no such answer).
  std::optional<InterpolationResult> run(std::int32_t max_degree = kMaxTotalDegree) {
    const Stopwatch timer;
    const std::size_t n = forms_.coordinates;
    const std::int64_t bound = degree_bound_of(forms_);
    stats_.degree_bound = static_cast<std::int32_t>(std::min<std::int64_t>(bound, kMaxTotalDegree));
    check_image_dimension(forms_, options_.seed, options_.budget);
    // The search treats the cap as the bound: a kernel at degree D ≥ e still has
    // dimension C(D − e + n, n), whether D is the bound or not.
    const bool capped = max_degree < stats_.degree_bound;
    const std::int32_t d_max = capped ? max_degree : stats_.degree_bound;
    const double max_columns = static_cast<double>(options_.max_columns);
    stats_.search_ms += timer.elapsed_ms();

    for (;;) {
      options_.budget.check("interpolation");
      const std::int32_t current = std::max(lower_, estimate_);
      const bool searching = estimate_ < lower_;
      std::int32_t degree = current;
      if (searching) {
        if (lower_ > d_max) {
          if (capped) return std::nullopt;
          throw NoSingleEquation("no implicit equation: no polynomial of degree at most " + std::to_string(d_max) +
                                     " (the degree bound) vanishes on the image, which is dense in " +
                                     (n == 3 ? "space" : "the plane"),
                                 {});
        }
        // Upward while a kernel costs at most an eighth of the one at the bound (half
        // the columns), or when the bound's matrix is too large; else at the bound,
        // and at once when the bound's matrix is tiny (kDirectColumns).
        const double here = monomial_count(n, lower_);
        const double at_bound = monomial_count(n, d_max);
        if (at_bound <= max_columns && (2 * here > at_bound || at_bound <= kDirectColumns)) degree = d_max;
      }
      // The degree bound is known: how far up the search is, for a watcher.
      options_.budget.report_stage("interpolation (degree tried of the degree bound)", degree, d_max);
      const double columns = monomial_count(n, degree);
      // The equation has at most one term per column: the budget's size limit applies.
      if (columns <= max_columns) options_.budget.check_terms(static_cast<std::size_t>(columns), "interpolation");
      if (columns > max_columns) {
        throw LimitExceeded(Limit::size, "interpolation: the implicit equation has degree at least " +
                                             std::to_string(current) + " (bound " + std::to_string(d_max) +
                                             "), whose matrix would exceed " + std::to_string(options_.max_columns) +
                                             " columns");
      }
      const MonomialBasis& basis = basis_of(degree);
      const unsigned threads = batch_threads(basis.size(), /*upward_step=*/searching && degree < d_max);
      stats_.threads = std::max(stats_.threads, threads);
      refuse_kernel_past_deadline(columns);
      const Stopwatch batch_timer;
      std::vector<KernelImage> images = run_batch(basis, threads);
      const double batch_ms = batch_timer.elapsed_ms();
      (searching ? stats_.search_ms : stats_.images_ms) += batch_ms;
      if (columns >= kTimedColumns) ms_per_cubed_column_ = batch_ms / (columns * columns * columns);
      for (KernelImage& image : images) {
        if (searching) ++stats_.degree_probes;
        if (auto answer = take(std::move(image))) {
          stats_.modulus_bits = lift_ ? lift_->modulus_bits() : 0;
          stats_.primes = lift_ ? lift_->primes() : 0;
          return InterpolationResult{std::move(*answer), stats_};
        }
      }
    }
  }

 private:
  const MonomialBasis& basis_of(std::int32_t degree) {
    auto it = bases_.find(degree);
    if (it == bases_.end()) it = bases_.emplace(degree, monomial_basis(forms_.coordinates, degree)).first;
    return it->second;
  }

  // FLINT's row reduction cannot be interrupted, and at 3000 columns one takes seconds:
  // a kernel that would end past the deadline is refused before it starts, so that
  // the answer comes within the time limit (issue 16: 4.5 s on a 3 s budget). Its
  // time is predicted from the last large kernel's, measured on this run (so under
  // this load), scaled by the cube of the growth in columns (the row reduction's
  // cost; the upward search grows them by at most a third a step from 200 columns on).
  void refuse_kernel_past_deadline(double columns) const {
    if (ms_per_cubed_column_ <= 0) return;
    const double predicted_seconds = ms_per_cubed_column_ * columns * columns * columns / 1000;
    options_.budget.refuse_past_deadline(
        predicted_seconds, "interpolation",
        "the kernel of " + std::to_string(static_cast<std::size_t>(columns)) + " columns");
  }

  // A prime per thread when a kernel is large enough to pay for starting one. A step
  // of the upward search runs alone: below the degree a second prime at the same
  // degree tells nothing new. At most kMaxThreads: the benchmark's equations need 1
  // to 4 primes, so more threads would mostly compute primes that are not needed.
  unsigned batch_threads(std::size_t columns, bool upward_step) const {
    if (options_.threads != 0) return options_.threads;
    if (upward_step || columns < kParallelColumns) return 1;
    return std::clamp(std::thread::hardware_concurrency(), 1u, kMaxThreads);
  }

  // The kernels of one batch, a prime per thread, in prime order so that the result
  // does not depend on scheduling.
  std::vector<KernelImage> run_batch(const MonomialBasis& basis, unsigned threads) {
    std::vector<mp_limb_t> batch(threads);
    for (auto& p : batch) p = primes_.next();
    taken_ += threads;
    if (taken_ > options_.max_primes) {
      throw LimitExceeded(Limit::size,
                          "interpolation: more than " + std::to_string(options_.max_primes) + " primes needed");
    }
    // How many primes the lift needs is known only when it stabilizes.
    options_.budget.report_step("interpolation (primes)", taken_, 0);
    std::vector<KernelImage> images(threads);
    run_one_per_thread(threads, [&](std::size_t i) {
      images[i] = kernel_modulo(forms_, basis, batch[i], options_.seed, options_.budget);
    });
    return images;
  }

  // Takes the kernel of one prime into the state; returns the verified equation
  // when this prime completes it.
  //
  // lower_ is proven (a zero kernel at degree d proves e > d) and estimate_ too, as
  // long as the image is a hypersurface: a kernel modulo p contains the reduction of
  // the true one, so the degree read from its nullity is never above e. A kernel
  // that contradicts them, or the leading monomial of the best prime, is unlucky.
  std::optional<Polynomial> take(KernelImage image) {
    stats_.rejected_points += image.rejected_points;
    if (!image.enough_points) {
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (image.nullity == 0) {
      // This refutes the degree the probes above it read: their primes were unlucky.
      if (estimate_ > 0 && image.degree >= estimate_) {
        stats_.unlucky_primes += estimate_probes_;
        estimate_probes_ = 0;
      }
      lower_ = std::max(lower_, image.degree + 1);
      settle_degree();
      return std::nullopt;
    }
    const std::optional<std::int32_t> read = degree_from_nullity(image.degree, image.nullity, forms_.coordinates);
    if (!read || *read < std::max(lower_, estimate_)) {
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (*read > estimate_) estimate_probes_ = 0;
    estimate_ = std::max(estimate_, *read);
    settle_degree();
    // A probe above e holds F's multiples and only tells the degree. At e the
    // nullity is 1 (read = degree) and the vector has degree exactly e: were it of
    // degree < e, its products with x, y, z would be further kernel vectors.
    if (image.degree != lift_degree_) {
      ++estimate_probes_;
      return std::nullopt;
    }
    if (image.nullity != 1) throw std::logic_error("interpolation: a kernel of dimension > 1 at the degree found");
    if (lead_ && image.lead > *lead_) {  // p divides F's leading coefficient
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (lead_ && image.lead < *lead_) {  // so did every prime so far
      stats_.unlucky_primes += lift_->primes();
      lift_.emplace(image.vector.size(), kLiftParams);
    }
    lead_ = image.lead;
    // The candidate is verified as soon as every coefficient has a value, without
    // waiting for a prime that changes none: that prime costs as much as the
    // verification or more (tp_33: 1.3 s against 0.3 s), the verification is needed
    // anyway, and a value is wrong only with probability about 2^-20 (kLiftParams).
    const Stopwatch reconstruction_timer;
    lift_->add(image.vector, image.prime);
    const bool complete = lift_->reconstruct();
    std::optional<Polynomial> candidate;
    if (complete) candidate = polynomial_of(basis_of(lift_degree_), lift_->integer_values());
    stats_.reconstruction_ms += reconstruction_timer.elapsed_ms();
    if (!candidate) return std::nullopt;
    stats_.degree = lift_degree_;
    stats_.rows = image.rows;
    stats_.columns = image.vector.size();
    return verified(std::move(*candidate));
  }

  // Points the reconstruction at the degree lower_ and estimate_ now give, starting
  // over when it changed (images at another degree are of no use).
  void settle_degree() {
    const std::int32_t degree = std::max(lower_, estimate_);
    if (estimate_ < lower_ || degree == lift_degree_) return;
    // Images at a degree below e come from unlucky primes only: a good one has no
    // kernel there.
    if (lift_) stats_.unlucky_primes += lift_->primes();
    lift_degree_ = degree;
    lift_.emplace(basis_of(degree).size(), kLiftParams);
    lead_.reset();
  }

  std::optional<Polynomial> verified(Polynomial candidate) {
    const Stopwatch verify_timer;
    const bool vanishes = verifier_.vanishes(candidate);
    stats_.verify_ms += verify_timer.elapsed_ms();
    if (vanishes) return candidate;
    return std::nullopt;
  }

  const Parametrization& parametrization_;
  const InterpolationParams& options_;
  MapForms forms_;
  PrimeSequence primes_;
  std::size_t taken_ = 0;
  // The last large kernel's milliseconds per cubed column (0 until one ran).
  double ms_per_cubed_column_ = 0;
  InterpolationStats stats_;
  std::map<std::int32_t, MonomialBasis> bases_;
  std::int32_t lower_ = 1;           // proven: e ≥ lower_
  std::int32_t estimate_ = 0;        // the largest degree read from a non-zero kernel (0: none)
  std::size_t estimate_probes_ = 0;  // kernels above estimate_ that read it
  std::int32_t lift_degree_ = 0;
  std::optional<CrtLift> lift_;
  std::optional<std::size_t> lead_;
  CandidateVerifier verifier_{parametrization_, forms_, options_, stats_};
};

}  // namespace

std::int32_t implicit_degree_bound(const Parametrization& parametrization, const Budget& budget) {
  return static_cast<std::int32_t>(
      std::min<std::int64_t>(degree_bound_of(map_forms(parametrization, budget)), kMaxTotalDegree));
}

InterpolationResult implicitize_by_interpolation(const Parametrization& parametrization,
                                                 const InterpolationParams& options) {
  const std::size_t n = parametrization.coordinates.size();
  if (n != 2 && n != 3) throw std::invalid_argument("implicitize_by_interpolation: two or three coordinates expected");
  return *InterpolationDriver(parametrization, options).run();
}

std::optional<InterpolationResult> implicitize_by_interpolation_up_to(const Parametrization& parametrization,
                                                                      std::int32_t max_degree,
                                                                      const InterpolationParams& options) {
  const std::size_t n = parametrization.coordinates.size();
  if (n != 2 && n != 3) {
    throw std::invalid_argument("implicitize_by_interpolation_up_to: two or three coordinates expected");
  }
  if (max_degree < 1) throw std::invalid_argument("implicitize_by_interpolation_up_to: max_degree ≥ 1 expected");
  return InterpolationDriver(parametrization, options).run(max_degree);
}

namespace {

// A hypersurface: the Jacobian has rank n − 1 at a point modulo the first prime of
// options.primes (a minor non-zero modulo p is non-zero).
bool has_hypersurface_rank(const MapForms& forms, const InterpolationParams& options) {
  PrimeSequence primes = options.primes;
  const mp_limb_t p = primes.next();
  nmod_t mod;
  nmod_init(&mod, p);
  ModularMap map(forms, mod, /*with_partials=*/true);
  ResidueStream stream(options.seed ^ 0x3c6ef372fe94f82bULL);
  std::vector<mp_limb_t> a(forms.parameters);
  for (int attempt = 0; attempt < 16; ++attempt) {
    for (auto& v : a) v = stream.next(p);
    if (const auto rank = map.jacobian_rank(a)) return *rank + 1 == forms.coordinates;
  }
  return false;
}

}  // namespace

ImplicitEquationCheck check_implicit_equation(const Polynomial& candidate, const Parametrization& parametrization,
                                              const InterpolationParams& options) {
  ImplicitEquationCheck check;
  const MapForms forms = map_forms(parametrization, options.budget);
  const std::size_t n = forms.coordinates;
  if (candidate.ring()->num_variables() != n) {
    throw std::invalid_argument("check_implicit_equation: one variable per coordinate expected");
  }
  check.vanishes = substitutes_to_zero(candidate, parametrization, options.budget);
  if (candidate.is_constant() || forms.parameters + 1 < n) return check;

  const std::int32_t d = candidate.total_degree();
  if (monomial_count(n, d) > static_cast<double>(options.max_columns)) {
    // The dense matrix is too large: the classes of the predicted support, whose size
    // follows the equation's sparsity, decide instead (sparse_interpolation.hpp).
    const std::optional<ImplicitSupport> support = predict_implicit_support(parametrization, options.budget);
    if (!support || support->largest_class > options.max_columns) {
      throw LimitExceeded(Limit::size, "check_implicit_equation: the matrix would exceed " +
                                           std::to_string(options.max_columns) +
                                           " columns, and so would the largest class of the predicted support");
    }
    check.minimal =
        is_minimal_on_support(candidate, parametrization, *support, options) && has_hypersurface_rank(forms, options);
    return check;
  }
  const MonomialBasis basis = monomial_basis(n, d);
  PrimeSequence primes = options.primes;
  const KernelImage image = kernel_modulo(forms, basis, primes.next(), options.seed, options.budget);
  if (!image.enough_points || image.nullity != 1) return check;

  if (!spans_kernel(candidate.primitive_part(), basis, image)) return check;

  check.minimal = has_hypersurface_rank(forms, options);
  return check;
}

}  // namespace implicitizer
