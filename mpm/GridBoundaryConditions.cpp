#include "mpm/GridBoundaryConditions.h"

#include <algorithm>

#include <string>

#include "core/deck/DeckNode.h"
#include "mpm/FaceMirrorPairs.h"

namespace tephra {

namespace {

int face_index(const DeckNode& face) {
  const std::string side = face.require_attribute("side");
  static const char* names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  for (int f = 0; f < 6; ++f)
    if (side == names[f]) return f;
  face.fail("Face side '" + side + "' is not one of x-, x+, y-, y+, z-, z+");
}

// Labels that only ICE reads; the MPM component leaves them to ICE.
bool ice_only_label(const std::string& label) {
  return label == "Pressure" || label == "Density" || label == "SpecificVol";
}

}  // namespace

GridBoundaryConditions parse_grid_boundary_conditions(const DeckNode* bcs, int material) {
  GridBoundaryConditions out;
  if (!bcs) return out;
  for (const DeckNode& face : bcs->children) {
    if (face.name != "Face") face.fail("unknown element <" + face.name + "> in <BoundaryConditions>");
    if (!face.attribute("side")) {
      // Vaango also accepts circle/rectangle/annulus patches of a face.
      face.missing_feature("boundary conditions on part of a face (circle, rectangle, annulus)");
    }
    const int f = face_index(face);
    for (const DeckNode& bc : face.children) {
      if (bc.name != "BCType") bc.fail("unknown element <" + bc.name + "> in <Face>");
      const std::string id = bc.require_attribute("id");
      const std::string var = bc.require_attribute("var");
      const std::string label = bc.require_attribute("label");
      if (id != "all") {
        const auto mid = parse_integer(id);
        if (!mid) bc.fail("BCType id must be 'all' or a material index, not '" + id + "'");
        if (*mid != material) continue;
      }
      if (ice_only_label(label)) continue;
      if (label == "Velocity" && var == "Dirichlet") {
        out.face[f].kind = FaceVelocityBC::Kind::Velocity;
        out.face[f].value = bc.get_vec3("value");
      } else if (label == "Velocity" && var == "Neumann" && bc.get_vec3("value").isZero()) {
        // Zero gradient (the MPMICE decks' open faces): a free face for the
        // grid, nothing to impose (Vaango's MPM applies only Dirichlet/symmetry).
      } else if (label == "Temperature" && var == "Dirichlet") {
        out.temperature[f] = bc.get_double("value");
      } else if (label == "Temperature" && var == "Neumann" && bc.get_double("value") == 0.0) {
        // Zero heat flux: the natural condition of the conduction (nothing to do).
      } else if (label == "Symmetric" && var == "symmetry") {
        out.face[f].kind = FaceVelocityBC::Kind::Symmetry;
      } else if (label == "Symmetric" || var == "symmetry") {
        bc.fail("a symmetry condition is written var=\"symmetry\" label=\"Symmetric\"");
      } else {
        bc.missing_feature("MPM boundary condition var=\"" + var + "\" label=\"" + label + "\"");
      }
    }
  }
  return out;
}

void GridBoundaryConditions::apply(const NodeGrid& g, std::vector<Vec3>& velocity) const {
  // Visits every node of face f (direction d = f/2): the node plane on the
  // domain face (index extra_d or n_d - 1 - extra_d), over the domain's nodes
  // in the other two directions. As Vaango (Patch::FaceNodes: the face nodes
  // of the patch without its extra cells), the nodes of the extra cells are
  // left free. Only the nodes of the active box (NodeGrid::active_box: the
  // whole grid in one process; on ranks closed under the mirror pairs).
  //
  // Threads: the rows (jb) of one face are shared among the threads of the
  // parallel region below (orphaned `omp for`). Within a face every node is
  // written once and read nowhere else in that face's visit, so a face's
  // nodes may be set in any order or at once; the faces keep their order
  // (the loops' barriers) where a later face reads or overwrites what an
  // earlier one set (velocity faces, the extra-node mirrors). The same bits
  // for any thread count.
  const NodeBox box = g.active_box();
  if (box.empty()) return;
  auto for_face = [&](int f, bool wait, auto&& fn) {
    const int d = f / 2;
    const int plane = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    const bool on = plane >= box.lo[d] && plane < box.hi[d];
    const int jb0 = std::max(g.extra[b], box.lo[b]), jb1 = on ? std::min(g.n[b] - g.extra[b], box.hi[b]) : jb0;
    const int ja0 = std::max(g.extra[a], box.lo[a]), ja1 = std::min(g.n[a] - g.extra[a], box.hi[a]);
    auto row = [&](int jb) {
      IntVec3 c;
      c[d] = plane;
      c[b] = jb;
      for (int ja = ja0; ja < ja1; ++ja) {
        c[a] = ja;
        fn(velocity[g.index(c)], d);
      }
    };
    if (wait) {
#pragma omp for schedule(static)
      for (int jb = jb0; jb < jb1; ++jb) row(jb);
    } else {
#pragma omp for schedule(static) nowait
      for (int jb = jb0; jb < jb1; ++jb) row(jb);
    }
  };
  // Visits the extra-node planes of face f over all nodes of the other two
  // directions: fn(v_extra, v_mirror, d) with the mirror node across the face
  // (the extra nodes lie beyond the face plane, their mirrors inside: no node
  // of one face's visit is both written and read).
  // wait = false: no barrier after the face (the low face of a symmetry
  // direction before its high face, below).
  auto for_extra = [&](int f, auto&& fn, bool wait = true) {
    for_face_mirror_pairs(g, f, [&](std::size_t e, std::size_t m, int d) { fn(velocity[e], velocity[m], d); }, wait);
  };
  // Nodes the faces visit (the threading threshold).
  long visits = 0;
  for (int f = 0; f < 6; ++f)
    if (face[f].kind != FaceVelocityBC::Kind::None) {
      const int d = f / 2;
      const long plane = long(box.hi[(d + 1) % 3] - box.lo[(d + 1) % 3]) * (box.hi[(d + 2) % 3] - box.lo[(d + 2) % 3]);
      visits += plane * (1 + (set_extra_nodes ? g.extra[d] : 0));
    }
  if (visits == 0) return;
#pragma omp parallel if (visits >= 4096)
  {
    for (int f = 0; f < 6; ++f)
      if (face[f].kind == FaceVelocityBC::Kind::Velocity) {
        for_face(f, true, [&](Vec3& v, int) { v = face[f].value; });
        if (set_extra_nodes) for_extra(f, [&](Vec3& v, const Vec3&, int) { v = face[f].value; });
      }
    // Symmetry: first v_n = 0 on the face nodes of every symmetry face, then
    // the extra nodes as mirrors. In that order, a mirror copies face nodes of
    // the other faces that already hold their own condition: the extra node
    // (x = -h, y = 0) beyond x- copies (x = +h, y = 0) after the y- face set its
    // v_y = 0. (Face by face, the x- mirror copied v_y of that node before the
    // y- face zeroed it, so the extra nodes along the edge kept the free
    // node's normal velocity: a spurious axial motion of the first particle
    // column at the axis of axisymmetric 3rdorderBS runs, h-independent;
    // docs/mpm-convergence.md "Axisymmetric 3rdorderBS".)
    // The zeros of the faces need no order among themselves (face f zeroes
    // component f/2 only; the two faces of one direction are different node
    // planes unless the domain has no cell in that direction, then a barrier):
    // no barrier between them, one after the last.
    for (int f = 0; f < 6; ++f)
      if (face[f].kind == FaceVelocityBC::Kind::Symmetry)
        for_face(f, g.n[f / 2] - 1 - 2 * g.extra[f / 2] <= 0, [&](Vec3& v, int d) { v[d] = 0.0; });
#pragma omp barrier
    // The mirrors face by face, except that the low face of a direction needs
    // no barrier before its high face when both are symmetry faces and the
    // direction has more than 4 extra + 1 node planes: the low face writes
    // planes [0, extra) from (extra, 2 extra], the high face (n - 1 - extra, n)
    // from [n - 1 - 2 extra, n - 1 - extra): disjoint. Between directions the
    // barrier stays (an edge's extra node copies one a direction before wrote).
    if (set_extra_nodes)
      for (int f = 0; f < 6; ++f)
        if (face[f].kind == FaceVelocityBC::Kind::Symmetry) {
          const int d = f / 2;
          const bool pair_follows =
              f % 2 == 0 && face[f + 1].kind == FaceVelocityBC::Kind::Symmetry && mirror_faces_disjoint(g, d);
          for_extra(
              f,
              [&](Vec3& v, const Vec3& mirror, int dd) {
                v = mirror;
                v[dd] = -mirror[dd];
              },
              !pair_follows);
        }
  }
}

}  // namespace tephra
