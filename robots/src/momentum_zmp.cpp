// The multibody ZMP from the rate of the momentum (momentum_zmp.hpp).
#include "wpg/robots/momentum_zmp.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "finite_differences.hpp"

namespace wpg::robots {
namespace {

// r <- r Rot(e_axis, angle) for a coordinate axis (0 x, 1 y, 2 z), c = cos(angle),
// s = sin(angle): only the two columns orthogonal to the axis change.
inline void rotateAboutCoordinateAxis(Eigen::Matrix3d& r, int axis, double c, double s) {
  const int i = axis == 2 ? 0 : axis + 1, j = axis == 0 ? 2 : axis - 1;  // (i, j, axis) cyclic
  const Eigen::Vector3d ci = r.col(i);
  r.col(i) = c * ci + s * r.col(j);
  r.col(j) = c * r.col(j) - s * ci;
}

int coordinateAxis(const Eigen::Vector3d& axis) {
  for (int i = 0; i < 3; ++i)
    if (axis == Eigen::Vector3d::Unit(i)) return i;
  return -1;
}

}  // namespace

MomentumZmp::MomentumZmp(const RobotModel& model, double gravity)
    : model_(model), gravity_(gravity) {
  if (!(gravity_ >= 0.0) || !std::isfinite(gravity_)) {
    throw std::invalid_argument("momentum ZMP: gravity must be finite and >= 0");
  }
  const std::size_t nb = model_.bodies().size();
  const std::size_t nj = static_cast<std::size_t>(model_.jointCount());
  bodies_.reserve(nb);
  motion_.resize(nb);
  host_.resize(nb);
  in_host_.resize(nb);
  welded_.assign(nj, 0);
  constant_.assign(nj, 0);
  weld_values_ = Eigen::VectorXd::Zero(model_.jointCount());
  total_mass_ = model_.totalMass();
  result_.joint_torques.resize(0, model_.jointCount());
}

void MomentumZmp::weldConstantJoints() {
  const int nj = model_.jointCount();
  const Eigen::Index n = qt_.cols();
  bool same = built_;
  for (int k = 0; k < nj; ++k) {
    const auto row = qt_.row(RobotModel::kFreeFlyerConfigurationSize + k);
    const double first = row(0);
    bool constant = true;
    for (Eigen::Index i = 1; i < n && constant; ++i) constant = row(i) == first;
    constant_[static_cast<std::size_t>(k)] = constant ? 1 : 0;
    if (constant != (welded_[static_cast<std::size_t>(k)] != 0) ||
        (constant && weld_values_(k) != first))
      same = false;
  }
  if (same) return;
  for (int k = 0; k < nj; ++k) {
    welded_[static_cast<std::size_t>(k)] = constant_[static_cast<std::size_t>(k)];
    weld_values_(k) = welded_[static_cast<std::size_t>(k)]
                          ? qt_(RobotModel::kFreeFlyerConfigurationSize + k, 0)
                          : 0.0;
  }
  buildBodies();
}

void MomentumZmp::buildBodies() {
  const std::vector<wpg::robots::Body>& model_bodies = model_.bodies();
  const std::size_t nb = model_bodies.size();
  // Mass, first moment and inertia about the origin summed per host, in the host's frame
  // (parallel axis theorem); a welded body's frame is placed by its joint at the held value.
  bodies_.clear();
  std::vector<Eigen::Vector3d>& first_moment = first_moment_;
  std::vector<Eigen::Matrix3d>& inertia_origin = inertia_origin_;
  first_moment.assign(nb, Eigen::Vector3d::Zero());
  inertia_origin.assign(nb, Eigen::Matrix3d::Zero());
  for (std::size_t b = 0; b < nb; ++b) {
    const wpg::robots::Body& body = model_bodies[b];
    if (body.parent >= 0 && welded_[static_cast<std::size_t>(body.joint)]) {
      host_[b] = host_[static_cast<std::size_t>(body.parent)];
      in_host_[b] = in_host_[static_cast<std::size_t>(body.parent)] *
                    model_.jointPlacement(body.joint, weld_values_(body.joint));
    } else {
      host_[b] = static_cast<int>(bodies_.size());
      in_host_[b] = Pose();
      Body lumped;
      if (body.parent >= 0) {
        const Joint& joint = model_.joints()[static_cast<std::size_t>(body.joint)];
        const Pose origin = in_host_[static_cast<std::size_t>(body.parent)] * joint.origin;
        lumped.parent = host_[static_cast<std::size_t>(body.parent)];
        lumped.q_index = RobotModel::kFreeFlyerConfigurationSize + joint.index;
        lumped.v_index = RobotModel::kFreeFlyerVelocitySize + joint.index;
        lumped.prismatic = joint.type == JointType::kPrismatic;
        lumped.joint_rotation = origin.rotation;
        lumped.joint_rotated = origin.rotation != Eigen::Matrix3d::Identity();
        lumped.joint_position = origin.position;
        lumped.axis = joint.axis;
        lumped.coordinate_axis = coordinateAxis(joint.axis);
      }
      bodies_.push_back(lumped);
    }
    const std::size_t h = static_cast<std::size_t>(host_[b]);
    const Pose& x = in_host_[b];
    const Eigen::Vector3d c = x * body.com;
    bodies_[h].mass += body.mass;
    first_moment[h] += body.mass * c;
    inertia_origin[h] += x.rotation * body.inertia * x.rotation.transpose() +
                         body.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() -
                                      c * c.transpose());
  }
  for (std::size_t h = 0; h < bodies_.size(); ++h) {
    Body& body = bodies_[h];
    body.com = body.mass > 0.0 ? Eigen::Vector3d(first_moment[h] / body.mass)
                               : Eigen::Vector3d::Zero();
    body.inertia = inertia_origin[h] - body.mass * (body.com.squaredNorm() *
                                                        Eigen::Matrix3d::Identity() -
                                                    body.com * body.com.transpose());
  }
  built_ = true;
}

