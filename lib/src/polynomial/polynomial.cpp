#include "implicitizer/polynomial/polynomial.hpp"

#include <algorithm>
#include <limits>
#include <new>
#include <numeric>
#include <optional>
#include <queue>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

namespace {

void require_same_ring(const Polynomial& a, const Polynomial& b) {
  if (a.ring() != b.ring() && !(*a.ring() == *b.ring())) {
    throw std::logic_error("polynomials from different rings");
  }
}

// The sum a·A + b·B of two sorted term lists, sorted, zero terms dropped.
void merge_scaled(const Ring& ring, const Integer& a, const std::vector<Integer>& ac, const std::vector<std::int32_t>& am,
                  const Integer& b, const std::vector<Integer>& bc, const std::vector<std::int32_t>& bm,
                  std::vector<Integer>& out_c, std::vector<std::int32_t>& out_m) {
  const std::size_t w = ring.monomial_size();
  out_c.reserve(ac.size() + bc.size());
  out_m.reserve(am.size() + bm.size());
  std::size_t i = 0, j = 0;
  while (i < ac.size() || j < bc.size()) {
    int cmp;
    if (i == ac.size()) {
      cmp = -1;
    } else if (j == bc.size()) {
      cmp = 1;
    } else {
      cmp = ring.compare(am.data() + i * w, bm.data() + j * w);
    }
    if (cmp > 0) {
      out_c.emplace_back(a * ac[i]);
      out_m.insert(out_m.end(), am.data() + i * w, am.data() + i * w + w);
      ++i;
    } else if (cmp < 0) {
      out_c.emplace_back(b * bc[j]);
      out_m.insert(out_m.end(), bm.data() + j * w, bm.data() + j * w + w);
      ++j;
    } else {
      Integer c = a * ac[i] + b * bc[j];
      if (c != 0) {
        out_c.push_back(std::move(c));
        out_m.insert(out_m.end(), am.data() + i * w, am.data() + i * w + w);
      }
      ++i;
      ++j;
    }
  }
}

constexpr const char* kMultiplication = "polynomial multiplication";

// The number of terms of a·b when it is known before multiplying, else nullopt. It is
// known exactly when one factor is a monomial (multiplying by it is injective on
// monomials) or when no variable occurs in both: then a·b's monomials are the pairs
// of a's and b's, all distinct, and no coefficient cancels (each is one product of
// non-zero integers). Shared variables can merge pairs, so an upper bound such as
// na·nb would refuse products that collapse ((1+t)^500·(1−t)^500 has 501 terms):
// those are refused while they grow instead.
std::optional<std::size_t> exact_product_terms(const Polynomial& a, const Polynomial& b) {
  const std::size_t na = a.num_terms(), nb = b.num_terms();
  if (na == 1 || nb == 1) return na * nb;
  if (share_a_variable(a, b)) return std::nullopt;
  // Saturating: a count past size_t is refused by any term limit all the same.
  return na > std::numeric_limits<std::size_t>::max() / nb ? std::numeric_limits<std::size_t>::max() : na * nb;
}

// Whether the exponent vectors of p's terms are affinely independent (v_i − v_0 of
// full rank m − 1): then the multisets of e terms give distinct monomials, so p^e has
// exactly C(m − 1 + e, e) terms and no coefficient cancels (each is one multinomial
// coefficient times one product of p's coefficients). Bareiss elimination on the
// differences, exact over ℤ.
bool has_affinely_independent_support(const Polynomial& p) {
  const std::size_t m = p.num_terms();
  const Ring& ring = *p.ring();
  const std::size_t n = ring.num_variables();
  if (m <= 2) return true;  // distinct monomials
  if (m - 1 > n) return false;
  std::vector<std::vector<Integer>> rows(m - 1, std::vector<Integer>(n));
  const std::int32_t* base = ring.exponents(p.monomial(0));
  for (std::size_t i = 1; i < m; ++i) {
    const std::int32_t* e = ring.exponents(p.monomial(i));
    for (std::size_t v = 0; v < n; ++v) rows[i - 1][v] = Integer(e[v]) - Integer(base[v]);
  }
  Integer previous = 1;
  std::size_t rank = 0;
  for (std::size_t col = 0; col < n && rank < rows.size(); ++col) {
    std::size_t pivot = rank;
    while (pivot < rows.size() && rows[pivot][col] == 0) ++pivot;
    if (pivot == rows.size()) continue;
    std::swap(rows[pivot], rows[rank]);
    for (std::size_t r = rank + 1; r < rows.size(); ++r) {
      for (std::size_t c = col + 1; c < n; ++c) {
        rows[r][c] = (rows[rank][col] * rows[r][c] - rows[r][col] * rows[rank][c]) / previous;
      }
      rows[r][col] = 0;
    }
    previous = rows[rank][col];
    ++rank;
  }
  return rank == m - 1;
}

// C(m − 1 + e, e), the number of multisets of e of m terms, saturating at the largest
// size_t.
std::size_t multiset_count(std::size_t m, unsigned e) {
  Integer count = 1;
  for (unsigned k = 1; k <= e; ++k) {
    count = count * Integer(static_cast<unsigned long>(m - 1 + k)) / Integer(k);
    if (count > Integer(static_cast<unsigned long>(std::numeric_limits<std::size_t>::max()))) {
      return std::numeric_limits<std::size_t>::max();
    }
  }
  return static_cast<std::size_t>(count.get_ui());
}

}  // namespace

