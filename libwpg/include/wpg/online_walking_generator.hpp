#pragma once
// The walking pattern generator as a robot controller embeds it: one step() per control
// period (5 ms) gives the CoM, the CoP and both feet to track; the NMPC runs inside at each
// sampling period (0.1 s) boundary (paper Fig. 3: WPG every T, interpolation every control
// period). A new velocity command, new obstacles and an external push can be given between
// any two control periods. generateWalk (walk_generator.hpp) is a loop over this class
// (walk_loop.hpp).
//
//   wpg::OnlineWalkingGenerator generator(parameters, settings);
//   generator.reset(Eigen::Vector3d(x, y, yaw));
//   generator.setCommand(Eigen::Vector3d(0.2, 0.0, 0.0));  // from the next NMPC sample on
//   for (;;) { const wpg::ControlSample& s = generator.step(); /* track s */ }
#include <vector>

#include <Eigen/Core>

#include "wpg/pattern_generator.hpp"
#include "wpg/swing_foot_trajectory.hpp"
#include "wpg/walk_trajectory.hpp"

namespace wpg {

// The reference of one control instant (world frame).
struct ControlSample {
  double time = 0.0;  // [s] since reset()
  // CoM position (z = com_height), velocity and acceleration (z rates 0) [m, m/s, m/s^2]; the
  // acceleration includes the external push of the period that starts here.
  Eigen::Vector3d com_position = Eigen::Vector3d::Zero();
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d com_acceleration = Eigen::Vector3d::Zero();
  // LIPM CoP z = c - h/g c'' of the controlled acceleration (eq. 3; a push moves the CoM
  // without passing through the feet) [m].
  Eigen::Vector2d cop = Eigen::Vector2d::Zero();
  // Ankles: x, y, z (sole height above the ground) [m], yaw [rad]. The swing foot follows the
  // 5th-order polynomials of swing_foot_trajectory.hpp towards the planned landing.
  Eigen::Vector4d left_foot = Eigen::Vector4d::Zero();
  Eigen::Vector4d right_foot = Eigen::Vector4d::Zero();
  SupportState support = SupportState::kDouble;
  double free_flyer_yaw = 0.0;  // [rad], mean of the two foot yaws
  bool nmpc_sample = false;     // the NMPC ran at this instant (see lastIteration())
};

class OnlineWalkingGenerator {
 public:
  // Throws std::invalid_argument when the parameters or the settings do not validate.
  // Starts standing at the origin (reset()).
  // `extra_families`: constraint families added to the NMPC after the paper's ones.
  OnlineWalkingGenerator(const WalkingParameters& parameters, const GeneratorSettings& settings,
                         const ConstraintFamilies& extra_families = {});

  // Standing with the ankles side by side about `pose` = (x, y, yaw) [m, m, rad] of the point
  // between them, CoM at rest above it; time 0, zero command, no push; obstacles are kept.
  // Throws std::invalid_argument unless pose has 3 finite entries.
  void reset(const Eigen::Ref<const Eigen::VectorXd>& pose = Eigen::Vector3d::Zero());

  // Robot-frame velocity command [vx m/s, vy m/s, omega rad/s], clamped to the parameters'
  // limits; used from the next NMPC sample on (the next step() with atSamplingInstant()).
  // A zero command stops the walk (one step, a side-by-side step, then standing).
  // Throws std::invalid_argument unless it has 3 finite entries.
  void setCommand(const Eigen::Ref<const Eigen::VectorXd>& command);
  const Eigen::Vector3d& command() const { return command_; }

  // Obstacles to keep the steps away from (eq. 18-19), taken and owned; each is checked with
  // Obstacle::validate (std::invalid_argument naming "obstacles[i]"). Used from the next NMPC
  // sample on; an empty list removes them. Allocates (not for every control period).
  void setObstacles(std::vector<Obstacle> obstacles);
  const std::vector<Obstacle>& obstacles() const { return generator_.obstacles(); }
  // The distance the NMPC measures obstacles with; null without obstacles.
  const ObstacleSet* obstacleDistance() const { return generator_.obstacleDistance(); }

