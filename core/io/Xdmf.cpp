#include "core/io/Xdmf.h"

#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

namespace tephra {
namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// XDMF attribute types by component count: Tensor is the full 3x3 (9 values,
// row-major), Vector 3, Scalar 1.
const char* attribute_type(int components) {
  return components == 9 ? "Tensor" : components == 3 ? "Vector" : "Scalar";
}

// Dimensions are listed slowest first (k j i), the order of the HDF5 arrays.
std::string dims_kji(const IntVec3& n) {
  return std::to_string(n[2]) + " " + std::to_string(n[1]) + " " + std::to_string(n[0]);
}

void data_item(std::ostringstream& x, const std::string& dims, const char* number_type,
               const std::string& ref, const std::string& indent) {
  x << indent << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << number_type
    << "\" Precision=\"8\" Format=\"HDF\">" << escape(ref) << "</DataItem>\n";
}

// A structured mesh of `cells` cells whose first cell has index `first`.
struct Mesh {
  IntVec3 first;
  IntVec3 cells;
  IntVec3 face_shift = IntVec3::Zero();  // face fields: a mesh moved by -dx/2 along their axis
  std::vector<const SavedGridField*> fields;
};

// "grid" for the interior, "grid_with_extra_cells" for interior plus extra
// cells, else "grid_from_i_j_k" after the first cell.
std::string mesh_name(const Mesh& m, const Grid& g) {
  if (m.first == IntVec3::Zero() && m.cells == g.cells) return "grid";
  if (m.first == -g.extra_cells && m.cells == g.cells + 2 * g.extra_cells)
    return "grid_with_extra_cells";
  const std::string faces = m.face_shift[0] ? "x_faces_" : m.face_shift[1] ? "y_faces_" : m.face_shift[2] ? "z_faces_" : "";
  if (!faces.empty() && m.first == IntVec3::Zero()) return "grid_" + faces.substr(0, faces.size() - 1);
  return "grid_" + faces + "from_" + std::to_string(m.first[0]) + "_" + std::to_string(m.first[1]) + "_" +
         std::to_string(m.first[2]);
}

}  // namespace