Polynomial::Polynomial(RingPtr ring) : ring_(std::move(ring)), content_(0) {}

Polynomial::Polynomial(RingPtr ring, Rational content, std::vector<Integer> coefficients,
                       std::vector<std::int32_t> monomials)
    : ring_(std::move(ring)),
      content_(std::move(content)),
      coefficients_(std::move(coefficients)),
      monomials_(std::move(monomials)) {
  normalize();
}

void Polynomial::normalize() {
  if (coefficients_.empty() || content_ == 0) {
    content_ = 0;
    coefficients_.clear();
    monomials_.clear();
    return;
  }
  Integer g = 0;
  for (const auto& c : coefficients_) {
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (g == 1) break;
  }
  if (coefficients_.front() < 0) g = -g;
  if (g != 1) {
    for (auto& c : coefficients_) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
    content_ = content_ * to_rational(g);
  }
}

Polynomial Polynomial::constant(RingPtr ring, const Rational& c) {
  std::vector<std::int32_t> zero(ring->num_variables(), 0);
  return term(std::move(ring), c, zero);
}

Polynomial Polynomial::variable(RingPtr ring, std::size_t index) {
  if (index >= ring->num_variables()) throw std::out_of_range("variable index out of range");
  std::vector<std::int32_t> e(ring->num_variables(), 0);
  e[index] = 1;
  return term(std::move(ring), Rational(1), e);
}

Polynomial Polynomial::term(RingPtr ring, const Rational& c, std::span<const std::int32_t> exponents) {
  if (exponents.size() != ring->num_variables()) throw std::invalid_argument("exponent vector has the wrong length");
  if (c == 0) return Polynomial(std::move(ring));
  std::vector<std::int32_t> m(ring->monomial_size());
  ring->encode(exponents.data(), m.data());
  return Polynomial(std::move(ring), c, {Integer(1)}, std::move(m));
}

Polynomial Polynomial::from_terms(RingPtr ring, const Rational& content, std::vector<Integer> coefficients,
                                  std::vector<std::int32_t> monomials) {
  const std::size_t w = ring->monomial_size();
  const std::size_t n = coefficients.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return ring->compare(monomials.data() + a * w, monomials.data() + b * w) > 0;
  });
  std::vector<Integer> c;
  std::vector<std::int32_t> m;
  c.reserve(n);
  m.reserve(n * w);
  for (std::size_t k = 0; k < n;) {
    const std::size_t first = order[k];
    Integer sum = std::move(coefficients[first]);
    std::size_t next = k + 1;
    while (next < n && ring->compare(monomials.data() + order[next] * w, monomials.data() + first * w) == 0) {
      sum += coefficients[order[next]];
      ++next;
    }
    if (sum != 0) {
      c.push_back(std::move(sum));
      m.insert(m.end(), monomials.data() + first * w, monomials.data() + first * w + w);
    }
    k = next;
  }
  return Polynomial(std::move(ring), content, std::move(c), std::move(m));
}

