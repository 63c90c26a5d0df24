#pragma once
// Whole-body inverse kinematics for walking: the feet follow their targets exactly through a
// leg IK, the upper body keeps a reference posture (SRDF "half_sitting"), the waist (root link)
// keeps roll = pitch = 0 and the requested yaw, and its position is found by Newton iterations
// so that the WHOLE-BODY centre of mass equals the requested CoM (the pattern generator's CoM),
// with the analytic Jacobian of comAtWaist() (forward differences when a leg is numerical).
//
// Each leg is the chain of six or more actuated joints from the root to its sole frame, with
// nothing else hanging from it. A leg of HRP-2's structure (below) is solved in closed form;
// any other (hip axes that do not meet, a seventh joint, a rotated sole frame) by
// NumericalLegIk (damped least squares with the joint limits, from the reference posture's
// angles; joints beyond six held at the reference posture: lockedLegJoints), whose angles are
// the closed form's on HRP-2 within 1e-10 rad (tested).
//
// Leg structure of the analytic IK (HRP-2's): from the root,
// six revolute joints with axes z, x, y, y, y, x (hip yaw, hip roll, hip pitch, knee, ankle
// pitch, ankle roll) and identity joint-frame rotations; the three hip axes intersect (hip roll
// and pitch origins at 0), the knee origin is (0, y_k, -thigh), the ankle pitch origin
// (0, y_a, -shank) (lateral offsets along the pitch axes are allowed: HRP-2 has y_a = -+0.035),
// the ankle roll origin at 0. The sole frame is any frame of the last leg body without rotation
// (HRP-2: LLEG_SOLE/RLEG_SOLE, 0.105 m below the ankle).
//
// Feet targets follow wpg::WalkTrajectory: x, y, z of the sole point under the ankle (z = 0 on
// the ground), yaw; feet are flat (roll = pitch = 0). solve() does not allocate and is const
// (one WalkingIk may serve several threads). The RobotModel must outlive the WalkingIk.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wpg/robots/numerical_leg_ik.hpp"
#include "wpg/robots/robot_model.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg::robots {

struct WalkingIkSettings {
  std::string left_sole_frame = "LLEG_SOLE";    // frame on the left sole, under the ankle
  std::string right_sole_frame = "RLEG_SOLE";   // frame on the right sole, under the ankle
  std::string reference_posture = "half_sitting";  // SRDF state held by every non-leg joint
  double com_tolerance = 1e-12;  // [m] Newton stops when |CoM(q) - target| <= this
  int max_iterations = 30;       // Newton iterations on the waist position
  double jacobian_step = 1e-6;   // [m] forward-difference step of the CoM / waist Jacobian when
                                 // a leg is out of reach (else the Jacobian is analytic)
  double joint_limit_tolerance = 1e-9;  // [rad or m] a joint beyond its limit by more is reported
  bool numerical_legs = false;  // solve every leg with NumericalLegIk, even HRP-2-like ones
};

struct WalkingIkTarget {
  Eigen::Vector4d left_foot = Eigen::Vector4d::Zero();   // sole x, y, z [m], yaw [rad]
  Eigen::Vector4d right_foot = Eigen::Vector4d::Zero();  // sole x, y, z [m], yaw [rad]
  Eigen::Vector3d com = Eigen::Vector3d::Zero();         // whole-body CoM, world [m]
  double waist_yaw = 0.0;                                 // [rad], free-flyer yaw
};

enum class WalkingIkStatus : std::uint8_t {
  kSolved = 0,         // feet reached, CoM within com_tolerance
  kLegOutOfReach = 1,  // a foot target is beyond the leg's reach (knee straightened): foot error > 0
  kNotConverged = 2,   // the CoM Newton iterations hit max_iterations
};
const char* walkingIkStatusName(WalkingIkStatus status);

struct WalkingIkResult {
  WalkingIkStatus status = WalkingIkStatus::kSolved;
  int iterations = 0;              // CoM evaluations after the initial guess (Jacobian included)
  double com_error = 0.0;          // |CoM(q) - target| [m]
  double foot_position_error = 0.0;  // max over both soles, from forward kinematics [m]
  double foot_rotation_error = 0.0;  // max over both soles, |R - R_target|_F / sqrt(2) [rad]
  // Joint-limit violations (not clamped): bit k set when joint k (configuration order, k < 64)
  // is beyond its limits by more than joint_limit_tolerance; the largest excess [rad or m].
  std::uint64_t limit_violations = 0;
  double max_limit_violation = 0.0;
};

// One IK per sample of a walk.
struct WalkingIkTrajectory {
  Eigen::MatrixXd q;                     // n x nq, one configuration per row
  std::vector<WalkingIkResult> samples;  // n
  std::vector<double> solve_time;        // n, wall time of each sample's solve [s]
  int failures = 0;                      // samples whose status is not kSolved
  double max_com_error = 0.0;            // [m]
  double max_foot_position_error = 0.0;  // [m]
  std::uint64_t limit_violations = 0;    // union over the samples (bit k: joint k)
  int samples_with_limit_violations = 0;
  double max_limit_violation = 0.0;      // [rad or m]
};

