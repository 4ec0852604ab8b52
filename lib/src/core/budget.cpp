#include "implicitizer/core/budget.hpp"

#include <limits>
#include <sstream>

namespace implicitizer {

Budget::Budget() : cancelled_(std::make_shared<std::atomic<bool>>(false)) {}

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

void Budget::check(const char* where) const {
  if (is_cancelled()) {
    throw LimitExceeded(Limit::cancelled, std::string("computation cancelled during ") + where);
  }
  if (has_deadline_ && Clock::now() > deadline_) {
    std::ostringstream msg;
    msg << "time limit of " << timeout_seconds_ << " s exceeded during " << where;
    throw LimitExceeded(Limit::time, msg.str());
  }
}

void Budget::check_terms(std::size_t terms, const char* where) const {
  if (max_terms_ != 0 && terms > max_terms_) {
    std::ostringstream msg;
    msg << "size limit exceeded during " << where << ": a polynomial reached " << terms << " terms (limit "
        << max_terms_ << ")";
    throw LimitExceeded(Limit::size, msg.str());
  }
  check(where);
}

double Budget::seconds_left() const {
  if (!has_deadline_) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(deadline_ - Clock::now()).count();
}

}  // namespace implicitizer