  // External horizontal acceleration of the CoM [m/s^2] (world; a force divided by the mass,
  // paper Sec. V-B) during the coming control period only (the next step()).
  // Throws std::invalid_argument unless it has 2 finite entries.
  void setPushAcceleration(const Eigen::Ref<const Eigen::VectorXd>& acceleration);

  // One control period: at a sampling instant, first the fall check (capture point within
  // fall_capture_distance of a foot) and the NMPC; then the reference at the current time,
  // and the CoM integrated to the end of the period (with the push). When the robot has
  // fallen, returns currentSample() and does nothing else until reset(). Does not allocate
  // once warmed up.
  const ControlSample& step();
  // The reference at the current time under the plan in force, without running the NMPC or
  // moving on (e.g. the closing sample of a recorded walk).
  const ControlSample& currentSample();

  // The CoM state (position, velocity, acceleration) per axis at time() [m, m/s, m/s^2].
  const Eigen::Vector3d& comStateX() const { return com_x_; }
  const Eigen::Vector3d& comStateY() const { return com_y_; }
  // Re-initialisation of the WPG (paper Fig. 3: the dynamic filter's corrected state becomes
  // the initial CoM state of the next NMPC iteration). Only at a sampling instant (before the
  // step() that runs the NMPC): the CoM state at time() becomes (com_x, com_y); the NMPC
  // plans from it and the interpolation continues from it.
  // Throws std::logic_error off a sampling instant, std::invalid_argument unless both have 3
  // finite entries.
  void reinitializeCom(const Eigen::Ref<const Eigen::VectorXd>& com_x,
                       const Eigen::Ref<const Eigen::VectorXd>& com_y);

  // What the plan in force previews (no NMPC run, no push, no state change): the reference at
  // the next `ticks` control instants from time() on, as step() would give it if the NMPC
  // kept its current solution (jerks and steps of the plan shifted in time). This is all a
  // controller knows of the coming motion, e.g. the dynamic filter's preview (Sec. IV).
  // Fills time, com, com_vel, com_acc, cop, the feet, free_flyer_yaw and support of `out`
  // (cleared first; no allocation once its capacity suffices). Beyond the NMPC's horizon the
  // last jerk is held. Throws std::logic_error at a sampling instant (the NMPC of the coming
  // sample has not run: call it after the step() that ran it).
  void previewReference(int ticks, WalkTrajectory& out) const;

  double time() const;                // [s], the instant the next step() starts at
  bool atSamplingInstant() const { return sub_sample_ == 0; }  // the next step() runs the NMPC
  const MpcIterationLog& lastIteration() const { return last_iteration_; }
  bool landed() const { return landed_; }  // a foot landed at the end of the last step()
  const Footstep& lastLanding() const { return generator_.lastLanding(); }
  bool fallen() const { return fallen_; }
  // Capture point distance to the nearest foot at the last sampling instant [m].
  double captureDistance() const { return capture_distance_; }
  const PatternGenerator& patternGenerator() const { return generator_; }
  const WalkingParameters& parameters() const { return generator_.parameters(); }

 private:
  void runNmpcSample(double t);
  void fillSample(double t);

  GeneratorSettings settings_;
  PatternGenerator generator_;
  SwingFootTrajectory swing_;
  bool swing_started_ = false;
  int sub_samples_ = 0;  // control periods per sampling period
  double height_over_gravity_ = 0.0, omega0_ = 0.0;

  long sample_index_ = 0;  // NMPC samples since reset
  int sub_sample_ = 0;     // control period within the sample
  Eigen::Vector3d com_x_ = Eigen::Vector3d::Zero(), com_y_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d command_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d push_ = Eigen::Vector2d::Zero();
  bool landed_ = false, fallen_ = false;
  double capture_distance_ = 0.0;
  MpcIterationLog last_iteration_;
  ControlSample sample_;
};

}  // namespace wpg
