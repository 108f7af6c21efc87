#include "core/base/Errors.h"

namespace tephra {

std::string SourceLocation::str() const {
  std::string s = file.empty() ? std::string("<deck>") : file;
  if (line > 0) s += ":" + std::to_string(line);
  if (!element.empty()) s += ": <" + element + ">";
  return s;
}

DeckError::DeckError(const SourceLocation& where, const std::string& message)
    : TephraError(ExitCode::InvalidDeck, where.str() + ": " + message), where_(where) {}

MissingFeature::MissingFeature(const SourceLocation& where, const std::string& feature)
    : TephraError(ExitCode::MissingFeature,
                  where.str() + ": valid input, but Tephra does not have this feature yet: " + feature) {}

}  // namespace tephra
