#include "implicitizer/modular/pencil_determinant.hpp"

#include <flint/fmpz.h>
#include <flint/nmod_mat.h>
#include <flint/nmod_vec.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "implicitizer/core/stopwatch.hpp"
#include "implicitizer/modular/crt_lift.hpp"
#include "implicitizer/modular/flint_handles.hpp"
#include "implicitizer/modular/one_per_thread.hpp"

namespace implicitizer {

MatrixPencil::MatrixPencil(std::size_t size, std::size_t num_variables)
    : size_(size), num_variables_(num_variables), entries_((num_variables + 1) * size * size) {}

Integer MatrixPencil::entry_norm(std::size_t row, std::size_t col) const {
  Integer norm = 0;
  for (std::size_t part = 0; part <= num_variables_; ++part) norm += abs(at(part, row, col));
  return norm;
}

std::size_t MatrixPencil::determinant_coefficient_bits() const {
  std::size_t bits = 1;
  for (std::size_t row = 0; row < size_; ++row) {
    Integer sum = 0;
    for (std::size_t col = 0; col < size_; ++col) sum += entry_norm(row, col);
    if (sum == 0) return 1;  // a zero row: the determinant is 0
    bits += mpz_sizeinbase(sum.get_mpz_t(), 2);
  }
  return bits;
}

namespace {

// The size of the determinant timed to predict larger ones.
constexpr std::size_t kTimedSize = 128;

// The pencil reduced modulo one prime, evaluated at points of a grid.
class ModularPencil {
 public:
  ModularPencil(const MatrixPencil& pencil, const std::vector<std::size_t>& minor, mp_limb_t p, const Budget& budget)
      : n_(pencil.size()),
        k_(pencil.num_variables()),
        minor_(minor),
        matrix_(n_, n_, p),
        divisor_(minor.size(), minor.size(), p) {
    nmod_init(&mod_, p);
    reduced_.resize((k_ + 1) * n_ * n_);
    Fmpz c;
    for (std::size_t part = 0; part <= k_; ++part) {
      for (std::size_t r = 0; r < n_; ++r) {
        budget.check("determinant (the pencil modulo p)");
        for (std::size_t col = 0; col < n_; ++col) {
          fmpz_set_mpz(c.get(), pencil.at(part, r, col).get_mpz_t());
          reduced_[(part * n_ + r) * n_ + col] = fmpz_fdiv_ui(c.get(), p);
        }
      }
    }
    // Which parts are non-zero per entry, so that sparse pencils (Macaulay's
    // matrix) evaluate in time proportional to their non-zeros.
    for (std::size_t part = 1; part <= k_; ++part) {
      bool any = false;
      for (std::size_t i = 0; i < n_ * n_ && !any; ++i) any = reduced_[part * n_ * n_ + i] != 0;
      if (any) active_parts_.push_back(part);
    }
  }

  // det(A(u)) mod p, or the quotient by the minor; nullopt when the minor vanishes.
  std::optional<mp_limb_t> evaluate(const mp_limb_t* u) {
    for (std::size_t r = 0; r < n_; ++r) {
      for (std::size_t col = 0; col < n_; ++col) {
        mp_limb_t v = reduced_[r * n_ + col];
        for (std::size_t part : active_parts_) {
          const mp_limb_t a = reduced_[(part * n_ + r) * n_ + col];
          if (a != 0) v = nmod_add(v, nmod_mul(a, u[part - 1], mod_), mod_);
        }
        nmod_mat_entry(matrix_.get(), r, col) = v;
      }
    }
    mp_limb_t divisor = 1;
    if (!minor_.empty()) {
      for (std::size_t i = 0; i < minor_.size(); ++i) {
        for (std::size_t j = 0; j < minor_.size(); ++j) {
          nmod_mat_entry(divisor_.get(), i, j) = nmod_mat_entry(matrix_.get(), minor_[i], minor_[j]);
        }
      }
      divisor = _nmod_mat_det(divisor_.get());
      if (divisor == 0) return std::nullopt;
    }
    const mp_limb_t det = _nmod_mat_det(matrix_.get());
    return minor_.empty() ? det : nmod_mul(det, n_invmod(divisor, mod_.n), mod_);
  }

