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
    deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
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
