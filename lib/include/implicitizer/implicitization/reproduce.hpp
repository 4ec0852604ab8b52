#pragma once
/// \file
/// Scripts that recompute an implicitization in Singular and in Macaulay2, so that a
/// mathematician can check an answer with a system nobody here wrote.

#include <string>

#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer {

/// A Singular script that builds the same ideal and prints the generators of its
/// elimination ideal (`eliminate`), one per line.
std::string singular_script(const Parametrization& parametrization);

/// A Macaulay2 script that builds the same ideal and prints the generators of its
/// elimination ideal (`eliminate`).
std::string macaulay2_script(const Parametrization& parametrization);

/// Both scripts.
struct ReproduceScripts {
  std::string singular;   ///< singular_script()
  std::string macaulay2;  ///< macaulay2_script()
};

/// Both scripts from one printing of the ideal (what every answer carries; one
/// printing instead of the two of singular_script() and macaulay2_script()).
ReproduceScripts reproduce_scripts(const Parametrization& parametrization);

}  // namespace implicitizer
