// The model folder: model.json ("hair25d-model", versioned) and PNG textures.
// Written atomically (a temporary folder, then a rename); read back with
// validation (types, ids, relative paths that stay inside the folder).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "hair25d/core/hair_model.h"
#include "hair25d/core/image_io.h"

namespace hair25d {

inline constexpr int kModelFormatVersion = 1;

void write_model(const std::filesystem::path& folder, const HairModel& model);
// The same files written into an existing folder, not atomically: for callers
// that add files of their own inside write_folder_atomically.
void write_model_into(const std::filesystem::path& folder, const HairModel& model);
// The names write_model_into may put in the folder (for check_output_folder).
std::vector<std::string> model_folder_names();
HairModel read_model(const std::filesystem::path& folder, const ImageLimits& limits = {});

}  // namespace hair25d
