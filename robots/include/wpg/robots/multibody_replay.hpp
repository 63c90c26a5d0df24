#pragma once
// Replay of a joint trajectory q(t) through the multibody model (Simbody, inverse dynamics):
// velocities and accelerations by finite differences, the external wrench that realizes the
// motion (the total contact wrench), the joint torques, the multibody ZMP and the whole-body
// CoM per sample. Each MultibodyReplay owns its own Simbody system and state: use one per
// thread. Simbody stays in the implementation (pimpl).
//
// Finite differences (sample period dt, samples k = 0..n-1, n >= 3), the same scheme for every
// coordinate of the velocity layout (see robot_model.hpp):
//   mid-point velocities  v(k+1/2) = (q(k+1) - q(k)) / dt, for the orientation
//                         omega(k+1/2) = log(R(k+1) R(k)') / dt (world frame),
//   v(k) = (v(k-1/2) + v(k+1/2)) / 2,   a(k) = (v(k+1/2) - v(k-1/2)) / dt   (interior),
//   end samples: linear extrapolation of v and a from the two nearest interior samples
//   (a constant acceleration when n = 3). Second-order accurate: accelerations are exact for
//   cubic q(t) (the WPG's CoM is piecewise cubic), velocities for quadratic q(t); for a LIPM
//   motion the ZMP error is (dt w)^2 / 12 |c - z| (2.5e-5 |c - z| at 5 ms).
// ZMP: the wrench (moment n about the world origin, force f) that the ground must apply;
//   p_x = -n_y / f_z, p_y = n_x / f_z on the ground plane z = 0 (NaN when f_z <= 0).
//   With an external force at the CoM (the pushes of paper Sec. V-B, which the WPG adds to
//   the CoM acceleration), run() subtracts its wrench: the ground's share remains.
// The RobotModel must outlive the replay.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "wpg/robots/robot_model.hpp"

namespace wpg::robots {

struct MultibodyReplaySettings {
  double gravity = 9.81;  // [m/s^2], along -z (WalkingParameters::gravity)
  // Joint torques of run() (result().joint_torques). Without them, run() welds the joints whose
  // value is the same in every sample (their velocity and acceleration are exactly 0): Simbody
  // then has fewer bodies (HRP-2 walking: 13 instead of 31, the upper body held in its posture)
  // and gives the same base wrench, ZMP and CoM up to round-off, at about half the cost.
  bool joint_torques = true;
  // Threads that share run()'s samples, each with its own Simbody system (built at the first
  // run that uses it): the results are the same whatever the count (every sample is
  // independent). 1 where the caller already runs one replay per core (a batch's workers).
  int threads = 1;
};

struct MultibodyReplayResult {
  double dt = 0.0;                // [s], sample period
  Eigen::MatrixXd velocity;       // n x nv, velocity layout of robot_model.hpp
  Eigen::MatrixXd acceleration;   // n x nv
  Eigen::MatrixXd base_wrench;    // n x 6: moment about the world origin [N m], force [N]; world
  Eigen::MatrixXd joint_torques;  // n x joints [N m or N]; 0 x joints without joint_torques
  Eigen::MatrixXd zmp;            // n x 2, world, on z = 0 [m]
  Eigen::MatrixXd com;            // n x 3, whole-body CoM, world [m]
};

// Inverse dynamics of one sample.
struct InverseDynamicsSample {
  Eigen::Matrix<double, 6, 1> base_wrench = Eigen::Matrix<double, 6, 1>::Zero();  // as above
  Eigen::Vector2d zmp = Eigen::Vector2d::Zero();
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
};

class MultibodyReplay {
 public:
  // The Simbody systems (free-flyer root, a pin or slider per joint, gravity) are built when
  // first needed: a run without joint torques never needs the one with every joint a mobility.
  explicit MultibodyReplay(const RobotModel& model, MultibodyReplaySettings settings = {});
  ~MultibodyReplay();
  MultibodyReplay(const MultibodyReplay&) = delete;
  MultibodyReplay& operator=(const MultibodyReplay&) = delete;

  const RobotModel& model() const { return model_; }

