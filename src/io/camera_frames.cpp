#include "vibrotherm/io/camera_frames.hpp"

#include <filesystem>
#include <iomanip>
#include <stdexcept>

#include "vibrotherm/store/atomic_file.hpp"

namespace vibrotherm::io {
namespace {

void Check(herr_t status, const std::string& path, const std::string& what) {
  if (status < 0) throw std::runtime_error(path + ": cannot write " + what + " (HDF5)");
}

void WriteStringAttribute(hid_t object, const char* name, const std::string& value, const std::string& path) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.size());
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, type, value.c_str());
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  Check(status, path, std::string("the attribute ") + name);
}

void WriteRealAttribute(hid_t object, const std::string& name, const std::vector<double>& values,
                        const std::string& path) {
  const hsize_t n = values.size();
  const hid_t space = n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr);
  const hid_t attr = H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, values.data());
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  Check(status, path, "the attribute " + name);
}

}  // namespace

CameraFrames::~CameraFrames() {
  if (group_ >= 0) H5Gclose(group_);
  if (file_ >= 0) H5Fclose(file_);  // left as .partial: never looks complete
}

void CameraFrames::Open(const std::string& h5_path, const CameraGrid& grid,
                        const std::map<std::string, double>& attributes) {
  path_ = h5_path;
  grid_ = grid;
  file_ = H5Fcreate(store::AtomicFile::partial_name(h5_path).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error(h5_path + ": cannot create the file");
  group_ = H5Gcreate2(file_, "camera", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (group_ < 0) throw std::runtime_error(h5_path + ": cannot create the group /camera");
  for (const auto& [name, value] : attributes) WriteRealAttribute(group_, name, {value}, path_);
  const double x1 = grid.x0 + grid.pixel * grid.cols, y1 = grid.y0 + grid.pixel * grid.rows;
  WriteRealAttribute(group_, "window", {grid.x0, grid.y0, x1, y1}, path_);
  std::vector<double> x(grid.cols), y(grid.rows);
  for (std::size_t j = 0; j < grid.cols; ++j) x[j] = grid.x0 + (j + 0.5) * grid.pixel;
  for (std::size_t i = 0; i < grid.rows; ++i) y[i] = grid.y0 + (i + 0.5) * grid.pixel;
  WriteArray("x", x, grid.cols, 1, "m", {});
  WriteArray("y", y, grid.rows, 1, "m", {});
  Flush();
}

void CameraFrames::Flush() {
  // On disk as written: a run killed between two frames leaves a file a restart can reopen.
  if (file_ >= 0 && H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error(path_ + ": cannot flush the file");
}

void CameraFrames::WriteArray(const std::string& name, const std::vector<double>& values, std::size_t rows,
                              std::size_t cols, const std::string& units,
                              const std::map<std::string, double>& attributes) {
  const hsize_t dims[2] = {rows, cols};
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  const hid_t dataset = H5Dcreate2(group_, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT,
                                   H5P_DEFAULT);
  herr_t status = dataset < 0 ? -1 : 0;
  if (status >= 0 && !values.empty())
    status = H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Sclose(space);
  if (status < 0) {
    if (dataset >= 0) H5Dclose(dataset);
    throw std::runtime_error(path_ + ": cannot write dataset /camera/" + name + " (HDF5)");
  }
  WriteStringAttribute(dataset, "units", units, path_);
  for (const auto& [key, value] : attributes) WriteRealAttribute(dataset, key, {value}, path_);
  H5Dclose(dataset);
}

void CameraFrames::Reopen(const std::string& h5_path, const CameraGrid& grid, int kept,
                          const std::vector<double>& times) {
  path_ = h5_path;
  grid_ = grid;
  times_ = times;
  H5E_BEGIN_TRY { file_ = H5Fopen(store::AtomicFile::partial_name(h5_path).c_str(), H5F_ACC_RDWR, H5P_DEFAULT); }
  H5E_END_TRY;
  if (file_ < 0) throw std::runtime_error("-restart: cannot resume '" + store::AtomicFile::partial_name(h5_path) + "'");
  group_ = H5Gopen2(file_, "camera", H5P_DEFAULT);
  if (group_ < 0) throw std::runtime_error(h5_path + ": no group /camera");
  defect_ = H5Lexists(group_, "defect_0", H5P_DEFAULT) > 0;
  // Frames the interrupted run wrote after its checkpoint are written again.
  for (int k = kept;; ++k) {
    bool found = false;
    for (const std::string& name :
         {"frame_" + std::to_string(k), "clean_" + std::to_string(k), "defect_" + std::to_string(k)})
      if (H5Lexists(group_, name.c_str(), H5P_DEFAULT) > 0) found = H5Ldelete(group_, name.c_str(), H5P_DEFAULT) >= 0;
    if (!found) break;
  }
}

void CameraFrames::Write(int k, double start, double end, const std::vector<double>& clean,
                         const std::vector<double>& noisy) {
  const double centre = 0.5 * (start + end);
  const std::map<std::string, double> when = {{"time", centre}, {"window_start", start}, {"window_end", end}};
  WriteArray("frame_" + std::to_string(k), noisy, grid_.rows, grid_.cols, "K", when);
  WriteArray("clean_" + std::to_string(k), clean, grid_.rows, grid_.cols, "K", when);
  times_.insert(times_.end(), {centre, start, end});
  Flush();
}

void CameraFrames::WriteDefect(int k, double start, double end, const std::vector<double>& defect) {
  const std::map<std::string, double> when = {{"time", 0.5 * (start + end)}, {"window_start", start}, {"window_end", end}};
  WriteArray("defect_" + std::to_string(k), defect, grid_.rows, grid_.cols, "K", when);
  defect_ = true;
  Flush();
}

void CameraFrames::Finish() {
  WriteArray("time", times_, times_.size() / 3, 3, "s", {});
  H5Gclose(group_);
  group_ = -1;
  const herr_t status = H5Fclose(file_);
  file_ = -1;
  Check(status, path_, "the file");
  store::AtomicFile::publish(path_);
  WriteXdmf();
}

void CameraFrames::WriteXdmf() const {
  const std::filesystem::path h5(path_);
  const std::string xmf = (h5.parent_path() / h5.stem()).string() + ".xmf";
  const std::string file = h5.filename().string();
  store::AtomicFile out(xmf);
  std::ostream& s = out.stream();
  s << std::setprecision(17);
  s << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
    << "  <Grid Name=\"camera\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  // A one-pixel-thick slab of voxels (3DCoRectMesh, z from 0 to one pixel), pixels as its
  // cells: both ParaView readers (XDMF Reader, Xdmf3 Reader S) read it in the x-y plane; a
  // 2DCoRectMesh lands in the y-z plane. Dimensions and origin slowest first (z, y, x).
  for (std::size_t k = 0; k < times_.size() / 3; ++k) {
    s << "   <Grid Name=\"frame_" << k << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << times_[3 * k] << "\"/>\n"
      << "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"2 " << grid_.rows + 1 << " " << grid_.cols + 1
      << "\"/>\n    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
      << "     <DataItem Format=\"XML\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"3\">0 " << grid_.y0 << " "
      << grid_.x0 << "</DataItem>\n"
      << "     <DataItem Format=\"XML\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"3\">" << grid_.pixel << " "
      << grid_.pixel << " " << grid_.pixel << "</DataItem>\n    </Geometry>\n";
    std::vector<std::pair<std::string, std::string>> attributes = {{"frame", "temperature_rise"},
                                                                   {"clean", "temperature_rise_clean"}};
    if (defect_) attributes.push_back({"defect", "temperature_rise_defect"});
    for (const auto& [name, title] : attributes)
      s << "    <Attribute Name=\"" << title
        << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "     <DataItem Format=\"HDF\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"1 " << grid_.rows << " "
        << grid_.cols << "\">" << file << ":/camera/" << name << "_" << k << "</DataItem>\n    </Attribute>\n";
    s << "   </Grid>\n";
  }
  s << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.commit();
}

}  // namespace vibrotherm::io
