#include "mpmice/app/CommandLine.h"

#include <iostream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"

namespace tephra::app {

int run_command_line(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: tephra DECK [options]\n";
    return static_cast<int>(ExitCode::BadCommandLine);
  }
  try {
    auto deck = load_deck(argv[1]);
    std::cout << "read " << deck->path << "\n";
  } catch (const TephraError& e) {
    std::cerr << "tephra: error: " << e.what() << "\n";
    return static_cast<int>(e.code());
  }
  return 0;
}

}  // namespace tephra::app
