#include "implicitizer/implicitization/sparse_interpolation.hpp"

#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/implicitization/verify.hpp"
#include "implicitizer/modular/one_per_thread.hpp"
#include "interpolation_kernel.hpp"

namespace implicitizer {

namespace {

// The most threads of the scan: its classes are independent kernels.
constexpr unsigned kMaxScanThreads = 4;

// A scan whose kernels add up to fewer cubed columns than this runs on one thread
// (about 150 kernels of 100 columns: a few milliseconds, less than starting threads
// costs under load).
constexpr double kParallelCubedColumns = 1.5e8;

// The outcome of the scan: the one class left and its kernels of dimension 1.
struct ClassScan {
  std::optional<std::size_t> chosen;  // index into the bases
  std::vector<KernelImage> images;    // of the chosen class, nullity 1, one per prime
  std::size_t kernels = 0;            // kernels computed
  std::size_t rejected_points = 0;
  unsigned threads = 1;
};

std::vector<MonomialBasis> class_bases(const ImplicitSupport& support) {
  std::vector<MonomialBasis> bases;
  bases.reserve(support.classes.size());
  for (const auto& c : support.classes) bases.push_back(monomial_basis_of(3, c));
  return bases;
}

unsigned scan_threads(const ImplicitSupport& support, const InterpolationParams& options) {
  if (options.threads != 0) return options.threads;
  if (support.cubed_columns < kParallelCubedColumns) return 1;
  return std::clamp(std::thread::hardware_concurrency(), 1u, kMaxScanThreads);
}

// The kernels of the classes `open` modulo p, several classes per thread (strided, so
// that the large and small classes spread evenly).
std::vector<KernelImage> kernels_of_classes(const MapForms& forms, const std::vector<MonomialBasis>& bases,
                                            const std::vector<std::size_t>& open, mp_limb_t p, unsigned threads,
                                            const InterpolationParams& options) {
  std::vector<KernelImage> images(open.size());
  const std::size_t count = std::min<std::size_t>(threads, open.size());
  run_one_per_thread(count, [&](std::size_t t) {
    for (std::size_t i = t; i < open.size(); i += count) {
      options.budget.check("sparse interpolation (classes)");
      images[i] = kernel_modulo(forms, bases[open[i]], p, options.seed, options.budget);
    }
  });
  return images;
}

// Fact 1 of sparse_interpolation.hpp, prime by prime: a class with a zero kernel at a
// prime is closed for good; the scan ends when one class is left with a kernel of
// dimension 1 at the last prime, or after kSparseScanPrimes primes.
ClassScan scan_classes(const MapForms& forms, const std::vector<MonomialBasis>& bases, unsigned threads,
                       PrimeSequence& primes, const InterpolationParams& options) {
  ClassScan scan;
  scan.threads = threads;
  std::vector<std::size_t> open(bases.size());
  for (std::size_t c = 0; c < open.size(); ++c) open[c] = c;
  for (std::size_t round = 0; round < kSparseScanPrimes && !open.empty(); ++round) {
    const mp_limb_t p = primes.next();
    std::vector<KernelImage> images = kernels_of_classes(forms, bases, open, p, threads, options);
    scan.kernels += images.size();
    std::vector<std::size_t> still_open;
    std::optional<KernelImage> last;
    for (std::size_t i = 0; i < open.size(); ++i) {
      scan.rejected_points += images[i].rejected_points;
      if (images[i].enough_points && images[i].nullity == 0) continue;
      still_open.push_back(open[i]);
      last = std::move(images[i]);
    }
    open = std::move(still_open);
    if (open.size() == 1 && last->enough_points && last->nullity == 1) {
      scan.chosen = open.front();
      scan.images.push_back(std::move(*last));
      return scan;
    }
  }
  return scan;
}

// Whether p does not divide every coefficient of F's top-degree part (then
// deg (F mod p) = deg F, the last step of the header's argument).
bool keeps_degree_modulo(const Polynomial& f, mp_limb_t p) {
  const std::int32_t d = f.total_degree();
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    std::int32_t degree = 0;
    for (std::int32_t e : f.exponents(t)) degree += e;
    if (degree == d && mpz_fdiv_ui(to_integer(f.coefficient(t)).get_mpz_t(), p) != 0) return true;
  }
  return false;
}

// The lift of the chosen class's kernels to a verified candidate, prime by prime.
class SparseLift {
 public:
  SparseLift(const Parametrization& p, const MapForms& forms, const MonomialBasis& basis,
             const InterpolationParams& options, InterpolationStats& stats)
      : basis_(basis), stats_(stats), lift_(basis.size(), kLiftParams), verifier_(p, forms, options, stats) {}

