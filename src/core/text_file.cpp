#include "ari_social_sim/core/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::core {

std::uintmax_t check_text_file(const std::string& path, const std::string& what,
                               std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error == std::errc::too_many_symbolic_link_levels) {
    // fs::status reports a loop as a file not found.
    throw ConfigError(path + ": cannot open the file (a symbolic link loop)");
  }
  if (!fs::exists(status)) {
    throw ConfigError(path + ": cannot open the file (it does not exist)");
  }
  if (fs::is_directory(status)) {
    throw ConfigError(path + ": expected " + what + ", got a directory");
  }
  if (!fs::is_regular_file(status)) {
    throw ConfigError(path + ": expected " + what +
                      ", got a special file (device, FIFO or socket)");
  }
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) {
    throw ConfigError(path + ": cannot open the file (" + error.message() + ")");
  }
  if (size > max_bytes) {
    throw ConfigError(path + ": expected " + what + " of at most " + std::to_string(max_bytes) +
                      " bytes, got " + std::to_string(size) + " bytes");
  }
  return size;
}

std::string read_text_file(const std::string& path, const std::string& what,
                           std::uintmax_t max_bytes) {
  check_text_file(path, what, max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ConfigError(path + ": cannot open the file (" + std::strerror(errno) + ")");
  }
  std::string text(max_bytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) {
    throw ConfigError(path + ": cannot read the file (" + std::strerror(errno) + ")");
  }
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > max_bytes) {
    throw ConfigError(path + ": expected " + what + " of at most " + std::to_string(max_bytes) +
                      " bytes, got more (it grew while read)");
  }
  return text;
}

}  // namespace ari_social_sim::core
