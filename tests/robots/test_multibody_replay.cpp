// Multibody replay (Simbody inverse dynamics): static ZMP, LIPM translation, a spinning rigid
// robot against Euler's equations, finite differences, timing of IK + replay of a 20 s walk.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "alloc_counter.hpp"
#include "hrp2_model.hpp"
#include "wpg/robots/multibody_replay.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/robots/walking_ik.hpp"

namespace {

using wpg::robots::MultibodyReplay;
using wpg::robots::Pose;
using wpg::robots::RobotModel;
using wpg::robots::WalkingIk;

constexpr double kGravity = 9.81;
constexpr double kDt = 0.005;

using wpg_test::hrp2;

Eigen::MatrixXd repeatRows(const Eigen::VectorXd& q, int n) {
  return q.transpose().replicate(n, 1);
}

TEST(MultibodyReplay, StaticHalfSittingZmpIsTheComProjection) {
  const RobotModel& model = hrp2();
  MultibodyReplay replay(model);
  const Eigen::VectorXd q = model.halfSitting();
  const auto& result = replay.run(repeatRows(q, 6), kDt);
  const Eigen::Vector3d com = model.centerOfMass(q);
  EXPECT_EQ(result.velocity.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(result.acceleration.cwiseAbs().maxCoeff(), 0.0);
  double zmp_error = 0.0;
  for (int k = 0; k < 6; ++k) {
    zmp_error = std::max(zmp_error, (result.zmp.row(k).transpose() - com.head<2>()).norm());
    EXPECT_LT((result.com.row(k).transpose() - com).norm(), 1e-12);
    EXPECT_LT(std::abs(result.base_wrench(k, 5) - model.totalMass() * kGravity), 1e-9);
    EXPECT_LT(result.base_wrench.row(k).segment<2>(3).norm(), 1e-9);
  }
  std::printf("static half-sitting: |ZMP - CoM projection| = %.2e m\n", zmp_error);
  RecordProperty("static_zmp_error_m", std::to_string(zmp_error));
  EXPECT_LT(zmp_error, 1e-9);
  // gravity loads the knees (torque about y of the bent legs)
  EXPECT_GT(std::abs(result.joint_torques(0, model.jointIndex("RLEG_JOINT3"))), 1.0);
}

// Static poses with random base orientations and joints: Simbody's CoM equals the model's,
// the supporting force is M g and the ZMP is the CoM projection (checks the quaternion order,
// the free-flyer u order and the shift of the moment to the world origin).
TEST(MultibodyReplay, SimbodyAgreesWithTheModelInStaticPoses) {
  const RobotModel& model = hrp2();
  MultibodyReplay replay(model);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.nv());
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::VectorXd q = model.halfSitting();
    for (int k = 0; k < model.jointCount(); ++k) q(7 + k) += 0.3 * u(rng);
    RobotModel::setFreeFlyer(q, Eigen::Vector3d(u(rng), u(rng), 0.7 + 0.1 * u(rng)),
                             Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng))));
    Eigen::VectorXd tau;
    const auto sample = replay.inverseDynamics(q, zero, zero, &tau);
    const Eigen::Vector3d com = model.centerOfMass(q);
    EXPECT_LT((sample.com - com).norm(), 1e-12);
    EXPECT_LT((sample.base_wrench.tail<3>() - Eigen::Vector3d(0, 0, model.totalMass() * kGravity)).norm(), 1e-9);
    EXPECT_LT((sample.zmp - com.head<2>()).norm(), 1e-9);
    EXPECT_EQ(tau.size(), model.jointCount());
  }
}

