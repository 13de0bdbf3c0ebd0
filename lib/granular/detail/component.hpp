#pragma once
// Optional parts of the library that link heavy dependencies (the SLEPc method: PETSc, MPI and
// what they load; the HDF5 writer: libhdf5) live in their own files, libgranular_<name>.so beside
// libgranular, so that a run that never uses them does not load those libraries at start-up. The
// first call that needs one loads it. A static libgranular has them built in and loads nothing.
namespace granular::detail {

/// The address of the C-linkage function `entry` of the component `name` ("slepc", "hdf5"),
/// loading libgranular_<name>.so on first use from the folder that holds libgranular (or from
/// $GRANULAR_COMPONENT_DIR when set, which must be absolute). `needed_for` names what needs it, for the message
/// ("the SLEPc method"). Thread-safe; the component stays loaded. Throws IoError when the file
/// is missing or does not load.
void* component_entry(const char* name, const char* entry, const char* needed_for);

}  // namespace granular::detail

/// The function table `const Table*` of the component NAME (a bare word: slepc, hdf5, mpi), made
/// by its C-linkage entry granular_NAME_component(): called directly when the components are built
/// in, else looked up with component_entry. A macro because the shared build must not name the
/// entry (libgranular does not define it). Keep the result in a function-local static.
#if GRANULAR_COMPONENTS_BUILT_IN
#define GRANULAR_COMPONENT_TABLE(Table, NAME, needed_for) granular_##NAME##_component()
#else
#define GRANULAR_COMPONENT_TABLE(Table, NAME, needed_for) \
  reinterpret_cast<const Table* (*)()>(                   \
      ::granular::detail::component_entry(#NAME, "granular_" #NAME "_component", needed_for))()
#endif