bool share_a_variable(const Polynomial& a, const Polynomial& b) {
  const std::vector<bool> in_a = a.occurring_variables();
  const std::vector<bool> in_b = b.occurring_variables();
  for (std::size_t v = 0; v < in_a.size() && v < in_b.size(); ++v) {
    if (in_a[v] && in_b[v]) return true;
  }
  return false;
}

std::vector<bool> Polynomial::occurring_variables() const {
  std::vector<bool> occurs(ring_->num_variables(), false);
  for (std::size_t t = 0; t < num_terms(); ++t) {
    const std::int32_t* e = ring_->exponents(monomial(t));
    for (std::size_t v = 0; v < occurs.size(); ++v) occurs[v] = occurs[v] || e[v] != 0;
  }
  return occurs;
}

bool Polynomial::is_constant() const {
  if (is_zero()) return true;
  return num_terms() == 1 && ring_->total_degree(monomial(0)) == 0;
}

Rational Polynomial::coefficient(std::size_t i) const { return content_ * to_rational(coefficients_.at(i)); }

std::vector<std::int32_t> Polynomial::exponents(std::size_t i) const {
  const std::int32_t* e = ring_->exponents(monomial(i));
  return std::vector<std::int32_t>(e, e + ring_->num_variables());
}

std::int32_t Polynomial::total_degree() const {
  std::int32_t d = -1;
  for (std::size_t i = 0; i < num_terms(); ++i) d = std::max(d, ring_->total_degree(monomial(i)));
  return d;
}

std::int32_t Polynomial::degree_in(std::size_t var) const {
  std::int32_t d = -1;
  for (std::size_t i = 0; i < num_terms(); ++i) d = std::max(d, ring_->exponents(monomial(i))[var]);
  return d;
}

Polynomial Polynomial::operator-() const {
  Polynomial r = *this;
  r.content_ = -content_;
  return r;
}

Polynomial Polynomial::operator+(const Polynomial& other) const {
  require_same_ring(*this, other);
  if (is_zero()) return other;
  if (other.is_zero()) return *this;
  // c_a·A + c_b·B = (g/L)·(a'·A + b'·B) with L the lcm of the denominators and g the
  // gcd of the numerators: integer arithmetic on the primitive parts only.
  const mpq_class ca = to_mpq(content_), cb = to_mpq(other.content_);
  Integer l, g;
  mpz_lcm(l.get_mpz_t(), ca.get_den_mpz_t(), cb.get_den_mpz_t());
  mpz_gcd(g.get_mpz_t(), ca.get_num_mpz_t(), cb.get_num_mpz_t());
  const Integer a = (ca.get_num() / g) * (l / ca.get_den());
  const Integer b = (cb.get_num() / g) * (l / cb.get_den());
  std::vector<Integer> c;
  std::vector<std::int32_t> m;
  merge_scaled(*ring_, a, coefficients_, monomials_, b, other.coefficients_, other.monomials_, c, m);
  mpq_class content(g, l);
  content.canonicalize();
  return Polynomial(ring_, to_rational(content), std::move(c), std::move(m));
}

Polynomial Polynomial::operator-(const Polynomial& other) const { return *this + (-other); }

Polynomial Polynomial::operator*(const Polynomial& other) const { return multiply(other, Budget()); }

Polynomial Polynomial::multiply(const Polynomial& other, const Budget& budget) const {
  require_same_ring(*this, other);
  if (is_zero() || other.is_zero()) return Polynomial(ring_);
  if (std::int64_t{total_degree()} + other.total_degree() > kMaxTotalDegree) {
    throw LimitExceeded(Limit::size, "degree limit exceeded in a product");
  }
  // The prediction costs a pass over both factors: only where a limit can use it.
  std::optional<std::size_t> terms;
  if (budget.max_terms() != 0 || budget.memory_account() != nullptr) terms = exact_product_terms(*this, other);
  if (terms) {
    budget.check_predicted_terms(*terms, kMultiplication, [&] {
      return "the product of " + std::to_string(num_terms()) + " and " + std::to_string(other.num_terms()) +
             " terms in disjoint variables";
    });
  }
  try {
    return multiply_johnson(other, budget, terms.value_or(0));
  } catch (const std::bad_alloc&) {
    // A vector the memory account refused at once: the limit, named with the phase.
    budget.rethrow_bad_alloc(kMultiplication);
  }
}

