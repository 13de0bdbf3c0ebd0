#pragma once
// An output file written under a temporary name and put in place by commit(), whatever its format
// (AtomicFile for text, Hdf5File for HDF5): what RunMetadata::write commits after the JSON, so a
// job's files appear in one order — the metadata first, never an output without it.
namespace granular {

class PendingOutput {
 public:
  virtual ~PendingOutput() = default;
  /// Puts the file in place under its name (fsynced); throws IoError naming the file and the cause.
  virtual void commit() = 0;

 protected:
  PendingOutput() = default;
  PendingOutput(const PendingOutput&) = default;
  PendingOutput& operator=(const PendingOutput&) = default;
};

}  // namespace granular
