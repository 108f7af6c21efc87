#pragma once
// Checks a whole loaded deck against Tephra's schema (core/deck/Schema.h)
// before the first step (DESIGN.md §8 "fail loudly and early"):
//   - every element and attribute is known (else: nearest valid name);
//   - REQUIRED elements/attributes are present, non-MULTIPLE ones at most once;
//   - element text and attribute values have the declared type (number,
//     integer, true/false, [x, y, z], lists) and lie in the declared range;
//   - strings with a fixed set of values hold one of them (else: nearest);
//   - need_applies_to: a child tied to values of its parent's attribute
//     (e.g. flow_model type="johnson_cook" -> A, B, C, n, m) is required for
//     those values and not allowed for others;
//   - ONE_OF / ALL_OR_NONE_OF groups of children or attributes.
// All problems are collected; one DeckError is thrown, located at the first
// problem (file, line, element path) and listing every problem.
#include <string>
#include <vector>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"

namespace tephra {

class Schema;

struct DeckProblem {
  SourceLocation where;
  std::string message;
};

// Throws DeckError if the deck does not conform to the built-in schema.
void validate_deck(const Deck& deck);

// The same against a given schema; returns the problems instead of throwing.
std::vector<DeckProblem> check_deck(const DeckNode& root, const Schema& schema);

// Levenshtein distance (for "did you mean" suggestions).
size_t edit_distance(const std::string& a, const std::string& b);
// The candidate nearest to `name` (empty if there is none).
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace tephra
