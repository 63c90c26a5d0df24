// `constraints:` and `costs:` of a scenario (extension_sections.hpp).
#include "extension_sections.hpp"

#include <algorithm>

#include "plain_scalar.hpp"
#include "wpg/nearest_name.hpp"
#include "wpg/nmpc/extension_registry.hpp"

namespace wpg::datasets::detail {
namespace {

const char* sectionName(ExtensionKind kind) {
  return kind == ExtensionKind::kConstraint ? "constraints" : "costs";
}

template <class Spec>
std::vector<std::string> namesOf(const std::vector<Spec>& specs) {
  std::vector<std::string> names;
  for (const Spec& spec : specs) names.push_back(spec.name);
  return names;
}

}  // namespace

std::vector<ExtensionUse> readExtensions(const YAML::Node& node, ExtensionKind kind,
                                         const WalkingParameters& walking, const Source& source) {
  std::vector<ExtensionUse> uses;
  if (!node.IsDefined() || node.IsNull()) return uses;
  const std::string section = sectionName(kind);
  const bool constraint = kind == ExtensionKind::kConstraint;
  const std::vector<std::string> names =
      constraint ? namesOf(registeredConstraintFamilies()) : namesOf(registeredCostTerms());
  const std::string expected =
      std::string("a map of registered ") + (constraint ? "constraint families" : "cost terms") +
      " (" + joinNames(names) + ") to maps of their parameters";
  if (node.IsMap()) {
    for (const auto& pair : node) {
      const std::string name = pair.first.IsScalar() ? pair.first.Scalar() : "";
      if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) {
        source.failWith(childKey(section, name),
                        std::string("unknown ") + (constraint ? "constraint family" : "cost term") +
                            (nearestName(name, names).empty()
                                 ? std::string()
                                 : ", did you mean '" + nearestName(name, names) + "'?") +
                            " (registered: " + joinNames(names) + ")");
      }
    }
  }
  const Entries entries = readMap(node, section, names, expected, source, /*null_is_empty=*/true);
  ExtensionContext context;
  context.walking = walking;
  for (const auto& [name, parameters] : entries) {
    const std::string key = childKey(section, name);
    ExtensionUse use;
    use.name = name;
    if (!parameters.IsNull()) {
      if (!parameters.IsMap()) source.fail(key, "a map of parameters to numbers", parameters);
      for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        const std::string parameter = it->first.IsScalar() ? it->first.Scalar() : "";
        if (parameter.empty()) source.fail(key, "parameter names as keys", it->first);
        const double value = readNumber(it->second, childKey(key, parameter), "a number", source);
        if (!use.arguments.emplace(parameter, value).second)
          source.failWith(childKey(key, parameter), "appears twice; give each key once");
      }
    }
    try {
      use.arguments = constraint ? checkConstraintFamily(name, use.arguments, context)
                                 : checkCostTerm(name, use.arguments, context);
    } catch (const ExtensionError& error) {
      source.failWith(error.parameter().empty() ? key : childKey(key, error.parameter()),
                      error.what());
    }
    uses.push_back(std::move(use));
  }
  return uses;
}

void emitExtensions(YAML::Emitter& out, ExtensionKind kind,
                    const std::vector<ExtensionUse>& uses) {
  if (uses.empty()) return;
  emitKey(out, sectionName(kind));
  out << YAML::BeginMap;
  for (const ExtensionUse& use : uses) {
    emitKey(out, use.name);
    out << YAML::Flow << YAML::BeginMap;
    for (const auto& [parameter, value] : use.arguments) {
      emitKey(out, parameter);
      emitScalar(out, formatNumber(value));
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

}  // namespace wpg::datasets::detail
