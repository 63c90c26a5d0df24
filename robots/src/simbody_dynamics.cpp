// The only translation unit that includes Simbody: builds the Simbody system of a RobotModel
// and evaluates the inverse dynamics of one sample for MultibodyReplay.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "wpg/robots/multibody_replay.hpp"

// Debian's Simbody 3.7 libraries are built WITHOUT NDEBUG, and SimTKcommon's StateImpl.h
// changes the layout of its cache entries with NDEBUG (debug-only members): a translation unit
// that includes <Simbody.h> with NDEBUG defined (CMake's Release flags) corrupts memory in
// System::realizeTopology(). So Simbody's headers are read without NDEBUG, then NDEBUG (and
// with it a disabled assert()) is restored for the rest of this file.
#ifdef NDEBUG
#define WPG_ROBOTS_RESTORE_NDEBUG
#undef NDEBUG
#endif
#include <Simbody.h>
#ifdef WPG_ROBOTS_RESTORE_NDEBUG
#undef WPG_ROBOTS_RESTORE_NDEBUG
#define NDEBUG
#include <cassert>  // re-reads NDEBUG: assert() off again
#endif

namespace wpg::robots {
namespace {

SimTK::Vec3 toVec3(const Eigen::Vector3d& v) { return SimTK::Vec3(v.x(), v.y(), v.z()); }

SimTK::Rotation toRotation(const Eigen::Matrix3d& r) {
  SimTK::Mat33 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = r(i, j);
  }
  return SimTK::Rotation(m);
}

}  // namespace

// One Simbody system of the robot. Joints in `welded` (a mask over the joints, configuration
// order) are not mobilities: their child body is merged, at the joint value `weld_values(k)`,
// into the body it hangs from (mass, CoM and inertia summed: the same rigid assembly). With no
// joint welded, every body of the model is a Simbody body.
//
// Gravity is not a force element: a uniform field -g e_z acts on every body as the acceleration
// +g e_z of the whole system would (the classic inverse-dynamics shortcut, Featherstone's RNEA:
// the root gets the acceleration a_root + g e_z and no body is weighed). The residual is the
// same, and Simbody spares the per-body gravity forces of every sample.
struct MultibodyReplay::Simbody {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::State state;
  double gravity = 0.0;        // [m/s^2], along -z
  std::vector<SimTK::MobilizedBody> mobilized;  // the Simbody bodies (root first)
  std::vector<double> body_mass;             // per Simbody body [kg]
  std::vector<SimTK::Vec3> body_first_moment;  // per Simbody body: mass x CoM, body frame [kg m]
  double total_mass = 0.0;
  int free_q = 0, free_u = 0;  // first q (quaternion w x y z, then x y z) and u (w, v) of the root
  std::vector<int> joint_q, joint_u;  // per joint k; -1 when welded
  std::vector<bool> welded;           // per joint k
  Eigen::VectorXd weld_values;        // per joint k: the value a welded joint is held at
  SimTK::Vector no_mobility_forces;   // empty: no applied mobility forces
  SimTK::Vector_<SimTK::SpatialVec> no_body_forces;  // empty: no applied body forces
  SimTK::Vector udot, residual;

  Simbody(const RobotModel& model, double gravity_magnitude, std::vector<bool> welded_joints,
          const Eigen::VectorXd& values);
};