class WalkingIk {
 public:
  enum Side { kLeft = 0, kRight = 1 };
  using LegAngles = Eigen::Matrix<double, 6, 1>;

  // Throws std::invalid_argument when a leg has fewer than six joints (or more than
  // NumericalLegIk::kMaxLegJoints) or a branch, the legs share a joint, a frame or the
  // reference posture is unknown, or the robot has more than 64 joints.
  explicit WalkingIk(const RobotModel& model, WalkingIkSettings settings = {});

  const RobotModel& model() const { return model_; }
  const WalkingIkSettings& settings() const { return settings_; }
  // Whether a leg is solved in closed form (HRP-2's structure) or by NumericalLegIk.
  bool analyticLeg(Side side) const { return legs_[side].analytic; }
  // Configuration indices (into q) of the joints of a leg, from the root.
  const std::vector<int>& legConfigurationIndices(Side side) const { return legs_[side].chain_q; }
  // The reference posture the upper body holds, root at the origin.
  const Eigen::VectorXd& referenceConfiguration() const { return reference_; }

  // Whole-body IK. q (nq entries) is written completely: free-flyer, legs, reference posture
  // elsewhere. Never throws for reachable or unreachable targets (see the status); throws
  // std::invalid_argument for a wrong q size or a non-finite target.
  WalkingIkResult solve(const WalkingIkTarget& target, Eigen::Ref<Eigen::VectorXd> q) const;

  // Analytic leg IK (analytic legs only: std::logic_error otherwise): joint angles (hip yaw ... ankle roll) that put the sole frame at `sole`
  // (world) with the root at `waist` (world). Returns false when the target is out of reach;
  // the angles then straighten the knee towards it (and the sole misses its target).
  bool solveLeg(Side side, const Pose& waist, const Pose& sole, LegAngles& angles) const;
  // Forward kinematics of the sole frame for given leg angles (root at `waist`).
  Pose legForwardKinematics(Side side, const Pose& waist, const LegAngles& angles) const;
  // The whole-body CoM that solve() matches: root at `waist_position` with yaw
  // target.waist_yaw (level), legs on the feet of `target` by solveLeg, upper body in the
  // reference posture. With `jacobian`, also d CoM / d waist_position, analytic: with M the
  // total mass, I + (1 / M) sum over the legs of G D, where D = d(leg angles) / d(waist position)
  // = -J^-1 (I; 0) (J: the 6 x 6 sole Jacobian of the leg angles; the soles are held) and G
  // column i = a_i x sum_{k >= i} m_k (x_k - o_i) (joint axis a_i through o_i, leg body CoMs
  // x_k). Meaningful while both feet are reachable (a straight knee makes J singular); NaN
  // when a leg is numerical.
  Eigen::Vector3d comAtWaist(const WalkingIkTarget& target, const Eigen::Vector3d& waist_position,
                             Eigen::Matrix3d* jacobian = nullptr) const;

  // IK of every sample of a walk: feet and free-flyer yaw from `walk`, CoM from `com`
  // (n x 3, e.g. a CoM corrected by the dynamic filter) or from walk.com. Newton starts from
  // the previous samples' solutions (extrapolated), not from the reference posture as solve()
  // does: the same configurations within the CoM tolerance, in one step instead of four.
  WalkingIkTrajectory solveTrajectory(const WalkTrajectory& walk) const;
  WalkingIkTrajectory solveTrajectory(const WalkTrajectory& walk,
                                      const Eigen::Ref<const Eigen::MatrixXd>& com) const;
  // The same into `out`, whose buffers are reused: no allocation when they already have the
  // walk's size (the filter's window at every NMPC iteration). Without `timed`, solve_time is
  // 0 (two clock reads per sample spared, for a caller that times the whole).
  void solveTrajectory(const WalkTrajectory& walk, const Eigen::Ref<const Eigen::MatrixXd>& com,
                       WalkingIkTrajectory& out, bool timed = true) const;

  // The warm start of solves 5 ms apart (solveTrajectory's): the CoM offset from the waist, in
  // the waist yaw frame, of the last solutions, most recent first.
  struct WarmStart {
    Eigen::Vector3d offsets[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                  Eigen::Vector3d::Zero()};
    int solved_in_a_row = 0;  // 0: start from the reference posture (first sample, a failure)
  };
  // solve() of the next sample of a sequence: Newton starts from the offset extrapolated
  // (quadratic) from the last three solutions of `warm_start`, which it then updates. The
  // same configuration as solve() within the CoM tolerance, in about half the evaluations.
  WalkingIkResult solveNext(const WalkingIkTarget& target, Eigen::Ref<Eigen::VectorXd> q,
                            WarmStart& warm_start) const;