  // Takes one kernel of the chosen class; returns the proven equation when this one
  // completes it.
  std::optional<Polynomial> take(KernelImage image) {
    if (!image.enough_points || image.nullity != 1) {
      ++stats_.unlucky_primes;  // a larger kernel than the scan's: the prime is unlucky
      return std::nullopt;
    }
    if (lead_ && image.lead > *lead_) {  // p divides F's leading coefficient
      ++stats_.unlucky_primes;
      return std::nullopt;
    }
    if (lead_ && image.lead < *lead_) {  // so did every prime so far
      stats_.unlucky_primes += lift_.primes();
      lift_ = CrtLift(basis_.size(), kLiftParams);
      proof_primes_.clear();
    }
    lead_ = image.lead;
    proof_primes_.push_back(image.prime);
    const Stopwatch reconstruction_timer;
    lift_.add(image.vector, image.prime);
    const bool complete = lift_.reconstruct();
    std::optional<Polynomial> candidate;
    if (complete) candidate = polynomial_of(basis_, lift_.integer_values());
    stats_.reconstruction_ms += reconstruction_timer.elapsed_ms();
    if (!candidate) return std::nullopt;
    stats_.rows = image.rows;
    stats_.modulus_bits = lift_.modulus_bits();
    stats_.primes = lift_.primes();
    return proven(std::move(*candidate));
  }

 private:
  std::optional<Polynomial> proven(Polynomial candidate) {
    const Stopwatch verify_timer;
    const bool vanishes = verifier_.vanishes(candidate);
    stats_.verify_ms += verify_timer.elapsed_ms();
    const bool degree_kept = std::any_of(proof_primes_.begin(), proof_primes_.end(),
                                         [&](mp_limb_t p) { return keeps_degree_modulo(candidate, p); });
    if (vanishes && degree_kept) return candidate;
    return std::nullopt;
  }

  const MonomialBasis& basis_;
  InterpolationStats& stats_;
  CrtLift lift_;
  std::optional<std::size_t> lead_;
  std::vector<mp_limb_t> proof_primes_;  // primes of the images in lift_: the class's kernel is 1-dimensional
  CandidateVerifier verifier_;
};

void check_shape(const Parametrization& p, const char* who) {
  if (p.coordinates.size() != 3 || p.parameter_ring->num_variables() != 2) {
    throw std::invalid_argument(std::string(who) + ": three coordinates in two parameters expected");
  }
}

void check_class_size(const ImplicitSupport& support, const InterpolationParams& options) {
  if (support.largest_class <= options.max_columns) return;
  throw LimitExceeded(Limit::size, "sparse interpolation: the largest class of the predicted support has " +
                                       std::to_string(support.largest_class) + " monomials, more than " +
                                       std::to_string(options.max_columns) + " columns");
}

}  // namespace

std::optional<InterpolationResult> implicitize_by_sparse_interpolation(const Parametrization& parametrization,
                                                                       const ImplicitSupport& support,
                                                                       const InterpolationParams& options) {
  check_shape(parametrization, "implicitize_by_sparse_interpolation");
  check_class_size(support, options);
  const Stopwatch timer;
  InterpolationStats stats;
  stats.degree_bound = support.total_degree;
  const MapForms forms = map_forms(parametrization, options.budget);
  check_image_dimension(forms, options.seed, options.budget);
  const std::vector<MonomialBasis> bases = class_bases(support);
  PrimeSequence primes = options.primes;
  ClassScan scan = scan_classes(forms, bases, scan_threads(support, options), primes, options);
  stats.degree_probes = scan.kernels;
  stats.rejected_points = scan.rejected_points;
  stats.threads = scan.threads;
  stats.search_ms = timer.elapsed_ms();
  if (!scan.chosen) return std::nullopt;

  const MonomialBasis& basis = bases[*scan.chosen];
  SparseLift lift(parametrization, forms, basis, options, stats);
  std::optional<Polynomial> answer = lift.take(std::move(scan.images.front()));
  const Stopwatch images_timer;
  for (std::size_t taken = kSparseScanPrimes; !answer; ++taken) {
    if (taken >= options.max_primes) return std::nullopt;
    options.budget.check("sparse interpolation");
    KernelImage image = kernel_modulo(forms, basis, primes.next(), options.seed, options.budget);
    stats.rejected_points += image.rejected_points;
    answer = lift.take(std::move(image));
  }
  stats.images_ms = images_timer.elapsed_ms();
  stats.degree = answer->total_degree();
  stats.columns = basis.size();
  return InterpolationResult{std::move(*answer), stats};
}

bool is_minimal_on_support(const Polynomial& candidate, const Parametrization& parametrization,
                           const ImplicitSupport& support, const InterpolationParams& options) {
  check_shape(parametrization, "is_minimal_on_support");
  check_class_size(support, options);
  const Polynomial f = candidate.primitive_part();
  // The class holding every monomial of the candidate, or none.
  std::map<std::vector<std::int32_t>, std::size_t> class_of;
  for (std::size_t c = 0; c < support.classes.size(); ++c) {
    const auto& e = support.classes[c];
    for (std::size_t i = 0; i < e.size(); i += 3) class_of.emplace(std::vector<std::int32_t>(&e[i], &e[i] + 3), c);
  }
  std::optional<std::size_t> home;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const auto it = class_of.find(f.exponents(t));
    if (it == class_of.end() || (home && *home != it->second)) return false;
    home = it->second;
  }
  if (!home) return false;
  const MapForms forms = map_forms(parametrization, options.budget);
  const std::vector<MonomialBasis> bases = class_bases(support);
  PrimeSequence primes = options.primes;
  const ClassScan scan = scan_classes(forms, bases, scan_threads(support, options), primes, options);
  if (scan.chosen != home) return false;
  const KernelImage& image = scan.images.front();
  if (!keeps_degree_modulo(f, image.prime)) return false;

  return spans_kernel(f, bases[*home], image);
}

}  // namespace implicitizer
