#include "vibrotherm/store/checkpoint.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>

#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/util/all_gather.hpp"
#include "vibrotherm/util/write_failure.hpp"

namespace vibrotherm::store {
namespace {

/// 2: crack_state.csv has one schema in 2D and 3D and a contact cell's values one layout
/// (issue 39); a run checkpointed in format 1 would append its rows under the old header.
constexpr int kFormat = 2;

/// A flat byte buffer: how rank 0 hands the file it read to the other ranks.
class Bytes {
 public:
  template <typename T>
  void Put(const T* data, std::size_t n) {
    Put(static_cast<long long>(n));
    const auto* p = reinterpret_cast<const char*>(data);
    buffer.insert(buffer.end(), p, p + n * sizeof(T));
  }
  void Put(long long n) {
    const auto* p = reinterpret_cast<const char*>(&n);
    buffer.insert(buffer.end(), p, p + sizeof(n));
  }
  long long Long() {
    long long n;
    std::memcpy(&n, buffer.data() + at, sizeof(n));
    at += sizeof(n);
    return n;
  }
  template <typename T>
  std::vector<T> Array() {
    std::vector<T> out(static_cast<std::size_t>(Long()));
    std::memcpy(out.data(), buffer.data() + at, out.size() * sizeof(T));
    at += out.size() * sizeof(T);
    return out;
  }
  std::vector<char> buffer;
  std::size_t at = 0;
};

bool WriteArray(hid_t group, const char* name, hid_t type, const void* data, std::size_t n) {
  const hsize_t dims[1] = {n};
  const hid_t space = H5Screate_simple(1, dims, nullptr);
  const hid_t set = H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = set >= 0 && (n == 0 || H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  return ok;
}

template <typename T>
bool ReadArray(hid_t group, const char* name, hid_t type, std::vector<T>* out) {
  const hid_t set = H5Dopen2(group, name, H5P_DEFAULT);
  if (set < 0) return false;
  const hid_t space = H5Dget_space(set);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  out->resize(n);
  const bool ok = n == 0 || H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out->data()) >= 0;
  H5Sclose(space);
  H5Dclose(set);
  return ok;
}

bool WriteIntAttribute(hid_t object, const char* name, long long value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(object, name, H5T_NATIVE_LLONG, space, H5P_DEFAULT, H5P_DEFAULT);
  const bool ok = attr >= 0 && H5Awrite(attr, H5T_NATIVE_LLONG, &value) >= 0;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  return ok;
}

bool ReadIntAttribute(hid_t object, const char* name, long long* value) {
  const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
  const bool ok = attr >= 0 && H5Aread(attr, H5T_NATIVE_LLONG, value) >= 0;
  if (attr >= 0) H5Aclose(attr);
  return ok;
}

}  // namespace

void Checkpoint::PutShared(const std::string& name, std::vector<double> values) {
  Table& t = tables_[name];
  t.kind = kShared;
  t.keys = {0};
  t.counts = {static_cast<long long>(values.size())};
  t.values = std::move(values);
}

void Checkpoint::PutPerRank(const std::string& name, std::vector<double> values) {
  PetscMPIInt rank;
  MPI_Comm_rank(comm_, &rank);
  Table& t = tables_[name];
  t.kind = kPerRank;
  t.keys = {rank};
  t.counts = {static_cast<long long>(values.size())};
  t.values = std::move(values);
}

void Checkpoint::PutKeyed(const std::string& name, std::vector<long long> keys, std::vector<long long> counts,
                          std::vector<double> values) {
  Table& t = tables_[name];
  t.kind = kKeyed;
  t.keys = std::move(keys);
  t.counts = std::move(counts);
  t.values = std::move(values);
}

void Checkpoint::PutKeyed(const std::string& name, std::vector<long long> keys, int width,
                          std::vector<double> values) {
  std::vector<long long> counts(keys.size(), width);
  PutKeyed(name, std::move(keys), std::move(counts), std::move(values));
}

void Checkpoint::PutText(const std::string& name, const std::string& text) {
  Table& t = tables_[name];
  t.kind = kText;
  t.text = text;
}

void Checkpoint::IndexLocal() {
  PetscMPIInt size;
  MPI_Comm_size(comm_, &size);
  writer_ranks_ = size;
  for (auto& [name, t] : tables_) {
    t.offset.clear();
    t.item.clear();
    std::size_t offset = 0;
    for (std::size_t i = 0; i < t.keys.size(); ++i) {
      t.offset[t.keys[i]] = offset;
      t.item[t.keys[i]] = i;
      offset += static_cast<std::size_t>(t.counts[i]);
    }
  }
}

void Checkpoint::Nest(const std::string& prefix, const Checkpoint& inner) {
  for (const auto& [name, t] : inner.tables_) {
    Table copy = t;
    copy.offset.clear();
    copy.item.clear();
    tables_[prefix + "/" + name] = std::move(copy);
  }
}

void Checkpoint::Extract(const std::string& prefix, Checkpoint* inner) const {
  inner->tables_.clear();
  inner->writer_ranks_ = writer_ranks_;
  inner->path_ = path_;
  const std::string head = prefix + "/";
  for (const auto& [name, t] : tables_)
    if (name.compare(0, head.size(), head) == 0) inner->tables_[name.substr(head.size())] = t;
}

PetscErrorCode Checkpoint::Gathered(const Table& mine, Table* all) const {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  all->kind = mine.kind;
  all->text = mine.text;
  if (mine.kind == kShared || mine.kind == kText) {  // every rank holds the same: rank 0's
    all->keys = mine.keys, all->counts = mine.counts, all->values = mine.values;
    PetscFunctionReturn(0);
  }
  std::vector<long long> k, c;
  std::vector<double> v;
  PetscCall(util::GatherToRoot(comm_, mine.keys, &k));
  PetscCall(util::GatherToRoot(comm_, mine.counts, &c));
  PetscCall(util::GatherToRoot(comm_, mine.values, &v));
  if (rank != 0) PetscFunctionReturn(0);
  const std::size_t n = k.size();
  std::vector<long long> offset(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + c[i];
  // Sorted by key: the file is the same whatever the partition.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return k[a] < k[b]; });
  for (std::size_t i : order) {
    all->keys.push_back(k[i]);
    all->counts.push_back(c[i]);
    all->values.insert(all->values.end(), v.begin() + offset[i], v.begin() + offset[i + 1]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::Write(const std::string& path) const {
  PetscFunctionBeginUser;
  PetscMPIInt rank, size;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  std::map<std::string, Table> all;
  for (const auto& [name, mine] : tables_) PetscCall(Gathered(mine, &all[name]));
  int ok = 1;
  if (rank == 0) {
    const std::string partial = AtomicFile::partial_name(path);
    const hid_t file = H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ok = file >= 0 && WriteIntAttribute(file, "format", kFormat) && WriteIntAttribute(file, "ranks", size);
    for (const auto& [name, t] : all) {
      if (!ok) break;
      std::string flat = name;  // one level of groups: "wave/u" is stored as "wave.u"
      std::replace(flat.begin(), flat.end(), '/', '.');
      const hid_t group = H5Gcreate2(file, flat.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      ok = group >= 0 && WriteIntAttribute(group, "kind", t.kind) &&
           WriteArray(group, "keys", H5T_NATIVE_LLONG, t.keys.data(), t.keys.size()) &&
           WriteArray(group, "counts", H5T_NATIVE_LLONG, t.counts.data(), t.counts.size()) &&
           WriteArray(group, "values", H5T_NATIVE_DOUBLE, t.values.data(), t.values.size()) &&
           WriteArray(group, "text", H5T_NATIVE_CHAR, t.text.data(), t.text.size());
      if (group >= 0) H5Gclose(group);
    }
    if (file >= 0) ok = H5Fclose(file) >= 0 && ok;
    if (ok) ok = std::rename(partial.c_str(), path.c_str()) == 0;
    else std::remove(partial.c_str());
  }
  char reason[256] = "";  // why rank 0 could not write it, for every rank's line
  if (rank == 0 && !ok) std::snprintf(reason, sizeof(reason), "%s", WriteFailureReason(path).c_str());
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, comm_));
  PetscCallMPI(MPI_Bcast(reason, sizeof(reason), MPI_CHAR, 0, comm_));
  PetscCheck(ok, comm_, PETSC_ERR_FILE_WRITE, "cannot write the checkpoint %s%s%s", path.c_str(),
             reason[0] ? ": " : "", reason);
  PetscFunctionReturn(0);
}

namespace {

struct ReadState {
  std::map<std::string, std::vector<long long>> kinds;
  Bytes* bytes;
  bool ok = true;
};

herr_t ReadGroup(hid_t file, const char* name, const H5L_info_t*, void* data) {
  auto* state = static_cast<ReadState*>(data);
  const hid_t group = H5Gopen2(file, name, H5P_DEFAULT);
  long long kind = -1;
  std::vector<long long> keys, counts;
  std::vector<double> values;
  std::vector<char> text;
  const bool ok = group >= 0 && ReadIntAttribute(group, "kind", &kind) &&
                  ReadArray(group, "keys", H5T_NATIVE_LLONG, &keys) &&
                  ReadArray(group, "counts", H5T_NATIVE_LLONG, &counts) &&
                  ReadArray(group, "values", H5T_NATIVE_DOUBLE, &values) &&
                  ReadArray(group, "text", H5T_NATIVE_CHAR, &text);
  if (group >= 0) H5Gclose(group);
  if (!ok) {
    state->ok = false;
    return 1;  // stop iterating
  }
  Bytes& b = *state->bytes;
  b.Put(name, std::strlen(name));
  b.Put(kind);
  b.Put(keys.data(), keys.size());
  b.Put(counts.data(), counts.size());
  b.Put(values.data(), values.size());
  b.Put(text.data(), text.size());
  return 0;
}

}  // namespace

PetscErrorCode Checkpoint::Read(const std::string& path, const std::string& option) {
  PetscFunctionBeginUser;
  option_ = option;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  path_ = path;
  Bytes bytes;
  long long status[3] = {0, 0, 0};  // ok, format, ranks
  if (rank == 0) {
    H5E_BEGIN_TRY {  // a missing or foreign file is an input error, not an HDF5 trace
      const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      bool ok = file >= 0 && ReadIntAttribute(file, "format", &status[1]) && ReadIntAttribute(file, "ranks", &status[2]);
      ReadState state;
      state.bytes = &bytes;
      if (ok) ok = H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, nullptr, ReadGroup, &state) >= 0 && state.ok;
      if (file >= 0) H5Fclose(file);
      status[0] = ok;
    }
    H5E_END_TRY;
  }
  PetscCallMPI(MPI_Bcast(status, 3, MPI_LONG_LONG, 0, comm_));
  PetscCheck(status[0], comm_, PETSC_ERR_FILE_OPEN, "%s: cannot read the checkpoint %s (missing, or not written by vibrotherm)",
             option_.c_str(), path.c_str());
  PetscCheck(status[1] == kFormat, comm_, PETSC_ERR_USER_INPUT,  // the user's file: one line, exit 2
             "%s: %s has checkpoint format %lld, this vibrotherm reads %d (finish that run with the vibrotherm "
             "that wrote it, or run it again from its start)",
             option_.c_str(), path.c_str(), status[1], kFormat);
  writer_ranks_ = static_cast<int>(status[2]);
  long long size = static_cast<long long>(bytes.buffer.size());
  PetscCallMPI(MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, comm_));
  bytes.buffer.resize(static_cast<std::size_t>(size));
  PetscCallMPI(MPI_Bcast(bytes.buffer.data(), static_cast<int>(size), MPI_CHAR, 0, comm_));
  tables_.clear();
  while (bytes.at < bytes.buffer.size()) {
    const std::vector<char> stored = bytes.Array<char>();
    std::string name(stored.begin(), stored.end());
    std::replace(name.begin(), name.end(), '.', '/');
    Table& t = tables_[name];
    t.kind = static_cast<int>(bytes.Long());
    t.keys = bytes.Array<long long>();
    t.counts = bytes.Array<long long>();
    t.values = bytes.Array<double>();
    const std::vector<char> text = bytes.Array<char>();
    t.text.assign(text.begin(), text.end());
    std::size_t offset = 0;
    for (std::size_t i = 0; i < t.keys.size(); ++i) {
      t.offset[t.keys[i]] = offset;
      t.item[t.keys[i]] = i;
      offset += static_cast<std::size_t>(t.counts[i]);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::Find(const std::string& name, int kind, const Table** table) const {
  PetscFunctionBeginUser;
  const auto it = tables_.find(name);
  PetscCheck(it != tables_.end() && it->second.kind == kind, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "%s: the checkpoint %s has no '%s' (written by another scene or version?)", option_.c_str(),
             path_.c_str(), name.c_str());
  *table = &it->second;
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::GetShared(const std::string& name, std::vector<double>* values, std::size_t expected) const {
  PetscFunctionBeginUser;
  const Table* t;
  PetscCall(Find(name, kShared, &t));
  PetscCheck(expected == 0 || t->values.size() == expected, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
             "%s: '%s' in %s has %zu values, expected %zu", option_.c_str(), name.c_str(), path_.c_str(),
             t->values.size(), expected);
  *values = t->values;
  PetscFunctionReturn(0);
}

bool Checkpoint::same_ranks() const {
  PetscMPIInt size;
  MPI_Comm_size(comm_, &size);
  return size == writer_ranks_;
}

double Checkpoint::Scalar(const std::string& name) const {
  const auto it = tables_.find(name);
  return it == tables_.end() || it->second.values.empty() ? NAN : it->second.values[0];
}

PetscErrorCode Checkpoint::GetPerRank(const std::string& name, std::vector<double>* values) const {
  PetscFunctionBeginUser;
  const Table* t;
  PetscCall(Find(name, kPerRank, &t));
  PetscMPIInt rank, size;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  const std::size_t width = t->counts.empty() ? 0 : static_cast<std::size_t>(t->counts[0]);
  values->assign(width, 0.0);
  if (size == writer_ranks_) {
    const std::size_t at = t->offset.at(rank);
    std::copy(t->values.begin() + at, t->values.begin() + at + width, values->begin());
  } else if (rank == 0) {
    for (std::size_t i = 0; i < t->values.size(); ++i) (*values)[i % width] += t->values[i];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::GetKeyed(const std::string& name, const std::vector<long long>& keys,
                                    std::vector<long long>* counts, std::vector<double>* values) const {
  PetscFunctionBeginUser;
  const Table* t;
  PetscCall(Find(name, kKeyed, &t));
  counts->clear();
  values->clear();
  for (long long key : keys) {
    const auto it = t->item.find(key);
    PetscCheck(it != t->item.end(), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED,
               "%s: '%s' in %s has no item %lld (the checkpoint belongs to another mesh)", option_.c_str(),
               name.c_str(), path_.c_str(), key);
    const std::size_t at = t->offset.at(key);
    const long long n = t->counts[it->second];
    counts->push_back(n);
    values->insert(values->end(), t->values.begin() + at, t->values.begin() + at + n);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::GetKeyed(const std::string& name, const std::vector<long long>& keys, int width,
                                    std::vector<double>* values) const {
  PetscFunctionBeginUser;
  std::vector<long long> counts;
  PetscCall(GetKeyed(name, keys, &counts, values));
  for (long long n : counts)
    PetscCheck(n == width, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: '%s' in %s has items of %lld values, expected %d",
               option_.c_str(), name.c_str(), path_.c_str(), n, width);
  PetscFunctionReturn(0);
}

PetscErrorCode PutOwnedValues(Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys,
                              Vec v) {
  PetscFunctionBeginUser;
  const PetscScalar* a;
  PetscCall(VecGetArrayRead(v, &a));
  checkpoint.PutKeyed(name, keys, 1, std::vector<double>(a, a + keys.size()));
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode GetOwnedValues(const Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys,
                              Vec v) {
  PetscFunctionBeginUser;
  std::vector<double> values;
  PetscCall(checkpoint.GetKeyed(name, keys, 1, &values));
  PetscScalar* a;
  PetscCall(VecGetArray(v, &a));
  std::copy(values.begin(), values.end(), a);
  PetscCall(VecRestoreArray(v, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode Checkpoint::GetText(const std::string& name, std::string* text) const {
  PetscFunctionBeginUser;
  const Table* t;
  PetscCall(Find(name, kText, &t));
  *text = t->text;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::store
