#include "implicitizer/core/budget.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace implicitizer {

Budget::Budget() : shared_(std::make_shared<Shared>()) {}

Budget Budget::with_timeout(double seconds) {
  Budget b;
  b.set_timeout(seconds);
  return b;
}

Budget& Budget::set_timeout(double seconds) {
  has_deadline_ = seconds > 0;
  timeout_seconds_ = has_deadline_ ? seconds : 0;
  if (has_deadline_) {
    // Converting more seconds than Clock::duration holds (about 292 years of
    // nanoseconds) is undefined and in practice wraps into the past, so a huge or
    // infinite timeout would fire at once. Such a deadline saturates at the end of
    // time; half the room left keeps the double's rounding well clear of overflow.
    const Clock::time_point now = Clock::now();
    const std::chrono::duration<double> wanted(seconds);
    deadline_ = wanted < (Clock::time_point::max() - now) / 2
                    ? now + std::chrono::duration_cast<Clock::duration>(wanted)
                    : Clock::time_point::max();
  }
  return *this;
}

Budget& Budget::set_max_terms(std::size_t terms) {
  max_terms_ = terms;
  return *this;
}

Budget& Budget::set_max_memory(std::size_t bytes) {
  memory_ = bytes == 0 ? nullptr : std::make_shared<MemoryAccount>(bytes);
  return *this;
}

Budget& Budget::set_max_work(std::uint64_t units) {
  max_work_ = units;
  work_ = units == 0 ? nullptr : std::make_shared<std::atomic<std::uint64_t>>(0);
  return *this;
}

void Budget::charge_work(std::uint64_t units, const char* where) const {
  if (!work_) return;
  const std::uint64_t done = work_->fetch_add(units, std::memory_order_relaxed) + units;
  if (done > max_work_) {
    std::ostringstream msg;
    msg << "work allowance of " << max_work_ << " units spent during " << located(where);
    throw LimitExceeded(Limit::work, msg.str());
  }
}

Budget& Budget::set_max_variables(std::size_t variables) {
  max_variables_ = variables;
  return *this;
}

Budget& Budget::set_max_polynomials(std::size_t polynomials) {
  max_polynomials_ = polynomials;
  return *this;
}

namespace {

[[noreturn]] void throw_count_limit(std::size_t count, const char* unit, const char* what, std::size_t limit) {
  std::ostringstream msg;
  msg << what << " has " << count << " " << unit << "; the limit is " << limit;
  throw LimitExceeded(Limit::size, msg.str());
}

constexpr double kMiB = 1024.0 * 1024.0;

[[noreturn]] void throw_memory_limit(const MemoryAccount& account, const std::string& where) {
  std::ostringstream msg;
  msg.precision(3);
  msg << "memory limit of " << static_cast<double>(account.limit_bytes()) / kMiB << " MiB exceeded during " << where
      << " (the computation held " << static_cast<double>(account.peak_bytes()) / kMiB << " MiB)";
  throw LimitExceeded(Limit::memory, msg.str());
}

}  // namespace

std::string Budget::located(const char* where) const {
  return phase_ ? std::string(where) + " in " + phase_ : std::string(where);
}

Budget Budget::in_phase(const char* phase) const {
  Budget copy = *this;
  copy.phase_ = phase;
  return copy;
}

void Budget::rethrow_bad_alloc(const char* where) const {
  if (memory_ && memory_->exceeded()) throw_memory_limit(*memory_, located(where));
  throw;
}

void Budget::check_variables(std::size_t count, const char* what) const {
  if (max_variables_ != 0 && count > max_variables_) throw_count_limit(count, "variables", what, max_variables_);
}

void Budget::check_polynomials(std::size_t count, const char* what) const {
  if (max_polynomials_ != 0 && count > max_polynomials_) {
    throw_count_limit(count, "polynomials", what, max_polynomials_);
  }
}

void Budget::check(const char* where) const {
  if (is_cancelled()) {
    throw LimitExceeded(Limit::cancelled, "computation cancelled during " + located(where));
  }
  if (memory_ && memory_->exceeded()) throw_memory_limit(*memory_, located(where));
  if (has_deadline_ && Clock::now() > deadline_) {
    std::ostringstream msg;
    msg << "time limit of " << timeout_seconds_ << " s exceeded during " << located(where);
    throw LimitExceeded(Limit::time, msg.str());
  }
}

void Budget::check_terms(std::size_t terms, const char* where) const {
  if (max_terms_ != 0 && terms > max_terms_) {
    std::ostringstream msg;
    msg << "size limit exceeded during " << located(where) << ": a polynomial reached " << terms << " terms (limit "
        << max_terms_ << ")";
    throw LimitExceeded(Limit::size, msg.str());
  }
  check(where);
}

void Budget::throw_predicted_terms(std::size_t terms, const char* where, const std::string& what) const {
  std::ostringstream msg;
  msg << "size limit exceeded during " << located(where) << ": " << what << " would have " << terms << " terms (limit "
      << max_terms_ << "); refused before it was built";
  throw LimitExceeded(Limit::size, msg.str());
}

double Budget::seconds_left() const {
  if (!has_deadline_) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(deadline_ - Clock::now()).count();
}

void Budget::refuse_past_deadline(double predicted_seconds, const char* where, const std::string& what) const {
  const double left = seconds_left();
  if (predicted_seconds <= left) return;
  std::ostringstream msg;
  msg.precision(2);
  msg << "time limit of " << timeout_seconds_ << " s exceeded during " << located(where) << ": " << what
      << " would take about " << predicted_seconds << " s and " << std::max(0.0, left) << " s are left";
  throw LimitExceeded(Limit::time, msg.str());
}

}  // namespace implicitizer
