#include "vibrotherm/io/h5_tables.hpp"

#include <hdf5.h>

#include <stdexcept>

#include "vibrotherm/store/atomic_file.hpp"

namespace vibrotherm::io {
namespace {

void Check(herr_t status, const std::string& path, const std::string& what) {
  if (status < 0) throw std::runtime_error(path + ": cannot write " + what + " (HDF5)");
}

void WriteUnits(hid_t dataset, const std::string& units, const std::string& path) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, units.size());
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(dataset, "units", type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, type, units.c_str());
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  Check(status, path, "the units attribute");
}

}  // namespace

void WriteH5Tables(const std::string& path, const std::map<std::string, H5Table>& tables) {
  const std::string partial = store::AtomicFile::partial_name(path);
  const hid_t file = H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error(path + ": cannot create the file");
  for (const auto& [name, table] : tables) {
    const hsize_t dims[2] = {table.rows, table.cols};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t dataset = H5Dcreate2(file, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    herr_t status = dataset < 0 ? -1 : 0;
    if (status >= 0 && !table.values.empty())
      status = H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, table.values.data());
    if (status >= 0 && !table.units.empty()) WriteUnits(dataset, table.units, path);
    if (dataset >= 0) H5Dclose(dataset);
    H5Sclose(space);
    if (status < 0) {
      H5Fclose(file);
      throw std::runtime_error(path + ": cannot write dataset " + name + " (HDF5)");
    }
  }
  Check(H5Fclose(file), path, "the file");
  store::AtomicFile::publish(path);
}

}  // namespace vibrotherm::io
