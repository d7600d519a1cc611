#pragma once

#include <cstdint>
#include <string>

namespace ari_social_sim::core {

/// Checks what the file system can tell about a file a user named, before a byte is read: that
/// `path` exists, is a regular file (not a directory, device, FIFO or socket) and holds at most
/// `max_bytes`. `what` names the expected content in the messages ("a YAML file", "a URDF file").
/// Returns the size; throws ConfigError naming the path and what was found.
std::uintmax_t check_text_file(const std::string& path, const std::string& what,
                               std::uintmax_t max_bytes);

/// The whole of a file that check_text_file accepts, read without ever holding more than
/// `max_bytes` + 1 bytes (a file that grew since it was measured is refused all the same).
std::string read_text_file(const std::string& path, const std::string& what,
                           std::uintmax_t max_bytes);

}  // namespace ari_social_sim::core
