#include "implicitizer/core/errors.hpp"

namespace implicitizer {

const char* to_string(Limit limit) {
  switch (limit) {
    case Limit::time:
      return "time";
    case Limit::size:
      return "size";
    case Limit::memory:
      return "memory";
    case Limit::work:
      return "work";
    case Limit::cancelled:
      return "cancelled";
  }
  return "unknown";
}

}  // namespace implicitizer