MultibodyReplay::Simbody::Simbody(const RobotModel& model, double gravity_magnitude,
                                  std::vector<bool> welded_joints, const Eigen::VectorXd& values)
    : gravity(gravity_magnitude), welded(std::move(welded_joints)), weld_values(values) {
  const std::vector<Body>& bodies = model.bodies();
  const std::size_t nb = bodies.size();
  // Each model body goes into a Simbody body, its host (itself unless its joint is welded), at
  // a fixed placement in the host frame. Mass properties are summed per host: mass, first
  // moment and inertia about the host origin (parallel axis theorem), in the host frame.
  std::vector<int> host(nb, 0);
  std::vector<Pose> in_host(nb);
  std::vector<double> mass(nb, 0.0);
  std::vector<Eigen::Vector3d> first_moment(nb, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> inertia_origin(nb, Eigen::Matrix3d::Zero());
  std::vector<int> bodies_in_host(nb, 0);
  for (std::size_t b = 0; b < nb; ++b) {
    const Body& body = bodies[b];
    if (body.parent >= 0 && welded[body.joint]) {
      host[b] = host[body.parent];
      in_host[b] = in_host[body.parent] * model.jointPlacement(body.joint, weld_values(body.joint));
    } else {
      host[b] = static_cast<int>(b);
    }
    const int h = host[b];
    const Pose& x = in_host[b];
    const Eigen::Vector3d c = x * body.com;
    mass[h] += body.mass;
    first_moment[h] += body.mass * c;
    inertia_origin[h] += x.rotation * body.inertia * x.rotation.transpose() +
                         body.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() -
                                      c * c.transpose());
    ++bodies_in_host[h];
  }
  std::vector<SimTK::MobilizedBody> mobods(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    if (host[b] != static_cast<int>(b)) continue;
    const Body& body = bodies[b];
    // Simbody wants the inertia about the body origin; a body alone keeps its own CoM (no round
    // trip through the first moment), so an unwelded system is the model's bodies exactly.
    const Eigen::Vector3d com = bodies_in_host[b] == 1 ? body.com
                                : mass[b] > 0.0        ? Eigen::Vector3d(first_moment[b] / mass[b])
                                                       : Eigen::Vector3d::Zero();
    SimTK::Mat33 inertia;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        inertia(i, j) = 0.5 * (inertia_origin[b](i, j) + inertia_origin[b](j, i));
      }
    }
    const SimTK::Body::Rigid rigid(
        SimTK::MassProperties(mass[b], toVec3(com), SimTK::Inertia(inertia)));
    body_mass.push_back(mass[b]);
    body_first_moment.push_back(mass[b] * toVec3(com));
    total_mass += mass[b];
    if (body.parent < 0) {
      mobods[b] = SimTK::MobilizedBody::Free(matter.updGround(), SimTK::Transform(), rigid,
                                             SimTK::Transform());
      continue;
    }
    const Joint& joint = model.joints()[body.joint];
    SimTK::MobilizedBody& parent = mobods[host[body.parent]];
    // The joint frame in the host of the parent body.
    const Pose origin = in_host[body.parent] * joint.origin;
    // Pin turns about z, Slider moves along x of its F/M frames: align them with the axis.
    const bool prismatic = joint.type == JointType::kPrismatic;
    const SimTK::Rotation align(SimTK::UnitVec3(toVec3(joint.axis)),
                                prismatic ? SimTK::CoordinateAxis(SimTK::XAxis)
                                          : SimTK::CoordinateAxis(SimTK::ZAxis));
    const SimTK::Transform x_pf(toRotation(origin.rotation) * align, toVec3(origin.position));
    const SimTK::Transform x_bm(align, SimTK::Vec3(0));
    if (prismatic) {
      mobods[b] = SimTK::MobilizedBody::Slider(parent, x_pf, rigid, x_bm);
    } else {
      mobods[b] = SimTK::MobilizedBody::Pin(parent, x_pf, rigid, x_bm);
    }
  }
  for (std::size_t b = 0; b < nb; ++b) {
    if (host[b] == static_cast<int>(b)) mobilized.push_back(mobods[b]);
  }
  system.realizeTopology();
  state = system.getDefaultState();
  system.realizeModel(state);
  free_q = mobods[0].getFirstQIndex(state);
  free_u = mobods[0].getFirstUIndex(state);
  if (mobods[0].getNumQ(state) != 7 || mobods[0].getNumU(state) != 6) {
    throw std::logic_error("multibody replay: the Simbody free mobilizer is not in quaternion mode");
  }
  joint_q.assign(model.jointCount(), -1);
  joint_u.assign(model.jointCount(), -1);
  for (std::size_t b = 1; b < nb; ++b) {
    if (host[b] != static_cast<int>(b)) continue;
    joint_q[bodies[b].joint] = mobods[b].getFirstQIndex(state);
    joint_u[bodies[b].joint] = mobods[b].getFirstUIndex(state);
  }
  udot.resize(state.getNU());
  udot = 0;
  residual.resize(state.getNU());
  residual = 0;
  system.realize(state, SimTK::Stage::Velocity);
}

MultibodyReplay::MultibodyReplay(const RobotModel& model, MultibodyReplaySettings settings)
    : model_(model), settings_(settings) {
  if (!(settings_.gravity >= 0.0) || !std::isfinite(settings_.gravity)) {
    throw std::invalid_argument("multibody replay: gravity must be finite and >= 0");
  }
  simbody_ = std::make_unique<Simbody>(model_, settings_.gravity,
                                       std::vector<bool>(model_.jointCount(), false),
                                       Eigen::VectorXd::Zero(model_.jointCount()));
  q_.resize(model_.nq());
  v_.resize(model_.nv());
  a_.resize(model_.nv());
  tau_.resize(model_.jointCount());
}