Polynomial Polynomial::multiply_johnson(const Polynomial& other, const Budget& budget, std::size_t known_terms) const {
  // Johnson's heap multiplication: one heap entry per term of the shorter factor,
  // producing the product's terms in decreasing order with O(log n) work each.
  const Polynomial& a = num_terms() <= other.num_terms() ? *this : other;
  const Polynomial& b = num_terms() <= other.num_terms() ? other : *this;
  const Ring& ring = *ring_;
  const std::size_t w = ring.monomial_size();
  const std::size_t na = a.num_terms(), nb = b.num_terms();
  // data() + i·w, not &product[i·w]: a ring without variables has w = 0 and an empty
  // vector, whose operator[] is undefined even for index 0 (found by fuzz/).
  std::vector<std::size_t> next(na, 0);          // next term of b for row i
  std::vector<std::int32_t> product(na * w);     // current product monomial of row i
  auto less = [&](std::size_t i, std::size_t j) { return ring.compare(product.data() + i * w, product.data() + j * w) < 0; };
  std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(less)> heap(less);
  for (std::size_t i = 0; i < na; ++i) {
    ring.multiply(a.monomial(i), b.monomial(0), product.data() + i * w);
    heap.push(i);
  }
  std::vector<Integer> c;
  std::vector<std::int32_t> m;
  // A known size is allocated once: no doubling holds the old and the new array at once.
  c.reserve(known_terms);
  m.reserve(known_terms * w);
  std::size_t steps = 0;
  while (!heap.empty()) {
    const std::size_t i = heap.top();
    heap.pop();
    const std::int32_t* mono = product.data() + i * w;
    if (!m.empty() && ring.compare(&m[m.size() - w], mono) == 0) {
      mpz_addmul(c.back().get_mpz_t(), a.coefficients_[i].get_mpz_t(), b.coefficients_[next[i]].get_mpz_t());
    } else {
      if (!c.empty() && c.back() == 0) {
        c.pop_back();
        m.resize(m.size() - w);
      }
      c.emplace_back(a.coefficients_[i] * b.coefficients_[next[i]]);
      m.insert(m.end(), mono, mono + w);
    }
    if (++next[i] < nb) {
      ring.multiply(a.monomial(i), b.monomial(next[i]), product.data() + i * w);
      heap.push(i);
    }
    if ((++steps & 0xfff) == 0) budget.check_terms(c.size(), kMultiplication);
  }
  if (!c.empty() && c.back() == 0) {
    c.pop_back();
    m.resize(m.size() - w);
  }
  budget.check_terms(c.size(), kMultiplication);
  // Gauss's lemma: the product of primitive polynomials is primitive.
  Polynomial r(ring_);
  r.content_ = content_ * other.content_;
  r.coefficients_ = std::move(c);
  r.monomials_ = std::move(m);
  return r;
}

Polynomial Polynomial::pow(unsigned exponent, const Budget& budget) const {
  Polynomial result = constant(ring_, Rational(1));
  if (exponent == 0) return result;
  if (std::int64_t{total_degree()} * exponent > kMaxTotalDegree) {
    throw LimitExceeded(Limit::size, "degree limit exceeded in a power");
  }
  if (budget.max_terms() != 0 && !is_zero() && has_affinely_independent_support(*this)) {
    budget.check_predicted_terms(multiset_count(num_terms(), exponent), "polynomial power", [&] {
      return "the power " + std::to_string(exponent) + " of " + std::to_string(num_terms()) + " terms";
    });
  }
  // Repeated multiplication by the base keeps one factor small, which for sparse
  // polynomials beats squaring (the squares are dense and large).
  for (unsigned k = 0; k < exponent; ++k) {
    result = result.multiply(*this, budget);
    budget.check("polynomial power");
  }
  return result;
}

