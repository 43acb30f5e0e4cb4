// SPDX-License-Identifier: GPL-3.0-or-later
#include <ndda/physics/blas.h>

#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>

namespace ndda
{
  std::string
  blas_description()
  {
    void *dgemm = dlsym(RTLD_DEFAULT, "dgemm_");
    if (dgemm == nullptr)
      return "none found (no dgemm_ in the process)";
    Dl_info info;
    if (dladdr(dgemm, &info) == 0 || info.dli_fname == nullptr)
      return "unknown (dgemm_ in no known library)";
    // OpenBLAS if the library of dgemm_, or one it depends on, has
    // OpenBLAS's own entry point (Debian's OpenBLAS libblas.so.3 is an
    // interface on libopenblas.so.0; OpenBLAS's LAPACK may be loaded beside
    // another BLAS, so the whole process is not asked).
    std::string name = "not OpenBLAS";
    if (void *library = dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD))
      {
        if (void *config = dlsym(library, "openblas_get_config"))
          {
            using GetConfig = char *(*)();
            name            = reinterpret_cast<GetConfig>(config)();
          }
        dlclose(library);
      }
    // The file behind Debian's alternatives links.
    char        resolved[PATH_MAX];
    const char *file =
      realpath(info.dli_fname, resolved) != nullptr ? resolved : info.dli_fname;
    name += std::string(" (") + file + ")";
    return name;
  }
} // namespace ndda
