#include "vibrotherm/io/xdmf_index.hpp"

#include <iomanip>

namespace vibrotherm::io {
namespace {

const char* kHeader = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n";
const char* kFooter = "  </Domain>\n</Xdmf>\n";

void WriteDataItem(std::ostream& out, const std::string& pad, const char* type, PetscInt rows, PetscInt columns,
                   const std::string& data) {
  out << pad << "<DataItem Format=\"HDF\" DataType=\"" << type << "\""
      << (type[0] == 'F' ? " Precision=\"8\"" : "") << " Dimensions=\"" << rows << " " << columns << "\">" << data
      << "</DataItem>\n";
}

/// A uniform grid; `time` null: no <Time> (a static grid).
void WriteUniformGrid(std::ostream& out, const std::string& pad, const XdmfGrid& g, const double* time,
                      const std::vector<XdmfAttribute>& attributes) {
  out << pad << "<Grid Name=\"" << g.name << "\" GridType=\"Uniform\">\n";
  if (time) out << pad << "  <Time Value=\"" << *time << "\"/>\n";
  out << pad << "  <Topology TopologyType=\"" << g.topology_type << "\" NumberOfElements=\"" << g.cells << "\""
      << (g.topology_type == "Polyline" ? " NodesPerElement=\"2\"" : "") << ">\n";
  WriteDataItem(out, pad + "    ", "Int", g.cells, g.corners, g.topology);
  out << pad << "  </Topology>\n" << pad << "  <Geometry GeometryType=\"" << (g.dim == 3 ? "XYZ" : "XY") << "\">\n";
  WriteDataItem(out, pad + "    ", "Float", g.vertices, g.dim, g.geometry);
  out << pad << "  </Geometry>\n";
  for (const XdmfAttribute& a : attributes) {
    out << pad << "  <Attribute Name=\"" << a.name << "\" AttributeType=\"" << (a.components == 1 ? "Scalar" : "Vector")
        << "\" Center=\"" << (a.cell ? "Cell" : "Node") << "\">\n";
    WriteDataItem(out, pad + "    ", "Float", a.cell ? g.cells : g.vertices, a.components, a.data);
    out << pad << "  </Attribute>\n";
  }
  out << pad << "</Grid>\n";
}

}  // namespace

void WriteXdmfSeries(std::ostream& out, const XdmfGrid& grid, const std::vector<XdmfStep>& steps) {
  out << std::setprecision(12) << kHeader;
  out << "    <Grid Name=\"" << grid.name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfStep& step : steps) WriteUniformGrid(out, "      ", grid, &step.time, step.attributes);
  out << "    </Grid>\n" << kFooter;
}

void WriteXdmfCollection(std::ostream& out, const std::string& name, const std::vector<XdmfGrid>& grids) {
  out << kHeader << "    <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
  for (const XdmfGrid& g : grids) WriteUniformGrid(out, "      ", g, nullptr, {});
  out << "    </Grid>\n" << kFooter;
}

}  // namespace vibrotherm::io