namespace {

// The meshes and particle grids of one file's layout, inside a Spatial
// collection. `prefix` names the grids of one rank file ("r1_"); a rank file's
// pieces carry their dataset path (SavedGridField::dataset) and the empty
// interior mesh is left out for them.
void frame_content(std::ostringstream& x, const SavedFrame& f, const std::string& h5, const std::string& prefix) {
  const bool pieces = !prefix.empty();
  if (f.has_grid) {
    // Cell fields of extent n and node fields of extent n+1 live on the same
    // mesh of n cells; fields that include the extra cells get a second mesh.
    // A face field (n + 1 values along its axis) is cell data on a mesh of
    // n + 1 cells moved by -dx/2 along that axis: its cells are centred on the faces.
    std::map<std::tuple<int, int, int, int, int, int, int>, Mesh> meshes;
    auto key = [](const IntVec3& a, const IntVec3& b, int face_axis) {
      return std::make_tuple(a[0], a[1], a[2], b[0], b[1], b[2], face_axis);
    };
    meshes[key(IntVec3::Zero(), f.grid.cells, -1)] = Mesh{IntVec3::Zero(), f.grid.cells, IntVec3::Zero(), {}};
    for (const SavedGridField& g : f.grid_fields) {
      const bool node = g.field.location == GridLocation::Node;
      const IntVec3 shift = node ? IntVec3(IntVec3::Zero()) : location_stagger(g.field.location);
      const IntVec3 cells = node ? IntVec3(g.extent - IntVec3::Ones()) : g.extent;
      int axis = -1;
      for (int d = 0; d < 3; ++d)
        if (shift[d]) axis = d;
      auto& m = meshes[key(g.first_index, cells, axis)];
      m.first = g.first_index;
      m.cells = cells;
      m.face_shift = shift;
      m.fields.push_back(&g);
    }
    // The interior mesh first, then any other (in key order).
    std::vector<const Mesh*> order;
    for (const auto& [k, m] : meshes)
      if (m.first == IntVec3::Zero() && m.cells == f.grid.cells && m.face_shift == IntVec3::Zero()) {
        if (!pieces || !m.fields.empty()) order.insert(order.begin(), &m);
      }
      else if (!m.fields.empty()) order.push_back(&m);
    for (const Mesh* mp : order) {
      const Mesh& m = *mp;
      const Vec3 origin = f.grid.lower + f.grid.dx.cwiseProduct(m.first.cast<double>()) -
                          0.5 * f.grid.dx.cwiseProduct(m.face_shift.cast<double>());
      x << "        <Grid Name=\"" << prefix << mesh_name(m, f.grid) << "\" GridType=\"Uniform\">\n"
        << "          <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\""
        << dims_kji(m.cells + IntVec3::Ones()) << "\"/>\n"
        // ORIGIN_DXDYDZ lists origin and spacing slowest direction first
        // (z y x), like Dimensions.
        << "          <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
        << "            <DataItem Name=\"Origin\" Dimensions=\"3\" NumberType=\"Float\" "
           "Precision=\"8\" Format=\"XML\">"
        << num(origin[2]) << " " << num(origin[1]) << " " << num(origin[0]) << "</DataItem>\n"
        << "            <DataItem Name=\"Spacing\" Dimensions=\"3\" NumberType=\"Float\" "
           "Precision=\"8\" Format=\"XML\">"
        << num(f.grid.dx[2]) << " " << num(f.grid.dx[1]) << " " << num(f.grid.dx[0])
        << "</DataItem>\n"
        << "          </Geometry>\n";
      for (const SavedGridField* g : m.fields) {
        const FieldArray& d = g->field.data;
        std::string dims = dims_kji(g->extent);
        if (d.components > 1) dims += " " + std::to_string(d.components);
        x << "          <Attribute Name=\"" << escape(d.label) << "_mat" << d.material
          << "\" AttributeType=\"" << attribute_type(d.components) << "\" Center=\""
          << (g->field.location == GridLocation::Node ? "Node" : "Cell") << "\">\n";  // faces: cells of the moved mesh
        const std::string set =
            g->dataset.empty() ? "/grid/mat" + std::to_string(d.material) + "/" + d.label : g->dataset;
        data_item(x, dims, "Float", h5 + ":" + set, "            ");
        x << "          </Attribute>\n";
      }
      x << "        </Grid>\n";
    }
  }
  for (const SavedParticles& p : f.particles) {
    // A Polyvertex grid of zero points trips some readers: empty sets are
    // kept in the .h5 file but left out of the index.
    if (p.count == 0) continue;
    const std::string n = std::to_string(p.count);
    const std::string base = h5 + ":/particles/mat" + std::to_string(p.block.material) + "/";
    x << "        <Grid Name=\"" << prefix << "particles_mat" << p.block.material << "\" GridType=\"Uniform\">\n"
      << "          <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\"/>\n"
      << "          <Geometry GeometryType=\"XYZ\">\n";
    data_item(x, n + " 3", "Float", base + "position", "            ");
    x << "          </Geometry>\n"
      << "          <Attribute Name=\"particleID\" AttributeType=\"Scalar\" Center=\"Node\">\n";
    data_item(x, n, "Int", base + "particleID", "            ");
    x << "          </Attribute>\n";
    for (const FieldArray& d : p.block.fields) {
      std::string dims = n;
      if (d.components > 1) dims += " " + std::to_string(d.components);
      x << "          <Attribute Name=\"" << escape(d.label) << "\" AttributeType=\""
        << attribute_type(d.components) << "\" Center=\"Node\">\n";
      data_item(x, dims, "Float", base + d.label, "            ");
      x << "          </Attribute>\n";
    }
    x << "        </Grid>\n";
  }
}

void open_frame(std::ostringstream& x, int step, double time) {
  x << "      <Grid Name=\"step_" << step << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
    << "        <Time Value=\"" << num(time) << "\"/>\n";
}

}  // namespace

std::string xdmf_frame_grid(const SavedFrame& f, const std::string& h5) {
  std::ostringstream x;
  open_frame(x, f.step, f.time);
  frame_content(x, f, h5, "");
  x << "      </Grid>\n";
  return x.str();
}

std::string xdmf_rank_frame_grid(const std::vector<std::pair<SavedFrame, std::string>>& ranks) {
  std::ostringstream x;
  if (ranks.empty()) return "";
  open_frame(x, ranks.front().first.step, ranks.front().first.time);
  for (std::size_t r = 0; r < ranks.size(); ++r)
    frame_content(x, ranks[r].first, ranks[r].second, "r" + std::to_string(r) + "_");
  x << "      </Grid>\n";
  return x.str();
}

std::string xdmf_document(const std::vector<std::string>& frame_grids) {
  std::string out =
      "<?xml version=\"1.0\" ?>\n"
      "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      "<Xdmf Version=\"3.0\">\n"
      "  <Domain>\n"
      "    <Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const std::string& g : frame_grids) out += g;
  out +=
      "    </Grid>\n"
      "  </Domain>\n"
      "</Xdmf>\n";
  return out;
}

}  // namespace tephra