 private:
  struct Leg {
    bool analytic = true;          // HRP-2's structure: the closed form; else NumericalLegIk
    std::vector<int> chain_body;   // body indices of the leg's joints, from the root
    std::vector<int> chain_q;      // their indices into q
    // The analytic leg's geometry (when `analytic`):
    std::array<int, 6> body{};     // body indices, hip yaw first
    std::array<int, 6> q_index{};  // indices into q
    std::array<Eigen::Vector3d, 6> origin{};  // joint origins in the parent body frame
    std::array<int, 6> axis{};     // joint axes: 0 x, 1 y, 2 z (z x y y y x)
    Eigen::Vector3d hip = Eigen::Vector3d::Zero();  // hip yaw origin in the root frame
    double thigh = 0.0, shank = 0.0;  // hip-pitch -> knee, knee -> ankle (along -z) [m]
    double lateral = 0.0;             // y offset hip-pitch frame -> ankle (knee + ankle) [m]
    Eigen::Vector3d sole = Eigen::Vector3d::Zero();  // sole frame origin in the foot frame
  };
  struct LegMassPoint { double mass; Eigen::Vector3d com; };  // in its body frame

  // The analytic leg IK of solveLeg() as the forward kinematics needs it: the cosine and sine
  // of each angle; angles() evaluates the angles from what their formulas take.
  struct LegSolution {
    double c[6] = {1, 1, 1, 1, 1, 1}, s[6] = {0, 0, 0, 0, 0, 0};
    double r_x = 0, r_y = 0, r_z = 0, v_z = 0;  // hip - ankle in the foot frame, (Rx(q5) r)_z
    double ratio = 0, c3 = 1, a = 0, b = 0;     // acos arguments; the knee's (a, b)
    double m01 = 0, m11 = 1, m21 = 0, m20 = 0, m22 = 1;  // the hip's rotation entries
    void angles(LegAngles& q) const;
    NumericalLegIk::Angles numeric;  // a numerical leg's angles, from the root
  };

  Leg makeLeg(const std::string& sole_frame) const;
  // The analytic geometry of `leg` (chain filled); false (with `why`) when it is not HRP-2's.
  bool makeAnalyticLeg(const Frame& sole, Leg& leg, std::string& why) const;
  // A numerical leg of more than six joints keeps the extra ones at the reference posture
  // (the solution is then unique near it): those whose columns the Jacobian there needs least.
  static std::vector<int> lockedLegJoints(const NumericalLegIk& leg,
                                          const Eigen::VectorXd& reference);
  // A numerical leg's IK for the root at `waist`, from the reference posture's angles: its
  // angles into `out`, its bodies' mass moment added to `moment`, the sole it reaches.
  bool solveNumericalLeg(Side side, const Pose& waist, const Pose& sole, LegSolution& out,
                         Eigen::Vector3d& moment, Pose& reached) const;
  bool solveLegCosines(Side side, const Pose& waist, const Pose& sole, LegSolution& out) const;
  // solve() with the initial waist position target.com - Rz(waist_yaw) com_offset.
  WalkingIkResult solveFrom(const WalkingIkTarget& target, const Eigen::Vector3d& com_offset,
                            Eigen::Ref<Eigen::VectorXd> q) const;
  // Whole-body CoM for the waist at (p, yaw), legs by IK; also the legs' solutions,
  // reachability and, when `jacobian` is not null, d CoM / d p (comAtWaist); when
  // `reached_soles` is not null, the two sole poses (left, right) that the leg angles reach
  // (forward kinematics).
  Eigen::Vector3d comForWaist(const Eigen::Vector3d& p, const Eigen::Matrix3d& waist_rotation,
                              const Pose (&soles)[2], LegSolution (&legs)[2], bool& reachable,
                              Eigen::Matrix3d* jacobian = nullptr,
                              Pose* reached_soles = nullptr) const;
  // pose <- pose * (joint i of the leg at `angle`): the joint origin, then the rotation.
  static void advanceLeg(const Leg& leg, int i, double angle, Pose& pose);

  const RobotModel& model_;
  WalkingIkSettings settings_;
  std::array<Leg, 2> legs_;
  std::array<std::vector<LegMassPoint>, 2> leg_mass_;  // per leg body, from the root
  std::array<std::shared_ptr<const NumericalLegIk>, 2> numerical_;  // numerical legs only
  std::array<NumericalLegIk::Angles, 2> numerical_start_;  // their reference posture angles
  Eigen::VectorXd reference_;          // reference posture, root at the origin
  double upper_mass_ = 0.0;            // every body but the legs
  Eigen::Vector3d upper_com_ = Eigen::Vector3d::Zero();  // in the root frame
  Eigen::Vector3d reference_com_offset_ = Eigen::Vector3d::Zero();  // CoM - root, reference
  double total_mass_ = 0.0;
};

}  // namespace wpg::robots
