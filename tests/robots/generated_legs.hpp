#pragma once
// URDF robots with generated legs, for the IK tests: a root link and two legs, each a chain of
// revolute joints ending in a massless sole frame, with an SRDF whose half_sitting is empty.
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace wpg::test {

struct GeneratedJoint {
  Eigen::Vector3d origin;  // in the previous joint's frame (the root's for the first)
  Eigen::Vector3d axis;    // unit, in the joint's frame
  double lower = -3.0, upper = 3.0;
};

struct GeneratedLeg {
  std::vector<GeneratedJoint> joints;
  Eigen::Vector3d sole;  // sole frame in the last joint's frame
};

// A generated leg and the nominal axis of each joint ('x', 'y', 'z': hip yaw 'z', knee 'y'...).
struct GeneralLegShape {
  GeneratedLeg leg;
  std::vector<char> kind;
};

// HRP-2's leg structure (hip yaw z, roll x, pitch y, knee y, ankle pitch y, roll x; hip and
// ankle axes intersecting) with random lengths and offsets: what the analytic IK solves.
// `side` +1 left, -1 right.
inline GeneratedLeg hrp2LikeLeg(std::mt19937& rng, double side) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double thigh = 0.15 + 0.35 * u(rng), shank = 0.15 + 0.35 * u(rng);
  GeneratedLeg leg;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  leg.joints = {
      {Eigen::Vector3d(0.02 * (u(rng) - 0.5), side * (0.04 + 0.08 * u(rng)), -0.1 * u(rng)), z},
      {Eigen::Vector3d::Zero(), x},
      {Eigen::Vector3d::Zero(), y},
      {Eigen::Vector3d(0.0, side * 0.04 * (u(rng) - 0.5), -thigh), y, 0.0, 2.6},
      {Eigen::Vector3d(0.0, side * 0.04 * (u(rng) - 0.5), -shank), y},
      {Eigen::Vector3d::Zero(), x}};
  leg.sole = Eigen::Vector3d(0.0, 0.0, -(0.04 + 0.08 * u(rng)));
  return leg;
}

// A leg of HRP-2's order of joints (hip yaw, roll, pitch, knee, ankle pitch, roll; with 7
// joints a second yaw above the ankle) whose axes are tilted by up to 0.3 rad and whose joints
// are 1-6 cm apart: no two hip axes meet, the analytic IK does not apply.
inline GeneralLegShape generalLeg(std::mt19937& rng, double side, int joints) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                        z = Eigen::Vector3d::UnitZ();
  std::vector<Eigen::Vector3d> axes = {z, x, y, y, y, x};
  if (joints >= 7) axes.insert(axes.begin() + 4, z);
  while (static_cast<int>(axes.size()) < joints) axes.insert(axes.begin() + 1, x);
  axes.resize(static_cast<std::size_t>(joints));
  GeneralLegShape shape;
  for (int i = 0; i < joints; ++i) {
    GeneratedJoint joint;
    joint.origin = Eigen::Vector3d(0.03 * u(rng), 0.02 * u(rng), -(0.01 + 0.04 * std::abs(u(rng))));
    if (i == 0) joint.origin.y() += side * 0.1;
    if (axes[i] == y && i > 0 && axes[i - 1] == y) joint.origin.z() -= 0.25 + 0.1 * u(rng);
    const Eigen::Vector3d tilt(u(rng), u(rng), u(rng));
    joint.axis = (Eigen::AngleAxisd(0.3 * std::abs(u(rng)), tilt.normalized()) * axes[i]).normalized();
    shape.leg.joints.push_back(joint);
    shape.kind.push_back(axes[i] == z ? 'z' : axes[i] == x ? 'x' : 'y');
  }
  shape.leg.sole = Eigen::Vector3d(0.0, 0.0, -0.1);
  return shape;
}

inline std::string vector3(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out.precision(17);
  out << v.x() << ' ' << v.y() << ' ' << v.z();
  return out.str();
}

// Writes `path` (.urdf) and the .srdf beside it; the soles are LEFT_SOLE and RIGHT_SOLE.
inline void writeTwoLeggedRobot(const std::string& path, const GeneratedLeg& left,
                                const GeneratedLeg& right) {
  std::ofstream out(path);
  out << "<robot name=\"generated\">\n"
      << "  <link name=\"base\"><inertial><origin xyz=\"0 0 0.1\"/><mass value=\"10\"/>"
         "<inertia ixx=\"0.2\" ixy=\"0\" ixz=\"0\" iyy=\"0.2\" iyz=\"0\" izz=\"0.1\"/>"
         "</inertial></link>\n";
  const auto writeLeg = [&](const GeneratedLeg& leg, const std::string& name) {
    std::string parent = "base";
    for (std::size_t i = 0; i < leg.joints.size(); ++i) {
      const GeneratedJoint& j = leg.joints[i];
      const std::string link = name + "_link" + std::to_string(i);
      out << "  <joint name=\"" << name << "_joint" << i << "\" type=\"revolute\"><parent link=\""
          << parent << "\"/><child link=\"" << link << "\"/><origin xyz=\"" << vector3(j.origin)
          << "\"/><axis xyz=\"" << vector3(j.axis) << "\"/><limit lower=\"" << j.lower
          << "\" upper=\"" << j.upper << "\" effort=\"100\" velocity=\"3\"/></joint>\n"
          << "  <link name=\"" << link << "\"><inertial><origin xyz=\"0.01 0 -0.05\"/>"
          << "<mass value=\"1.5\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" "
             "iyz=\"0\" izz=\"0.005\"/></inertial></link>\n";
      parent = link;
    }
    const std::string sole = name == "left" ? "LEFT_SOLE" : "RIGHT_SOLE";
    out << "  <joint name=\"" << sole << "_JOINT\" type=\"fixed\"><parent link=\"" << parent
        << "\"/><child link=\"" << sole << "\"/><origin xyz=\"" << vector3(leg.sole)
        << "\"/></joint>\n  <link name=\"" << sole << "\"/>\n";
  };
  writeLeg(left, "left");
  writeLeg(right, "right");
  out << "</robot>\n";
  std::string srdf = path.substr(0, path.size() - 5) + ".srdf";
  std::ofstream(srdf) << "<robot name=\"generated\"><group_state name=\"half_sitting\" "
                         "group=\"all\"/></robot>\n";
}

}  // namespace wpg::test
