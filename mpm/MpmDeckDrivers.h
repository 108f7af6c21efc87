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

// <initialize_stress_using_body_force> and the materials' <initialize_with_body_force>:
// warnings when one is set without the other (no effect, as in Vaango), MissingFeature
// with a rotating frame, MMS or a prescribed deformation (mpm/loads/BodyForceStress.h).
void check_body_force_stress(const Deck& deck, MpmSetup& setup);

}  // namespace tephra