 private:
  std::size_t n_;
  std::size_t k_;
  const std::vector<std::size_t>& minor_;
  nmod_t mod_;
  std::vector<mp_limb_t> reduced_;
  std::vector<std::size_t> active_parts_;
  NmodMatrix matrix_;
  NmodMatrix divisor_;
};

std::size_t power(std::size_t base, std::size_t exponent) {
  std::size_t r = 1;
  for (std::size_t i = 0; i < exponent; ++i) r *= base;
  return r;
}

// Exponent vectors of the grid whose total degree is at most D, with their flat index.
struct DenseSupport {
  std::vector<std::size_t> flat;
  std::vector<std::vector<std::int32_t>> exponents;
};

DenseSupport support_of(std::size_t k, std::size_t points, std::int32_t degree_bound) {
  DenseSupport s;
  const std::size_t total = power(points, k);
  std::vector<std::int32_t> e(k);
  for (std::size_t flat = 0; flat < total; ++flat) {
    std::size_t rest = flat;
    std::int32_t degree = 0;
    for (std::size_t v = k; v-- > 0;) {
      e[v] = static_cast<std::int32_t>(rest % points);
      rest /= points;
      degree += e[v];
    }
    if (degree <= degree_bound) {
      s.flat.push_back(flat);
      s.exponents.push_back(e);
    }
  }
  return s;
}

// The image of the answer modulo p: its coefficients on `support` (the exponents
// of total degree ≤ D), or nullopt when the divisor minor vanished at a point (the
// prime, or these nodes, are unlucky: the caller takes another prime).
//
// The points form the principal lattice {(x_i, y_j, z_k) : i + j + k ≤ D} on random
// nodes, which is unisolvent for total degree ≤ D: C(D+3, 3) determinants instead
// of the (D+1)³ of a full grid (220 against 1000 for D = 9, 1330 against 6859 for
// D = 18). Write P = Σ_k Q_k(x, y)·N_k(z) in the Newton basis N_k of the z-nodes,
// deg Q_k ≤ D − k. At (x_i, y_j) the first D − i − j + 1 values along z fix the
// first Newton coefficients Q_k(x_i, y_j), k ≤ D − i − j, since divided
// differences only look at the values before them. Each Q_k is then a problem of
// the same shape with degree D − k, one dimension lower. Finally the Newton
// coefficients are converted to monomial ones along each axis (Horner).
// Distinct random nodes per variable: random rather than 0, 1, 2, … so that no
// structure of the input (a minor that vanishes at u = 0) meets the lattice.
std::vector<std::vector<mp_limb_t>> random_nodes(ResidueStream& stream, std::size_t k, std::size_t points,
                                                 mp_limb_t p) {
  std::vector<std::vector<mp_limb_t>> nodes(k);
  for (auto& list : nodes) {
    while (list.size() < points) {
      const mp_limb_t v = stream.next(p);
      if (std::find(list.begin(), list.end(), v) == list.end()) list.push_back(v);
    }
  }
  return nodes;
}

// The values on the principal lattice, stored densely with `stride`, and its lines.
struct LatticeValues {
  const DenseSupport& support;
  std::int32_t degree;
  std::vector<std::size_t> stride;
  std::vector<mp_limb_t> values;

