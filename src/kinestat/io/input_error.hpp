// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one error type for bad input: every message names file, line and column so that a
// user can jump straight to the problem (`file:line:column: what was expected`).

#include <string>

#include "kinestat/error.hpp"

namespace kinestat::io {

using kinestat::SourceLocation;

/// Thrown by readers for malformed or inconsistent input. `what()` is the full one-line
/// message `file:line:column: error: <problem>`; the CLI prints it and exits with code 2.
class InputError : public Error {
 public:
  InputError(SourceLocation where, const std::string& problem);
  const std::string& problem() const { return problem_; }

 private:
  std::string problem_;
};

}  // namespace kinestat::io