// The whole robot (joints fixed in half-sitting) translated along a LIPM trajectory
// c(t) = z + a cosh(w t) (x), z + b sinh(w t) (y), w^2 = g / h: the LIPM CoP is z (constant)
// and, without rotation, the multibody ZMP must equal it. The 3-point second difference
// makes an error of (dt^2 / 12) c'''' = (dt w)^2 / 12 (c - z), i.e. 2.5e-5 |c - z| at 5 ms:
// below 1e-6 m while |c - z| < 4 cm (here at most 1.6 cm).
TEST(MultibodyReplay, TranslationAlongALipmTrajectoryGivesTheLipmCop) {
  const RobotModel& model = hrp2();
  MultibodyReplay replay(model);
  const Eigen::VectorXd q0 = model.halfSitting();
  const Eigen::Vector3d c0 = model.centerOfMass(q0);
  const double h = c0.z(), w = std::sqrt(kGravity / h);
  const Eigen::Vector2d cop(0.03, -0.02);  // z of the LIPM
  const double a = 0.01, b = 0.01;
  const int n = 121;  // t in [-0.3, 0.3]
  Eigen::MatrixXd q = repeatRows(q0, n);
  auto com_at = [&](double t) {
    return Eigen::Vector3d(cop.x() + a * std::cosh(w * t), cop.y() + b * std::sinh(w * t), h);
  };
  for (int k = 0; k < n; ++k) {
    const double t = -0.3 + kDt * k;
    q.row(k).head<3>() = (q0.head<3>() + com_at(t) - c0).transpose();
  }
  const auto& result = replay.run(q, kDt);
  double max_error = 0.0, max_interior_error = 0.0;
  for (int k = 0; k < n; ++k) {
    const double e = (result.zmp.row(k).transpose() - cop).norm();
    max_error = std::max(max_error, e);
    if (k > 0 && k + 1 < n) max_interior_error = std::max(max_interior_error, e);
    EXPECT_LT((result.com.row(k).transpose() - com_at(-0.3 + kDt * k)).norm(), 1e-12);
  }
  std::printf("LIPM translation: |multibody ZMP - LIPM CoP| max %.2e m (interior %.2e m)\n",
              max_error, max_interior_error);
  RecordProperty("lipm_translation_zmp_error_m", std::to_string(max_error));
  EXPECT_LT(max_error, 1e-6);

  // with the exact velocity and acceleration the ZMP is exact
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.nv()), acc = Eigen::VectorXd::Zero(model.nv());
  const double t = 0.3;
  Eigen::VectorXd q_t = q0;
  q_t.head<3>() = q0.head<3>() + com_at(t) - c0;
  v.head<2>() << a * w * std::sinh(w * t), b * w * std::cosh(w * t);
  acc.head<2>() << a * w * w * std::cosh(w * t), b * w * w * std::sinh(w * t);
  const auto exact = replay.inverseDynamics(q_t, v, acc);
  EXPECT_LT((exact.zmp - cop).norm(), 1e-12);
}

// A horizontal force F at the CoM of the static robot: the ground supplies -F, and the ZMP moves
// by h F / (M g) in its direction. On the LIPM translation, a force that also accelerates the CoM
// (as the WPG's pushes do) leaves the ground ZMP at the LIPM CoP of the unpushed acceleration.
TEST(MultibodyReplay, ExternalForceAtTheCom) {
  const RobotModel& model = hrp2();
  MultibodyReplay replay(model);
  const Eigen::VectorXd q0 = model.halfSitting();
  const Eigen::Vector3d c = model.centerOfMass(q0);
  const double weight = model.totalMass() * kGravity;
  const int n = 5;
  Eigen::MatrixXd force(n, 3);
  force.rowwise() = Eigen::RowVector3d(30.0, -20.0, 10.0);
  const auto& result = replay.run(repeatRows(q0, n), kDt, force);
  const Eigen::Vector3d ground = Eigen::Vector3d(0, 0, weight) - force.row(0).transpose();
  const Eigen::Vector2d expected(c.x() - c.z() * ground.x() / ground.z(),
                                 c.y() - c.z() * ground.y() / ground.z());
  for (int k = 0; k < n; ++k) {
    EXPECT_LT((result.base_wrench.row(k).tail<3>().transpose() - ground).norm(), 1e-9);
    EXPECT_LT((result.zmp.row(k).transpose() - expected).norm(), 1e-12);
  }
  EXPECT_GT(result.zmp(0, 0), c.x() + 0.03);  // pushed forward: the ZMP moves forward

  // translation c(t) = c0 + (F / 2M) t^2 along x: all of it is the push, the ZMP stays under c0
  Eigen::MatrixXd q = repeatRows(q0, 41);
  Eigen::MatrixXd push(41, 3);
  push.rowwise() = Eigen::RowVector3d(40.0, 0.0, 0.0);
  for (int k = 0; k < 41; ++k) {
    const double t = kDt * k;
    q(k, 0) += 0.5 * 40.0 / model.totalMass() * t * t;
  }
  const auto& pushed = replay.run(q, kDt, push);
  for (int k = 0; k < 41; ++k) {
    EXPECT_LT((pushed.zmp.row(k).transpose() - pushed.com.row(k).head<2>().transpose()).norm(), 1e-9);
  }
  EXPECT_THROW(replay.run(q, kDt, push.topRows(3)), std::invalid_argument);
}

