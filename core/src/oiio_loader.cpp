#include "oiio_loader.h"

#include <dlfcn.h>

#include <string>
#include <vector>

#include "hair25d/core/error.h"

namespace hair25d::oiio_plugin {

namespace fs = std::filesystem;

namespace {

struct Loaded {
  const Api* api = nullptr;
  std::string error;
};

// Where the module may be: beside this library (build tree and install
// alike), the build tree's core folder, the installed library folder, then
// the loader's own search path.
std::vector<fs::path> candidates() {
  std::vector<fs::path> out;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&api_for), &info) != 0 && info.dli_fname != nullptr)
    out.push_back(fs::path(info.dli_fname).parent_path() / kFileName);
#ifdef HAIR25D_CORE_OIIO_BUILD_DIR
  out.push_back(fs::path(HAIR25D_CORE_OIIO_BUILD_DIR) / kFileName);
#endif
#ifdef HAIR25D_CORE_OIIO_INSTALL_DIR
  out.push_back(fs::path(HAIR25D_CORE_OIIO_INSTALL_DIR) / kFileName);
#endif
  out.push_back(kFileName);
  return out;
}

Loaded load() {
  Loaded loaded;
  for (const fs::path& path : candidates()) {
    // The handle stays open for the life of the process: the module's code
    // is used until exit. RTLD_LOCAL keeps OpenImageIO's symbols private.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      if (loaded.error.empty() && why != nullptr) loaded.error = why;
      continue;
    }
    using Entry = const Api* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, kEntryPoint));
    const Api* api = entry != nullptr ? entry() : nullptr;
    if (api == nullptr || api->abi_version != kAbiVersion || api->read == nullptr ||
        api->write == nullptr) {
      loaded.error = path.string() + " is not a matching hair25d_core_oiio module";
      dlclose(handle);
      continue;
    }
    loaded.api = api;
    loaded.error.clear();
    return loaded;
  }
  return loaded;
}

}  // namespace

const Api& api_for(const fs::path& file) {
  static const Loaded loaded = load();  // thread-safe, once; read-only afterwards
  if (loaded.api == nullptr) {
    throw Error(file.string() + ": reading or writing this format needs " + kFileName +
                " (OpenImageIO), which could not be loaded: " + loaded.error);
  }
  return *loaded.api;
}

}  // namespace hair25d::oiio_plugin