  // The lines along `axis`: every support point with index 0 on the axis starts one,
  // of length D − (sum of its other indices) + 1; f(base, length).
  template <typename F>
  void for_each_line(std::size_t axis, F&& f) const {
    for (std::size_t s = 0; s < support.flat.size(); ++s) {
      const auto& e = support.exponents[s];
      if (e[axis] != 0) continue;
      std::int32_t others = 0;
      for (std::int32_t x : e) others += x;
      f(support.flat[s], static_cast<std::size_t>(degree - others) + 1);
    }
  }
};

// Divided differences along `x`'s axis, in place: level l turns c_i into
// f[x_{i−l}, …, x_i].
void divided_differences_along(LatticeValues& lattice, std::size_t axis, const std::vector<mp_limb_t>& x, nmod_t mod) {
  const std::size_t st = lattice.stride[axis];
  std::vector<mp_limb_t> line(x.size());
  lattice.for_each_line(axis, [&](std::size_t base, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) line[i] = lattice.values[base + i * st];
    for (std::size_t l = 1; l < n; ++l) {
      for (std::size_t i = n - 1; i >= l; --i) {
        const mp_limb_t difference = nmod_sub(line[i], line[i - 1], mod);
        line[i] = nmod_mul(difference, n_invmod(nmod_sub(x[i], x[i - l], mod), mod.n), mod);
      }
    }
    for (std::size_t i = 0; i < n; ++i) lattice.values[base + i * st] = line[i];
  });
}

// Newton to monomial coefficients along `x`'s axis, by Horner: q ← q·(x − x_j) + c_j
// for j = n−2, …, 0.
void newton_to_monomial_along(LatticeValues& lattice, std::size_t axis, const std::vector<mp_limb_t>& x, nmod_t mod) {
  const std::size_t st = lattice.stride[axis];
  std::vector<mp_limb_t> line(x.size()), next(x.size());
  lattice.for_each_line(axis, [&](std::size_t base, std::size_t n) {
    std::fill(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(n), 0);
    line[0] = lattice.values[base + (n - 1) * st];
    for (std::size_t j = n - 1; j-- > 0;) {
      const std::size_t length = n - 1 - j;  // current degree + 1
      next[0] = 0;
      for (std::size_t t = 0; t <= length; ++t) {
        const mp_limb_t shifted = t > 0 ? line[t - 1] : 0;
        const mp_limb_t kept = t < length ? nmod_mul(line[t], x[j], mod) : 0;
        next[t] = nmod_sub(shifted, kept, mod);
      }
      next[0] = nmod_add(next[0], lattice.values[base + j * st], mod);
      std::copy(next.begin(), next.begin() + static_cast<std::ptrdiff_t>(length + 1), line.begin());
    }
    for (std::size_t i = 0; i < n; ++i) lattice.values[base + i * st] = line[i];
  });
}

// The polynomial with coefficients `image` on `support` at the point u.
mp_limb_t evaluate_image(const std::vector<mp_limb_t>& image, const DenseSupport& support,
                         const std::vector<mp_limb_t>& u, std::size_t points, nmod_t mod) {
  const std::size_t k = u.size();
  std::vector<std::vector<mp_limb_t>> powers(k, std::vector<mp_limb_t>(points, 1));
  for (std::size_t v = 0; v < k; ++v) {
    for (std::size_t e = 1; e < points; ++e) powers[v][e] = nmod_mul(powers[v][e - 1], u[v], mod);
  }
  mp_limb_t sum = 0;
  for (std::size_t s = 0; s < image.size(); ++s) {
    mp_limb_t term = image[s];
    for (std::size_t v = 0; v < k; ++v) {
      term = nmod_mul(term, powers[v][static_cast<std::size_t>(support.exponents[s][v])], mod);
    }
    sum = nmod_add(sum, term, mod);
  }
  return sum;
}

std::optional<std::vector<mp_limb_t>> image_modulo(const MatrixPencil& pencil, const PencilDeterminantParams& options,
                                                   const DenseSupport& support, mp_limb_t p, std::uint64_t seed,
                                                   std::size_t& evaluations) {
  const std::size_t k = pencil.num_variables();
  const std::size_t points = static_cast<std::size_t>(options.degree_bound) + 1;
  ModularPencil modular(pencil, options.divisor_minor, p, options.budget);
  nmod_t mod;
  nmod_init(&mod, p);
  ResidueStream stream(seed ^ p);
  const std::vector<std::vector<mp_limb_t>> nodes = random_nodes(stream, k, points, p);

  LatticeValues lattice{support, options.degree_bound, std::vector<std::size_t>(k, 1), {}};
  for (std::size_t v = k; v-- > 1;) lattice.stride[v - 1] = lattice.stride[v] * points;
  lattice.values.resize(lattice.stride.empty() ? 1 : lattice.stride[0] * points);
  std::vector<mp_limb_t> u(k);
  for (std::size_t s = 0; s < support.flat.size(); ++s) {
    options.budget.check("determinant evaluation");  // an evaluation is a whole determinant
    for (std::size_t v = 0; v < k; ++v) u[v] = nodes[v][static_cast<std::size_t>(support.exponents[s][v])];
    const auto value = modular.evaluate(u.data());
    ++evaluations;
    if (!value) return std::nullopt;
    lattice.values[support.flat[s]] = *value;
  }
  for (std::size_t axis = k; axis-- > 0;) {
    divided_differences_along(lattice, axis, nodes[axis], mod);
    options.budget.check("determinant interpolation");
  }
  for (std::size_t axis = 0; axis < k; ++axis) newton_to_monomial_along(lattice, axis, nodes[axis], mod);

  // One check point off the lattice: the interpolant agrees with the determinant
  // there unless the degree bound was wrong (the lattice alone cannot tell).
  for (auto& v : u) v = stream.next(p);
  std::vector<mp_limb_t> image(support.flat.size());
  for (std::size_t s = 0; s < image.size(); ++s) image[s] = lattice.values[support.flat[s]];
  if (const auto check = modular.evaluate(u.data())) {
    ++evaluations;
    if (evaluate_image(image, support, u, points, mod) != *check) {
      throw std::logic_error("pencil_determinant: the determinant exceeds its degree bound");
    }
  }
  return image;
}

void check_arguments(const MatrixPencil& pencil, const RingPtr& ring, const PencilDeterminantParams& options) {
  if (ring->num_variables() != pencil.num_variables())
    throw std::invalid_argument("pencil_determinant: ring and pencil differ in variables");
  if (options.degree_bound < 0) throw std::invalid_argument("pencil_determinant: negative degree bound");
  for (std::size_t i = 0; i < options.divisor_minor.size(); ++i) {
    if (options.divisor_minor[i] >= pencil.size() ||
        (i > 0 && options.divisor_minor[i] <= options.divisor_minor[i - 1])) {
      throw std::invalid_argument("pencil_determinant: the divisor minor's indices must increase within the matrix");
    }
  }
}

// A second thread pays only when a prime takes longer than starting one: on a busy
// machine a new thread can wait a scheduler tick (about 4 ms, measured), so below
// ~3·10⁶ operations per prime (a few ms) the primes run in this thread.
unsigned threads_for(const MatrixPencil& pencil, const DenseSupport& support, const PencilDeterminantParams& options) {
  const double operations_per_prime =
      static_cast<double>(support.flat.size()) * static_cast<double>(pencil.size() * pencil.size() * pencil.size()) / 3;
  const unsigned automatic_threads =
      operations_per_prime < 3e6 ? 1u : std::max(1u, std::thread::hardware_concurrency());
  return std::max(1u, options.threads != 0 ? options.threads : automatic_threads);
}

// The polynomial whose coefficients on `support` are the lifted integers.
Polynomial polynomial_of(const CrtLift& crt, const DenseSupport& support, const RingPtr& ring) {
  std::vector<Integer> coefficients;
  std::vector<std::int32_t> monomials;
  std::vector<std::int32_t> encoded(ring->monomial_size());
  for (std::size_t s = 0; s < support.flat.size(); ++s) {
    Integer value = crt.integer(s);
    if (value == 0) continue;
    coefficients.push_back(std::move(value));
    ring->encode(support.exponents[s].data(), encoded.data());
    monomials.insert(monomials.end(), encoded.begin(), encoded.end());
  }
  return Polynomial::from_terms(ring, Rational(1), std::move(coefficients), std::move(monomials));
}

// A timing of the small determinant is reused for this long: the auxiliary
// resultant's probes and the determinant that follows them ask within milliseconds
// of one another, and one timing is three 128 × 128 determinants (its cost is in
// docs/algorithms.md).
constexpr double kTimingReuseMs = 1000;

// The fastest of three timings of a kTimedSize determinant, in ms: one that a
// scheduler tick interrupted would multiply the prediction and refuse what would end
// in time. Measured on this run (so under this load), at most once per
// kTimingReuseMs for the whole process.
double small_determinant_ms() {
  static std::mutex mutex;
  static std::optional<Stopwatch> measured_at;
  static double fastest_ms = 0;
  const std::lock_guard<std::mutex> lock(mutex);
  if (measured_at && measured_at->elapsed_ms() < kTimingReuseMs) return fastest_ms;
  const mp_limb_t p = PrimeSequence().next();
  NmodMatrix sample(kTimedSize, kTimedSize, p);
  for (int run = 0; run < 3; ++run) {
    ResidueStream stream(static_cast<std::uint64_t>(run));
    for (std::size_t r = 0; r < kTimedSize; ++r) {
      for (std::size_t c = 0; c < kTimedSize; ++c) nmod_mat_entry(sample.get(), r, c) = stream.next(p);
    }
    const Stopwatch timer;
    (void)_nmod_mat_det(sample.get());  // overwrites the matrix: refilled above
    const double ms = timer.elapsed_ms();
    fastest_ms = run == 0 ? ms : std::min(fastest_ms, ms);
  }
  measured_at.emplace();
  return fastest_ms;
}

}  // namespace

