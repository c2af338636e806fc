#pragma once
/// @file
/// The physics check: a push run in a real engine (Box2D), not
/// in fixel's own model. Everything here is a *measurement*: the engine works
/// in floating point, so its outcome is evidence about a plan, never a
/// decision of fixel's exact analysis. No engine type appears in this header.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fixel/rational.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/seating.h"

namespace fixel::physics {

/// A constant wrench in the world frame (axes of frame A): a force (N)
/// through the centre of mass and a moment (N·m) about it. Doubles: this is
/// an engine input. For a point mass (dof 2) the moment is ignored.
struct Wrench {
  double fx = 0, fy = 0, m = 0;
};

/// Rounds an exact wrench (length dof) for the engine. Throws InputError
/// naming `field` if its length is not the scene's dof.
Wrench to_wrench(const VectorQ& w, int dof, const std::string& field = "wrench");

/// Parses "wx,wy,wm" ("wx,wy" for dof 2) exactly, then rounds it. Throws
/// ParseError / InputError naming `field`.
Wrench parse_wrench(const std::string& text, int dof, const std::string& field = "--wrench");

/// The motion of the part from the scene's pose: (x, y) displacement of the
/// centre of mass in frame A (m) and rotation θ about it (rad, CCW).
struct Pose {
  double x = 0, y = 0, theta = 0;
};

/// How a push ended (see docs/physics.md for the exact definitions).
enum class Outcome {
  kSeated,   ///< Every gap < gap_tolerance, at rest, for one h.
  kJammed,   ///< At rest for one h, touching a fixel, with a gap open.
  kEscaped,  ///< No contact, and free flight provably never returns.
  kTimeout,  ///< None of the above within the time limit.
};
std::string to_string(Outcome outcome);

/// Options of a push run.
struct PushOptions {
  Rational time = 20;            ///< T: the wrench is held for T·h (> 0).
  long steps_per_h = 1000;       ///< dt = h / steps_per_h; at least 1000.
  int velocity_iterations = 20;  ///< Box2D solver iterations per step (1 to kMaxSolverIterations).
  int position_iterations = 10;  ///< Box2D position iterations per step (1 to kMaxSolverIterations).
  int trajectory_samples = 200;  ///< Poses kept for the SVG (about this many).
  int max_events = 2000;         ///< Contact events kept (later ones dropped).
  bool stop_at_outcome = true;   ///< Stop as soon as the outcome is decided.
  /// An impulse p (N·s, N·s, N·m·s; world frame, about the centre of mass)
  /// delivered at t = 0 on top of the wrench: ν ← ν^ℓ + M⁻¹ p. Finite, and
  /// small enough for the engine's floats (else InputError).
  std::optional<std::array<double, 3>> impulse;
  /// Polled every 1024 engine steps (may be null): cancelling it or passing
  /// its deadline throws StoppedError.
  RunControl* control = nullptr;
};

/// Checks `options`' ranges (time > 0, steps_per_h >= 1000, iterations 1 to
/// kMaxSolverIterations) and the step limit time · steps_per_h <=
/// kMaxPushSteps (named by steps_per_h when it is not the default, else by
/// time); throws InputError naming the field. push() and validate_region()
/// call it first.
void check_push_options(const PushOptions& options);

/// The most engine steps one push may take, time · steps_per_h (the
/// default push takes 20,000): 1.2 to 8 minutes on the bundled parts.
constexpr long kMaxPushSteps = 100000000;
/// The most Box2D solver iterations (velocity or position) per step.
constexpr int kMaxSolverIterations = 1000;

/// One recorded pose of the trajectory.
struct TrajectorySample {
  double t = 0;  ///< Time since the push began (s).
  Pose pose;
};

/// A contact beginning or ending in the engine.
struct ContactEvent {
  double t = 0;  ///< s
  int fixel = 0;
  bool begin = true;
  Pose pose;  ///< The part's pose at that step.
};

/// The result of one push.
struct PushResult {
  Outcome outcome = Outcome::kTimeout;
  std::optional<double> time_to_seat;  ///< s; start of the seated-at-rest window.
  double time_end = 0;                 ///< Simulated time when the run stopped (s).
  Pose final_pose;
  /// Signed gap of every fixel at the end (m): distance from f_i to the true
  /// polygon of the part (negative inside).
  std::vector<double> final_gaps;
  std::vector<int> contacts_at_rest;  ///< Fixels touching at the end (engine contacts).
  std::vector<int> open_fixels;       ///< Jammed: fixels whose gap is open.
  double dt = 0;                      ///< Engine step (s).
  long steps_per_h = 0;               ///< dt = h / steps_per_h (PushOptions::steps_per_h).
  int velocity_iterations = 0;        ///< Box2D's solver iterations per step, as run.
  int position_iterations = 0;
  double length_scale = 0;   ///< Engine length units per metre of the scene.
  double part_size = 0;      ///< Bounding-box diagonal of the part (m).
  double gap_tolerance = 0;  ///< 1e-4 · part_size (m).
  double rest_speed = 0;     ///< "At rest" speed bound (m/s), see docs/physics.md.
  /// The push's own time scale (s): the least of √(m·size/|F|), √(I/|M|)
  /// and, for an impulse, size/|Δv|; 0 when nothing pushes.
  double time_scale = 0;
  /// Where the engine's thresholds do not suit the push (a time scale of
  /// under 50 engine steps, or over 10 h): read the outcome with care.
  std::vector<std::string> warnings;
  long steps = 0;  ///< Engine steps taken.
  std::vector<TrajectorySample> trajectory;
  std::vector<ContactEvent> events;
};

/// Runs the part from the scene's pose (velocity ν^ℓ) under the constant
/// wrench `w`, held for options.time · h. Throws SceneError if the scene has
/// no boundary or its polygon self-intersects or cannot be partitioned
/// (naming the curve), InputError for bad options.
PushResult push(const Scene& scene, const Wrench& w, const PushOptions& options = {});
/// The same with an exact wrench (length dof), rounded for the engine.
PushResult push(const Scene& scene, const VectorQ& w, const PushOptions& options = {});

/// The wrench of a frictionless unit push (|force| = 1 N) at parameter u of
/// curve `curve`, with the part at `pose` (usually q*): force R(θ)·n_B, moment
/// (b − c) ⊗ n_B, where b is the body-frame boundary point, c the centre of
/// mass and n_B the unit inward normal there (right-hand derivative at a
/// polyline vertex, left-hand at the curve's end). Throws InputError naming
/// `field` for a curve index or u out of range, InputError naming
/// `pose.theta` when it is not finite, SceneError for a zero tangent.
Wrench push_wrench_at(const Scene& scene, int curve, const Rational& u, const Pose& pose,
                      const std::string& field = "--at");

/// A curve and a parameter on it, parsed from "K:U" (U exact).
struct CurvePoint {
  int curve = 0;
  Rational u;
};
/// Parses "K:U" and checks it against the scene's boundary. Throws
/// ParseError / InputError naming `field`.
CurvePoint parse_curve_point(const Scene& scene, const std::string& text, const std::string& field = "--at");

/// The part as the engine sees it (frame A, metres), exposed for tests and
/// drawings.
struct PartPolygon {
  std::vector<std::array<double, 2>> outline;              ///< CCW, curves polygonised.
  std::vector<int> edge_curve;                             ///< Curve of outline edge k (from vertex k).
  std::vector<std::vector<std::array<double, 2>>> pieces;  ///< Convex pieces (CGAL partition).
  double size = 0;                                         ///< Bounding-box diagonal.
  double chordal_tolerance = 0;                            ///< Max chord error used (< 1e-4 · size).
};
/// Polygonises the boundary and splits it into convex pieces. Throws
/// SceneError naming the curve if the polygon self-intersects, and naming
/// "body.boundary" if there is none or it cannot be partitioned. `control`
/// (may be null) is polled between the stages: StoppedError past its
/// deadline or when cancelled.
PartPolygon part_polygon(const Scene& scene, RunControl* control = nullptr);

/// For the mapping test: at t = 0, the engine distance from each fixel's
/// circle to the part's fixtures, minus the documented contact offset, in
/// metres. It equals ψ_i up to float rounding.
std::vector<double> initial_engine_gaps(const Scene& scene);

/// A push model for region validation: the constant wrench to apply for a
/// push at parameter u of the interval's curve.
using PushModel = std::function<Wrench(const RegionInterval& interval, const Rational& u)>;

/// The one-step model (the paper's region): the impulse p = τ (d, r ⊗ d) at
/// the scene pose, d the unit inward normal, held as the force p/h. τ is the
/// midpoint of the interval's certified magnitudes when bounded, twice the
/// lower end when unbounded (the apex norm |p_apex| when that end is 0), or
/// the point's own magnitudes when the interval has none. The model keeps
/// references to `scene` and `S`: both must outlive it. Throws InputError
/// naming S when it is not this scene's (check_seating_set_of).
PushModel one_step_push_model(const Scene& scene, const SeatingSet& S, const Rational& pusher_mu);

/// The sustained-push model: the frictionless push wrench of
/// push_wrench_at at the seated pose q* (fixel::seated_pose, solved once
/// here), scaled to |force| = `force` N. Throws what seated_pose throws,
/// and InputError naming `force` unless it is finite and above 0.
/// The model keeps a reference to `scene`, which must outlive it.
PushModel seated_push_model(const Scene& scene, double force = 1);

/// Validation counts of one IN interval, or of the whole region.
struct Validation {
  int pushes = 0;
  int seated = 0;
  int jammed = 0, escaped = 0, timeout = 0;  ///< The other outcomes.
  int warned = 0;                            ///< Pushes whose PushResult has warnings.
  int seated_warned = 0;                     ///< Of the seated pushes, those that warned.
};
struct RegionValidation {
  std::vector<std::optional<Validation>> intervals;  ///< Per interval; set for IN ones.
  Validation total;
  std::uint64_t seed = 0;
  std::string model = "one-step impulse p/h held for T";  ///< Named in the reports.
  PushOptions options;
  std::string first_warning;  ///< The first push's warning, if any pushed warned.
};

/// For every IN interval, `pushes` pushes at deterministic pseudo-random
/// parameters of the interval (seeded), each run through push().
RegionValidation validate_region(const Scene& scene, const Region& region, const PushModel& model, int pushes,
                                 std::uint64_t seed, const PushOptions& options = {});

/// `fixel push --json`: {"outcome", "time_to_seat", "final_pose", "final_gaps",
/// "contacts_at_rest", "open_fixels", "wrench", "dt", "length_scale",
/// "part_size", "gap_tolerance", "rest_speed", "time_scale", "warnings", "time", "steps",
/// "events"}.
std::string push_json(const Scene& scene, const Wrench& w, const PushResult& r);
/// The same as a readable report.
std::string push_text(const Scene& scene, const Wrench& w, const PushResult& r);
/// Draws the trajectory: ghost outlines, the fixels, contact events, and
/// with `w` the push: an arrow along its force's line of action at the
/// start, ending where that line enters the part. Throws InputError if the
/// file cannot be written.
void write_push_svg(const std::string& path, const Scene& scene, const PushResult& r, const Wrench* w = nullptr);

/// Adds "validation" to a region JSON document (from region_json): per IN
/// interval {"pushes", "seated"}, and a total with the seed and engine step.
std::string add_validation_json(const std::string& region_json_text, const RegionValidation& v);
/// The text lines of a validation.
std::string validation_text(const Region& region, const RegionValidation& v);

}  // namespace fixel::physics