// Composite inertia about the CoM, world axes, from the model (independent of Simbody).
Eigen::Matrix3d compositeInertia(const RobotModel& model, const Eigen::VectorXd& q) {
  std::vector<Pose> poses;
  model.forwardKinematics(q, poses);
  const Eigen::Vector3d c = model.centerOfMass(q);
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const auto& body = model.bodies()[i];
    const Eigen::Vector3d r = poses[i] * body.com - c;
    inertia += poses[i].rotation * body.inertia * poses[i].rotation.transpose() +
               body.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  return inertia;
}

// The rigid robot spinning about the vertical axis through its CoM, theta(t) = w0 t + al t^2/2:
// Euler's equations give the moment about the CoM, n = I al e_z + w e_z x (I w e_z) (the
// products of inertia make it horizontal), hence the ZMP.
TEST(MultibodyReplay, SpinningRigidRobotFollowsEulersEquations) {
  const RobotModel& model = hrp2();
  MultibodyReplay replay(model);
  const Eigen::VectorXd q0 = model.halfSitting();
  const Eigen::Vector3d c = model.centerOfMass(q0);
  const Eigen::Quaterniond r0 = RobotModel::freeFlyerOrientation(q0);
  const double w0 = 1.5, al = 2.0;
  auto configuration = [&](double t) {
    const double theta = w0 * t + 0.5 * al * t * t;
    const Eigen::Quaterniond rz(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()));
    Eigen::VectorXd q = q0;
    RobotModel::setFreeFlyer(q, c + rz * (q0.head<3>() - c), rz * r0);
    return q;
  };
  auto expected_wrench = [&](double t) {
    const Eigen::VectorXd q = configuration(t);
    const Eigen::Matrix3d inertia = compositeInertia(model, q);
    const Eigen::Vector3d omega(0, 0, w0 + al * t), alpha(0, 0, al);
    const Eigen::Vector3d force(0, 0, model.totalMass() * kGravity);
    const Eigen::Vector3d moment_com = inertia * alpha + omega.cross(inertia * omega);
    Eigen::Matrix<double, 6, 1> wrench;
    wrench << moment_com + c.cross(force), force;
    return wrench;
  };
  // exact derivatives
  {
    const double t = 0.2;
    const Eigen::VectorXd q = configuration(t);
    const double wt = w0 + al * t;
    const Eigen::Vector3d arm = q.head<3>() - c;
    Eigen::VectorXd v = Eigen::VectorXd::Zero(model.nv()), a = Eigen::VectorXd::Zero(model.nv());
    const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
    v.head<3>() = wt * ez.cross(arm);
    v.segment<3>(3) = wt * ez;
    a.head<3>() = al * ez.cross(arm) + wt * wt * ez.cross(ez.cross(arm));
    a.segment<3>(3) = al * ez;
    const auto sample = replay.inverseDynamics(q, v, a);
    const Eigen::Matrix<double, 6, 1> expected = expected_wrench(t);
    EXPECT_LT((sample.base_wrench - expected).norm(), 1e-9) << sample.base_wrench.transpose()
                                                            << "\n" << expected.transpose();
    EXPECT_LT((sample.zmp - MultibodyReplay::zmpOfWrench(expected)).norm(), 1e-12);
    // the gyroscopic moment moves the ZMP away from the CoM projection
    EXPECT_GT((sample.zmp - c.head<2>()).norm(), 1e-4);
  }
  // finite differences over 0.5 s
  const int n = 101;
  Eigen::MatrixXd q(n, model.nq());
  for (int k = 0; k < n; ++k) q.row(k) = configuration(kDt * k).transpose();
  const auto& result = replay.run(q, kDt);
  double max_error = 0.0;
  for (int k = 0; k < n; ++k) {
    max_error = std::max(max_error, (result.zmp.row(k).transpose() -
                                     MultibodyReplay::zmpOfWrench(expected_wrench(kDt * k))).norm());
  }
  std::printf("spinning robot: |ZMP(finite differences) - ZMP(Euler)| max %.2e m\n", max_error);
  EXPECT_LT(max_error, 1e-6);  // O(dt^2) finite differences
}

