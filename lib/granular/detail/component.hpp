#pragma once
// Optional parts of the library that link heavy dependencies (the SLEPc method: PETSc, MPI and
// what they load; the HDF5 writer: libhdf5) live in their own files, libgranular_<name>.so beside
// libgranular, so that a run that never uses them does not load those libraries at start-up. The
// first call that needs one loads it. A static libgranular has them built in and loads nothing.
namespace granular::detail {

/// The address of the C-linkage function `entry` of the component `name` ("slepc", "hdf5"),
/// loading libgranular_<name>.so on first use from the folder that holds libgranular (or from
/// $GRANULAR_COMPONENT_DIR when set). `needed_for` names what needs it, for the message
/// ("the SLEPc method"). Thread-safe; the component stays loaded. Throws IoError when the file
/// is missing or does not load.
void* component_entry(const char* name, const char* entry, const char* needed_for);

}  // namespace granular::detail