MultibodyReplay::Simbody& MultibodyReplay::simbodyFor(const Eigen::Ref<const Eigen::MatrixXd>& q) {
  if (settings_.joint_torques) return *simbody_;
  const int nj = model_.jointCount();
  std::vector<bool> constant(nj, false);
  Eigen::VectorXd values(nj);
  bool any = false;
  for (int k = 0; k < nj; ++k) {
    const auto column = q.col(RobotModel::kFreeFlyerConfigurationSize + k);
    values(k) = column(0);
    constant[k] = (column.array() == values(k)).all();
    any = any || constant[k];
  }
  if (!any) return *simbody_;
  bool same = welded_ != nullptr && welded_->welded == constant;
  for (int k = 0; same && k < nj; ++k) {
    if (constant[k] && welded_->weld_values(k) != values(k)) same = false;
  }
  if (!same) welded_ = std::make_unique<Simbody>(model_, settings_.gravity, constant, values);
  return *welded_;
}

MultibodyReplay::~MultibodyReplay() = default;

void MultibodyReplay::sampleDynamics(Simbody& s, const Eigen::Ref<const Eigen::VectorXd>& q,
                                     const Eigen::Ref<const Eigen::VectorXd>& v,
                                     const Eigen::Ref<const Eigen::VectorXd>& a,
                                     InverseDynamicsSample& out,
                                     Eigen::Ref<Eigen::VectorXd> joint_torques) {
  const int nj = model_.jointCount();
  const double qnorm = q.segment<4>(3).norm();
  {
    SimTK::Vector& sq = s.state.updQ();
    for (int i = 0; i < 4; ++i) sq[s.free_q + i] = q(3 + i) / qnorm;  // w x y z
    for (int i = 0; i < 3; ++i) sq[s.free_q + 4 + i] = q(i);
    for (int k = 0; k < nj; ++k) {
      if (s.joint_q[k] >= 0) sq[s.joint_q[k]] = q(RobotModel::kFreeFlyerConfigurationSize + k);
    }
  }
  {
    // Simbody's free mobilizer: u = (angular velocity, linear velocity), both in Ground.
    SimTK::Vector& su = s.state.updU();
    for (int i = 0; i < 3; ++i) {
      su[s.free_u + i] = v(3 + i);
      su[s.free_u + 3 + i] = v(i);
      s.udot[s.free_u + i] = a(3 + i);
      s.udot[s.free_u + 3 + i] = a(i);
    }
    s.udot[s.free_u + 5] += s.gravity;  // gravity as an upward acceleration of everything
    for (int k = 0; k < nj; ++k) {
      if (s.joint_u[k] < 0) continue;  // welded: constant over the run, v = a = 0
      su[s.joint_u[k]] = v(RobotModel::kFreeFlyerVelocitySize + k);
      s.udot[s.joint_u[k]] = a(RobotModel::kFreeFlyerVelocitySize + k);
    }
  }
  s.system.realize(s.state, SimTK::Stage::Velocity);
  // residual = M udot + C (gravity in udot): what must be applied at each mobility. At the free
  // mobilizer: the external wrench on the root, moment about the root origin, in Ground.
  s.matter.calcResidualForceIgnoringConstraints(s.state, s.no_mobility_forces, s.no_body_forces,
                                                s.udot, s.residual);
  Eigen::Vector3d moment, force;
  for (int i = 0; i < 3; ++i) {
    moment(i) = s.residual[s.free_u + i];
    force(i) = s.residual[s.free_u + 3 + i];
  }
  out.base_wrench.head<3>() = moment + q.head<3>().cross(force);  // about the world origin
  out.base_wrench.tail<3>() = force;
  out.zmp = zmpOfWrench(out.base_wrench);
  // Whole-body CoM from the body poses of the Position stage (what
  // calcSystemMassCenterLocationInGround sums, without its per-body mass property look-ups).
  SimTK::Vec3 first_moment(0);
  for (std::size_t b = 0; b < s.mobilized.size(); ++b) {
    const SimTK::Transform& x_gb = s.mobilized[b].getBodyTransform(s.state);
    first_moment += x_gb.R() * s.body_first_moment[b] + s.body_mass[b] * x_gb.p();
  }
  out.com = Eigen::Vector3d(first_moment[0], first_moment[1], first_moment[2]) / s.total_mass;
  if (joint_torques.size() == nj) {
    for (int k = 0; k < nj; ++k) {
      joint_torques(k) = s.joint_u[k] >= 0 ? s.residual[s.joint_u[k]]
                                           : std::numeric_limits<double>::quiet_NaN();
    }
  }
}

}  // namespace wpg::robots
