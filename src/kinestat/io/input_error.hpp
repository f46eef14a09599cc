#pragma once
// The one error type for bad input: every message names file, line and column so that a
// user can jump straight to the problem (`file:line:column: what was expected`).

#include <stdexcept>
#include <string>

namespace kinestat::io {

/// A position in an input file. Lines and columns are 1-based; 0 means "unknown".
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// Thrown by readers for malformed or inconsistent input. `what()` is the full one-line
/// message `file:line:column: error: <problem>`; the CLI prints it and exits with code 2.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& problem);
  const SourceLocation& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  SourceLocation where_;
  std::string problem_;
};

}  // namespace kinestat::io