// Accelerations are exact for cubic q(t) (the second difference), velocities for quadratic
// ones (the central difference errs by dt^2 q''' / 6 = 1.5e-5 here).
TEST(MultibodyReplay, FiniteDifferencesOfCubics) {
  const RobotModel& model = hrp2();
  MultibodyReplay replay(model);
  const Eigen::VectorXd q0 = model.halfSitting();
  const int n = 40;
  Eigen::MatrixXd q(n, model.nq());
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
  auto angle = [](double t) { return 0.3 + 0.5 * t - 0.8 * t * t + 0.6 * t * t * t; };
  auto rate = [](double t) { return 0.5 - 1.6 * t + 1.8 * t * t; };
  auto accel = [](double t) { return -1.6 + 3.6 * t; };
  for (int k = 0; k < n; ++k) {
    const double t = kDt * k;
    Eigen::VectorXd qk = q0;
    RobotModel::setFreeFlyer(qk, q0.head<3>() + Eigen::Vector3d(angle(t), -angle(t), 0.5 * angle(t)),
                             Eigen::Quaterniond(Eigen::AngleAxisd(angle(t), axis)));
    qk.tail(model.jointCount()).array() += angle(t);
    q.row(k) = qk.transpose();
  }
  Eigen::MatrixXd v, a;
  replay.differentiate(q, kDt, v, a);
  double v_error = 0.0, a_error = 0.0;
  for (int k = 0; k < n; ++k) {
    const double t = kDt * k;
    Eigen::VectorXd v_exact(model.nv()), a_exact(model.nv());
    const double central_rate = rate(t) + kDt * kDt * 3.6 / 6.0;  // (f(t+h) - f(t-h)) / 2h
    v_exact.head<3>() = Eigen::Vector3d(1, -1, 0.5) * central_rate;
    v_exact.segment<3>(3) = axis * central_rate;
    v_exact.tail(model.jointCount()).setConstant(central_rate);
    a_exact.head<3>() = Eigen::Vector3d(1, -1, 0.5) * accel(t);
    a_exact.segment<3>(3) = axis * accel(t);
    a_exact.tail(model.jointCount()).setConstant(accel(t));
    v_error = std::max(v_error, (v.row(k).transpose() - v_exact).cwiseAbs().maxCoeff());
    a_error = std::max(a_error, (a.row(k).transpose() - a_exact).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(v_error, 1e-10);
  EXPECT_LT(a_error, 1e-8);
  EXPECT_THROW(replay.differentiate(q.topRows(2), kDt, v, a), std::invalid_argument);
  EXPECT_THROW(replay.differentiate(q, 0.0, v, a), std::invalid_argument);
  Eigen::MatrixXd bad = q;
  bad(3, 3) = 3.0;
  EXPECT_THROW(replay.run(bad, kDt), std::invalid_argument);
}

// A 20 s walk-like motion at 5 ms (4000 samples): IK then replay. Prints the time; the
// replay loop does not allocate per sample.
TEST(MultibodyReplay, WalkReplayTiming) {
  const RobotModel& model = hrp2();
  const WalkingIk ik(model);
  MultibodyReplay replay(model);
  wpg::WalkTrajectory walk;
  const int n = 4000;
  const double step_time = 0.8, step_length = 0.2;
  for (int i = 0; i < n; ++i) {
    const double t = kDt * i;
    const int step = static_cast<int>(t / step_time);
    const double phase = t / step_time - step;  // 0..1 within the step
    const double swing = phase < 0.125 ? 0.0 : (phase - 0.125) / 0.875;  // 0.1 s double support
    const double lift = 0.05 * std::sin(M_PI * swing);
    // the swinging foot goes from (step - 1) to (step + 1) step lengths
    const bool left_swings = step % 2 == 0;
    const double swing_x = step_length * (step - 1 + 2.0 * (0.5 - 0.5 * std::cos(M_PI * swing)));
    const double stance_x = step_length * step;
    const Eigen::Vector4d swing_foot(swing_x, left_swings ? 0.095 : -0.095, lift, 0.0);
    const Eigen::Vector4d stance_foot(stance_x, left_swings ? -0.095 : 0.095, 0.0, 0.0);
    walk.time.push_back(t);
    walk.left_foot.push_back(left_swings ? swing_foot : stance_foot);
    walk.right_foot.push_back(left_swings ? stance_foot : swing_foot);
    walk.com.emplace_back(step_length / step_time * t - 0.5 * step_length,
                          0.07 * std::sin(M_PI * t / step_time), 0.814);
    walk.free_flyer_yaw.push_back(0.0);
  }
  const auto start = std::chrono::steady_clock::now();
  const auto ik_result = ik.solveTrajectory(walk);
  const auto middle = std::chrono::steady_clock::now();
  const auto& replayed = replay.run(ik_result.q, kDt);
  const auto end = std::chrono::steady_clock::now();
  const double ik_s = std::chrono::duration<double>(middle - start).count();
  const double replay_s = std::chrono::duration<double>(end - middle).count();
  std::printf("20 s walk (%d samples): IK %.3f s, replay %.3f s, total %.3f s (%.0fx real time); "
              "IK max CoM error %.2e m, max feet error %.2e m, %d samples with limit violations\n",
              n, ik_s, replay_s, ik_s + replay_s, 20.0 / (ik_s + replay_s), ik_result.max_com_error,
              ik_result.max_foot_position_error, ik_result.samples_with_limit_violations);
  RecordProperty("walk_ik_seconds", std::to_string(ik_s));
  RecordProperty("walk_replay_seconds", std::to_string(replay_s));
  EXPECT_EQ(ik_result.failures, 0);
  EXPECT_LT(ik_result.max_com_error, 1e-10);
  EXPECT_LT(ik_result.max_foot_position_error, 1e-9);
  EXPECT_LT((replayed.com - [&] {
              Eigen::MatrixXd com(n, 3);
              for (int i = 0; i < n; ++i) com.row(i) = walk.com[i].transpose();
              return com;
            }()).cwiseAbs().maxCoeff(),
            1e-10);
  EXPECT_TRUE(replayed.zmp.allFinite());
  EXPECT_LT(ik_s + replay_s, 5.0);  // loose: the target (< 0.5 s) is reported, not enforced

  // A second replay of the same size reuses every buffer: per sample, only Simbody's own
  // calcResidualForceIgnoringConstraints() allocates (its internal temporaries).
  const Eigen::VectorXd q0 = ik_result.q.row(0).transpose();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.nv());
  long before = wpg_test::allocationCount();
  replay.inverseDynamics(q0, zero, zero);
  const long simbody_per_sample = wpg_test::allocationCount() - before;
  before = wpg_test::allocationCount();
  replay.run(ik_result.q, kDt);
  const long allocations = wpg_test::allocationCount() - before;
  std::printf("allocations in a second replay of %d samples: %ld (Simbody's inverse dynamics: %ld "
              "per call)\n", n, allocations, simbody_per_sample);
  EXPECT_LE(allocations, n * simbody_per_sample + 4);
}

}  // namespace

