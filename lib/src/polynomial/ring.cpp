#include "implicitizer/polynomial/ring.hpp"

#include <algorithm>
#include <set>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

RingPtr Ring::make(std::vector<std::string> variables, const MonomialOrder& order) {
  if (variables.size() > kMaxVariables) {
    throw LimitExceeded(Limit::size, "a ring of " + std::to_string(variables.size()) + " variables; the limit is " +
                                         std::to_string(kMaxVariables));
  }
  std::set<std::string> seen;
  for (const auto& v : variables) {
    if (v.empty()) throw InputError("invalid_variables", "empty variable name");
    if (!seen.insert(v).second) throw InputError("invalid_variables", "variable '" + v + "' is listed twice");
  }
  return RingPtr(new Ring(std::move(variables), order));
}

Ring::Ring(std::vector<std::string> variables, const MonomialOrder& order)
    : variables_(std::move(variables)), order_(order), matrix_(order.matrix(variables_.size())) {
  key_size_ = matrix_.size();
  degree_weights_ = order_.degree_weights(variables_.size());
  is_elimination_order_ =
      std::any_of(degree_weights_.begin(), degree_weights_.end(), [](std::int32_t w) { return w == 0; });
}

std::optional<std::size_t> Ring::index_of(const std::string& name) const {
  auto it = std::find(variables_.begin(), variables_.end(), name);
  if (it == variables_.end()) return std::nullopt;
  return static_cast<std::size_t>(it - variables_.begin());
}

void Ring::encode(const std::int32_t* exponents, std::int32_t* out) const {
  const std::size_t n = variables_.size();
  for (std::size_t r = 0; r < key_size_; ++r) {
    std::int64_t key = 0;
    for (std::size_t i = 0; i < n; ++i) key += std::int64_t{matrix_[r][i]} * exponents[i];
    out[r] = static_cast<std::int32_t>(key);
  }
  std::copy(exponents, exponents + n, out + key_size_);
}

std::int32_t Ring::total_degree(const std::int32_t* m) const {
  std::int32_t d = 0;
  for (std::size_t i = 0; i < variables_.size(); ++i) d += m[key_size_ + i];
  return d;
}

void Ring::lcm(const std::int32_t* a, const std::int32_t* b, std::int32_t* out) const {
  const std::size_t n = variables_.size();
  std::vector<std::int32_t> e(n);
  for (std::size_t i = 0; i < n; ++i) e[i] = std::max(a[key_size_ + i], b[key_size_ + i]);
  encode(e.data(), out);
}

bool Ring::coprime(const std::int32_t* a, const std::int32_t* b) const {
  const std::size_t n = monomial_size();
  for (std::size_t i = key_size_; i < n; ++i) {
    if (a[i] > 0 && b[i] > 0) return false;
  }
  return true;
}

std::uint64_t Ring::divisor_mask(const std::int32_t* m) const {
  // Each variable owns 64/n bits (at least one); bit j of variable i is set when its
  // exponent exceeds j. Divisibility then implies mask inclusion.
  const std::size_t n = variables_.size();
  if (n == 0) return 0;
  const std::size_t per = std::max<std::size_t>(1, 64 / n);
  std::uint64_t mask = 0;
  // Variable i's bits start at i·per; an exponent e sets the lowest min(e, per) of them.
  for (std::size_t i = 0; i < n && i * per < 64; ++i) {
    const std::size_t width = std::min(per, 64 - i * per);
    const std::int32_t e = m[key_size_ + i];
    if (e <= 0) continue;
    const std::size_t set = std::min<std::size_t>(static_cast<std::size_t>(e), width);
    const std::uint64_t bits = set == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << set) - 1;
    mask |= bits << (i * per);
  }
  return mask;
}

bool Ring::operator==(const Ring& other) const { return variables_ == other.variables_ && order_ == other.order_; }

}  // namespace implicitizer
