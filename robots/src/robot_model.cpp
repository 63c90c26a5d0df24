#include "wpg/robots/robot_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "urdf_loader.hpp"

namespace wpg::robots {
namespace {

// Mass properties being merged into one body (links welded by fixed joints).
struct MassAccumulator {
  int count = 0;                                               // links with mass
  Eigen::Vector3d single_com = Eigen::Vector3d::Zero();        // when count == 1: exact copy
  Eigen::Matrix3d single_inertia = Eigen::Matrix3d::Zero();
  double mass = 0.0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();      // sum m_i c_i
  Eigen::Matrix3d inertia_origin = Eigen::Matrix3d::Zero();    // about the body origin

  void add(double m, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com) {
    if (m == 0.0 && inertia_com.isZero(0.0)) return;  // a massless frame
    ++count;
    single_com = com;
    single_inertia = inertia_com;
    mass += m;
    first_moment += m * com;
    // parallel axis theorem: I_O = I_c + m (|c|^2 1 - c c')
    inertia_origin += inertia_com +
                      m * (com.squaredNorm() * Eigen::Matrix3d::Identity() - com * com.transpose());
  }
  void writeTo(Body& body) const {
    body.mass = mass;
    if (count == 1) {  // no round trip through the parallel axis theorem
      body.com = single_com;
      body.inertia = single_inertia;
      return;
    }
    body.com = mass > 0.0 ? Eigen::Vector3d(first_moment / mass) : Eigen::Vector3d::Zero();
    body.inertia = inertia_origin - mass * (body.com.squaredNorm() * Eigen::Matrix3d::Identity() -
                                            body.com * body.com.transpose());
  }
};

}  // namespace

RobotModel::RobotModel(const std::string& urdf_path, const std::string& srdf_path)
    : urdf_path_(urdf_path) {
  const detail::UrdfDescription urdf = detail::readUrdf(urdf_path);
  name_ = urdf.name;

  std::unordered_map<std::string, int> link_index;
  for (int i = 0; i < static_cast<int>(urdf.links.size()); ++i) link_index[urdf.links[i].name] = i;
  // child joints of each link, in document order
  std::vector<std::vector<int>> child_joints(urdf.links.size());
  for (int j = 0; j < static_cast<int>(urdf.joints.size()); ++j) {
    const auto parent = link_index.find(urdf.joints[j].parent_link);
    if (parent == link_index.end() || link_index.count(urdf.joints[j].child_link) == 0) {
      throw std::runtime_error("URDF file " + urdf_path + ": joint " + urdf.joints[j].name +
                               " refers to an unknown link");
    }
    child_joints[parent->second].push_back(j);
  }

  // Depth-first walk from the root (children in document order, so bodies are topologically
  // ordered): a new body per actuated joint, a frame for every link.
  std::vector<MassAccumulator> mass(1);
  std::vector<int> joint_document_index;  // per created joint slot: its index in urdf.joints
  std::vector<bool> visited(urdf.links.size(), false);
  bodies_.push_back(Body{urdf.root_link, -1, -1});
  std::function<void(int, int, const Pose&)> visit = [&](int link_id, int body, const Pose& placement) {
    if (visited[link_id]) throw std::runtime_error("URDF file " + urdf_path + " is not a tree");
    visited[link_id] = true;
    const detail::UrdfLink& link = urdf.links[link_id];
    frames_.push_back(Frame{link.name, body, placement});
    mass[body].add(link.mass, placement * link.com,
                   placement.rotation * link.inertia * placement.rotation.transpose());
    for (int j : child_joints[link_id]) {
      const detail::UrdfJoint& uj = urdf.joints[j];
      const Pose origin = placement * uj.origin;  // joint frame in the body frame
      const int child = link_index.at(uj.child_link);
      if (uj.type == detail::UrdfJointType::kFixed) {
        visit(child, body, origin);
        continue;
      }
      Joint joint;
      joint.name = uj.name;
      joint.type = uj.type == detail::UrdfJointType::kRevolute     ? JointType::kRevolute
                   : uj.type == detail::UrdfJointType::kContinuous ? JointType::kContinuous
                                                                   : JointType::kPrismatic;
      joint.origin = origin;
      joint.axis = uj.axis;
      joint.lower = uj.lower;
      joint.upper = uj.upper;
      joint.velocity_limit = uj.velocity;
      joint.effort_limit = uj.effort;
      joint.body = static_cast<int>(bodies_.size());
      joints_.push_back(joint);
      joint_document_index.push_back(j);
      bodies_.push_back(Body{uj.child_link, body, static_cast<int>(joints_.size()) - 1});
      mass.emplace_back();
      visit(child, joint.body, Pose{});
    }
  };
  visit(link_index.at(urdf.root_link), 0, Pose{});
  if (frames_.size() != urdf.links.size()) {
    throw std::runtime_error("URDF file " + urdf_path + ": not every link hangs from the root " +
                             urdf.root_link);
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) mass[b].writeTo(bodies_[b]);

  // Configuration order = document order of the actuated joints.
  std::vector<int> order(joints_.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return joint_document_index[a] < joint_document_index[b];
  });
  std::vector<Joint> sorted;
  for (int slot : order) sorted.push_back(joints_[slot]);
  joints_ = std::move(sorted);
  const int nj = jointCount();
  lower_.resize(nj);
  upper_.resize(nj);
  for (int k = 0; k < nj; ++k) {
    joints_[k].index = k;
    bodies_[joints_[k].body].joint = k;
    joint_names_.push_back(joints_[k].name);
    lower_(k) = joints_[k].lower;
    upper_(k) = joints_[k].upper;
  }
  for (const Body& body : bodies_) total_mass_ += body.mass;
  if (!(total_mass_ > 0.0)) throw std::runtime_error("URDF file " + urdf_path + " has no mass");