void MomentumZmp::sampleWrench(Eigen::Index k, Eigen::Matrix<double, 6, 1>& wrench,
                               Eigen::Vector3d& com) {
  const auto q = qt_.col(k);
  const auto v = vt_.col(k);
  const auto a = at_.col(k);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  Eigen::Vector3d mass_moment = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const Body& body = bodies_[b];
    Motion& m = motion_[b];
    if (body.parent < 0) {
      // The free-flyer: v = (linear velocity of the root origin, angular velocity), world;
      // gravity as an upward acceleration of everything (no body is weighed).
      m.position = q.head<3>();
      m.rotation = Eigen::Quaterniond(q(3), q(4), q(5), q(6)).normalized().toRotationMatrix();
      m.omega = v.segment<3>(3);
      m.alpha = a.segment<3>(3);
      m.acceleration = a.head<3>();
      m.acceleration.z() += gravity_;
    } else {
      const Motion& p = motion_[static_cast<std::size_t>(body.parent)];
      const double qj = q(body.q_index), vj = v(body.v_index), aj = a(body.v_index);
      Eigen::Matrix3d joint_frame;
      if (body.joint_rotated) {
        joint_frame.noalias() = p.rotation * body.joint_rotation;
      } else {
        joint_frame = p.rotation;
      }
      const Eigen::Vector3d axis = body.coordinate_axis >= 0
                                       ? Eigen::Vector3d(joint_frame.col(body.coordinate_axis))
                                       : Eigen::Vector3d(joint_frame * body.axis);
      Eigen::Vector3d r = p.rotation * body.joint_position;  // parent origin -> joint origin
      const Eigen::Vector3d axis_rate = vj * axis;
      if (body.prismatic) {
        r += qj * axis;
        m.rotation = joint_frame;
        m.omega = p.omega;
        m.alpha = p.alpha;
        // the axis turns with the parent: Coriolis 2 omega x s q' and the slide's s q''
        m.acceleration = p.acceleration + p.alpha.cross(r) + p.omega.cross(p.omega.cross(r)) +
                         2.0 * p.omega.cross(axis_rate) + aj * axis;
      } else {
        m.rotation = joint_frame;
        if (body.coordinate_axis >= 0) {
          rotateAboutCoordinateAxis(m.rotation, body.coordinate_axis, std::cos(qj), std::sin(qj));
        } else {
          m.rotation = joint_frame * Eigen::AngleAxisd(qj, body.axis).toRotationMatrix();
        }
        m.omega = p.omega + axis_rate;
        m.alpha = p.alpha + aj * axis + p.omega.cross(axis_rate);  // the axis turns with the parent
        m.acceleration = p.acceleration + p.alpha.cross(r) + p.omega.cross(p.omega.cross(r));
      }
      m.position = p.position + r;
    }
    // This body's share: m a_c at its CoM, and the rate of its spin about it, R (I R'alpha +
    // R'omega x I R'omega) (body axes, then world).
    const Eigen::Vector3d to_com = m.rotation * body.com;
    const Eigen::Vector3d com_b = m.position + to_com;
    const Eigen::Vector3d com_force =
        body.mass * (m.acceleration + m.alpha.cross(to_com) + m.omega.cross(m.omega.cross(to_com)));
    const Eigen::Vector3d local_alpha = m.rotation.transpose() * m.alpha;
    const Eigen::Vector3d local_omega = m.rotation.transpose() * m.omega;
    const Eigen::Vector3d spin_rate =
        body.inertia * local_alpha + local_omega.cross(body.inertia * local_omega);
    force += com_force;
    moment += com_b.cross(com_force) + m.rotation * spin_rate;
    mass_moment += body.mass * com_b;
  }
  wrench.head<3>() = moment;
  wrench.tail<3>() = force;
  com = mass_moment / total_mass_;
}

