#include "granular/detail/component.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>

#include "granular/error.hpp"

namespace granular::detail {

namespace {

/// The folder of the file this function was loaded from: libgranular.so, wherever it is (build
/// tree, install prefix, Python package), so the components are found beside it without a path
/// compiled in. $GRANULAR_COMPONENT_DIR overrides it: read with secure_getenv (ignored in a setuid
/// program) and absolute only, since a relative folder (or the "." once used when dladdr failed)
/// loads code from wherever the run happens to start.
std::string folder_of_libgranular(const char* needed_for) {
  if (const char* dir = secure_getenv("GRANULAR_COMPONENT_DIR"); dir != nullptr && *dir != '\0') {
    if (!std::filesystem::path(dir).is_absolute())
      throw IoError(std::string(needed_for) + ": GRANULAR_COMPONENT_DIR=" + dir +
                    " must be an absolute path (a relative one depends on the folder the run starts in)");
    return dir;
  }
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&folder_of_libgranular), &info) == 0 || info.dli_fname == nullptr)
    throw IoError(std::string(needed_for) +
                  ": the folder of libgranular is unknown (dladdr failed); set GRANULAR_COMPONENT_DIR to it");
  return std::filesystem::path(info.dli_fname).parent_path().string();
}

}  // namespace

void* component_entry(const char* name, const char* entry, const char* needed_for) {
  static std::mutex loading;
  const std::lock_guard<std::mutex> lock(loading);  // dlerror() is per thread, dlopen is not free
  const std::string file = "libgranular_" + std::string(name) + ".so";
  const std::string folder = folder_of_libgranular(needed_for);
  const std::string path = folder + "/" + file;
  // RTLD_GLOBAL: MPI and PETSc load plugins of their own that expect their symbols in the
  // global scope (as when a program links them). Never closed: atexit handlers live there.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw IoError(std::string(needed_for) + " needs " + file + ", which did not load from " + folder + ": " +
                  (why ? why : "unknown error"));
  }
  void* address = dlsym(handle, entry);
  if (address == nullptr)
    throw IoError(std::string(needed_for) + ": " + path + " has no entry point " + entry + " (a different version?)");
  return address;
}

}  // namespace granular::detail