Polynomial Polynomial::scaled(const Rational& c) const {
  if (c == 0 || is_zero()) return Polynomial(ring_);
  Polynomial r = *this;
  r.content_ = content_ * c;
  return r;
}

Polynomial Polynomial::divided_by(const Rational& c) const {
  if (c == 0) throw InputError("division_by_zero", "division by zero");
  return scaled(Rational(1) / c);
}

Polynomial Polynomial::derivative(std::size_t var) const {
  if (var >= ring_->num_variables()) throw std::out_of_range("variable index out of range");
  const std::size_t w = ring_->monomial_size();
  std::vector<Integer> c;
  std::vector<std::int32_t> m;
  std::vector<std::int32_t> e(ring_->num_variables());
  // Dividing by x_var keeps the order of the surviving terms (orders are compatible
  // with multiplication), so no sort is needed.
  for (std::size_t i = 0; i < num_terms(); ++i) {
    const std::int32_t* ex = ring_->exponents(monomial(i));
    if (ex[var] == 0) continue;
    c.emplace_back(coefficients_[i] * ex[var]);
    std::copy(ex, ex + e.size(), e.begin());
    e[var] -= 1;
    m.resize(m.size() + w);
    ring_->encode(e.data(), &m[m.size() - w]);
  }
  return Polynomial(ring_, content_, std::move(c), std::move(m));
}

Rational Polynomial::evaluate(std::span<const Rational> point) const {
  const std::size_t n = ring_->num_variables();
  if (point.size() != n) throw std::invalid_argument("point has the wrong number of coordinates");
  std::vector<mpq_class> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = to_mpq(point[i]);
  // Power tables per variable: each x_i^k computed once.
  std::vector<std::vector<mpq_class>> powers(n, std::vector<mpq_class>{mpq_class(1)});
  mpq_class sum = 0;
  for (std::size_t t = 0; t < num_terms(); ++t) {
    const std::int32_t* ex = ring_->exponents(monomial(t));
    mpq_class term = coefficients_[t];
    for (std::size_t i = 0; i < n; ++i) {
      auto& pw = powers[i];
      while (pw.size() <= static_cast<std::size_t>(ex[i])) pw.push_back(pw.back() * p[i]);
      if (ex[i] > 0) term *= pw[ex[i]];
    }
    sum += term;
  }
  return to_rational(sum) * content_;
}

void scale_to_integers(std::span<Polynomial> polynomials) {
  Integer denominator = 1;
  for (const Polynomial& p : polynomials) {
    if (!p.is_zero()) {
      mpz_lcm(denominator.get_mpz_t(), denominator.get_mpz_t(), to_mpq(p.content()).get_den().get_mpz_t());
    }
  }
  for (Polynomial& p : polynomials) p = p.scaled(to_rational(denominator));
}

Polynomial sum_of(const RingPtr& ring, std::vector<Polynomial> parts) {
  if (parts.empty()) return Polynomial(ring);
  while (parts.size() > 1) {
    std::vector<Polynomial> next;
    next.reserve((parts.size() + 1) / 2);
    for (std::size_t i = 0; i + 1 < parts.size(); i += 2) next.push_back(parts[i] + parts[i + 1]);
    if (parts.size() % 2) next.push_back(std::move(parts.back()));
    parts = std::move(next);
  }
  return std::move(parts.front());
}

