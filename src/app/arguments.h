// A small command-line reader: `--name value` and `--flag`, with errors that name the option.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vct {

class Arguments {
public:
    // `flags` are options that take no value; every other `--name` takes one.
    Arguments(const std::vector<std::string>& arguments, const std::set<std::string>& flags,
              const std::set<std::string>& valued);

    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string text(const std::string& name, const std::string& fallback) const;
    uint32_t unsignedInt(const std::string& name, uint32_t fallback, uint32_t min, uint32_t max) const;
    float number(const std::string& name, float fallback, float min, float max) const;
    std::optional<glm::vec3> vector3(const std::string& name) const;

private:
    std::map<std::string, std::string> values_;
};

}  // namespace vct