  // Reference postures from the SRDF.
  std::string srdf = srdf_path;
  if (srdf.empty()) {
    std::filesystem::path candidate(urdf_path);
    candidate.replace_extension(".srdf");
    if (std::filesystem::exists(candidate)) srdf = candidate.string();
  }
  if (!srdf.empty()) {
    reference_postures_ = detail::readSrdfGroupStates(srdf);
    for (const auto& [posture, values] : reference_postures_) {
      for (const auto& [joint, value] : values) {
        if (std::find(joint_names_.begin(), joint_names_.end(), joint) == joint_names_.end()) {
          throw std::runtime_error("SRDF file " + srdf + ": group state " + posture +
                                   " names the unknown joint " + joint);
        }
        (void)value;
      }
    }
  }
}

int RobotModel::jointIndex(const std::string& joint_name) const {
  const auto it = std::find(joint_names_.begin(), joint_names_.end(), joint_name);
  if (it == joint_names_.end()) {
    throw std::invalid_argument("robot " + name_ + " has no actuated joint " + joint_name);
  }
  return static_cast<int>(it - joint_names_.begin());
}

bool RobotModel::hasFrame(const std::string& frame_name) const {
  return std::any_of(frames_.begin(), frames_.end(),
                     [&](const Frame& f) { return f.name == frame_name; });
}

int RobotModel::frameIndex(const std::string& frame_name) const {
  for (std::size_t i = 0; i < frames_.size(); ++i) {
    if (frames_[i].name == frame_name) return static_cast<int>(i);
  }
  throw std::invalid_argument("robot " + name_ + " has no link/frame " + frame_name);
}

Eigen::VectorXd RobotModel::neutralConfiguration() const {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(nq());
  q(3) = 1.0;
  return q;
}

std::vector<std::string> RobotModel::referencePostureNames() const {
  std::vector<std::string> names;
  for (const auto& entry : reference_postures_) names.push_back(entry.first);
  return names;
}

