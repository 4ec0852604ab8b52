#pragma once
// Shared by the service and codec tests.

#include <gtest/gtest.h>

#include "implicitizer/core/errors.hpp"

namespace implicitizer::testing {

// The InputError `f` throws; fails the test when it throws nothing.
template <class F>
InputError input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("none", "none");
}

}  // namespace implicitizer::testing