// As interpolation refuses its kernels (docs/algorithms.md, "Kernels that would end
// past the deadline"): the time is predicted from a determinant of size kTimedSize
// (small_determinant_ms), scaled by the cube of the size (FLINT's elimination grows
// more slowly than that, so the prediction errs high); below 2·kTimedSize one
// evaluation is short enough for the checks between them.
void refuse_determinants_past_deadline(std::size_t size, std::size_t evaluations, const Budget& budget) {
  if (size < 2 * kTimedSize || !std::isfinite(budget.seconds_left())) return;
  const double scale = static_cast<double>(size) / kTimedSize;
  const double predicted = small_determinant_ms() / 1000 * scale * scale * scale * static_cast<double>(evaluations);
  budget.refuse_past_deadline(predicted, "the determinant",
                              std::to_string(evaluations) + " evaluations of a " + std::to_string(size) + "x" +
                                  std::to_string(size) + " matrix");
}

Polynomial pencil_determinant(const MatrixPencil& pencil, const RingPtr& ring, const PencilDeterminantParams& options,
                              PencilDeterminantStats* stats_out) {
  check_arguments(pencil, ring, options);
  const std::size_t k = pencil.num_variables();
  PencilDeterminantStats stats;
  if (pencil.size() == 0) {
    if (stats_out) *stats_out = stats;
    return Polynomial::constant(ring, Rational(1));
  }

  const std::size_t points = static_cast<std::size_t>(options.degree_bound) + 1;
  const DenseSupport support = support_of(k, points, options.degree_bound);
  // The answer has at most one term per monomial of the lattice: the size limit
  // applies before any work.
  options.budget.check_terms(support.flat.size(), "determinant");
  refuse_determinants_past_deadline(pencil.size(), support.flat.size() + 1, options.budget);
  CrtLift crt(support.flat.size());
  PrimeSequence primes = options.primes;
  const unsigned threads = threads_for(pencil, support, options);

  std::size_t stable = 0;
  bool done = false;
  while (!done) {
    // One batch: a prime per thread, run concurrently; the images are combined in
    // prime order so that the result does not depend on scheduling.
    std::vector<mp_limb_t> batch(threads);
    for (auto& p : batch) p = primes.next();
    std::vector<std::optional<std::vector<mp_limb_t>>> images(threads);
    std::vector<std::size_t> evaluations(threads, 0);
    run_one_per_thread(threads, [&](std::size_t i) {
      images[i] = image_modulo(pencil, options, support, batch[i], options.seed, evaluations[i]);
    });

    for (std::size_t i = 0; i < threads && !done; ++i) {
      stats.evaluations += evaluations[i];
      if (!images[i]) {
        ++stats.unlucky_primes;
        continue;
      }
      const bool changed = crt.add(*images[i], batch[i]);
      ++stats.primes;
      stats.modulus_bits = crt.modulus_bits();
      if (options.proven_bits > 0) {
        done = stats.modulus_bits > options.proven_bits + 1;
        stats.proven = done;
        // The bound fixes the primes needed: report the bits of the modulus so far.
        options.budget.report_stage("determinant (modulus bits of the proven bound)", stats.modulus_bits,
                                    options.proven_bits + 2);
      } else {
        stable = changed ? 0 : stable + 1;
        done = stable >= options.stable_primes;
        options.budget.report_stage("determinant (primes)", stats.primes, 0);
      }
    }
    if (!done && stats.primes + stats.unlucky_primes >= options.max_primes) {
      throw LimitExceeded(Limit::size, "determinant: more than " + std::to_string(options.max_primes) +
                                           " primes needed (coefficients too large)");
    }
  }

  if (stats_out) *stats_out = stats;
  return polynomial_of(crt, support, ring);
}

PencilProbe probe_pencil_determinant(const MatrixPencil& pencil, const std::vector<std::size_t>& divisor_minor,
                                     std::uint64_t seed, int trials, const Budget& budget) {
  if (pencil.size() == 0) return PencilProbe::nonzero;
  refuse_determinants_past_deadline(pencil.size(), static_cast<std::size_t>(std::max(trials, 0)), budget);
  PrimeSequence primes(/*skip=*/7);
  ResidueStream stream(seed);
  bool minor_always_zero = true;
  for (int trial = 0; trial < trials; ++trial) {
    const mp_limb_t p = primes.next();
    ModularPencil modular(pencil, divisor_minor, p, budget);
    budget.check("determinant probe");
    std::vector<mp_limb_t> u(pencil.num_variables());
    for (auto& v : u) v = stream.next(p);
    const auto value = modular.evaluate(u.data());
    if (!value) continue;
    minor_always_zero = false;
    if (*value != 0) return PencilProbe::nonzero;
  }
  return minor_always_zero && !divisor_minor.empty() ? PencilProbe::minor_zero : PencilProbe::zero;
}

}  // namespace implicitizer
