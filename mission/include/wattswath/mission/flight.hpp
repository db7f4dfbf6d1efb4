#pragma once
/// @file flight.hpp
/// How the autopilot flies a mission: the mission sequenced into navigation steps in local metres
/// (the autopilot's own rules for DO commands, holds and jumps), then flown by a flight-behaviour
/// model of its family (ArduCopter S-curves, ArduCopter's leash, PX4's jerk-limited velocity
/// tracking) into a sampled trajectory, and that trajectory as energy::Pieces for the effects to
/// integrate. docs/autopilots.md states what each model follows and leaves out.

#include <optional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "wattswath/energy/profile.hpp"
#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/autopilot.hpp"
#include "wattswath/mission/mission.hpp"

namespace wattswath::mission {

/// Part of a flight, as pilots and the measured phases count it.
enum class FlightPhase { Takeoff = 0, Mission, Return, Landing };
/// Number of flight phases.
inline constexpr int kFlightPhaseCount = 4;
/// Lower-case name ("takeoff", "mission", "return", "landing").
const char* toString(FlightPhase p);

/// One navigation step the autopilot executes, in the local ENU frame of the home position.
struct NavStep {
  /// What the step does.
  enum class Kind { Takeoff, Waypoint, SplineWaypoint, LoiterTime, LoiterTurns, Delay, ReturnToLaunch, Land };
  Kind kind = Kind::Waypoint;                              ///< what the step does
  Eigen::Vector3d target = Eigen::Vector3d::Zero();        ///< [m] ENU position (Takeoff: z only)
  bool has_position = true;                                ///< false: Land / LoiterTime "here"
  /// false: the item's altitude is written as 0, which ArduPilot reads as "the previous target's
  /// altitude" (ModeAuto::loc_from_cmd); without a position `target.z` is the item's altitude
  bool alt_given = true;
  double hold_s = 0.0;                                     ///< [s] hold after reaching (waypoint, loiter, delay)
  double speed_xy = 0.0;                                   ///< [m/s] horizontal speed in force (0: autopilot default)
  /// [m/s] horizontal speed in force by PX4's rule, where every DO_CHANGE_SPEED sets it whatever
  /// its speed type and -1 returns to the default (ArduPilot: no change); 0: default
  double speed_xy_px4 = 0.0;
  /// [m/s] horizontal speed in force by ArduCopter 3.x's rule (Copter::do_change_speed of 3.2-3.6
  /// reads param2 only: a climb or descent speed, type 2 or 3, sets the horizontal speed too); 0: default
  double speed_xy_3x = 0.0;
  double speed_up = 0.0;                                   ///< [m/s] climb speed in force (0: default)
  double speed_down = 0.0;                                 ///< [m/s] descent speed in force (0: default)
  /// [m/s] horizontal speed in force (0: default) as ArduCopter 4.1-4.4 has it: the first waypoint
  /// after a take-off or a circle restarts the waypoint controller at WPNAV_SPEED, dropping the
  /// DO_CHANGE_SPEED run before it (ArduPilot issue 21080, fixed in 4.5)
  double speed_xy_41 = 0.0;
  double speed_up_41 = 0.0;    ///< [m/s] climb speed in force by the same 4.1-4.4 rule (0: default)
  double speed_down_41 = 0.0;  ///< [m/s] descent speed in force by the same 4.1-4.4 rule (0: default)
  double accept_radius_m = 0.0;                            ///< [m] item acceptance radius (0: default)
  /// [m] Takeoff: the item's horizontal position (ENU east, north), which PX4 flies to after the
  /// climb (Mission::set_mission_items: "navigate to the actual waypoint now"); ArduCopter climbs in
  /// place and ignores it (ModeAuto::takeoff_start). NaN when the item gives none (lat/lon 0 or unset)
  Eigen::Vector2d takeoff_xy = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  /// LoiterTurns: the number of turns and the radius [m] as ArduPilot keeps them (whole numbers),
  /// circled clockwise seen from above unless `loiter_ccw`; `target` is the centre
  double loiter_turns = 0.0;
  double loiter_radius_m = 0.0;                            ///< [m] LoiterTurns: radius of the circle
  bool loiter_ccw = false;                                 ///< LoiterTurns: counter-clockwise (param3 < 0)
  int item = -1;                                           ///< index into Mission::items (-1: none)
  std::string where;                                       ///< the item's "FILE:LINE" for notes (empty: none)
};

/// True for the steps the vehicle flies to a position (waypoint, spline waypoint, loiter time).
bool isFlownTo(const NavStep& s);

/// Throws std::invalid_argument when the mission cannot be sequenced: no navigation item, a
/// speed of 0 or below (other than -1: "no change" for ArduPilot, "back to the default" for PX4),
/// a position not finite. Items after a
/// NAV_RETURN_TO_LAUNCH or NAV_LAND are never reached and are ignored (listed in `warnings`).
/// DO_JUMP is unrolled (bounded by `max_steps`). Altitudes: relative frames are above home,
/// absolute ones minus the home altitude, terrain frames are taken as above home (flat terrain).
std::vector<NavStep> sequenceMission(const Mission& m, std::vector<std::string>* warnings = nullptr,
                                     std::size_t max_steps = 100000);

/// One sample of a flown trajectory.
struct FlightSample {
  double t = 0.0;                                    ///< [s] since the take-off command
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< [m] ENU from home
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< [m/s] ENU
  FlightPhase phase = FlightPhase::Takeoff;          ///< phase the vehicle is in
  int step = -1;                                     ///< index of the NavStep being flown
  bool airborne = true;                              ///< false while spooling up or landed
};

/// When a step was reached.
struct StepEvent {
  int step = -1;              ///< index into the steps
  double reached_s = 0.0;     ///< [s] when the autopilot declared it reached (NaN: never)
  double completed_s = 0.0;   ///< [s] when it moved on (after any hold)
};

/// A flight predicted by a behaviour model.
struct FlownMission {
  std::vector<NavStep> steps;       ///< the sequenced mission
  std::vector<FlightSample> samples;  ///< trajectory, every FlightSettings::sample_dt
  std::vector<StepEvent> events;    ///< one per step
  std::vector<std::string> notes;   ///< what the model assumed (e.g. "RTL speed = WPNAV_SPEED")
  std::string model;                ///< the model and the parameters it flew with, in one line
};

/// How the airframe follows the autopilot's acceleration commands (used by the ArduCopter models,
/// whose position controllers close the loop with it): the horizontal drag deceleration
/// c1 v + c2 v^2 at the speed through the air that the lean angle must overcome (and that, at
/// ANGLE_MAX, caps the speed), and the lag of the achieved acceleration behind the commanded one
/// (docs/autopilots.md).
struct Airframe {
  double drag_linear_per_s = 0.0;     ///< [1/s] c1: rotor (momentum) drag per unit mass and speed
  double drag_quadratic_per_m = 0.0;  ///< [1/m] c2: body drag 0.5 rho CdA / m
  /// [m/s] the steady wind it flies in, where the air moves to (east, north); |wind| <= 40. The
  /// drag acts on the velocity relative to the air; the autopilot controls the ground velocity.
  Eigen::Vector2d wind = Eigen::Vector2d::Zero();
  /// [s] first-order lag of the achieved acceleration behind the command, when the vehicle file
  /// gives one; unset: the autopilot's attitude input time constant (ArduCopter ATC_INPUT_TC, whose
  /// shaping the lean follows: 0.15 s by default, and 0.15-0.175 s fitted on the ArduCopter 4.7 SITL
  /// logs' PSCN/PSCE target against achieved acceleration)
  std::optional<double> response_s;
  /// false: the vehicle is taken to be exactly on the autopilot's target (no tracking error)
  bool track = true;
};

/// The airframe of a vehicle: its body drag 0.5 rho CdA / m from the energy model's drag area,
/// no rotor drag term (the energy model has none), the default response time.
Airframe airframeOf(double drag_area_m2, double mass_kg, double air_density_kgpm3);

/// Typical distance [m] of a vehicle from the line it follows, horizontally and vertically.
struct TrackingError {
  double horizontal_m = 0.0;  ///< [m] median cross-track distance in cruise; 0..20
  double vertical_m = 0.0;    ///< [m] median height error in cruise; 0..20
};

/// Settings of the simulation.
struct FlightSettings {
  double dt = 0.01;         ///< [s] simulation step (the autopilots run at 100-400 Hz); 0.001..0.05
  double sample_dt = 0.1;   ///< [s] output sample interval, a multiple of dt; 0.01..1
  double max_time_s = 6 * 3600.0;  ///< [s] refuse missions longer than this (6 h)
  /// [s] from the take-off command to lift-off (motor spool-up, liftoff detection); < 0: the
  /// autopilot's documented spool time (ArduCopter MOT_SPOOL_TIME, PX4 COM_SPOOLUP_TIME)
  double takeoff_delay_s = -1.0;
  double landed_detect_s = 1.0;  ///< [s] from touch-down to "landed" (ArduCopter LAND_DETECTOR_TRIGGER_SEC)
  /// Fly every waypoint as a stop (brake into it, start the next leg from rest) even without a hold
  /// time: what some logged flights show where the firmware's rule is not known (calibration decides)
  bool stop_at_waypoints = false;
  /// Apply each DO_CHANGE_SPEED one waypoint later than AP_Mission's order says (to the leg after
  /// the one it precedes): what the IRIS+ ArduCopter 3.x logs show (calibration decides)
  bool speed_change_late = false;
  /// How far the vehicle typically sits off the line it is told to fly (GPS and EKF noise, gusts),
  /// measured on logs by calibration; 0: on the line. ArduCopter before 3.4 shortens the carrot's
  /// lead by it, which slows the cruise (the leash model); the other models do not use it.
  TrackingError tracking_error;
  Airframe airframe;  ///< how the vehicle follows its autopilot (S-curve model)
};

/// Flies `steps` with the behaviour model of `autopilot`. Throws std::invalid_argument naming the
/// parameter when a parameter is out of range (a speed of 0, ...), std::runtime_error when the
/// flight exceeds `s.max_time_s`.
FlownMission flyMission(const std::vector<NavStep>& steps, const AutopilotConfig& autopilot,
                        const FlightSettings& s = {});

/// The flown trajectory as constant-acceleration pieces (one per sample interval: speeds at the
/// ends, heading change as yaw, height change as climb), with the flight phase and step of each.
struct FlightPieces {
  std::vector<energy::Piece> pieces;       ///< for EnergyModel::evaluate
  std::vector<FlightPhase> phase;          ///< flight phase of each piece
  std::vector<int> step;                   ///< step of each piece
};

/// Converts a flown trajectory to pieces.
FlightPieces toPieces(const FlownMission& f);

}  // namespace wattswath::mission
