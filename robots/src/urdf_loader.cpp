// The only translation unit that includes urdfdom (and its TinyXML).
#include "urdf_loader.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <urdf_parser/urdf_parser.h>

namespace wpg::robots::detail {
namespace {

std::string readText(const std::string& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string("cannot read the ") + what + " file " + path);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error(std::string("error reading the ") + what + " file " + path);
  return text.str();
}

Pose toPose(const urdf::Pose& pose) {
  Pose out;
  const auto& r = pose.rotation;
  out.rotation = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  out.position = {pose.position.x, pose.position.y, pose.position.z};
  return out;
}

// A link that is the child of two joints, or a chain of parents that comes back to itself, is
// a loop: a URDF describes a tree. Checked on the XML before urdfdom, whose own refusal is a
// console message and no reason.
void checkTree(const TiXmlElement* robot, const std::string& path) {
  std::map<std::string, std::pair<std::string, std::string>> parent_of;  // child -> joint, parent
  for (const TiXmlElement* joint = robot->FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const TiXmlElement* parent = joint->FirstChildElement("parent");
    const TiXmlElement* child = joint->FirstChildElement("child");
    const char* name = joint->Attribute("name");
    const char* parent_link = parent ? parent->Attribute("link") : nullptr;
    const char* child_link = child ? child->Attribute("link") : nullptr;
    if (!name || !parent_link || !child_link) continue;  // urdfdom names what is missing
    const auto [it, inserted] = parent_of.emplace(child_link, std::pair{name, parent_link});
    if (!inserted) {
      throw std::runtime_error("URDF file " + path + ": link " + child_link +
                               " is the child of two joints, " + it->second.first + " and " +
                               name + " (a loop: a URDF describes a tree)");
    }
  }
  for (const auto& [link, joint] : parent_of) {
    std::string current = link;
    for (std::size_t steps = 0; parent_of.count(current) != 0; ++steps) {
      current = parent_of.at(current).second;
      if (current == link || steps > parent_of.size()) {
        throw std::runtime_error("URDF file " + path + ": the joints from link " + link +
                                 " lead back to it (a loop: a URDF describes a tree)");
      }
    }
  }
}

// Physical mass properties of a link with <inertial>: a positive mass and a positive definite
// inertia (a massless frame has no <inertial>). Simbody and the CoM would take anything.
void checkInertial(const std::string& link, double mass, const Eigen::Matrix3d& inertia,
                   const std::string& path) {
  if (!(mass > 0.0) || !std::isfinite(mass)) {
    std::ostringstream value;
    value << mass;
    throw std::runtime_error("URDF file " + path + ": link " + link + " has mass " +
                             value.str() + " kg, expected a positive mass (a massless frame has "
                             "no <inertial>)");
  }
  const Eigen::Vector3d eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(
      inertia, Eigen::EigenvaluesOnly).eigenvalues();
  if (!inertia.allFinite() || !(eigenvalues.minCoeff() > 0.0)) {
    std::ostringstream values;
    values << eigenvalues(0) << ", " << eigenvalues(1) << ", " << eigenvalues(2);
    throw std::runtime_error("URDF file " + path + ": link " + link + " has an inertia that is "
                             "not positive definite (eigenvalues " + values.str() + " kg m^2)");
  }
}

// Joint names in the order of the <joint> elements (urdfdom keeps them in a std::map).
std::vector<std::string> jointDocumentOrder(const std::string& xml, const std::string& path) {
  TiXmlDocument document;
  document.Parse(xml.c_str());
  if (document.Error()) {
    throw std::runtime_error("malformed URDF file " + path + ": " + document.ErrorDesc());
  }
  const TiXmlElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) throw std::runtime_error("URDF file " + path + " has no <robot> element");
  checkTree(robot, path);
  std::vector<std::string> names;
  for (const TiXmlElement* joint = robot->FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const char* name = joint->Attribute("name");
    if (name == nullptr) throw std::runtime_error("URDF file " + path + ": <joint> without a name");
    names.emplace_back(name);
  }
  return names;
}

}  // namespace

