// Wall times as people read them in progress lines ("1h05m", "3m20s", "42s").
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace lbdem::campaign {

/// A duration in seconds as "1h05m", "3m20s" or "42s".
inline std::string formatDuration(double s) {
    char buffer[32];
    if (s >= 3600)
        std::snprintf(buffer, sizeof buffer, "%dh%02dm", int(s / 3600),
                      int(std::fmod(s, 3600) / 60));
    else if (s >= 60)
        std::snprintf(buffer, sizeof buffer, "%dm%02ds", int(s / 60), int(std::fmod(s, 60)));
    else
        std::snprintf(buffer, sizeof buffer, "%.0fs", s);
    return buffer;
}

} // namespace lbdem::campaign
