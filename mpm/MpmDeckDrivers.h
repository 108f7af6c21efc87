#pragma once
// The parts of make_mpm_component (MpmDeck.cpp) that read the MPM loads and
// drivers: <PhysicalBC><MPM> loads (mpm/loads/), <use_prescribed_deformation>
// (mpm/PrescribedDeformation.h), whether AccStrainEnergy is saved
// (mpm/StrainWork.h), and the checks of <axisymmetric> (mpm/Axisymmetric.h)
// and <periodic> (mpm/PeriodicGrid.h) against the other options. Throws
// DeckError / MissingFeature.
namespace tephra {

struct Deck;
struct MpmSetup;

// After setup.grid and setup.flags are read.
void read_loads_and_drivers(const Deck& deck, MpmSetup& setup);
// After the materials and contact are read: combinations not implemented.
void check_driver_combinations(const Deck& deck, MpmSetup& setup);

}  // namespace tephra
