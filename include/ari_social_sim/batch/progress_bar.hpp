#pragma once

#include <cstdint>
#include <string>

namespace ari_social_sim::batch {

/// The batch tool's progress line: a bar, the count, the rate in episodes per minute and the
/// estimated time left at that rate, e.g.
///   `[##########----------]  50/100 episodes  62.5 ep/min  ETA 0:48`
/// Rate and ETA appear once one episode is done and some time has passed.
std::string progress_line(uint64_t done, uint64_t total, double elapsed_s, int bar_width = 20);

/// `m:ss` below an hour, `h:mm:ss` above.
std::string format_duration(double seconds);

}  // namespace ari_social_sim::batch
