#include "app/arguments.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "app/did_you_mean.h"
#include "error.h"

namespace vct {

Arguments::Arguments(const std::vector<std::string>& arguments, const std::set<std::string>& flags,
                     const std::set<std::string>& valued) {
    for (size_t i = 0; i < arguments.size(); ++i) {
        // "-h" is the one short option: what people type first when they meet a tool.
        const std::string& argument = arguments[i] == "-h" ? "--help" : arguments[i];
        if (argument.rfind("--", 0) != 0) throw Error("unexpected argument '" + argument + "' (see --help)");
        const std::string name = argument.substr(2);
        if (flags.count(name)) {
            values_[name] = "";
        } else if (valued.count(name)) {
            if (i + 1 >= arguments.size()) throw Error("option --" + name + " needs a value");
            values_[name] = arguments[++i];
        } else {
            std::vector<std::string> known(flags.begin(), flags.end());
            known.insert(known.end(), valued.begin(), valued.end());
            const std::string hint = didYouMean(name, known, "--");
            throw Error("unknown option --" + name + (hint.empty() ? " (see --help)" : hint));
        }
    }
}

std::string Arguments::text(const std::string& name, const std::string& fallback) const {
    auto found = values_.find(name);
    return found == values_.end() ? fallback : found->second;
}

uint32_t Arguments::unsignedInt(const std::string& name, uint32_t fallback, uint32_t min, uint32_t max) const {
    auto found = values_.find(name);
    if (found == values_.end()) return fallback;
    char* end = nullptr;
    const long long value = std::strtoll(found->second.c_str(), &end, 10);
    if (end == found->second.c_str() || *end != '\0' || value < min || value > max)
        throw Error("--" + name + " must be a whole number from " + std::to_string(min) + " to " + std::to_string(max) +
                    ", not '" + found->second + "'");
    return uint32_t(value);
}

float Arguments::number(const std::string& name, float fallback, float min, float max) const {
    auto found = values_.find(name);
    if (found == values_.end()) return fallback;
    char* end = nullptr;
    const float value = std::strtof(found->second.c_str(), &end);
    if (end == found->second.c_str() || *end != '\0' || !std::isfinite(value) || value < min || value > max) {
        std::ostringstream message;
        message << "--" << name << " must be a number from " << min << " to " << max << ", not '" << found->second
                << "'";
        throw Error(message.str());
    }
    return value;
}

std::optional<glm::vec3> Arguments::vector3(const std::string& name) const {
    auto found = values_.find(name);
    if (found == values_.end()) return std::nullopt;
    glm::vec3 value;
    char comma1 = 0, comma2 = 0;
    std::istringstream in(found->second);
    in >> value.x >> comma1 >> value.y >> comma2 >> value.z;
    if (!in || comma1 != ',' || comma2 != ',' || !in.eof() || !std::isfinite(value.x) || !std::isfinite(value.y) ||
        !std::isfinite(value.z))
        throw Error("--" + name + " must be three numbers separated by commas (x,y,z), not '" + found->second + "'");
    return value;
}

}  // namespace vct
