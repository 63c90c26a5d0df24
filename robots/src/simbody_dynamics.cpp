// The only translation unit that includes Simbody: builds the Simbody system of a RobotModel
// and evaluates the inverse dynamics of one sample for MultibodyReplay.
//
// Per sample, Simbody realizes the Position and Velocity stages (no further: inverse dynamics
// needs no forces) and computes the residual forces; everything constant is set up once
// (system, state, buffers, the welded system of a run). What makes it cheap (callgrind, 20 s
// walk, replay + filter: 2.15e9 -> 0.79e9 instructions in Simbody): joints constant over a
// run welded (13 bodies instead of 31 for a walk), gravity as the root's acceleration instead
// of a force element, body frames on the mobilizer frames (Simbody's node kinds without X_BM),
// the CoM from the body poses, raw access to Simbody's vectors.
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
  std::vector<Eigen::Vector3d> body_first_moment;  // per Simbody body: mass x CoM, its frame [kg m]
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
  // Simbody turns a Pin about z and moves a Slider along x of its F and M frames. The Simbody
  // frame of a body is its M frame (the model body frame rotated by `align`, which takes z or x
  // to the joint axis): with X_BM the identity, Simbody uses its cheaper node kind for the body.
  // `align` is the smallest rotation that does it (the identity for a z axis, e.g. a hip yaw).
  std::vector<Eigen::Matrix3d> align(nb, Eigen::Matrix3d::Identity());
  for (std::size_t b = 1; b < nb; ++b) {
    const Joint& joint = model.joints()[bodies[b].joint];
    const Eigen::Vector3d moving_axis = joint.type == JointType::kPrismatic
                                            ? Eigen::Vector3d::UnitX()
                                            : Eigen::Vector3d::UnitZ();
    align[b] = Eigen::Quaterniond::FromTwoVectors(moving_axis, joint.axis).toRotationMatrix();
  }
  // Each model body goes into a Simbody body, its host (itself unless its joint is welded), at
  // a fixed placement in the host's Simbody frame. Mass properties are summed per host: mass,
  // first moment and inertia about the host origin (parallel axis theorem), in that frame.
  std::vector<int> host(nb, 0);
  std::vector<Pose> in_host(nb);
  std::vector<double> mass(nb, 0.0);
  std::vector<Eigen::Vector3d> first_moment(nb, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> inertia_origin(nb, Eigen::Matrix3d::Zero());
  for (std::size_t b = 0; b < nb; ++b) {
    const Body& body = bodies[b];
    if (body.parent >= 0 && welded[body.joint]) {
      host[b] = host[body.parent];
      in_host[b] = in_host[body.parent] * model.jointPlacement(body.joint, weld_values(body.joint));
    } else {
      host[b] = static_cast<int>(b);
      in_host[b].rotation = align[b].transpose();
    }
    const int h = host[b];
    const Pose& x = in_host[b];
    const Eigen::Vector3d c = x * body.com;
    mass[h] += body.mass;
    first_moment[h] += body.mass * c;
    inertia_origin[h] += x.rotation * body.inertia * x.rotation.transpose() +
                         body.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() -
                                      c * c.transpose());
  }
  std::vector<SimTK::MobilizedBody> mobods(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    if (host[b] != static_cast<int>(b)) continue;
    const Body& body = bodies[b];
    // Simbody wants the inertia about the body origin.
    const Eigen::Vector3d com =
        mass[b] > 0.0 ? Eigen::Vector3d(first_moment[b] / mass[b]) : Eigen::Vector3d::Zero();
    SimTK::Mat33 inertia;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        inertia(i, j) = 0.5 * (inertia_origin[b](i, j) + inertia_origin[b](j, i));
      }
    }
    const SimTK::Body::Rigid rigid(
        SimTK::MassProperties(mass[b], toVec3(com), SimTK::Inertia(inertia)));
    body_mass.push_back(mass[b]);
    body_first_moment.push_back(first_moment[b]);
    total_mass += mass[b];
    if (body.parent < 0) {
      mobods[b] = SimTK::MobilizedBody::Free(matter.updGround(), SimTK::Transform(), rigid,
                                             SimTK::Transform());
      continue;
    }
    const Joint& joint = model.joints()[body.joint];
    SimTK::MobilizedBody& parent = mobods[host[body.parent]];
    // F: the joint frame (in the Simbody frame of the parent's host) turned by `align`.
    const Pose origin = in_host[body.parent] * joint.origin;
    Eigen::Matrix3d r_pf = origin.rotation * align[b];
    // Along parallel axes (HRP-2's hip pitch, knee, ankle pitch) and for a z axis on an unrotated
    // parent (hip yaw) F and the parent's frame agree (up to round-off): the exact identity lets
    // Simbody skip that rotation.
    if ((r_pf - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-15) r_pf.setIdentity();
    const SimTK::Transform x_pf(toRotation(r_pf), toVec3(origin.position));
    if (joint.type == JointType::kPrismatic) {
      mobods[b] = SimTK::MobilizedBody::Slider(parent, x_pf, rigid, SimTK::Transform());
    } else {
      mobods[b] = SimTK::MobilizedBody::Pin(parent, x_pf, rigid, SimTK::Transform());
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
  if (!state.getQ().hasContiguousData() || !state.getU().hasContiguousData()) {
    throw std::logic_error("multibody replay: Simbody's q and u are not contiguous vectors");
  }
}

MultibodyReplay::MultibodyReplay(const RobotModel& model, MultibodyReplaySettings settings)
    : model_(model), settings_(settings) {
  if (!(settings_.gravity >= 0.0) || !std::isfinite(settings_.gravity)) {
    throw std::invalid_argument("multibody replay: gravity must be finite and >= 0");
  }
  if (settings_.threads < 1) throw std::invalid_argument("multibody replay: threads must be >= 1");
  tau_.resize(model_.jointCount());
}

MultibodyReplay::Simbody& MultibodyReplay::fullSystem() {
  if (!simbody_) {
    simbody_ = std::make_unique<Simbody>(model_, settings_.gravity,
                                         std::vector<bool>(model_.jointCount(), false),
                                         Eigen::VectorXd::Zero(model_.jointCount()));
  }
  return *simbody_;
}

MultibodyReplay::Simbody& MultibodyReplay::simbodyFor(const Eigen::Ref<const Eigen::MatrixXd>& q) {
  if (settings_.joint_torques) return fullSystem();
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
  if (!any) return fullSystem();
  bool same = welded_ != nullptr && welded_->welded == constant;
  for (int k = 0; same && k < nj; ++k) {
    if (constant[k] && welded_->weld_values(k) != values(k)) same = false;
  }
  if (!same) welded_ = std::make_unique<Simbody>(model_, settings_.gravity, constant, values);
  return *welded_;
}

MultibodyReplay::Simbody& MultibodyReplay::helperSystem(std::size_t index, const Simbody& like) {
  if (helpers_.size() <= index) {
    helpers_.resize(index + 1);
    helper_tau_.resize(index + 1, Eigen::VectorXd(model_.jointCount()));
  }
  std::unique_ptr<Simbody>& helper = helpers_[index];
  if (!helper || helper->welded != like.welded || helper->weld_values != like.weld_values)
    helper = std::make_unique<Simbody>(model_, settings_.gravity, like.welded, like.weld_values);
  return *helper;
}

MultibodyReplay::~MultibodyReplay() = default;

void MultibodyReplay::sampleDynamics(Simbody& s, const Eigen::Ref<const Eigen::VectorXd>& q,
                                     const Eigen::Ref<const Eigen::VectorXd>& v,
                                     const Eigen::Ref<const Eigen::VectorXd>& a,
                                     InverseDynamicsSample& out,
                                     Eigen::Ref<Eigen::VectorXd> joint_torques) {
  const int nj = model_.jointCount();
  const double qnorm = q.segment<4>(3).norm();
  // Raw pointers into Simbody's contiguous vectors (their element access is an out-of-line,
  // range-checked call in Debian's build): one invalidation of the Position and Velocity stages.
  double* const sq = s.state.updQ().updContiguousScalarData();
  double* const su = s.state.updU().updContiguousScalarData();
  double* const udot = s.udot.updContiguousScalarData();
  for (int i = 0; i < 4; ++i) sq[s.free_q + i] = q(3 + i) / qnorm;  // w x y z
  for (int i = 0; i < 3; ++i) sq[s.free_q + 4 + i] = q(i);
  // Simbody's free mobilizer: u = (angular velocity, linear velocity), both in Ground.
  for (int i = 0; i < 3; ++i) {
    su[s.free_u + i] = v(3 + i);
    su[s.free_u + 3 + i] = v(i);
    udot[s.free_u + i] = a(3 + i);
    udot[s.free_u + 3 + i] = a(i);
  }
  udot[s.free_u + 5] += s.gravity;  // gravity as an upward acceleration of everything
  for (int k = 0; k < nj; ++k) {
    if (s.joint_q[k] < 0) continue;  // welded: constant over the run, v = a = 0
    sq[s.joint_q[k]] = q(RobotModel::kFreeFlyerConfigurationSize + k);
    su[s.joint_u[k]] = v(RobotModel::kFreeFlyerVelocitySize + k);
    udot[s.joint_u[k]] = a(RobotModel::kFreeFlyerVelocitySize + k);
  }
  s.system.realize(s.state, SimTK::Stage::Velocity);
  // residual = M udot + C (gravity in udot): what must be applied at each mobility. At the free
  // mobilizer: the external wrench on the root, moment about the root origin, in Ground.
  s.matter.calcResidualForceIgnoringConstraints(s.state, s.no_mobility_forces, s.no_body_forces,
                                                s.udot, s.residual);
  const double* const residual = s.residual.getContiguousScalarData();
  const Eigen::Map<const Eigen::Vector3d> moment(residual + s.free_u);
  const Eigen::Map<const Eigen::Vector3d> force(residual + s.free_u + 3);
  out.base_wrench.head<3>() = moment + q.head<3>().cross(force);  // about the world origin
  out.base_wrench.tail<3>() = force;
  out.zmp = zmpOfWrench(out.base_wrench);
  // Whole-body CoM from the body poses of the Position stage (what
  // calcSystemMassCenterLocationInGround sums, without its per-body mass property look-ups).
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < s.mobilized.size(); ++b) {
    const SimTK::Transform& x_gb = s.mobilized[b].getBodyTransform(s.state);
    // Rotation and Vec3 store packed doubles, the rotation by columns.
    const Eigen::Map<const Eigen::Matrix3d> r_gb(&x_gb.R().asMat33()(0, 0));
    const Eigen::Map<const Eigen::Vector3d> p_gb(&x_gb.p()[0]);
    first_moment += r_gb * s.body_first_moment[b] + s.body_mass[b] * p_gb;
  }
  out.com = first_moment / s.total_mass;
  if (joint_torques.size() == nj) {
    for (int k = 0; k < nj; ++k) {
      joint_torques(k) = s.joint_u[k] >= 0 ? residual[s.joint_u[k]]
                                           : std::numeric_limits<double>::quiet_NaN();
    }
  }
}

}  // namespace wpg::robots
