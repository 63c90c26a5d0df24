#include "wpg/walk_checks.hpp"

#include <cmath>
#include <vector>

#include "wpg/convex_polygon.hpp"
#include "wpg/support_polygon.hpp"

namespace wpg {
void swingFootPeaks(const WalkTrajectory& tr, WalkCheckReport& report) {
  report.swing_foot_speed_max = report.swing_foot_acceleration_max = 0.0;
  report.swing_foot_speed_max_time = report.swing_foot_acceleration_max_time = 0.0;
  for (std::size_t i = 1; i + 1 < tr.size(); ++i) {
    const double before = tr.time[i] - tr.time[i - 1], after = tr.time[i + 1] - tr.time[i];
    if (!(before > 0.0) || !(after > 0.0)) continue;
    for (const std::vector<Eigen::Vector4d>* foot : {&tr.left_foot, &tr.right_foot}) {
      const Eigen::Vector3d p0 = (*foot)[i - 1].head<3>(), p1 = (*foot)[i].head<3>(),
                            p2 = (*foot)[i + 1].head<3>();
      const double speed = ((p2 - p0) / (before + after)).norm();
      const double acceleration =
          ((p2 - p1) / after - (p1 - p0) / before).norm() / (0.5 * (before + after));
      if (speed > report.swing_foot_speed_max) {
        report.swing_foot_speed_max = speed;
        report.swing_foot_speed_max_time = tr.time[i];
      }
      if (acceleration > report.swing_foot_acceleration_max) {
        report.swing_foot_acceleration_max = acceleration;
        report.swing_foot_acceleration_max_time = tr.time[i];
      }
    }
  }
}

WalkCheckReport checkWalk(const WalkingParameters& w, const WalkTrajectory& tr) {
  WalkCheckReport report = checkSteps(w, tr);
  swingFootPeaks(tr, report);
  report.cop_sample_violation = -1.0;
  report.cop_control_violation = -1.0;
  report.cop_margin_excursion = -1.0;
  const std::size_t n = tr.size();
  const int per_sample = static_cast<int>(std::lround(w.sampling_period / w.control_period));
  // One polygon each (the sole, the CoP bounds of the sample's support, those of the NMPC
  // sample's support), so that each is built once per support phase, not once per sample. The
  // sizes are twice the half sizes, the doubles these checks have always used.
  SupportPolygonCache sole_polygon, margin_polygon, sample_polygon;
  const double sole_length = 2.0 * (0.5 * w.foot_length), sole_width = 2.0 * (0.5 * w.foot_width);
  const double cop_length = 2.0 * w.copHalfLength(), cop_width = 2.0 * w.copHalfWidth();
  for (std::size_t i = 0; i < n; ++i) {
    const double sole = sole_polygon.violation(tr.cop[i], tr.support[i], tr.left_foot[i],
                                               tr.right_foot[i], sole_length, sole_width);
    if (sole > report.cop_control_violation) {
      report.cop_control_violation = sole;
      report.cop_control_violation_time = tr.time[i];
    }
    report.cop_margin_excursion = std::max(
        report.cop_margin_excursion,
        margin_polygon.violation(tr.cop[i], tr.support[i], tr.left_foot[i], tr.right_foot[i],
                                 cop_length, cop_width));
    if (i % per_sample != 0) continue;
    // At an NMPC sample the CoP belongs to the single support that ends there, else to the
    // one that starts there, else (standing, starting) to the double support.
    SupportState support = SupportState::kDouble;
    if (i > 0 && tr.support[i - 1] != SupportState::kDouble) {
      support = tr.support[i - 1];
    } else if (i + 1 < n && tr.support[i] != SupportState::kDouble) {
      support = tr.support[i];
    }
    const double margin = sample_polygon.violation(tr.cop[i], support, tr.left_foot[i],
                                                   tr.right_foot[i], cop_length, cop_width);
    if (margin > report.cop_sample_violation) {
      report.cop_sample_violation = margin;
      report.cop_sample_violation_time = tr.time[i];
    }
  }
  return report;
}

WalkCheckReport checkSteps(const WalkingParameters& w, const WalkTrajectory& tr) {
  WalkCheckReport report;
  report.feasibility_violation = -1.0;
  const std::size_t n = tr.size();
  // Each landed step against the last footstep of the other side (the support it left from).
  ConvexPolygon feasibility[2];
  feasibility[0].setVertices(w.feasibilityVertices(FootSide::kLeft));
  feasibility[1].setVertices(w.feasibilityVertices(FootSide::kRight));
  int second_landing = -1;
  for (std::size_t k = 0; k < tr.footsteps.size(); ++k) {
    const Footstep& step = tr.footsteps[k];
    if (step.landing_time <= 0.0) continue;  // initial feet
    ++report.landed_steps;
    if (report.landed_steps == 2) second_landing = static_cast<int>(k);
    const Footstep* previous = nullptr;
    for (std::size_t j = k; j-- > 0;) {
      if (tr.footsteps[j].side != step.side) {
        previous = &tr.footsteps[j];
        break;
      }
    }
    if (!previous) continue;
    const double c = std::cos(previous->pose.z()), s = std::sin(previous->pose.z());
    const Eigen::Vector2d d = (step.pose - previous->pose).head<2>();
    const Eigen::Vector2d local(c * d.x() + s * d.y(), -s * d.x() + c * d.y());  // eq. (14)
    const ConvexPolygon& polygon = feasibility[step.side == FootSide::kLeft ? 0 : 1];
    report.feasibility_violation = std::max(report.feasibility_violation, polygon.violation(local));
    report.max_step_yaw_change =
        std::max(report.max_step_yaw_change, std::abs(step.pose.z() - previous->pose.z()));
  }
  if (second_landing >= 0 && n > 0) {
    const double t0 = tr.footsteps[second_landing].landing_time;
    std::size_t i0 = 0;
    while (i0 + 1 < n && tr.time[i0] < t0) ++i0;
    const double heading = tr.free_flyer_yaw[i0];
    const Eigen::Vector3d d = tr.com[n - 1] - tr.com[i0];
    const double elapsed = tr.time[n - 1] - tr.time[i0];
    if (elapsed > 0.0)
      report.speed_after_two_steps = (std::cos(heading) * d.x() + std::sin(heading) * d.y()) / elapsed;
  }
  return report;
}

}  // namespace wpg
