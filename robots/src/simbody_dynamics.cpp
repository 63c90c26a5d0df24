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

struct MultibodyReplay::Simbody {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  SimTK::Force::Gravity gravity;
  SimTK::State state;
  int free_q = 0, free_u = 0;  // first q (quaternion w x y z, then x y z) and u (w, v) of the root
  std::vector<int> joint_q, joint_u;  // per joint k
  SimTK::Vector no_mobility_forces;   // empty: no applied mobility forces
  SimTK::Vector udot, residual;
};

MultibodyReplay::MultibodyReplay(const RobotModel& model, MultibodyReplaySettings settings)
    : model_(model), settings_(settings), simbody_(std::make_unique<Simbody>()) {
  if (!(settings_.gravity >= 0.0) || !std::isfinite(settings_.gravity)) {
    throw std::invalid_argument("multibody replay: gravity must be finite and >= 0");
  }
  Simbody& s = *simbody_;
  const std::vector<Body>& bodies = model_.bodies();
  std::vector<SimTK::MobilizedBody> mobods;
  mobods.reserve(bodies.size());
  for (const Body& body : bodies) {
    // Simbody wants the inertia about the body origin.
    const Eigen::Matrix3d inertia_origin =
        body.inertia + body.mass * (body.com.squaredNorm() * Eigen::Matrix3d::Identity() -
                                    body.com * body.com.transpose());
    SimTK::Mat33 inertia;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) inertia(i, j) = 0.5 * (inertia_origin(i, j) + inertia_origin(j, i));
    }
    const SimTK::Body::Rigid rigid(
        SimTK::MassProperties(body.mass, toVec3(body.com), SimTK::Inertia(inertia)));
    if (body.parent < 0) {
      mobods.push_back(SimTK::MobilizedBody::Free(s.matter.updGround(), SimTK::Transform(), rigid,
                                                  SimTK::Transform()));
      continue;
    }
    const Joint& joint = model_.joints()[body.joint];
    SimTK::MobilizedBody& parent = mobods[body.parent];
    // Pin turns about z, Slider moves along x of its F/M frames: align them with the axis.
    const bool prismatic = joint.type == JointType::kPrismatic;
    const SimTK::Rotation align(SimTK::UnitVec3(toVec3(joint.axis)),
                                prismatic ? SimTK::CoordinateAxis(SimTK::XAxis)
                                          : SimTK::CoordinateAxis(SimTK::ZAxis));
    const SimTK::Transform x_pf(toRotation(joint.origin.rotation) * align,
                                toVec3(joint.origin.position));
    const SimTK::Transform x_bm(align, SimTK::Vec3(0));
    if (prismatic) {
      mobods.push_back(SimTK::MobilizedBody::Slider(parent, x_pf, rigid, x_bm));
    } else {
      mobods.push_back(SimTK::MobilizedBody::Pin(parent, x_pf, rigid, x_bm));
    }
  }
  s.gravity = SimTK::Force::Gravity(s.forces, s.matter, SimTK::UnitVec3(0, 0, -1), settings_.gravity);
  s.system.realizeTopology();
  s.state = s.system.getDefaultState();
  s.system.realizeModel(s.state);
  s.free_q = mobods[0].getFirstQIndex(s.state);
  s.free_u = mobods[0].getFirstUIndex(s.state);
  if (mobods[0].getNumQ(s.state) != 7 || mobods[0].getNumU(s.state) != 6) {
    throw std::logic_error("multibody replay: the Simbody free mobilizer is not in quaternion mode");
  }
  s.joint_q.resize(model_.jointCount());
  s.joint_u.resize(model_.jointCount());
  for (std::size_t b = 1; b < bodies.size(); ++b) {
    s.joint_q[bodies[b].joint] = mobods[b].getFirstQIndex(s.state);
    s.joint_u[bodies[b].joint] = mobods[b].getFirstUIndex(s.state);
  }
  s.udot.resize(s.state.getNU());
  s.udot = 0;
  s.residual.resize(s.state.getNU());
  s.residual = 0;
  s.system.realize(s.state, SimTK::Stage::Velocity);

  q_.resize(model_.nq());
  v_.resize(model_.nv());
  a_.resize(model_.nv());
  tau_.resize(model_.jointCount());
}

MultibodyReplay::~MultibodyReplay() = default;

void MultibodyReplay::sampleDynamics(const Eigen::Ref<const Eigen::VectorXd>& q,
                                     const Eigen::Ref<const Eigen::VectorXd>& v,
                                     const Eigen::Ref<const Eigen::VectorXd>& a,
                                     InverseDynamicsSample& out,
                                     Eigen::Ref<Eigen::VectorXd> joint_torques) {
  Simbody& s = *simbody_;
  const int nj = model_.jointCount();
  const double qnorm = q.segment<4>(3).norm();
  {
    SimTK::Vector& sq = s.state.updQ();
    for (int i = 0; i < 4; ++i) sq[s.free_q + i] = q(3 + i) / qnorm;  // w x y z
    for (int i = 0; i < 3; ++i) sq[s.free_q + 4 + i] = q(i);
    for (int k = 0; k < nj; ++k) sq[s.joint_q[k]] = q(RobotModel::kFreeFlyerConfigurationSize + k);
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
    for (int k = 0; k < nj; ++k) {
      su[s.joint_u[k]] = v(RobotModel::kFreeFlyerVelocitySize + k);
      s.udot[s.joint_u[k]] = a(RobotModel::kFreeFlyerVelocitySize + k);
    }
  }
  s.system.realize(s.state, SimTK::Stage::Velocity);
  // residual = M udot + C - (gravity): what must be applied at each mobility. At the free
  // mobilizer: the external wrench on the root, moment about the root origin, in Ground.
  s.matter.calcResidualForceIgnoringConstraints(s.state, s.no_mobility_forces,
                                                s.gravity.getBodyForces(s.state), s.udot,
                                                s.residual);
  Eigen::Vector3d moment, force;
  for (int i = 0; i < 3; ++i) {
    moment(i) = s.residual[s.free_u + i];
    force(i) = s.residual[s.free_u + 3 + i];
  }
  out.base_wrench.head<3>() = moment + q.head<3>().cross(force);  // about the world origin
  out.base_wrench.tail<3>() = force;
  out.zmp = zmpOfWrench(out.base_wrench);
  const SimTK::Vec3 com = s.matter.calcSystemMassCenterLocationInGround(s.state);
  out.com = Eigen::Vector3d(com[0], com[1], com[2]);
  if (joint_torques.size() == nj) {
    for (int k = 0; k < nj; ++k) joint_torques(k) = s.residual[s.joint_u[k]];
  }
}

}  // namespace wpg::robots
