#pragma once
// Finished realizations survive an interrupted run. Each finished realization is appended to a
// log as one self-checking line and flushed to disk; a resumed run reads the complete lines back
// and computes only the rest. Because each realization is a pure function of (seed, index) and
// results are reduced in index order, a resumed run's output equals an uninterrupted one's byte
// for byte.
//
// Format (text, so it can be inspected):
//   line 1:  granular-checkpoint 1 <parameters as one line of JSON>
//   then:    <index> <count> <v_1> … <v_count> <checksum>      (values in shortest round-trip form)
// A line cut short by a kill (no newline, wrong count or checksum) is ignored and recomputed.
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace granular {

class CheckpointLog {
 public:
  /// Opens `path` for a run described by `parameters` (canonical one-line JSON).
  /// resume = false: starts a new log (an existing one is replaced).
  /// resume = true: loads finished realizations; throws InvalidInput if the log was made with
  /// other parameters (naming the first that differs), IoError if it cannot be read.
  CheckpointLog(std::string path, std::string parameters, bool resume);
  ~CheckpointLog();
  CheckpointLog(const CheckpointLog&) = delete;
  CheckpointLog& operator=(const CheckpointLog&) = delete;

  /// Realizations already finished (loaded on resume), by index.
  const std::map<std::uint64_t, std::vector<double>>& finished() const { return finished_; }

  /// Appends one finished realization and flushes it to disk. Thread-safe.
  void append(std::uint64_t index, const std::vector<double>& values);

  /// Deletes the log (call after the outputs are safely written).
  void remove();

  const std::string& path() const { return path_; }

  /// Parses a log's text (what resume and the fuzz target use); corrupt lines are skipped.
  static std::map<std::uint64_t, std::vector<double>> parse_records(const std::string& text, std::string* header);

 private:
  std::string path_, parameters_;
  std::FILE* file_ = nullptr;
  std::mutex mutex_;
  std::map<std::uint64_t, std::vector<double>> finished_;
};

}  // namespace granular