namespace {

// Without joint torques the joints that stay constant over a run are welded (fewer Simbody
// bodies): the base wrench, ZMP and CoM are those of the full system up to round-off, and a
// later run with other constant values or other moving joints rebuilds the welded system.
TEST(MultibodyReplay, WeldingConstantJointsKeepsTheWrenchZmpAndCom) {
  const RobotModel& model = hrp2();
  MultibodyReplay full(model);
  wpg::robots::MultibodyReplaySettings settings;
  settings.joint_torques = false;
  MultibodyReplay welded(model, settings);
  const int n = 60;
  auto trajectory = [&](double arm_offset, bool move_chest) {
    Eigen::MatrixXd q(n, model.nq());
    const Eigen::VectorXd q0 = model.halfSitting();
    for (int k = 0; k < n; ++k) {
      const double t = kDt * k;
      Eigen::VectorXd qk = q0;
      RobotModel::setFreeFlyer(
          qk, q0.head<3>() + Eigen::Vector3d(0.2 * t, 0.03 * std::sin(5 * t), 0.0),
          Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * t, Eigen::Vector3d::UnitZ())));
      for (int i = 0; i < 12; ++i) qk(7 + i) += 0.2 * std::sin(3.0 * t + i);  // legs move
      qk(7 + model.jointIndex("LARM_JOINT1")) += arm_offset;  // constant over the run
      if (move_chest) qk(7 + model.jointIndex("CHEST_JOINT0")) += 0.3 * t * t;
      q.row(k) = qk.transpose();
    }
    return q;
  };
  double max_wrench = 0.0, max_zmp = 0.0, max_com = 0.0;
  Eigen::MatrixXd first_com;
  for (const auto& [arm_offset, move_chest] : {std::pair{0.0, false}, std::pair{0.4, false},
                                               std::pair{0.4, true}}) {
    const Eigen::MatrixXd q = trajectory(arm_offset, move_chest);
    const auto expected = full.run(q, kDt);  // a copy: both replays keep their own result
    const auto& result = welded.run(q, kDt);
    EXPECT_EQ(result.joint_torques.size(), 0);
    max_wrench =
        std::max(max_wrench, (result.base_wrench - expected.base_wrench).cwiseAbs().maxCoeff());
    max_zmp = std::max(max_zmp, (result.zmp - expected.zmp).cwiseAbs().maxCoeff());
    max_com = std::max(max_com, (result.com - expected.com).cwiseAbs().maxCoeff());
    // the arm's offset moves the CoM: a welded system left from the first run would miss it
    if (first_com.size() == 0) {
      first_com = expected.com;
    } else {
      EXPECT_GT((expected.com - first_com).cwiseAbs().maxCoeff(), 1e-4);
    }
  }
  std::printf("welded constant joints vs full system: wrench %.2e N (N m), ZMP %.2e m, CoM %.2e m\n",
              max_wrench, max_zmp, max_com);
  EXPECT_LT(max_wrench, 1e-9);
  EXPECT_LT(max_zmp, 1e-12);
  EXPECT_LT(max_com, 1e-14);
}

}  // namespace

