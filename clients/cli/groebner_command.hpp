#pragma once
/// \file
/// `implicitizer groebner`: arguments → GroebnerRequest → answer_groebner_request().

#include <span>
#include <string>

namespace implicitizer::cli {

/// Runs the command on the words after `groebner`; returns the exit status.
int run_groebner_command(std::span<const std::string> args);

}  // namespace implicitizer::cli
