#include "anchorbench/io/output_folder.hpp"

#include "anchorbench/io/input_error.hpp"

namespace anchorbench::io {

void CreateFolder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string() + ": cannot create the folder: " + error.message());
}

std::filesystem::path OutputFolder(const std::string& out, const std::string& config_name) {
  const std::filesystem::path folder = out.empty() ? std::filesystem::path("results") / config_name
                                                   : std::filesystem::path(out);
  CreateFolder(folder);
  return folder;
}

}  // namespace anchorbench::io