namespace {

// Samples shared among threads (MultibodyReplaySettings::threads): every row is the one-thread
// run's, to the last bit (each sample is independent), with and without an external force.
TEST(MultibodyReplay, ThreadsGiveTheSameRows) {
  const RobotModel& model = hrp2();
  const int n = 450;
  Eigen::MatrixXd q(n, model.nq()), force(n, 3);
  const Eigen::VectorXd q0 = model.halfSitting();
  for (int k = 0; k < n; ++k) {
    const double t = kDt * k;
    Eigen::VectorXd qk = q0;
    RobotModel::setFreeFlyer(qk, q0.head<3>() + Eigen::Vector3d(0.2 * t, 0.03 * std::sin(5 * t), 0.0),
                             Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * t, Eigen::Vector3d::UnitZ())));
    for (int i = 0; i < 12; ++i) qk(7 + i) += 0.2 * std::sin(3.0 * t + i);
    q.row(k) = qk.transpose();
    force.row(k) << 30.0 * std::sin(t), 0.0, 0.0;
  }
  wpg::robots::MultibodyReplaySettings settings;
  settings.joint_torques = false;
  MultibodyReplay one(model, settings);
  const auto expected = one.run(q, kDt, force);
  for (int threads : {2, 3}) {
    settings.threads = threads;
    MultibodyReplay shared(model, settings);
    const auto& result = shared.run(q, kDt, force);
    EXPECT_EQ(result.zmp, expected.zmp) << threads << " threads";
    EXPECT_EQ(result.base_wrench, expected.base_wrench);
    EXPECT_EQ(result.com, expected.com);
    EXPECT_EQ(shared.run(q.topRows(50), kDt).zmp, one.run(q.topRows(50), kDt).zmp);  // one thread
  }
  settings.threads = 0;
  EXPECT_THROW(MultibodyReplay(model, settings), std::invalid_argument);
}

}  // namespace

