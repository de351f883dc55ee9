#pragma once
// summary.md's targets section (bench_targets.cpp): the issues' speed and accuracy targets, judged on the rows of
// this run ("met", "**missed**", or "not measured" where a configuration is missing). A new target, mode or peer
// to compare with goes there.
#include <ostream>
#include <string>
#include <vector>

#include "bench_report.h"

namespace lidr::bench {

// "0.71 (0.66-0.78)": a's frame over b's in the same rounds (median, and its range over the rounds); "-" where b is
// missing. value: the median ratio, -1 where not measured.
std::string ratioCell(const Row& a, const Row* b, double& value);

// Writes "## Targets (issue 6)" (the default room at 1024x768, the budget at or above each scene's maximum
// overlap) and, where its configurations were measured, "## Targets (issue 25)" (deep, occluded scenes).
void writeTargets(std::ostream& o, const std::vector<Row>& rows);

// "## Targets (issue 37)" (bench_peer_targets.cpp), where LIDR's default was measured beside tiled or clustered:
// LIDR over the faster of the two ("best peer") with both ratios, and --mode auto over the fastest lossless mode.
void writePeerTargets(std::ostream& o, const std::vector<Row>& rows);

}  // namespace lidr::bench
