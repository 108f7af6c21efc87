#pragma once
// Reads a .ups deck into a DeckNode tree, resolving <include href=...>.
//
// Include rule (Vaango decks use both forms): the href is looked up next to
// the including file first, then relative to each of its parent folders in
// turn (so "inputs/ICE/EOSData/X.xml" written in inputs/ICE/deck.ups resolves
// against an ancestor). The included file's root element (<Uintah_Include>)
// is replaced by its children, in place of the <include> element.
// Malformed XML, a missing include, or an include cycle is a DeckError.
#include <memory>
#include <string>
#include <vector>

#include "core/deck/DeckNode.h"

namespace tephra {

struct Deck {
  DeckNode root;                    // <Uintah_specification>
  std::string path;                 // the deck file as given
  std::vector<std::string> files;   // every file read, the deck first
};

// Loads and resolves includes. Throws DeckError (exit 1) on any failure.
std::unique_ptr<Deck> load_deck(const std::string& path);

// Loads from a string (tests); `name` stands in for the file name in messages
// and `base_dir` is where includes are resolved from.
std::unique_ptr<Deck> load_deck_from_string(const std::string& xml, const std::string& name,
                                            const std::string& base_dir);

// The resolved deck written back as XML (copied into the output directory).
std::string to_xml(const DeckNode& root);

}  // namespace tephra