Polynomial Polynomial::compose(const RingPtr& target, std::span<const Polynomial> values, const Budget& budget) const {
  const std::size_t n = ring_->num_variables();
  if (values.size() != n) throw std::invalid_argument("compose needs one value per variable");
  std::vector<std::vector<Polynomial>> powers(n);
  for (std::size_t i = 0; i < n; ++i) powers[i].push_back(constant(target, Rational(1)));
  std::vector<Polynomial> parts;
  parts.reserve(num_terms());
  for (std::size_t t = 0; t < num_terms(); ++t) {
    const std::int32_t* ex = ring_->exponents(monomial(t));
    Polynomial term = constant(target, content_ * to_rational(coefficients_[t]));
    for (std::size_t i = 0; i < n; ++i) {
      if (ex[i] == 0) continue;
      auto& pw = powers[i];
      while (pw.size() <= static_cast<std::size_t>(ex[i])) pw.push_back(pw.back().multiply(values[i], budget));
      term = term.multiply(pw[ex[i]], budget);
    }
    parts.push_back(std::move(term));
    budget.check("composition");
  }
  return sum_of(target, std::move(parts));
}

Polynomial Polynomial::substitute(std::size_t var, const Polynomial& value, const Budget& budget) const {
  require_same_ring(*this, value);
  std::vector<Polynomial> values;
  for (std::size_t i = 0; i < ring_->num_variables(); ++i) {
    values.push_back(i == var ? value : variable(ring_, i));
  }
  return compose(ring_, values, budget);
}

Polynomial Polynomial::map_to(const RingPtr& target, std::span<const std::size_t> var_map) const {
  const std::size_t n = ring_->num_variables();
  if (var_map.size() != n) throw std::invalid_argument("map_to needs one target index per variable");
  const std::size_t w = target->monomial_size();
  std::vector<std::int32_t> e(target->num_variables());
  std::vector<std::int32_t> m(num_terms() * w);
  for (std::size_t t = 0; t < num_terms(); ++t) {
    std::fill(e.begin(), e.end(), 0);
    const std::int32_t* ex = ring_->exponents(monomial(t));
    for (std::size_t i = 0; i < n; ++i) {
      if (ex[i] == 0) continue;
      if (var_map[i] >= e.size()) throw std::out_of_range("map_to: target index out of range");
      e[var_map[i]] += ex[i];
    }
    target->encode(e.data(), m.data() + t * w);
  }
  return from_terms(target, content_, coefficients_, std::move(m));
}

Polynomial Polynomial::homogenize(std::size_t var) const {
  if (var >= ring_->num_variables()) throw std::out_of_range("variable index out of range");
  if (involves(var)) throw std::invalid_argument("homogenize: the homogenizing variable occurs already");
  const std::int32_t d = total_degree();
  const std::size_t w = ring_->monomial_size();
  std::vector<std::int32_t> m(num_terms() * w);
  for (std::size_t t = 0; t < num_terms(); ++t) {
    std::vector<std::int32_t> e = exponents(t);
    e[var] = d - ring_->total_degree(monomial(t));
    ring_->encode(e.data(), m.data() + t * w);
  }
  return from_terms(ring_, content_, coefficients_, std::move(m));
}

Polynomial Polynomial::primitive_part() const {
  Polynomial r = *this;
  if (!r.is_zero()) r.content_ = Rational(1);
  return r;
}

Polynomial Polynomial::monic() const {
  Polynomial r = *this;
  if (!r.is_zero()) r.content_ = Rational(1) / to_rational(coefficients_.front());
  return r;
}

bool Polynomial::operator==(const Polynomial& other) const {
  if (ring_ != other.ring_ && !(*ring_ == *other.ring_)) return false;
  return content_ == other.content_ && coefficients_ == other.coefficients_ && monomials_ == other.monomials_;
}

bool Polynomial::is_canonical() const {
  if (is_zero()) return content_ == 0 && monomials_.empty();
  const std::size_t w = ring_->monomial_size();
  if (monomials_.size() != coefficients_.size() * w || content_ == 0) return false;
  Integer g = 0;
  for (std::size_t i = 0; i < num_terms(); ++i) {
    if (coefficients_[i] == 0) return false;
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), coefficients_[i].get_mpz_t());
    if (i > 0 && ring_->compare(monomial(i - 1), monomial(i)) <= 0) return false;
    std::vector<std::int32_t> re(w);
    ring_->encode(ring_->exponents(monomial(i)), re.data());
    if (!std::equal(re.begin(), re.end(), monomial(i))) return false;
  }
  return g == 1 && coefficients_.front() > 0;
}

}  // namespace implicitizer
