// A checkpoint: a run's whole state as named tables, independent of how the
// meshes are partitioned (issue 16). Every table is a list of items, each a key
// and a run of doubles (its length per item may vary: a memory diagram):
//   shared    one item every rank agrees on (time, counters, global sums);
//   per rank  one item per rank (partial sums each rank accumulates): given back
//             per rank on the same rank count, as their sum on rank 0 otherwise,
//             so that a restart on the same ranks sums in the same order;
//   keyed     items with global keys (dofs, contact cells; mesh::PointOrigin):
//             each rank puts what it owns and gets back what it owns now.
// Doubles are stored bit for bit. Rank 0 writes one HDF5 file (one group per
// table: keys, counts, values) as <path>.partial and renames it: a checkpoint
// on disk is always complete. Reading: rank 0 reads, every rank gets a copy
// (states are small next to the meshes: 15k dofs in the paper scene).
#pragma once

#include <petscvec.h>

#include <map>
#include <string>
#include <vector>

namespace vibrotherm::store {

class Checkpoint {
 public:
  explicit Checkpoint(MPI_Comm comm) : comm_(comm) {}

  void PutShared(const std::string& name, std::vector<double> values);
  void PutPerRank(const std::string& name, std::vector<double> values);
  /// Items keys[i] with counts[i] values each, concatenated in values.
  void PutKeyed(const std::string& name, std::vector<long long> keys, std::vector<long long> counts,
                std::vector<double> values);
  /// The same with `width` values per item.
  void PutKeyed(const std::string& name, std::vector<long long> keys, int width, std::vector<double> values);
  void PutText(const std::string& name, const std::string& text);

  /// What this rank put becomes readable by this rank: an in-memory snapshot of the
  /// same run on the same partition (the periodic continuation's stored state).
  void IndexLocal();
  /// Copies every table of `inner` under "prefix/" (this rank's items: Write gathers them as any other).
  void Nest(const std::string& prefix, const Checkpoint& inner);
  /// The tables under "prefix/" as a checkpoint of their own, readable as this one is.
  void Extract(const std::string& prefix, Checkpoint* inner) const;

  /// Gathers on rank 0 and writes path atomically. Collective.
  PetscErrorCode Write(const std::string& path) const;
  /// Reads path (rank 0) and shares it with every rank; errors name the file and the option
  /// that named it. Collective.
  PetscErrorCode Read(const std::string& path, const std::string& option = "-restart");

  /// The shared item; errors when missing or (expected > 0) of another length.
  PetscErrorCode GetShared(const std::string& name, std::vector<double>* values, std::size_t expected = 0) const;
  double Scalar(const std::string& name) const;  ///< first value of a shared item (NaN if missing)
  /// This rank's item, or (another rank count) the sum over the writers on rank 0 and zeros elsewhere.
  PetscErrorCode GetPerRank(const std::string& name, std::vector<double>* values) const;
  /// The items of `keys` (fixed width: values = keys.size() × width); errors name a missing key.
  PetscErrorCode GetKeyed(const std::string& name, const std::vector<long long>& keys, int width,
                          std::vector<double>* values) const;
  /// Variable-length items: counts per key and the values concatenated.
  PetscErrorCode GetKeyed(const std::string& name, const std::vector<long long>& keys, std::vector<long long>* counts,
                          std::vector<double>* values) const;
  PetscErrorCode GetText(const std::string& name, std::string* text) const;
  bool Has(const std::string& name) const { return tables_.count(name) > 0; }
  /// Ranks of the run that wrote it, and whether this run has as many.
  int writer_ranks() const { return writer_ranks_; }
  bool same_ranks() const;

 private:
  enum Kind { kShared = 0, kPerRank = 1, kKeyed = 2, kText = 3 };
  struct Table {
    int kind = kShared;
    std::vector<long long> keys, counts;
    std::vector<double> values;
    std::string text;
    std::map<long long, std::size_t> offset;  ///< key → position in values (after reading)
    std::map<long long, std::size_t> item;    ///< key → item index (after reading)
  };
  PetscErrorCode Gathered(const Table& mine, Table* all) const;
  PetscErrorCode Find(const std::string& name, int kind, const Table** table) const;
  MPI_Comm comm_;
  std::map<std::string, Table> tables_;
  int writer_ranks_ = 0;
  std::string path_;  ///< the file read (for messages)
  std::string option_ = "-restart";  ///< the option that named it (for messages)
};

/// A vector's owned entries as keyed items (one value each, keys in the vector's local order), and back.
PetscErrorCode PutOwnedValues(Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys, Vec v);
PetscErrorCode GetOwnedValues(const Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys,
                              Vec v);

}  // namespace vibrotherm::store
