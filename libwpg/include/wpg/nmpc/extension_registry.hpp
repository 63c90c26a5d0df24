#pragma once
// The NMPC's extension points by name: constraint families (constraint_family.hpp) and cost
// terms (cost_term.hpp) registered with their parameters, so that scenario files
// (`constraints:`, `costs:`), the CLI's --set, Python and GeneratorSettings::constraints /
// ::costs can enable them without code. wpg registers its own (corridor, look_at:
// builtin_extensions.hpp) before the first look-up; a program registers more at start-up
// (docs/extending.md). The registry is process-wide and guarded by a mutex; look-ups happen
// when generators are built, never in the NMPC's loop.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/nmpc/constraint_family.hpp"
#include "wpg/nmpc/cost_term.hpp"
#include "wpg/walk_request.hpp"
#include "wpg/walking_parameters.hpp"

namespace wpg {

struct ExtensionParameter {
  std::string name;         // snake_case key, e.g. "left"
  std::string unit;         // e.g. "m", "rad", "1" (no unit)
  std::string description;  // one line, for listings and messages
  bool required = true;
  double default_value = 0.0;  // when not required and not given
};

// What an extension may check its parameters against: the walk's robot and start.
struct ExtensionContext {
  WalkingParameters walking;
  Eigen::Vector3d start_pose = Eigen::Vector3d::Zero();  // x, y, yaw where the walk starts
};

// A parameter (or, with parameter() empty, the extension's name) that is not what was
// expected; what() says what was expected and what came, without the key (the caller names
// it: "constraints.corridor.left").
class ExtensionError : public std::invalid_argument {
 public:
  ExtensionError(std::string parameter, const std::string& message)
      : std::invalid_argument(message), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }

 private:
  std::string parameter_;
};

template <class Product>
struct ExtensionSpec {
  std::string name;  // snake_case, unique among its kind
  std::string description;
  std::vector<ExtensionParameter> parameters;
  // Checks beyond each parameter being given and finite (ranges, against the robot): throws
  // ExtensionError naming the parameter. May be empty.
  std::function<void(const ExtensionArguments&, const ExtensionContext&)> check;
  // Builds it from checked arguments (every parameter present, defaults filled in).
  std::function<std::shared_ptr<const Product>(const ExtensionArguments&,
                                               const ExtensionContext&)>
      make;
};
using ConstraintFamilySpec = ExtensionSpec<ConstraintFamily>;
using CostTermSpec = ExtensionSpec<CostTerm>;

// Throws std::invalid_argument for an empty or taken name, a spec without `make`, or
// parameters named twice.
void registerConstraintFamily(ConstraintFamilySpec spec);
void registerCostTerm(CostTermSpec spec);

// Every registered one (wpg's included), sorted by name.
std::vector<ConstraintFamilySpec> registeredConstraintFamilies();
std::vector<CostTermSpec> registeredCostTerms();

// `arguments` checked against the spec of `name`: the name registered (else ExtensionError
// with an empty parameter and a did-you-mean), every parameter known (did-you-mean), the
// required ones given, all finite, then the spec's own check. Returns them with the defaults
// filled in.
ExtensionArguments checkConstraintFamily(const std::string& name,
                                         const ExtensionArguments& arguments,
                                         const ExtensionContext& context);
ExtensionArguments checkCostTerm(const std::string& name, const ExtensionArguments& arguments,
                                 const ExtensionContext& context);

// Checked (as above), then built.
std::shared_ptr<const ConstraintFamily> makeConstraintFamily(const ExtensionUse& use,
                                                             const ExtensionContext& context);
std::shared_ptr<const CostTerm> makeCostTerm(const ExtensionUse& use,
                                             const ExtensionContext& context);

}  // namespace wpg