UrdfDescription readUrdf(const std::string& path) {
  const std::string xml = readText(path, "URDF");
  const std::vector<std::string> joint_order = jointDocumentOrder(xml, path);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  if (!model) throw std::runtime_error("cannot parse the URDF file " + path + " (urdfdom)");
  if (!model->getRoot()) throw std::runtime_error("URDF file " + path + " has no root link");

  UrdfDescription out;
  out.name = model->getName();
  out.root_link = model->getRoot()->name;
  for (const auto& [name, link] : model->links_) {
    UrdfLink l;
    l.name = name;
    if (link->inertial) {
      const urdf::Inertial& in = *link->inertial;
      const Pose origin = toPose(in.origin);
      Eigen::Matrix3d inertia;
      inertia << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
      checkInertial(name, in.mass, inertia, path);
      l.mass = in.mass;
      l.com = origin.position;
      l.inertia = origin.rotation * inertia * origin.rotation.transpose();
    }
    out.links.push_back(std::move(l));
  }
  if (joint_order.size() != model->joints_.size()) {
    throw std::runtime_error("URDF file " + path + ": duplicate joint names");
  }
  for (const std::string& name : joint_order) {
    const auto it = model->joints_.find(name);
    if (it == model->joints_.end()) {
      throw std::runtime_error("URDF file " + path + ": joint " + name + " not parsed");
    }
    const urdf::Joint& joint = *it->second;
    UrdfJoint j;
    j.name = name;
    j.parent_link = joint.parent_link_name;
    j.child_link = joint.child_link_name;
    j.origin = toPose(joint.parent_to_joint_origin_transform);
    switch (joint.type) {
      case urdf::Joint::REVOLUTE: j.type = UrdfJointType::kRevolute; break;
      case urdf::Joint::CONTINUOUS: j.type = UrdfJointType::kContinuous; break;
      case urdf::Joint::PRISMATIC: j.type = UrdfJointType::kPrismatic; break;
      case urdf::Joint::FIXED: j.type = UrdfJointType::kFixed; break;
      default:
        throw std::runtime_error("URDF file " + path + ": joint " + name +
                                 " has an unsupported type (floating and planar joints are not "
                                 "supported; the free-flyer is added by wpg)");
    }
    if (j.type != UrdfJointType::kFixed) {
      const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
      if (!(axis.norm() > 0.0)) {
        throw std::runtime_error("URDF file " + path + ": joint " + name + " has a zero axis");
      }
      j.axis = axis.normalized();
      constexpr double kInf = std::numeric_limits<double>::infinity();
      j.lower = -kInf;
      j.upper = kInf;
      if (joint.limits) {
        j.velocity = joint.limits->velocity;
        j.effort = joint.limits->effort;
        if (j.type != UrdfJointType::kContinuous) {
          j.lower = joint.limits->lower;
          j.upper = joint.limits->upper;
        }
      }
    }
    out.joints.push_back(std::move(j));
  }
  return out;
}

std::map<std::string, std::map<std::string, double>> readSrdfGroupStates(const std::string& path) {
  const std::string xml = readText(path, "SRDF");
  TiXmlDocument document;
  document.Parse(xml.c_str());
  if (document.Error()) {
    throw std::runtime_error("malformed SRDF file " + path + ": " + document.ErrorDesc());
  }
  const TiXmlElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) throw std::runtime_error("SRDF file " + path + " has no <robot> element");
  std::map<std::string, std::map<std::string, double>> states;
  for (const TiXmlElement* state = robot->FirstChildElement("group_state"); state != nullptr;
       state = state->NextSiblingElement("group_state")) {
    const char* state_name = state->Attribute("name");
    if (state_name == nullptr) {
      throw std::runtime_error("SRDF file " + path + ": <group_state> without a name");
    }
    auto& values = states[state_name];
    for (const TiXmlElement* joint = state->FirstChildElement("joint"); joint != nullptr;
         joint = joint->NextSiblingElement("joint")) {
      const char* joint_name = joint->Attribute("name");
      const char* value = joint->Attribute("value");
      if (joint_name == nullptr || value == nullptr) {
        throw std::runtime_error("SRDF file " + path + ": group state " + state_name +
                                 " has a <joint> without name or value");
      }
      char* end = nullptr;
      const double v = std::strtod(value, &end);
      if (end == value || *end != '\0' || !std::isfinite(v)) {
        throw std::runtime_error("SRDF file " + path + ": group state " + state_name + ", joint " +
                                 joint_name + ": value '" + value + "' is not one number");
      }
      values[joint_name] = v;
    }
  }
  return states;
}

}  // namespace wpg::robots::detail
