#pragma once
// Which code this is: what a checkpoint records, so that a resume by another version of the
// toolkit is noticed instead of mixing realizations of two codes.
namespace granular {

/// The toolkit's version ("0.2.0"): semantic versioning, each version's changes in CHANGELOG.md.
const char* code_version();
/// The git commit the library was configured from (12 hex digits), "unknown" outside a git
/// checkout. Read when CMake configures; a commit made since reconfigures the build.
const char* code_commit();

}  // namespace granular
