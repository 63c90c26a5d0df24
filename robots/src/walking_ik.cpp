#include "wpg/robots/walking_ik.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/LU>

namespace wpg::robots {
namespace {

Eigen::Matrix3d rotZ(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

Pose soleTarget(const Eigen::Vector4d& foot) {
  Pose pose;
  pose.position = foot.head<3>();
  pose.rotation = rotZ(foot(3));
  return pose;
}

// r <- r Rot(axis, angle) for a coordinate axis (0 x, 1 y, 2 z), c = cos(angle), s = sin(angle):
// only the two columns orthogonal to the axis change (the same numbers as multiplying by
// Eigen::AngleAxisd(angle, unit axis).toRotationMatrix(), without the general 3 x 3 product).
inline void rotateAboutAxis(Eigen::Matrix3d& r, int axis, double c, double s) {
  const int i = axis == 2 ? 0 : axis + 1, j = axis == 0 ? 2 : axis - 1;  // (i, j, axis) cyclic
  const Eigen::Vector3d ci = r.col(i);
  r.col(i) = c * ci + s * r.col(j);
  r.col(j) = c * r.col(j) - s * ci;
}

}  // namespace

const char* walkingIkStatusName(WalkingIkStatus status) {
  switch (status) {
    case WalkingIkStatus::kSolved: return "solved";
    case WalkingIkStatus::kLegOutOfReach: return "leg_out_of_reach";
    case WalkingIkStatus::kNotConverged: return "not_converged";
  }
  return "unknown";
}

WalkingIk::WalkingIk(const RobotModel& model, WalkingIkSettings settings)
    : model_(model), settings_(std::move(settings)) {
  if (model_.jointCount() > 64) {
    throw std::invalid_argument("walking IK: at most 64 joints (limit-violation bit mask)");
  }
  if (!(settings_.com_tolerance > 0.0) || settings_.max_iterations < 1 ||
      !(settings_.jacobian_step > 0.0) || !(settings_.joint_limit_tolerance >= 0.0)) {
    throw std::invalid_argument("walking IK: settings must be positive");
  }
  legs_[kLeft] = makeLeg(settings_.left_sole_frame);
  legs_[kRight] = makeLeg(settings_.right_sole_frame);
  const std::vector<int>& right_bodies = legs_[kRight].chain_body;
  for (const int body : legs_[kLeft].chain_body) {
    if (std::find(right_bodies.begin(), right_bodies.end(), body) != right_bodies.end()) {
      throw std::invalid_argument("walking IK: the two sole frames share leg joints");
    }
  }
  reference_ = model_.referenceConfiguration(settings_.reference_posture);
  const std::string sole_frames[2] = {settings_.left_sole_frame, settings_.right_sole_frame};
  for (int side = 0; side < 2; ++side) {
    if (legs_[side].analytic) continue;
    numerical_start_[side].resize(static_cast<Eigen::Index>(legs_[side].chain_q.size()));
    for (std::size_t i = 0; i < legs_[side].chain_q.size(); ++i)
      numerical_start_[side](static_cast<Eigen::Index>(i)) = reference_(legs_[side].chain_q[i]);
    numerical_[side] = std::make_shared<const NumericalLegIk>(
        model_, sole_frames[side], NumericalLegIkSettings(),
        lockedLegJoints(NumericalLegIk(model_, sole_frames[side]), numerical_start_[side]));
  }

  // Mass of everything but the legs, held rigid in the reference posture, in the root frame.
  std::vector<Pose> poses;
  model_.forwardKinematics(reference_, poses);
  std::vector<bool> in_leg(model_.bodies().size(), false);
  for (int side = 0; side < 2; ++side) {
    for (const int b : legs_[side].chain_body) {
      const Body& body = model_.bodies()[b];
      in_leg[b] = true;
      leg_mass_[side].push_back({body.mass, body.com});
    }
  }
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < model_.bodies().size(); ++b) {
    if (in_leg[b]) continue;
    upper_mass_ += model_.bodies()[b].mass;
    moment += model_.bodies()[b].mass * (poses[b] * model_.bodies()[b].com);
  }
  total_mass_ = model_.totalMass();
  upper_com_ = upper_mass_ > 0.0 ? Eigen::Vector3d(moment / upper_mass_) : Eigen::Vector3d::Zero();
  reference_com_offset_ = model_.centerOfMass(reference_);  // root at the origin
}

void WalkingIk::advanceLeg(const Leg& leg, int i, double angle, Pose& pose) {
  pose.position += pose.rotation * leg.origin[i];  // joint frames are not rotated (makeLeg)
  rotateAboutAxis(pose.rotation, leg.axis[i], std::cos(angle), std::sin(angle));
}

Pose WalkingIk::legForwardKinematics(Side side, const Pose& waist, const LegAngles& angles) const {
  const Leg& leg = legs_[side];
  if (!leg.analytic) throw std::logic_error("walking IK: legForwardKinematics of a numerical leg");
  Pose pose = waist;
  for (int i = 0; i < 6; ++i) advanceLeg(leg, i, angles(i), pose);
  pose.position += pose.rotation * leg.sole;
  return pose;
}

bool WalkingIk::solveLeg(Side side, const Pose& waist, const Pose& sole, LegAngles& q) const {
  if (!legs_[side].analytic) throw std::logic_error("walking IK: solveLeg of a numerical leg");
  LegSolution solution;
  const bool reachable = solveLegCosines(side, waist, sole, solution);
  solution.angles(q);
  return reachable;
}

// The closed form of the leg IK without a trigonometric function: each angle's cosine and
// sine from the vectors and matrix entries whose atan2 (or acos) it is, by the sum formulas;
// the angles themselves (LegSolution::angles) only for the configuration solve() returns.
bool WalkingIk::solveLegCosines(Side side, const Pose& waist, const Pose& sole,
                                LegSolution& out) const {
  const Leg& leg = legs_[side];
  const double l1 = leg.thigh, l2 = leg.shank, d = leg.lateral;
  bool reachable = true;
  const Eigen::Vector3d hip = waist * leg.hip;
  const Eigen::Vector3d ankle = sole.position - sole.rotation * leg.sole;
  // r: hip seen from the ankle, in the foot frame. With s = hip pitch + knee + ankle pitch:
  // r = -Rx(-q5) Ry(-s) a, where a = ankle in the hip-roll frame = (x, d, z) (the lateral
  // offsets lie along the parallel pitch axes), so (Rx(q5) r)_y = -d fixes the ankle roll.
  const Eigen::Vector3d r = sole.rotation.transpose() * (hip - ankle);
  out.r_x = r.x();
  out.r_y = r.y();
  out.r_z = r.z();
  const double rho = std::sqrt(r.y() * r.y() + r.z() * r.z());
  double ratio = rho > 0.0 ? -d / rho : 0.0;
  if (ratio > 1.0 || ratio < -1.0) {
    reachable = false;
    ratio = std::clamp(ratio, -1.0, 1.0);
  }
  out.ratio = ratio;
  // q5 = acos(ratio) - atan2(r_z, r_y)
  const double c_phi = rho > 0.0 ? r.y() / rho : 1.0, s_phi = rho > 0.0 ? r.z() / rho : 0.0;
  const double s_psi = std::sqrt(1.0 - ratio * ratio);
  const double c5 = ratio * c_phi + s_psi * s_phi, s5 = s_psi * c_phi - ratio * s_phi;
  const double vz = s5 * r.y() + c5 * r.z();  // (Rx(q5) r)_z; (Rx(q5) r)_x = r_x
  out.v_z = vz;
  // knee: planar two-link in the pitch plane, distance ell between hip and ankle
  const double ell2 = r.x() * r.x() + vz * vz;
  double c3 = (ell2 - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
  if (c3 > 1.0 || c3 < -1.0) {
    reachable = false;
    c3 = std::clamp(c3, -1.0, 1.0);
  }
  out.c3 = c3;
  const double s3 = std::sqrt(1.0 - c3 * c3);  // knee bent forward: q3 = acos(c3) >= 0
  // ankle pitch q4 = atan2(-r_x, vz) - atan2(b, a): (vz, -r_x) is (l1 cos q3 + l2, l1 sin q3)
  // rotated by q4
  const double a = l1 * c3 + l2, b = l1 * s3;
  out.a = a;
  out.b = b;
  const double n1 = std::sqrt(r.x() * r.x() + vz * vz), n2 = std::sqrt(a * a + b * b);
  const double c_1 = n1 > 0.0 ? vz / n1 : 1.0, s_1 = n1 > 0.0 ? -r.x() / n1 : 0.0;
  const double c_2 = n2 > 0.0 ? a / n2 : 1.0, s_2 = n2 > 0.0 ? b / n2 : 0.0;
  const double c4 = c_1 * c_2 + s_1 * s_2, s4 = s_1 * c_2 - c_1 * s_2;
  // hip: Rz(q0) Rx(q1) Ry(q2) = Rw' Rf Rx(-q5) Ry(-(q3 + q4))
  Eigen::Matrix3d m = waist.rotation.transpose() * sole.rotation;
  rotateAboutAxis(m, 0, c5, -s5);  // Rx(-q5)
  rotateAboutAxis(m, 1, c3 * c4 - s3 * s4, -(s3 * c4 + c3 * s4));  // Ry(-(q3 + q4))
  out.m01 = m(0, 1);
  out.m11 = m(1, 1);
  out.m21 = m(2, 1);
  out.m20 = m(2, 0);
  out.m22 = m(2, 2);
  const double h = std::sqrt(m(0, 1) * m(0, 1) + m(1, 1) * m(1, 1));
  const double n_1 = std::sqrt(m(2, 1) * m(2, 1) + h * h);
  const double n_2 = std::sqrt(m(2, 0) * m(2, 0) + m(2, 2) * m(2, 2));
  out.c[0] = h > 0.0 ? m(1, 1) / h : 1.0;  // q0 = atan2(-m01, m11)
  out.s[0] = h > 0.0 ? -m(0, 1) / h : 0.0;
  out.c[1] = n_1 > 0.0 ? h / n_1 : 1.0;  // q1 = atan2(m21, h)
  out.s[1] = n_1 > 0.0 ? m(2, 1) / n_1 : 0.0;
  out.c[2] = n_2 > 0.0 ? m(2, 2) / n_2 : 1.0;  // q2 = atan2(-m20, m22)
  out.s[2] = n_2 > 0.0 ? -m(2, 0) / n_2 : 0.0;
  out.c[3] = c3;
  out.s[3] = s3;
  out.c[4] = c4;
  out.s[4] = s4;
  out.c[5] = c5;
  out.s[5] = s5;
  return reachable;
}

void WalkingIk::LegSolution::angles(LegAngles& q) const {
  q(0) = std::atan2(-m01, m11);
  q(1) = std::atan2(m21, std::sqrt(m01 * m01 + m11 * m11));
  q(2) = std::atan2(-m20, m22);
  q(3) = std::acos(c3);
  q(4) = std::atan2(-r_x, v_z) - std::atan2(b, a);
  q(5) = std::atan2(s[5], c[5]);  // acos(ratio) - atan2(r_z, r_y), in (-pi, pi]
}

Eigen::Vector3d WalkingIk::comForWaist(const Eigen::Vector3d& p, const Eigen::Matrix3d& waist_rotation,
                                       const Pose (&soles)[2], LegSolution (&legs)[2],
                                       bool& reachable, Eigen::Matrix3d* jacobian,
                                       Pose* reached_soles) const {
  const Pose waist{waist_rotation, p};
  Eigen::Vector3d moment = upper_mass_ * (waist * upper_com_);
  reachable = true;
  // d CoM / d p = I + (1 / M) sum over the legs of G D (comAtWaist in the header): the waist
  // translation moves every body by dp, and each leg's joints by D dp so that the sole stays.
  Eigen::Matrix3d leg_terms = Eigen::Matrix3d::Zero();
  bool numerical = false;
  for (int side = 0; side < 2; ++side) {
    const Leg& leg = legs_[side];
    const LegSolution& solution = legs[side];
    if (!leg.analytic) {  // its Jacobian by finite differences (solveFrom)
      Pose reached;
      reachable &= solveNumericalLeg(static_cast<Side>(side), waist, soles[side], legs[side],
                                     moment, reached);
      if (reached_soles != nullptr) reached_soles[side] = reached;
      numerical = true;
      continue;
    }
    reachable &= solveLegCosines(static_cast<Side>(side), waist, soles[side], legs[side]);
    Pose pose = waist;
    Eigen::Vector3d joint_origin[6], joint_axis[6], body_com[6];
    for (int i = 0; i < 6; ++i) {
      pose.position += pose.rotation * leg.origin[i];
      joint_origin[i] = pose.position;
      joint_axis[i] = pose.rotation.col(leg.axis[i]);  // the rotation about it keeps it
      rotateAboutAxis(pose.rotation, leg.axis[i], solution.c[i], solution.s[i]);
      body_com[i] = pose * leg_mass_[side][i].com;
      moment += leg_mass_[side][i].mass * body_com[i];
    }
    if (reached_soles != nullptr) {
      reached_soles[side] = pose;
      reached_soles[side].position += pose.rotation * leg.sole;
    }
    if (jacobian == nullptr) continue;
    // The sole is held while the waist translates by dp: the joint rates dtheta = D dp cancel
    // the sole twist, taken at the hip point h = o_0 (the three hip axes meet there, makeLeg):
    // hip columns (0, a_i), the others (a_i x (h - o_i), a_i). Linear rows: A dtheta_345 = -dp;
    // angular rows: B dtheta_012 + C dtheta_345 = 0 (A, B, C: 3 x 3 blocks).
    Eigen::Matrix3d a_block, b_block, c_block;
    for (int i = 0; i < 3; ++i) {
      a_block.col(i) = joint_axis[3 + i].cross(joint_origin[0] - joint_origin[3 + i]);
      b_block.col(i) = joint_axis[i];
      c_block.col(i) = joint_axis[3 + i];
    }
    const Eigen::Matrix3d lower_rates = -a_block.inverse();  // d theta_345 / dp
    const Eigen::Matrix3d hip_rates = -(b_block.inverse() * c_block) * lower_rates;
    // Column i of G: a_i x sum over the bodies k >= i of m_k (x_k - o_i), the rate of the
    // leg's mass moment per unit rate of joint i.
    Eigen::Matrix<double, 3, 6> moment_rate;
    Eigen::Vector3d subtree_moment = Eigen::Vector3d::Zero();
    double subtree_mass = 0.0;
    for (int i = 5; i >= 0; --i) {
      subtree_moment += leg_mass_[side][i].mass * body_com[i];
      subtree_mass += leg_mass_[side][i].mass;
      moment_rate.col(i) = joint_axis[i].cross(subtree_moment - subtree_mass * joint_origin[i]);
    }
    leg_terms.noalias() += moment_rate.leftCols<3>() * hip_rates;
    leg_terms.noalias() += moment_rate.rightCols<3>() * lower_rates;
  }
  if (jacobian != nullptr) {
    // Not finite for a numerical leg: solveFrom takes forward differences instead.
    *jacobian = numerical ? Eigen::Matrix3d::Constant(std::numeric_limits<double>::quiet_NaN())
                          : Eigen::Matrix3d(Eigen::Matrix3d::Identity() + leg_terms / total_mass_);
  }
  return moment / total_mass_;
}

Eigen::Vector3d WalkingIk::comAtWaist(const WalkingIkTarget& target,
                                      const Eigen::Vector3d& waist_position,
                                      Eigen::Matrix3d* jacobian) const {
  const Pose soles[2] = {soleTarget(target.left_foot), soleTarget(target.right_foot)};
  LegSolution legs[2];
  bool reachable = true;
  return comForWaist(waist_position, rotZ(target.waist_yaw), soles, legs, reachable, jacobian);
}

WalkingIkResult WalkingIk::solve(const WalkingIkTarget& target, Eigen::Ref<Eigen::VectorXd> q) const {
  return solveFrom(target, reference_com_offset_, q);
}

WalkingIkResult WalkingIk::solveFrom(const WalkingIkTarget& target,
                                     const Eigen::Vector3d& com_offset,
                                     Eigen::Ref<Eigen::VectorXd> q) const {
  if (q.size() != model_.nq()) {
    throw std::invalid_argument("walking IK: configuration of size " + std::to_string(q.size()) +
                                ", expected " + std::to_string(model_.nq()));
  }
  if (!target.left_foot.allFinite() || !target.right_foot.allFinite() || !target.com.allFinite() ||
      !std::isfinite(target.waist_yaw)) {
    throw std::invalid_argument("walking IK: non-finite target");
  }
  WalkingIkResult result;
  const Eigen::Matrix3d waist_rotation = rotZ(target.waist_yaw);
  const Pose soles[2] = {soleTarget(target.left_foot), soleTarget(target.right_foot)};
  LegSolution legs[2];
  bool reachable = true;

  // Newton on the waist position p: CoM(p) = target. Initial guess: the CoM offset from the
  // waist `com_offset` (waist yaw frame). The analytic Jacobian (comAtWaist) comes with the
  // first evaluation; it is reused while the residual shrinks fast (chord method), recomputed
  // otherwise. Forward differences replace it when a leg is out of reach (the sole then misses
  // its target and the analytic Jacobian, which holds the soles, does not apply) or when it is
  // not finite (a straight knee).
  Eigen::Vector3d p = target.com - waist_rotation * com_offset;
  Eigen::Matrix3d jacobian;
  Pose reached[2];  // the soles by forward kinematics of the last evaluation's leg angles
  Eigen::Vector3d residual =
      comForWaist(p, waist_rotation, soles, legs, reachable, &jacobian, reached) - target.com;
  bool jacobian_at_p = true;  // `jacobian` was evaluated at the current p
  Eigen::Matrix3d jacobian_inverse;
  bool have_jacobian = false;
  double previous_norm = residual.norm();
  result.status = WalkingIkStatus::kSolved;
  while (residual.norm() > settings_.com_tolerance) {
    if (result.iterations >= settings_.max_iterations) {
      result.status = WalkingIkStatus::kNotConverged;
      break;
    }
    if (!have_jacobian) {
      if (!jacobian_at_p && reachable) {  // evaluate again, with the Jacobian
        comForWaist(p, waist_rotation, soles, legs, reachable, &jacobian, reached);
        jacobian_at_p = true;
        ++result.iterations;
      }
      if (!reachable || !jacobian.allFinite()) {
        LegSolution scratch[2];
        bool scratch_reachable = true;
        for (int i = 0; i < 3; ++i) {
          Eigen::Vector3d shifted = p;
          shifted(i) += settings_.jacobian_step;
          jacobian.col(i) =
              (comForWaist(shifted, waist_rotation, soles, scratch, scratch_reachable) -
               target.com - residual) / settings_.jacobian_step;
        }
        result.iterations += 3;
      }
      jacobian_inverse = jacobian.inverse();
      have_jacobian = true;
    }
    p -= jacobian_inverse * residual;
    // Without the Jacobian: should the next step need a new one, p is evaluated again with it.
    residual = comForWaist(p, waist_rotation, soles, legs, reachable, nullptr, reached) -
               target.com;
    jacobian_at_p = false;
    ++result.iterations;
    const double norm = residual.norm();
    if (norm > 0.25 * previous_norm) have_jacobian = false;  // slow: refresh the Jacobian
    previous_norm = norm;
  }
  result.com_error = residual.norm();

  q = reference_;
  q.head<3>() = p;  // free-flyer: position, then the yaw quaternion (w, x, y, z)
  q.segment<4>(3) << std::cos(0.5 * target.waist_yaw), 0.0, 0.0, std::sin(0.5 * target.waist_yaw);
  for (int side = 0; side < 2; ++side) {
    if (legs_[side].analytic) {
      LegAngles angles;
      legs[side].angles(angles);
      for (int i = 0; i < 6; ++i) q(legs_[side].q_index[i]) = angles(i);
    } else {
      for (std::size_t i = 0; i < legs_[side].chain_q.size(); ++i)
        q(legs_[side].chain_q[i]) = legs[side].numeric(static_cast<Eigen::Index>(i));
    }
    const Pose& sole = reached[side];
    result.foot_position_error =
        std::max(result.foot_position_error, (sole.position - soles[side].position).norm());
    result.foot_rotation_error = std::max(
        result.foot_rotation_error, (sole.rotation - soles[side].rotation).norm() / std::sqrt(2.0));
  }
  if (!reachable && result.status == WalkingIkStatus::kSolved) {
    result.status = WalkingIkStatus::kLegOutOfReach;
  }
  const Eigen::VectorXd& lower = model_.jointLowerLimits();
  const Eigen::VectorXd& upper = model_.jointUpperLimits();
  for (int k = 0; k < model_.jointCount(); ++k) {
    const double v = q(RobotModel::kFreeFlyerConfigurationSize + k);
    const double excess = std::max(lower(k) - v, v - upper(k));
    if (excess > settings_.joint_limit_tolerance) {
      result.limit_violations |= std::uint64_t{1} << k;
      result.max_limit_violation = std::max(result.max_limit_violation, excess);
    }
  }
  return result;
}

WalkingIkTrajectory WalkingIk::solveTrajectory(const WalkTrajectory& walk) const {
  Eigen::MatrixXd com(static_cast<Eigen::Index>(walk.size()), 3);
  if (walk.com.size() != walk.size()) {
    throw std::invalid_argument("walking IK: walk with " + std::to_string(walk.com.size()) +
                                " CoM samples for " + std::to_string(walk.size()) + " times");
  }
  for (std::size_t i = 0; i < walk.size(); ++i) com.row(static_cast<Eigen::Index>(i)) = walk.com[i].transpose();
  return solveTrajectory(walk, com);
}

WalkingIkTrajectory WalkingIk::solveTrajectory(const WalkTrajectory& walk,
                                               const Eigen::Ref<const Eigen::MatrixXd>& com) const {
  WalkingIkTrajectory out;
  solveTrajectory(walk, com, out);
  return out;
}

WalkingIkResult WalkingIk::solveNext(const WalkingIkTarget& target, Eigen::Ref<Eigen::VectorXd> q,
                                     WarmStart& warm_start) const {
  // The CoM offset from the waist (in the waist yaw frame) extrapolated from the previous
  // solutions: the walk is smooth at 5 ms, so this is much closer than the reference
  // posture's offset and Newton needs one step instead of four.
  const Eigen::Vector3d* offsets = warm_start.offsets;
  const int solved = warm_start.solved_in_a_row;
  const Eigen::Vector3d com_offset =
      solved >= 3   ? Eigen::Vector3d(3.0 * (offsets[0] - offsets[1]) + offsets[2])
      : solved == 2 ? Eigen::Vector3d(2.0 * offsets[0] - offsets[1])
      : solved == 1 ? offsets[0]
                    : reference_com_offset_;
  const WalkingIkResult r = solveFrom(target, com_offset, q);
  if (r.status == WalkingIkStatus::kSolved) {
    warm_start.offsets[2] = warm_start.offsets[1];
    warm_start.offsets[1] = warm_start.offsets[0];
    warm_start.offsets[0] = rotZ(target.waist_yaw).transpose() * (target.com - q.head<3>());
    ++warm_start.solved_in_a_row;
  } else {
    warm_start.solved_in_a_row = 0;
  }
  return r;
}

void WalkingIk::solveTrajectory(const WalkTrajectory& walk,
                                const Eigen::Ref<const Eigen::MatrixXd>& com,
                                WalkingIkTrajectory& out, bool timed) const {
  const std::size_t n = walk.size();
  if (walk.left_foot.size() != n || walk.right_foot.size() != n || walk.free_flyer_yaw.size() != n) {
    throw std::invalid_argument("walking IK: walk with inconsistent sample counts (time " +
                                std::to_string(n) + ", feet " +
                                std::to_string(walk.left_foot.size()) + "/" +
                                std::to_string(walk.right_foot.size()) + ", yaw " +
                                std::to_string(walk.free_flyer_yaw.size()) + ")");
  }
  if (com.rows() != static_cast<Eigen::Index>(n) || com.cols() != 3) {
    throw std::invalid_argument("walking IK: CoM of size " + std::to_string(com.rows()) + " x " +
                                std::to_string(com.cols()) + ", expected " + std::to_string(n) +
                                " x 3");
  }
  out.q.resize(static_cast<Eigen::Index>(n), model_.nq());
  out.samples.resize(n);
  out.solve_time.resize(n);
  out.failures = 0;
  out.max_com_error = 0.0;
  out.max_foot_position_error = 0.0;
  out.limit_violations = 0;
  out.samples_with_limit_violations = 0;
  out.max_limit_violation = 0.0;
  WalkingIkTarget target;
  WarmStart warm_start;  // after a sample that was not solved, the start is the reference again
  // One configuration on the stack (at most 64 joints, checked at construction): this const
  // function may run on several threads, and allocates nothing when `out` has its size.
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, RobotModel::kFreeFlyerConfigurationSize + 64, 1> q(
      model_.nq());
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    target.left_foot = walk.left_foot[i];
    target.right_foot = walk.right_foot[i];
    target.com = com.row(row).transpose();
    target.waist_yaw = walk.free_flyer_yaw[i];
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = timed ? Clock::now() : Clock::time_point();
    const WalkingIkResult& r = out.samples[i] = solveNext(target, q, warm_start);
    out.solve_time[i] =
        timed ? std::chrono::duration<double>(Clock::now() - start).count() : 0.0;
    out.q.row(row) = q.transpose();
    if (r.status != WalkingIkStatus::kSolved) ++out.failures;
    out.max_com_error = std::max(out.max_com_error, r.com_error);
    out.max_foot_position_error = std::max(out.max_foot_position_error, r.foot_position_error);
    out.limit_violations |= r.limit_violations;
    if (r.limit_violations != 0) ++out.samples_with_limit_violations;
    out.max_limit_violation = std::max(out.max_limit_violation, r.max_limit_violation);
  }
}

}  // namespace wpg::robots
