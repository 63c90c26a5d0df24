// The process-wide registry of the NMPC's extensions (wpg/nmpc/extension_registry.hpp).
#include "wpg/nmpc/extension_registry.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <set>
#include <utility>

#include "wpg/nearest_name.hpp"
#include "wpg/nmpc/builtin_extensions.hpp"

namespace wpg {
namespace {

template <class Product>
struct Kind {
  const char* what;  // "constraint family", "cost term": for messages
  std::vector<ExtensionSpec<Product>> specs;
};

struct Registry {
  std::mutex mutex;
  Kind<ConstraintFamily> families{"constraint family", {}};
  Kind<CostTerm> costs{"cost term", {}};
};

template <class Product>
void add(Kind<Product>& kind, ExtensionSpec<Product> spec) {
  const std::string what = kind.what;
  if (spec.name.empty()) throw std::invalid_argument(what + ": expected a name, got none");
  if (!spec.make)
    throw std::invalid_argument(what + " '" + spec.name + "': expected a make function");
  for (const auto& known : kind.specs)
    if (known.name == spec.name)
      throw std::invalid_argument(what + " '" + spec.name + "': already registered");
  std::set<std::string> names;
  for (const auto& parameter : spec.parameters)
    if (parameter.name.empty() || !names.insert(parameter.name).second)
      throw std::invalid_argument(what + " '" + spec.name + "': parameter '" + parameter.name +
                                  "' empty or named twice");
  kind.specs.push_back(std::move(spec));
  std::sort(kind.specs.begin(), kind.specs.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
}

Registry& registry() {
  // wpg's own extensions are there before the first look-up or registration.
  static Registry* instance = [] {
    auto* created = new Registry;
    add(created->families, corridorConstraintSpec());
    add(created->costs, lookAtCostSpec());
    return created;
  }();
  return *instance;
}

template <class Product>
ExtensionSpec<Product> find(const Kind<Product>& kind, const std::string& name) {
  std::vector<std::string> names;
  for (const auto& spec : kind.specs) {
    if (spec.name == name) return spec;
    names.push_back(spec.name);
  }
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  throw ExtensionError("", std::string("expected a registered ") + kind.what + " (" + known +
                               "), got '" + name + "'" + didYouMean(name, names));
}

template <class Product>
ExtensionArguments check(const ExtensionSpec<Product>& spec, const ExtensionArguments& given,
                         const ExtensionContext& context) {
  std::vector<std::string> names;
  for (const auto& parameter : spec.parameters) names.push_back(parameter.name);
  for (const auto& [name, value] : given) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      throw ExtensionError(name, "unknown parameter of '" + spec.name + "' (expected " +
                                     (known.empty() ? std::string("none") : known) + ")" +
                                     didYouMean(name, names));
    }
    if (!std::isfinite(value)) throw ExtensionError(name, "expected a finite number");
  }
  ExtensionArguments arguments;
  for (const auto& parameter : spec.parameters) {
    const auto it = given.find(parameter.name);
    if (it != given.end()) {
      arguments[parameter.name] = it->second;
    } else if (parameter.required) {
      throw ExtensionError(parameter.name, "missing: expected " + parameter.description + " [" +
                                               parameter.unit + "]");
    } else {
      arguments[parameter.name] = parameter.default_value;
    }
  }
  if (spec.check) spec.check(arguments, context);
  return arguments;
}

template <class Product>
std::vector<ExtensionSpec<Product>> listed(Kind<Product> Registry::*member) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return (r.*member).specs;
}

template <class Product>
ExtensionSpec<Product> spec(Kind<Product> Registry::*member, const std::string& name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return find(r.*member, name);
}

}  // namespace

void registerConstraintFamily(ConstraintFamilySpec spec) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  add(r.families, std::move(spec));
}

void registerCostTerm(CostTermSpec spec) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  add(r.costs, std::move(spec));
}

std::vector<ConstraintFamilySpec> registeredConstraintFamilies() {
  return listed(&Registry::families);
}
std::vector<CostTermSpec> registeredCostTerms() { return listed(&Registry::costs); }

ExtensionArguments checkConstraintFamily(const std::string& name,
                                         const ExtensionArguments& arguments,
                                         const ExtensionContext& context) {
  return check(spec(&Registry::families, name), arguments, context);
}

ExtensionArguments checkCostTerm(const std::string& name, const ExtensionArguments& arguments,
                                 const ExtensionContext& context) {
  return check(spec(&Registry::costs, name), arguments, context);
}

std::shared_ptr<const ConstraintFamily> makeConstraintFamily(const ExtensionUse& use,
                                                             const ExtensionContext& context) {
  const ConstraintFamilySpec found = spec(&Registry::families, use.name);
  return found.make(check(found, use.arguments, context), context);
}

std::shared_ptr<const CostTerm> makeCostTerm(const ExtensionUse& use,
                                             const ExtensionContext& context) {
  const CostTermSpec found = spec(&Registry::costs, use.name);
  return found.make(check(found, use.arguments, context), context);
}

}  // namespace wpg
