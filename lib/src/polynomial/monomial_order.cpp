#include "implicitizer/polynomial/monomial_order.hpp"

#include <algorithm>
#include <sstream>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

MonomialOrder MonomialOrder::lex() {
  MonomialOrder o;
  o.kind_ = Kind::lex;
  return o;
}

MonomialOrder MonomialOrder::grlex() {
  MonomialOrder o;
  o.kind_ = Kind::grlex;
  return o;
}

MonomialOrder MonomialOrder::grevlex() { return MonomialOrder(); }

MonomialOrder MonomialOrder::weighted(std::vector<int> weights, const MonomialOrder& tie_break) {
  for (int w : weights) {
    if (w < 0 || w > 1024) throw InputError("invalid_order", "weights must lie in [0, 1024]");
  }
  MonomialOrder o;
  o.kind_ = Kind::weighted;
  o.weights_ = std::move(weights);
  o.first_ = std::make_shared<const MonomialOrder>(tie_break);
  return o;
}

MonomialOrder MonomialOrder::block(std::size_t first_block_size, const MonomialOrder& first,
                                   const MonomialOrder& rest) {
  MonomialOrder o;
  o.kind_ = Kind::block;
  o.first_block_size_ = first_block_size;
  o.first_ = std::make_shared<const MonomialOrder>(first);
  o.rest_ = std::make_shared<const MonomialOrder>(rest);
  return o;
}

MonomialOrder MonomialOrder::from_name(const std::string& name) {
  if (name == "lex") return lex();
  if (name == "grlex") return grlex();
  if (name == "grevlex") return grevlex();
  throw InputError("unknown_order", "unknown monomial order '" + name + "' (expected lex, grlex or grevlex)");
}

std::vector<std::vector<std::int32_t>> MonomialOrder::matrix(std::size_t n) const {
  std::vector<std::vector<std::int32_t>> rows;
  auto unit = [n](std::size_t i, std::int32_t v) {
    std::vector<std::int32_t> r(n, 0);
    r[i] = v;
    return r;
  };
  switch (kind_) {
    case Kind::lex:
      for (std::size_t i = 0; i < n; ++i) rows.push_back(unit(i, 1));
      break;
    case Kind::grlex:
      rows.emplace_back(n, 1);
      for (std::size_t i = 0; i + 1 < n; ++i) rows.push_back(unit(i, 1));
      break;
    case Kind::grevlex:
      // Degree, then the smaller exponent of the last variable wins, then of the one
      // before, ... The last row (x1) is implied by the degree and the others.
      rows.emplace_back(n, 1);
      for (std::size_t i = n; i-- > 1;) rows.push_back(unit(i, -1));
      break;
    case Kind::weighted: {
      if (weights_.size() != n) {
        throw InputError("invalid_order", "the weight vector has " + std::to_string(weights_.size()) +
                                              " entries for " + std::to_string(n) + " variables");
      }
      rows.emplace_back(weights_.begin(), weights_.end());
      auto tail = first_->matrix(n);
      rows.insert(rows.end(), tail.begin(), tail.end());
      break;
    }
    case Kind::block: {
      if (first_block_size_ > n) {
        throw InputError("invalid_order", "the first block has more variables than the ring");
      }
      const std::size_t k = first_block_size_;
      for (auto& r : first_->matrix(k)) {
        r.resize(n, 0);
        rows.push_back(std::move(r));
      }
      for (auto& r : rest_->matrix(n - k)) {
        std::vector<std::int32_t> full(k, 0);
        full.insert(full.end(), r.begin(), r.end());
        rows.push_back(std::move(full));
      }
      break;
    }
  }
  if (n == 0) rows.clear();
  return rows;
}

std::vector<std::int32_t> MonomialOrder::degree_weights(std::size_t n) const {
  switch (kind_) {
    case Kind::weighted:
      if (weights_.size() == n && std::any_of(weights_.begin(), weights_.end(), [](int w) { return w > 0; })) {
        return std::vector<std::int32_t>(weights_.begin(), weights_.end());
      }
      break;
    case Kind::block: {
      const std::size_t k = std::min(first_block_size_, n);
      auto weights = first_->degree_weights(k);
      weights.resize(n, 0);
      return weights;
    }
    case Kind::lex:
    case Kind::grlex:
    case Kind::grevlex:
      break;
  }
  return std::vector<std::int32_t>(n, 1);
}

std::string MonomialOrder::name() const {
  switch (kind_) {
    case Kind::lex:
      return "lex";
    case Kind::grlex:
      return "grlex";
    case Kind::grevlex:
      return "grevlex";
    case Kind::weighted: {
      std::ostringstream s;
      s << "weighted(";
      for (std::size_t i = 0; i < weights_.size(); ++i) s << (i ? "," : "") << weights_[i];
      s << ";" << first_->name() << ")";
      return s.str();
    }
    case Kind::block:
      return "block(" + std::to_string(first_block_size_) + ":" + first_->name() + "|" + rest_->name() + ")";
  }
  return "?";
}

std::string MonomialOrder::singular_name(std::size_t n) const {
  switch (kind_) {
    case Kind::lex:
      return "lp";
    case Kind::grlex:
      return "Dp";
    case Kind::grevlex:
      return "dp";
    case Kind::weighted: {
      std::ostringstream s;
      s << "(a(";
      for (std::size_t i = 0; i < weights_.size(); ++i) s << (i ? "," : "") << weights_[i];
      s << ")," << first_->singular_name(n) << ")";
      return s.str();
    }
    case Kind::block: {
      auto part = [](const MonomialOrder& o, std::size_t size) {
        std::string inner = o.singular_name(size);
        if (o.kind() == Kind::lex || o.kind() == Kind::grlex || o.kind() == Kind::grevlex) {
          return inner + "(" + std::to_string(size) + ")";
        }
        return inner;  // nested weighted/block orders: Singular needs explicit sizes; best effort
      };
      return "(" + part(*first_, first_block_size_) + "," + part(*rest_, n - first_block_size_) + ")";
    }
  }
  return "dp";
}

bool MonomialOrder::operator==(const MonomialOrder& other) const {
  if (kind_ != other.kind_ || weights_ != other.weights_ || first_block_size_ != other.first_block_size_) {
    return false;
  }
  auto same = [](const std::shared_ptr<const MonomialOrder>& a, const std::shared_ptr<const MonomialOrder>& b) {
    return (!a && !b) || (a && b && *a == *b);
  };
  return same(first_, other.first_) && same(rest_, other.rest_);
}

}  // namespace implicitizer
