#pragma once

#include <filesystem>
#include <string>

namespace anchorbench::io {

// Creates `folder` and its parents, or throws InputError naming it.
void CreateFolder(const std::filesystem::path& folder);

// Where a Monte Carlo command writes: --out if given, else results/<config name>/; created.
std::filesystem::path OutputFolder(const std::string& out, const std::string& config_name);

}  // namespace anchorbench::io