  // q: n x nq, one configuration per row, sampled every dt > 0, n >= 3. The result is kept in
  // this object (buffers reused between calls of the same size). Throws std::invalid_argument
  // on bad sizes, non-finite values or non-unit quaternions.
  const MultibodyReplayResult& run(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt);
  // The same with an external force applied at the whole-body CoM: com_force is n x 3, world
  // [N] (e.g. mass x the push acceleration of WalkRequest's pushes); base_wrench and zmp are
  // then the ground's share, the wrench of the inverse dynamics minus (c x F, F).
  const MultibodyReplayResult& run(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                   const Eigen::Ref<const Eigen::MatrixXd>& com_force);
  const MultibodyReplayResult& result() const { return result_; }
  // Builds now the Simbody systems that run() on q would build (without joint torques, the
  // system with q's constant joints welded, and one copy per helper thread), so that a caller
  // may build them on another thread while it computes the motion to replay: run() on a
  // motion with the same number of samples and the same constant joints then reuses them
  // (any other motion gets its own, as before). Checks nothing; results are unchanged.
  void prepare(const Eigen::Ref<const Eigen::MatrixXd>& q);

  // Finite differences alone (the scheme above): velocity and acceleration, n x nv.
  void differentiate(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                     Eigen::MatrixXd& velocity, Eigen::MatrixXd& acceleration) const;

  // Inverse dynamics of one sample with known q (nq), v and a (nv, velocity layout);
  // joint_torques (joints) is written when non-null. Checks sizes.
  InverseDynamicsSample inverseDynamics(const Eigen::Ref<const Eigen::VectorXd>& q,
                                        const Eigen::Ref<const Eigen::VectorXd>& v,
                                        const Eigen::Ref<const Eigen::VectorXd>& a,
                                        Eigen::VectorXd* joint_torques = nullptr);

  // ZMP on z = 0 of a wrench (moment about the world origin, force); NaN when f_z <= 0.
  static Eigen::Vector2d zmpOfWrench(const Eigen::Matrix<double, 6, 1>& wrench);

 private:
  struct Simbody;  // the Simbody system, state and buffers (simbody_dynamics.cpp)
  const MultibodyReplayResult& runImpl(const Eigen::Ref<const Eigen::MatrixXd>& q, double dt,
                                       const Eigen::Ref<const Eigen::MatrixXd>* com_force);
  // The system for a run of q: the full one, or (without joint torques) the one with the
  // joints constant over q welded, rebuilt only when that set or their values change.
  Simbody& simbodyFor(const Eigen::Ref<const Eigen::MatrixXd>& q);
  // The system with every joint a mobility, built at its first use.
  Simbody& fullSystem();
  // The threads run() uses for n samples.
  Eigen::Index threadsFor(Eigen::Index n) const;
  // A copy of `like` (the same welded joints and values) for helper thread `index` of run().
  Simbody& helperSystem(std::size_t index, const Simbody& like);
  void sampleDynamics(Simbody& simbody, const Eigen::Ref<const Eigen::VectorXd>& q,
                      const Eigen::Ref<const Eigen::VectorXd>& v,
                      const Eigen::Ref<const Eigen::VectorXd>& a, InverseDynamicsSample& out,
                      Eigen::Ref<Eigen::VectorXd> joint_torques);

  const RobotModel& model_;
  MultibodyReplaySettings settings_;
  std::unique_ptr<Simbody> simbody_;  // every joint a mobility (inverseDynamics, torques)
  std::unique_ptr<Simbody> welded_;   // the last run's constant joints welded (may be null)
  MultibodyReplayResult result_;
  Eigen::MatrixXd qt_, vt_, at_;  // run(): q, velocity, acceleration, one sample per column
  Eigen::VectorXd fd_before_, fd_after_;  // run(): the finite differences' scratch
  Eigen::VectorXd tau_;           // per-sample joint torques
  std::vector<std::unique_ptr<Simbody>> helpers_;  // the helper threads' systems
  std::vector<Eigen::VectorXd> helper_tau_;        // and joint torques
};

}  // namespace wpg::robots
