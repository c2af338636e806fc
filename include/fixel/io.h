#pragma once
/// @file
/// Result documents: the JSON contract of docs/formats.md and readable reports.

#include <optional>
#include <string>
#include <vector>

#include "fixel/guaranteed.h"
#include "fixel/outcomes.h"
#include "fixel/push_plan.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/seat_report.h"
#include "fixel/seating.h"
#include "fixel/stepper.h"
#include "fixel/sustained.h"
#include "fixel/verify.h"

namespace fixel {

/// `fixel seat --json`: {"scene", "dof", "sliding", "velocity_after",
/// "tangential_velocity", "apex", "rays", "halfspaces": [{"a", "c"}]} and,
/// with an impulse, "contains", "y" and "y_names" (eq. 27; sliding contacts
/// only). With G: "guaranteed_set": {"non_seating": [{"modes",
/// "open_fixel", "closed", "strict"}], "pieces": [{"closed", "strict"}],
/// "lost_fraction"} and, with an impulse, "guaranteed". With `stable`:
/// "stability_cone" and "seat_and_stay" (H-forms) and, with an impulse,
/// "seat_and_stay_contains". Numbers are exact strings. `report` comes from
/// seat_report(scene, S, impulse, G, stable) with the same G. Throws
/// InputError naming S or G when they are not this scene's
/// (check_guaranteed_set_of).
std::string seat_json(const Scene& scene, const SeatingSet& S, const SeatReport& report,
                      const GuaranteedSet* G = nullptr);

/// The same content as a readable report (the same checks).
std::string seat_text(const Scene& scene, const SeatingSet& S, const SeatReport& report,
                      const GuaranteedSet* G = nullptr);

/// Writes into directory `dir` (created if needed): `seating_set.off` (S
/// clipped to seating_dump_box(S, length)); with G, `guaranteed_<k>.off` for
/// each piece of G (its closure clipped to the same box); with a boundary, `boundary.obj`
/// (the outline as a sampled polyline) and one
/// `segment_<k>_<family>_<method>.off` per Bézier piece, edge family and cone
/// method (the cone clipped to the box [−1, 1]³; pieces whose tangent cone
/// is not pointed have no cone). Each `.off` file is standard OFF without
/// comments, with its metadata in a JSON sidecar of the same stem (`X.json`,
/// docs/formats.md). Returns the written paths, sidecars included.
/// Throws InputError if the directory cannot be created or written, or,
/// before anything is written, naming S or G when they are not this
/// scene's (check_guaranteed_set_of).
std::vector<std::string> dump_off(const Scene& scene, const SeatingSet& S, const std::string& dir,
                                  const Rational& length, const GuaranteedSet* G = nullptr);

/// `fixel simulate --json`: {"seated", "steps": [{"q", "velocity", "gaps",
/// "p_n", "p_f", "pivots"}]}.
/// With `first_step`, the count of one-step outcomes of the first impulse
/// ("outcomes_of_first_step": {"total", "seating"}; the text warns when
/// there is more than one).
std::string simulation_json(const Scene& scene, const Simulation& sim, const OutcomeCount* first_step = nullptr);
/// The same as a readable report.
std::string simulation_text(const Scene& scene, const Simulation& sim, const OutcomeCount* first_step = nullptr);

/// `fixel solutions --json`: {"impulse", "solutions": [{"seated", "modes",
/// "velocity", "gaps", "p_n", "p_t", "isolated"}], "seating": n, "non_seating": m}.
std::string outcomes_json(const Scene& scene, const VectorQ& p_ext, const std::vector<Outcome>& outcomes);
/// The same as a readable report.
std::string outcomes_text(const Scene& scene, const VectorQ& p_ext, const std::vector<Outcome>& outcomes);

/// `fixel region --json` / `fixel sample --json`: {"scene", "method",
/// "resolution", "pusher_mu", "intervals": [{"curve", "u0", "u1", "status",
/// "half_line", "magnitudes": {"min", "min_inclusive", "max",
/// "max_inclusive"} | null}], "counts", "stats": {...}}.
/// The method, resolution and pusher μ are the ones the region records.
/// `seat` (a sustained region: J's seated pose) adds "seated_pose" (as in
/// sustained_json, with |θ*| in "theta_abs") and "seat_note" (the note or
/// warning of seat_rotation_note) before "push".
std::string region_json(const Scene& scene, const Region& region, const SeatedPose* seat = nullptr);
/// The same as a readable report.
std::string region_text(const Scene& scene, const Region& region);

/// `fixel seat --sustained --json`: {"scene", "seated_pose": {"exact",
/// "approx", "algebraic", "enclosure", "theta_abs", "at_scene_pose",
/// "contacts"}, "sustained": {"cone", "jam_cones", "pieces", "empty",
/// "empty_reason"?, "strongly_stable", "mu"}} and, with a wrench, "wrench",
/// "contains" and "why_not" (docs/formats.md). With `approach` (J′ of
/// approach.h, made from J), an "approach" object: "decided", "t_star",
/// "theta_star", "on_edges", "empty" and, with `approach_wrench`, its
/// "contains", "why_not" and "hold".
/// With `with_seating` (the CLI's) the keys of `seat --json` for S come
/// first, so the document adds J's keys to S's; when S cannot be built for
/// the scene (a friction interval: the one-step model needs one value),
/// "seating_unavailable" gives the reason instead. Throws InputError naming
/// J (or J') when it was built from a scene that differs where J looks.
std::string sustained_json(const Scene& scene, const SustainedSet& J, const std::optional<WrenchVerdict>& wrench,
                           const ApproachSet* approach = nullptr,
                           const std::optional<ApproachVerdict>& approach_wrench = std::nullopt,
                           bool with_seating = false);
/// The same as a readable report (the same checks).
std::string sustained_text(const Scene& scene, const SustainedSet& J, const std::optional<WrenchVerdict>& wrench,
                           const ApproachSet* approach = nullptr,
                           const std::optional<ApproachVerdict>& approach_wrench = std::nullopt);
/// A "warning: ..." line (ending in a newline) for a seat turned by
/// |θ*| >= 0.2 rad, where Box2D studies saw J fail more often on the way
/// (docs/physics.md), and otherwise a "note: ..." line saying that J is
/// decided in the model linearised at q*. Display (θ* as a double).
std::string seat_rotation_note(const SeatedPose& q);
/// Writes J's cones into `dir` as OFF files clipped to [−1, 1]³ (display:
/// rows rounded to double): `sustained_cone.off`, `sustained_jam_<i>_<j>.off`
/// and `sustained_piece_<k>.off`, each with its JSON sidecar (as dump_off).
/// Returns the written paths, sidecars included. Throws
/// InputError if the directory cannot be created or written, or, before
/// anything is written, naming J when it is another scene's.
std::vector<std::string> dump_sustained_off(const Scene& scene, const SustainedSet& J, const std::string& dir);
/// The "seated_pose" object of sustained_json, as compact JSON text.
std::string seated_pose_json(const SeatedPose& q);

/// `fixel verify` output: one line per check, then a summary line.
std::string verification_text(const std::vector<VerificationCheck>& checks);
/// `fixel verify --json`: {"checks": [{"name", "passed", "detail"}], "passed": bool}.
std::string verification_json(const std::vector<VerificationCheck>& checks);

/// `fixel push-plan --json`: {"scene", "curve", "u", "point", "normal",
/// "wrench_direction", "one_step": {"status", "magnitudes", "relative_width",
/// "sample_impulse", "sample_outcomes": {"total", "seating"}}, "guaranteed":
/// {...} | null, "sustained": {"status"} | {"note"}}.
std::string push_plan_json(const Scene& scene, const PushPlan& plan);
/// The same as a readable report.
std::string push_plan_text(const Scene& scene, const PushPlan& plan);

}  // namespace fixel