const MultibodyReplayResult& MomentumZmp::run(const Eigen::Ref<const Eigen::MatrixXd>& q,
                                              double dt) {
  return runImpl(q, dt, nullptr);
}

const MultibodyReplayResult& MomentumZmp::run(const Eigen::Ref<const Eigen::MatrixXd>& q,
                                              double dt,
                                              const Eigen::Ref<const Eigen::MatrixXd>& com_force) {
  detail::checkComForce(q, com_force);
  return runImpl(q, dt, &com_force);
}

const MultibodyReplayResult& MomentumZmp::runImpl(
    const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
    const Eigen::Ref<const Eigen::MatrixXd>* com_force) {
  detail::checkedTranspose(model_, q, dt, qt_);
  const Eigen::Index n = q.rows();
  result_.dt = dt;
  detail::differentiateSamples(qt_, dt, vt_, at_, fd_before_, fd_after_);
  result_.velocity = vt_.transpose();
  result_.acceleration = at_.transpose();
  weldConstantJoints();
  result_.base_wrench.resize(n, 6);
  result_.zmp.resize(n, 2);
  result_.com.resize(n, 3);
  Eigen::Matrix<double, 6, 1> wrench;
  Eigen::Vector3d com;
  for (Eigen::Index k = 0; k < n; ++k) {
    sampleWrench(k, wrench, com);
    if (com_force != nullptr) {  // the ground's share: minus the wrench of the force at the CoM
      const Eigen::Vector3d force = com_force->row(k).transpose();
      wrench.head<3>() -= com.cross(force);
      wrench.tail<3>() -= force;
    }
    result_.base_wrench.row(k) = wrench.transpose();
    result_.zmp.row(k) = MultibodyReplay::zmpOfWrench(wrench).transpose();
    result_.com.row(k) = com.transpose();
  }
  return result_;
}

}  // namespace wpg::robots
