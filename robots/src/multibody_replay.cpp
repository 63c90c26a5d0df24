// MultibodyReplay without Simbody: the loop over samples (the checks and finite differences
// are finite_differences.cpp, the Simbody part, construction and one sample of inverse
// dynamics, simbody_dynamics.cpp).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "wpg/robots/multibody_replay.hpp"

#include "finite_differences.hpp"

namespace wpg::robots {

void MultibodyReplay::differentiate(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                    Eigen::MatrixXd& velocity,
                                    Eigen::MatrixXd& acceleration) const {
  detail::checkTrajectorySize(model_, q, dt);
  const Eigen::MatrixXd qt = q.transpose();
  Eigen::MatrixXd vt, at;
  Eigen::VectorXd before, after;
  detail::differentiateSamples(qt, dt, vt, at, before, after);
  velocity = vt.transpose();
  acceleration = at.transpose();
}

Eigen::Vector2d MultibodyReplay::zmpOfWrench(const Eigen::Matrix<double, 6, 1>& wrench) {
  const double fz = wrench(5);
  if (!(fz > 0.0)) {
    return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  return {-wrench(1) / fz, wrench(0) / fz};
}

const MultibodyReplayResult& MultibodyReplay::run(const Eigen::Ref<const Eigen::MatrixXd>& q,
                                                  double dt) {
  return runImpl(q, dt, nullptr);
}

const MultibodyReplayResult& MultibodyReplay::run(const Eigen::Ref<const Eigen::MatrixXd>& q,
                                                  double dt,
                                                  const Eigen::Ref<const Eigen::MatrixXd>& com_force) {
  detail::checkComForce(q, com_force);
  return runImpl(q, dt, &com_force);
}

Eigen::Index MultibodyReplay::threadsFor(Eigen::Index n) const {
  // Short runs stay on this thread: starting one costs about what 10 samples do.
  return std::min<Eigen::Index>(std::max(1, settings_.threads), std::max<Eigen::Index>(1, n / 100));
}

void MultibodyReplay::prepare(const Eigen::Ref<const Eigen::MatrixXd>& q) {
  if (q.rows() < 1 || q.cols() != model_.nq()) return;  // run() reports what is wrong
  Simbody& simbody = simbodyFor(q);
  for (Eigen::Index t = 1; t < threadsFor(q.rows()); ++t)
    (void)helperSystem(static_cast<std::size_t>(t - 1), simbody);
}

const MultibodyReplayResult& MultibodyReplay::runImpl(
    const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
    const Eigen::Ref<const Eigen::MatrixXd>* com_force) {
  detail::checkedTranspose(model_, q, dt, qt_);
  const Eigen::Index n = q.rows();
  result_.dt = dt;
  detail::differentiateSamples(qt_, dt, vt_, at_, fd_before_, fd_after_);
  result_.velocity = vt_.transpose();
  result_.acceleration = at_.transpose();
  result_.base_wrench.resize(n, 6);
  Simbody& simbody = simbodyFor(q);
  result_.joint_torques.resize(settings_.joint_torques ? n : 0, model_.jointCount());
  result_.zmp.resize(n, 2);
  result_.com.resize(n, 3);
  // Samples [begin, end) on one Simbody system; every sample is independent (q, v and a are
  // known), so the rows do not depend on how the samples are shared among threads.
  const auto replaySamples = [&](Simbody& system, Eigen::VectorXd& tau, Eigen::Index begin,
                                 Eigen::Index end) {
    InverseDynamicsSample sample;
    for (Eigen::Index k = begin; k < end; ++k) {
      sampleDynamics(system, qt_.col(k), vt_.col(k), at_.col(k), sample, tau);
      if (com_force != nullptr) {  // the ground's share: minus the wrench of the force at the CoM
        const Eigen::Vector3d force = com_force->row(k).transpose();
        sample.base_wrench.head<3>() -= sample.com.cross(force);
        sample.base_wrench.tail<3>() -= force;
        sample.zmp = zmpOfWrench(sample.base_wrench);
      }
      result_.base_wrench.row(k) = sample.base_wrench.transpose();
      if (settings_.joint_torques) result_.joint_torques.row(k) = tau.transpose();
      result_.zmp.row(k) = sample.zmp.transpose();
      result_.com.row(k) = sample.com.transpose();
    }
  };
  const Eigen::Index threads = threadsFor(n);
  // Every helper's system and buffer first: helperSystem() may grow the vectors that hold
  // them, which must not move while a thread uses one.
  std::vector<Simbody*> systems;
  for (Eigen::Index t = 1; t < threads; ++t)
    systems.push_back(&helperSystem(static_cast<std::size_t>(t - 1), simbody));
  // Blocks of samples handed out in turn rather than one share per thread: the threads end
  // together even when one of them is slowed (a busy core, a cold cache).
  constexpr Eigen::Index kBlock = 50;
  std::atomic<Eigen::Index> next_block{0};
  const auto replayBlocks = [&](Simbody& system, Eigen::VectorXd& tau) {
    for (Eigen::Index first = kBlock * next_block++; first < n; first = kBlock * next_block++)
      replaySamples(system, tau, first, std::min(n, first + kBlock));
  };
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  for (Eigen::Index t = 1; t < threads; ++t) {
    Simbody& system = *systems[static_cast<std::size_t>(t - 1)];
    Eigen::VectorXd& tau = helper_tau_[static_cast<std::size_t>(t - 1)];
    pool.emplace_back([&, t] {
      try {
        replayBlocks(system, tau);
      } catch (...) {
        errors[static_cast<std::size_t>(t)] = std::current_exception();
        next_block = n;  // the others stop at their next block
      }
    });
  }
  try {
    replayBlocks(simbody, tau_);
  } catch (...) {
    errors[0] = std::current_exception();
    next_block = n;
  }
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return result_;
}

InverseDynamicsSample MultibodyReplay::inverseDynamics(const Eigen::Ref<const Eigen::VectorXd>& q,
                                                       const Eigen::Ref<const Eigen::VectorXd>& v,
                                                       const Eigen::Ref<const Eigen::VectorXd>& a,
                                                       Eigen::VectorXd* joint_torques) {
  model_.checkConfiguration(q);
  if (v.size() != model_.nv() || a.size() != model_.nv() || !v.allFinite() || !a.allFinite()) {
    throw std::invalid_argument("multibody replay: v and a must have " +
                                std::to_string(model_.nv()) + " finite entries");
  }
  InverseDynamicsSample out;
  sampleDynamics(fullSystem(), q, v, a, out, tau_);
  if (joint_torques != nullptr) *joint_torques = tau_;
  return out;
}

}  // namespace wpg::robots
