#include "page_bench.h"

#include <algorithm>
#include <cstdio>

namespace lidr::web {

std::string benchTable(const std::string& what, const std::vector<BenchRow>& rows) {
    std::string table = "lidr-web bench: " + what + "\n";
    char line[200];
    std::snprintf(line, sizeof line, "%-18s %6s %9s %9s %9s %9s %8s\n", "mode", "frames", "mean ms", "median ms",
                  "min ms", "max ms", "fps");
    table += line;
    for (const BenchRow& row : rows) {
        if (!row.refused.empty() || row.frameMs.empty()) {
            table += row.mode + std::string(row.mode.size() < 18 ? 18 - row.mode.size() : 0, ' ') + " refused: " +
                     (row.refused.empty() ? "no frame" : row.refused) + "\n";
            continue;
        }
        std::vector<double> sorted = row.frameMs;
        std::sort(sorted.begin(), sorted.end());
        double sum = 0.0;
        for (double ms : sorted) sum += ms;
        const double mean = sum / double(sorted.size());
        const size_t n = sorted.size();
        const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        std::snprintf(line, sizeof line, "%-18s %6zu %9.2f %9.2f %9.2f %9.2f %8.1f\n", row.mode.c_str(), n, mean,
                      median, sorted.front(), sorted.back(), mean > 0.0 ? 1000.0 / mean : 0.0);
        table += line;
    }
    return table;
}

}  // namespace lidr::web
