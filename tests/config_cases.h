#pragma once
// Named cases for the tests that sweep packing schemes, budgets, index widths, volume tests and overlaps. Each
// builder lists exactly the combinations a test covers (nothing is filtered out in the test), and the test runs
// them as a table:
//
//     const ConfigCase c = GENERATE(from_range(packingCases()));
//     DYNAMIC_SECTION(c.name) { ... c.packing ... }
//
// so a failure names its case, and `lidr-tests "[tag]" -c "bitshift budget 4, 8-bit"` runs one.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lidr/technique/packing_scheme.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr::test {

inline const std::vector<int> kBudgets = {1, 2, 4, 8, 16};
inline const std::vector<int> kIndexWidths = {4, 8, 16};

struct ConfigCase {
    std::string name;        // e.g. "max-stencil budget 4, 8-bit, backface, k 8"
    PackingConfig packing;   // a concrete scheme, budget and index width
    VolumeTest volumeTest = VolumeTest::BackFace;
    int overlap = 0;         // controlled-overlap scenes: the lights on every lit pixel (0: not part of the case)
};

inline ConfigCase packingCase(PackingSchemeKind scheme, int budget, int indexBits) {
    return {std::string(packingSchemeName(scheme)) + " budget " + std::to_string(budget) + ", " +
                std::to_string(indexBits) + "-bit",
            {scheme, budget, indexBits}};
}

// Each scheme with each (index width, budget) pair, scheme by scheme.
inline std::vector<ConfigCase> packingCasesFor(const std::vector<std::pair<int, int>>& widthBudgets,
                                               const std::vector<PackingSchemeKind>& schemes = packingSchemes()) {
    std::vector<ConfigCase> cases;
    for (PackingSchemeKind scheme : schemes)
        for (const auto& [bits, budget] : widthBudgets) cases.push_back(packingCase(scheme, budget, bits));
    return cases;
}

// Each scheme x index width x budget: scheme, then width, then budget.
inline std::vector<ConfigCase> packingCases(const std::vector<int>& budgets = kBudgets,
                                            const std::vector<int>& widths = kIndexWidths,
                                            const std::vector<PackingSchemeKind>& schemes = packingSchemes()) {
    std::vector<std::pair<int, int>> widthBudgets;
    for (int bits : widths)
        for (int budget : budgets) widthBudgets.emplace_back(bits, budget);
    return packingCasesFor(widthBudgets, schemes);
}

// Each case once per volume test, volume test first.
inline std::vector<ConfigCase> withVolumeTests(const std::vector<ConfigCase>& cases, const std::vector<VolumeTest>& tests) {
    std::vector<ConfigCase> out;
    for (VolumeTest test : tests)
        for (ConfigCase c : cases) {
            c.name += std::string(", ") + volumeTestName(test);
            c.volumeTest = test;
            out.push_back(std::move(c));
        }
    return out;
}

// Each case once per overlap k that overlapsOf(case) lists.
inline std::vector<ConfigCase> withOverlaps(const std::vector<ConfigCase>& cases,
                                            const std::function<std::vector<int>(const ConfigCase&)>& overlapsOf) {
    std::vector<ConfigCase> out;
    for (const ConfigCase& c : cases)
        for (int k : overlapsOf(c)) {
            ConfigCase withK = c;
            withK.name += ", k " + std::to_string(k);
            withK.overlap = k;
            out.push_back(std::move(withK));
        }
    return out;
}

}  // namespace lidr::test