namespace {

// prepare() builds on another thread the systems run() will use: the rows are those of a
// replay that built its own, to the last bit, whether the prepared motion's constant joints
// are the replayed one's (the systems reused) or not (run() builds the right ones).
TEST(MultibodyReplay, PreparedSystemsGiveTheSameRows) {
  const RobotModel& model = hrp2();
  const int n = 300;
  const auto motion = [&](double arm) {
    Eigen::MatrixXd q(n, model.nq());
    const Eigen::VectorXd q0 = model.halfSitting();
    for (int k = 0; k < n; ++k) {
      const double t = kDt * k;
      Eigen::VectorXd qk = q0;
      RobotModel::setFreeFlyer(qk, q0.head<3>() + Eigen::Vector3d(0.2 * t, 0.0, 0.0),
                               Eigen::Quaterniond::Identity());
      for (int i = 0; i < 12; ++i) qk(7 + i) += 0.2 * std::sin(3.0 * t + i);
      qk(7 + model.jointIndex("LARM_JOINT1")) += arm;  // constant over the run
      q.row(k) = qk.transpose();
    }
    return q;
  };
  const Eigen::MatrixXd q = motion(0.0), other_arm = motion(0.4);
  wpg::robots::MultibodyReplaySettings settings;
  settings.joint_torques = false;
  settings.threads = 2;
  MultibodyReplay own(model, settings);
  const auto expected = own.run(q, kDt);
  for (const Eigen::MatrixXd* prepared : {&q, &other_arm}) {
    MultibodyReplay replay(model, settings);
    std::thread building([&] { replay.prepare(*prepared); });
    building.join();
    const auto& result = replay.run(q, kDt);
    EXPECT_EQ(result.zmp, expected.zmp);
    EXPECT_EQ(result.base_wrench, expected.base_wrench);
    EXPECT_EQ(result.com, expected.com);
  }
  MultibodyReplay replay(model, settings);
  replay.prepare(Eigen::MatrixXd(2, 3));  // wrong size: nothing built, nothing thrown
  EXPECT_THROW(replay.run(Eigen::MatrixXd(2, 3), kDt), std::invalid_argument);
}

}  // namespace
