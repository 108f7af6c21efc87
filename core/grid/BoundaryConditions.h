#pragma once
// Boundary-condition descriptions read from <Grid><BoundaryConditions>:
//
//   <Face side="x-">                       (or circle/rectangle/annulus/ellipse)
//     <BCType id="all|0|1.." var="Dirichlet|Neumann|symmetry|..." label="Velocity|...">
//       <value> 0.0 </value>  or  <value> [0, 0, 0] </value>
//     </BCType>
//   </Face>
//
// This is a description only: the MPM and ICE components decide how to apply
// each entry (Neumann is a normal gradient, Dirichlet a value, symmetry a
// mirror; computeFromDensity derives the specific volume from rho).
#include <optional>
#include <string>
#include <vector>

#include "core/base/Errors.h"
#include "core/base/Types.h"

namespace tephra {

class DeckNode;

// Domain faces in Uintah's order: 0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+.
enum class GridFace : int { XMinus = 0, XPlus, YMinus, YPlus, ZMinus, ZPlus };
inline int face_axis(GridFace f) { return static_cast<int>(f) / 2; }
inline bool face_is_upper(GridFace f) { return static_cast<int>(f) % 2 == 1; }
const char* face_name(GridFace f);  // "x-", ...

// Which part of the face a <Face> covers. Side: the whole face; the others
// are regions on the face (geometry kept, applying them is up to the user).
enum class FaceRegion { Side, Circle, Rectangle, Annulus, Ellipse };

struct FaceRegionGeometry {
  FaceRegion kind = FaceRegion::Side;
  Vec3 origin = Vec3::Zero();        // circle, annulus, ellipse
  double radius = 0;                 // circle
  double inner_radius = 0, outer_radius = 0;  // annulus
  double major_radius = 0, minor_radius = 0, angle_deg = 0;  // ellipse
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();  // rectangle
  std::string name;                  // optional name="..."
};

// The `var` attribute. Kinds listed in Vaango's schema that Tephra cannot
// represent (file inputs, swirl, turbulent inlets, ...) are MissingFeature.
enum class BCKind { Dirichlet, Neumann, Symmetry, ComputeFromDensity, LODI, Sine, Creep, Slip, Custom };
const char* bc_kind_name(BCKind k);

constexpr int kAllMaterials = -1;

struct BoundaryCondition {
  GridFace face = GridFace::XMinus;
  FaceRegionGeometry region;
  int material = kAllMaterials;     // id="all" -> kAllMaterials, else the material index
  BCKind kind = BCKind::Dirichlet;
  std::string label;                // Velocity, Pressure, Temperature, Density, SpecificVol, Symmetric, ...
  bool has_value = false;
  bool is_vector = false;           // Velocity (and any [a,b,c] value) -> vector
  double scalar = 0;                // when has_value && !is_vector
  Vec3 vector = Vec3::Zero();       // when has_value && is_vector
  SourceLocation where;             // the <BCType> element
};

// <LODI>, <SINE_BC> and <microSlip> blocks: parameters kept for the ICE
// component that implements them.
struct LodiParameters {
  double press_infinity = 0, sigma = 0;
  std::optional<double> li_scale;
  std::string material;
  SourceLocation where;
};
struct SineParameters {
  double omega = 0, amplitude = 0, reference_pressure = 0;
  Vec3 reference_velocity = Vec3::Zero();
  SourceLocation where;
};
struct MicroSlipParameters {
  double alpha_momentum = 0, alpha_temperature = 0;
  SourceLocation where;
};

class BoundaryConditions {
 public:
  std::vector<BoundaryCondition> list;  // in deck order
  std::optional<LodiParameters> lodi;
  std::optional<SineParameters> sine;
  std::optional<MicroSlipParameters> micro_slip;

  // The whole-face (Side) condition for (face, material, label): an entry with
  // that exact material id wins over id="all". nullptr when none.
  const BoundaryCondition* find(GridFace face, int material, const std::string& label) const;
  // Every entry on a face for a material (its own id or "all"), any region.
  std::vector<const BoundaryCondition*> on_face(GridFace face, int material) const;
  bool empty() const { return list.empty(); }
};

// Reads <Grid><BoundaryConditions>; an absent block gives an empty set.
// DeckError for a bad side, id, var or value; MissingFeature for var kinds
// Tephra cannot represent.
BoundaryConditions parse_boundary_conditions(const DeckNode& grid_section);

}  // namespace tephra
