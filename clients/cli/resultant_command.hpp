#pragma once
/// \file
/// `implicitizer resultant`: arguments → ResultantRequest → answer_resultant_request().

#include <span>
#include <string>

namespace implicitizer::cli {

/// Runs the command on the words after `resultant`; returns the exit status.
int run_resultant_command(std::span<const std::string> args);

}  // namespace implicitizer::cli
