#pragma once

#include <string>

namespace ari_social_sim::tools {

/// docs/parameters.md: every private parameter of every node and every key of every
/// configuration file, with type, default, range and meaning, from the config structs' visit
/// (core/config_fields.hpp).
std::string parameters_page();

}  // namespace ari_social_sim::tools
