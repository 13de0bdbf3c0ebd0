#pragma once
// Finished realizations survive an interrupted run. Each finished realization is appended to a
// log as one self-checking line and flushed to disk; a resumed run reads the complete lines back
// and computes only the rest. Because each realization is a pure function of (seed, index) and
// results are reduced in index order, a resumed run's output equals an uninterrupted one's byte
// for byte.
//
// Format (text, so it can be inspected):
//   line 1:  granular-checkpoint 1 <parameters as one line of JSON, with "granular_commit" and
//            "granular_version" (the code that wrote it) put first>
//   then:    <index> <count> <v_1> … <v_count> <checksum>      (values in shortest round-trip form)
// A line cut short by a kill (no newline, wrong count or checksum) is ignored and recomputed.
#include <cstdint>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace granular {

using CheckpointRecords = std::map<std::uint64_t, std::vector<double>>;

class CheckpointLog {
 public:
  /// Creates (or atomically replaces) the log at `path` for a run described by `parameters`
  /// (canonical one-line JSON), holding `records` already finished, and opens it for appending.
  CheckpointLog(std::string path, std::string parameters, const CheckpointRecords& records = {});
  ~CheckpointLog();
  CheckpointLog(const CheckpointLog&) = delete;
  CheckpointLog& operator=(const CheckpointLog&) = delete;

  /// Reads the finished realizations of a run: the log at `base` and those of other MPI ranks
  /// (`base.rank<k>`). Throws InvalidInput when there is none (naming `resume`), when a file is
  /// not a checkpoint, or when it was made with other parameters (naming the first that differs).
  /// A log made by another code — another version, or the same version built from another commit
  /// when both commits are known (the header records code_version() and code_commit()) — is
  /// refused naming both, unless `accept_other_version`.
  static CheckpointRecords load(const std::string& base, const std::string& parameters,
                                bool accept_other_version = false);

  /// "" when every log of `base` was made by this code (as load judges it); else a sentence naming both
  /// ("checkpoint 'P' was made by granular 0.0.9 (commit …), this is granular 0.1.0 (commit …)").
  static std::string other_version(const std::string& base);

  /// The code that made the log at `base` ("0.1.0 (commit 0123456789ab)"), "" when there is none.
  static std::string code_of(const std::string& base);
  /// Every code whose realizations the logs of `base` hold, oldest first: after resumes accepted
  /// across versions, each of them (a log rewritten on resume keeps the list of the one it
  /// replaces, in its header's "granular_contributors"); empty when there is no log.
  static std::vector<std::string> codes_of(const std::string& base);

  /// Which files belong to the checkpoint `base`: always `base` and every `base.rank<k>` (the logs
  /// of further MPI ranks); with `cases`, also `base.<i>[.rank<k>]` (the logs of a study's cases,
  /// which take `base` as their prefix); with `temporaries`, also the `.tmp.<pid>` a killed run
  /// left of any of them. A file named alike (`base.bak`, `base.rankx`) is never one of them.
  struct Members {
    bool cases = false;
    bool temporaries = false;
  };
  /// The existing files of `base` that `which` takes, sorted (named as `base` is: in its folder).
  static std::vector<std::string> files(const std::string& base, Members which);

  /// Before a run that does not resume but logs to `base` (with `cases`, also to its case logs):
  /// finished work is never lost to a run not told to discard it. Throws InvalidInput naming
  /// `checkpoint` when an interrupted run's log is there (the message says: continue it with
  /// `resume`, or discard its realizations with `fresh`); with `discard`, removes every file of it
  /// instead, temporaries included.
  static void settle(const std::string& base, bool discard, bool cases);

  /// This code, named as code_of names a log's maker ("0.1.0 (commit 0123456789ab)").
  static std::string this_code();

  /// Whether `base` or any `base.rank<k>` exists.
  static bool exists(const std::string& base);

  /// The log file of an MPI rank: `base` for rank 0, `base.rank<k>` otherwise.
  static std::string rank_path(const std::string& base, int rank);

  /// Removes `base`, every `base.rank<k>` and the temporaries a killed run left of them
  /// (`base[.rank<k>].tmp.<pid>`), after the outputs are safely written; nothing else.
  static void remove_all(const std::string& base);

  /// Appends one finished realization and flushes it to disk. Thread-safe.
  void append(std::uint64_t index, const std::vector<double>& values);

  const std::string& path() const { return path_; }

  /// Parses a log's text (what resume and the fuzz target use); corrupt lines are skipped.
  static CheckpointRecords parse_records(const std::string& text, std::string* header);

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::mutex mutex_;
};

}  // namespace granular
