#include "lidr/packing_scheme.h"

#include "lidr/bitshift_scheme.h"
#include "lidr/error.h"

namespace lidr {

std::string PackingScheme::describe() const {
    return name() + " budget " + std::to_string(config_.budget) + ", " + std::to_string(config_.indexBits) +
           "-bit indices, " + std::to_string(targetCount()) + " target" + (targetCount() > 1 ? "s" : "");
}

std::vector<std::string> packingSchemeNames() { return {"bitshift"}; }

std::unique_ptr<PackingScheme> createPackingScheme(const PackingConfig& config, const GlInfo& info) {
    if (config.scheme == "bitshift") return std::make_unique<BitShiftScheme>(config, info);
    std::string valid;
    for (const auto& n : packingSchemeNames()) valid += (valid.empty() ? "" : ", ") + n;
    throw UnsupportedError("unknown packing scheme '" + config.scheme + "' (valid: " + valid + ")");
}

}  // namespace lidr
