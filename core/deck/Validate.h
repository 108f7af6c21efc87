#pragma once
// Schema validation of a whole deck (implemented with the deck schema).
#include "core/deck/DeckLoader.h"

namespace tephra {

// Throws DeckError at the first element that the schema does not allow.
void validate_deck(const Deck& deck);

}  // namespace tephra
