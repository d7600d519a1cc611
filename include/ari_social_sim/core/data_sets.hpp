#pragma once

#include <string>

namespace ari_social_sim::core {

/// The folder the public data sets live in (docs/data.md): $ARI_DATA_DIR when set and not empty,
/// else ~/.local/share/ari_social_sim/data, where scripts/fetch_data.sh puts them by default.
/// None of them is part of the repository; nothing the product needs by default is in them.
std::string data_dir();

/// The folder of one data set below data_dir(): `fformation` (the F-formation recordings as CSV)
/// or `dialogue/mpgt` (the MPGT conversations).
std::string data_set_dir(const std::string& name);

/// Whether data_set_dir(name) is a folder that holds at least one file. fetch_data.sh moves a set
/// in place only once every file of it is checked, so a folder that exists is complete.
bool data_set_present(const std::string& name);

/// One sentence for a user or a skipped test: which set is missing, where it was looked for and
/// the command that fetches it.
std::string missing_data_set_message(const std::string& name);

}  // namespace ari_social_sim::core
