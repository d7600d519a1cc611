#include "ari_social_sim/core/data_sets.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace ari_social_sim::core {
namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

}  // namespace

std::string data_dir() {
  std::string configured = environment("ARI_DATA_DIR");
  if (!configured.empty()) {
    return configured;
  }
  return environment("HOME") + "/.local/share/ari_social_sim/data";
}

std::string data_set_dir(const std::string& name) {
  return data_dir() + "/" + name;
}

bool data_set_present(const std::string& name) {
  std::error_code error;
  const std::filesystem::directory_iterator entries(data_set_dir(name), error);
  return !error && entries != std::filesystem::directory_iterator();
}

std::string missing_data_set_message(const std::string& name) {
  return "data set '" + name + "' is not in " + data_set_dir(name) +
         ": fetch it with scripts/fetch_data.sh, or set ARI_DATA_DIR to a folder that holds " +
         name + "/";
}

}  // namespace ari_social_sim::core
