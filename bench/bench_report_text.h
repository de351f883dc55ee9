#pragma once
// How lidr-bench's report files write numbers and name rows (bench_report.cpp defines them): shared by the CSV
// files, summary.md (bench_summary.cpp, bench_targets.cpp) and the plots (bench_plots.cpp).
#include <string>
#include <vector>

#include "bench_report.h"

namespace lidr::bench {

// A number with at most `precision` decimals, trailing zeros dropped ("0.25", "12").
std::string num(double v, int precision = 4);
// Milliseconds as the summary shows them: 0 decimals from 100, 1 from 10, else 2.
std::string ms(double v);
// "scene WxH": a row's scene and size.
std::string sceneKey(const Row& r);
// The rows' scene keys in measurement order, each once.
std::vector<std::string> sceneOrder(const std::vector<Row>& rows);
// The row of that scene, size and configuration key; null where it was not measured.
const Row* findRow(const std::vector<Row>& rows, const std::string& scene, int w, int h, const std::string& key);

}  // namespace lidr::bench
