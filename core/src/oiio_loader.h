// Finds and loads libhair25d_core_oiio (oiio_plugin.h) once, on first use.
#pragma once

#include <filesystem>

#include "oiio_plugin.h"

namespace hair25d::oiio_plugin {

// The module's functions. Throws hair25d::Error naming `file` (the image that
// needs it) when the module cannot be found or loaded.
const Api& api_for(const std::filesystem::path& file);

}  // namespace hair25d::oiio_plugin
