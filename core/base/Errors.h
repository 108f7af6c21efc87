#pragma once
// Errors and the process exit codes they map to (docs/input.md):
//   0 success, 1 invalid deck, 2 bad command line,
//   3 valid deck that needs a feature Tephra does not have yet,
//   4 a run stopped on a numerical failure.
#include <stdexcept>
#include <string>

namespace tephra {

enum class ExitCode : int {
  Success = 0,
  InvalidDeck = 1,
  BadCommandLine = 2,
  MissingFeature = 3,
  NumericalFailure = 4,
};

// Where in the input an error comes from: the file, the 1-based line and the
// element path (e.g. "Grid/Level/Box/resolution").
struct SourceLocation {
  std::string file;
  int line = 0;
  std::string element;
  std::string str() const;  // "file:line: <element>"
};

class TephraError : public std::runtime_error {
 public:
  TephraError(ExitCode code, const std::string& what) : std::runtime_error(what), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// Exit 1: the deck is malformed or invalid. The message names file:line and element.
class DeckError : public TephraError {
 public:
  DeckError(const SourceLocation& where, const std::string& message);
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

// Exit 3: the deck is valid but asks for something Tephra does not have yet.
class MissingFeature : public TephraError {
 public:
  MissingFeature(const SourceLocation& where, const std::string& feature);
};

// Exit 2: the command line is wrong.
class UsageError : public TephraError {
 public:
  explicit UsageError(const std::string& message) : TephraError(ExitCode::BadCommandLine, message) {}
};

// Exit 4: a run stopped on a numerical failure (NaN, dt < delt_min, negative J, ...).
class NumericalFailure : public TephraError {
 public:
  explicit NumericalFailure(const std::string& message)
      : TephraError(ExitCode::NumericalFailure, message) {}
};

// Any other failure (I/O, corrupt checkpoint): exit 1 with the message.
class RuntimeFailure : public TephraError {
 public:
  explicit RuntimeFailure(const std::string& message) : TephraError(ExitCode::InvalidDeck, message) {}
};

}  // namespace tephra
