#include "granular/blas_library.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

namespace granular {

std::string blas_library() {
  // dlsym finds the copy the dynamic linker bound for the whole process (libgranular links BLAS
  // through LAPACK, so it is loaded); dladdr names the file it came from.
  void* routine = dlsym(RTLD_DEFAULT, "dgemv_");
  Dl_info info{};
  if (routine == nullptr || dladdr(routine, &info) == 0 || info.dli_fname == nullptr) return "unknown";
  std::error_code error;
  const auto file = std::filesystem::canonical(info.dli_fname, error);
  std::string out = error ? std::string(info.dli_fname) : file.string();
  using Config = const char* (*)();
  if (auto config = reinterpret_cast<Config>(dlsym(RTLD_DEFAULT, "openblas_get_config")); config != nullptr)
    out = std::string(config()) + ": " + out;
  return out;
}

namespace {
using GetThreads = int (*)();
using SetThreads = void (*)(int);
}  // namespace

SerialBlas::SerialBlas() {
  const auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (get == nullptr || set == nullptr) return;
  previous_ = get();
  set(1);
}

SerialBlas::~SerialBlas() {
  if (previous_ < 1) return;
  if (const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); set != nullptr)
    set(previous_);
}

}  // namespace granular