Eigen::VectorXd RobotModel::referenceConfiguration(
    const std::string& posture, const std::vector<std::string>& ground_frames) const {
  const auto it = reference_postures_.find(posture);
  if (it == reference_postures_.end()) {
    throw std::invalid_argument("robot " + name_ + " has no reference posture '" + posture +
                                "' (SRDF <group_state>)");
  }
  Eigen::VectorXd q = neutralConfiguration();
  for (const auto& [joint, value] : it->second) {
    q(kFreeFlyerConfigurationSize + jointIndex(joint)) = value;
  }
  if (!ground_frames.empty()) {
    double lowest = std::numeric_limits<double>::infinity();
    for (const std::string& frame : ground_frames) {
      lowest = std::min(lowest, framePose(q, frame).position.z());
    }
    q(2) = -lowest;
  }
  return q;
}

Eigen::VectorXd RobotModel::halfSitting(const std::string& left_sole_frame,
                                        const std::string& right_sole_frame) const {
  return referenceConfiguration("half_sitting", {left_sole_frame, right_sole_frame});
}

void RobotModel::setFreeFlyer(Eigen::Ref<Eigen::VectorXd> q, const Eigen::Vector3d& position,
                              const Eigen::Quaterniond& orientation) {
  if (q.size() < kFreeFlyerConfigurationSize) {
    throw std::invalid_argument("setFreeFlyer: configuration shorter than 7");
  }
  const Eigen::Quaterniond unit = orientation.normalized();
  q.head<3>() = position;
  q(3) = unit.w();
  q(4) = unit.x();
  q(5) = unit.y();
  q(6) = unit.z();
}

Eigen::Quaterniond RobotModel::freeFlyerOrientation(const Eigen::Ref<const Eigen::VectorXd>& q) {
  return Eigen::Quaterniond(q(3), q(4), q(5), q(6));
}

void RobotModel::checkConfiguration(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  if (q.size() != nq()) {
    throw std::invalid_argument("configuration of robot " + name_ + ": expected " +
                                std::to_string(nq()) + " entries, got " + std::to_string(q.size()));
  }
  if (!q.allFinite()) throw std::invalid_argument("configuration has non-finite entries");
  const double norm = q.segment<4>(3).norm();
  if (std::abs(norm - 1.0) > 1e-6) {
    throw std::invalid_argument("configuration: free-flyer quaternion norm " +
                                std::to_string(norm) + ", expected 1");
  }
}

std::vector<int> RobotModel::jointLimitViolations(const Eigen::Ref<const Eigen::VectorXd>& q,
                                                  double tolerance) const {
  checkConfiguration(q);
  std::vector<int> out;
  for (int k = 0; k < jointCount(); ++k) {
    const double v = q(kFreeFlyerConfigurationSize + k);
    if (v < lower_(k) - tolerance || v > upper_(k) + tolerance) out.push_back(k);
  }
  return out;
}

Pose RobotModel::jointPlacement(int k, double value) const {
  const Joint& joint = joints_.at(static_cast<std::size_t>(k));
  Pose motion;
  if (joint.type == JointType::kPrismatic) {
    motion.position = joint.axis * value;
  } else {
    motion.rotation = Eigen::AngleAxisd(value, joint.axis).toRotationMatrix();
  }
  return joint.origin * motion;
}

void RobotModel::forwardKinematics(const Eigen::Ref<const Eigen::VectorXd>& q,
                                   std::vector<Pose>& body_poses) const {
  checkConfiguration(q);
  body_poses.resize(bodies_.size());
  body_poses[0].position = q.head<3>();
  body_poses[0].rotation = freeFlyerOrientation(q).normalized().toRotationMatrix();
  for (std::size_t b = 1; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    body_poses[b] = body_poses[body.parent] *
                    jointPlacement(body.joint, q(kFreeFlyerConfigurationSize + body.joint));
  }
}

Pose RobotModel::framePose(const Eigen::Ref<const Eigen::VectorXd>& q,
                           const std::string& frame_name) const {
  const Frame& frame = frames_[frameIndex(frame_name)];
  std::vector<Pose> poses;
  forwardKinematics(q, poses);
  return poses[frame.body] * frame.placement;
}

Eigen::Vector3d RobotModel::centerOfMass(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  std::vector<Pose> poses;
  forwardKinematics(q, poses);
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    moment += bodies_[b].mass * (poses[b] * bodies_[b].com);
  }
  return moment / total_mass_;
}

}  // namespace wpg::robots
