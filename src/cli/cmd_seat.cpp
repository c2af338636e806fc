// fixel seat: the seating set S (or the sustained set J), and fixel dump.
#include <iostream>
#include <memory>
#include <optional>

#include "cli.h"
#include "fixel/approach.h"
#include "fixel/error.h"
#include "fixel/io.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seat_report.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"
#include "fixel/svg.h"

namespace fixel::cli {
namespace {

struct SeatArgs {
  std::vector<std::string> scene_paths;
  std::string scene_path, impulse_text, svg_path, wrench_text;
  bool json = false, guaranteed = false, stable = false, sustained = false;
  RunOptions run;
};

int run_sustained_seat(const Scene& scene, const SeatArgs& a) {
  if (a.guaranteed || a.stable || !a.svg_path.empty() || !a.impulse_text.empty())
    throw InputError("--sustained", "", "cannot be combined with --guaranteed, --stable, --svg or --impulse");
  std::optional<VectorQ> w_W;
  if (!a.wrench_text.empty()) w_W = parse_impulse(a.wrench_text, 3, "--wrench");
  const SustainedSet J = sustained_set(scene);
  const ApproachSet A = approach_set(scene, J);
  std::optional<WrenchVerdict> wrench;
  std::optional<ApproachVerdict> approach_wrench;
  if (w_W) {
    wrench = wrench_verdict(J, *w_W);
    approach_wrench = approach_verdict(A, *w_W);
  }
  std::cout << (a.json ? sustained_json(scene, J, wrench, &A, approach_wrench, true)
                       : sustained_text(scene, J, wrench, &A, approach_wrench));
  return 0;
}

int run_seat(const SeatArgs& a) {
  const Scene scene = read_scene(a.scene_path);
  if (a.sustained) return run_sustained_seat(scene, a);
  if (!a.wrench_text.empty()) throw InputError("--wrench", a.wrench_text, "needs --sustained");
  const SeatingSet S = seating_set(scene);
  std::optional<GuaranteedSet> G;
  if (a.guaranteed) G = guaranteed_set(scene, S, run_control());
  const GuaranteedSet* g = G ? &*G : nullptr;
  std::optional<VectorQ> impulse;
  if (!a.impulse_text.empty()) impulse = with_background(scene, parse_impulse(a.impulse_text, scene.body.dof));
  // Every input check before any output (the picture is a p_theta slice).
  if (!a.svg_path.empty() && scene.body.dof != 3)
    throw InputError("--svg", a.svg_path,
                     "cannot be drawn for a point mass: the S/G picture needs dof 3 (a slice at constant p_theta)");
  check_writable(a.svg_path, "--svg");
  check_not_input(a.scene_path, a.svg_path, "--svg");
  const SeatReport report = seat_report(scene, S, impulse, g, a.stable);
  if (impulse) print_background_note(scene, *impulse, a.json);
  std::cout << (a.json ? seat_json(scene, S, report, g) : seat_text(scene, S, report, g));
  if (!a.svg_path.empty()) {
    write_guaranteed_svg(a.svg_path, scene, S, g, impulse ? (*impulse)[2] : default_slice_theta(S), impulse);
    if (!a.json) std::cout << "wrote " << a.svg_path << "\n";
  }
  return 0;
}

struct DumpArgs {
  std::string scene_path, off_dir, length_text = "1";
  bool guaranteed = false, sustained = false;
  RunOptions run;
};

int run_dump(const DumpArgs& a) {
  arm_run_control(a.run);
  check_output_folder(a.off_dir, "--off");  // before anything is computed, as for every output
  const Rational length = parse_rational(a.length_text, "--length");
  const Scene scene = read_scene(a.scene_path);
  if (a.sustained) {
    const SustainedSet J = sustained_set(scene);
    for (const auto& path : dump_sustained_off(scene, J, a.off_dir)) std::cout << "wrote " << path << "\n";
    if (!J.pieces_decided)
      std::cout << "no sustained_piece_*.off: J's pieces are undecided here (q* only enclosed; seat --sustained says "
                   "why)\n";
  }
  const SeatingSet S = seating_set(scene);
  std::optional<GuaranteedSet> G;
  if (a.guaranteed) G = guaranteed_set(scene, S, run_control());
  for (const auto& path : dump_off(scene, S, a.off_dir, length, G ? &*G : nullptr))
    std::cout << "wrote " << path << "\n";
  return 0;
}

}  // namespace

Command add_seat(CLI::App& app) {
  auto a = std::make_shared<SeatArgs>();
  auto* cmd = app.add_subcommand("seat", "The seating impulse set S (paper §3): apex, rays and facets");
  cmd->add_option("scene", a->scene_paths, kScenesHelp)->required();
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout (one line per scene for several)");
  cmd->add_option("--impulse", a->impulse_text, "Test an impulse: px,py[,ptheta] (exact numbers; b0 is added)");
  cmd->add_flag("--guaranteed", a->guaranteed, "Also compute G, the impulses whose every outcome seats");
  cmd->add_flag("--stable", a->stable, "Also give the seat-and-stay set S ∩ h·C_stab");
  cmd->add_option("--svg", a->svg_path, "Draw the slice p_theta = const of S (and of G with --guaranteed); dof 3");
  cmd->add_flag("--sustained", a->sustained,
                "The sustained-push wrench set J at the seated pose q* (past the paper); --json adds its keys to S's");
  cmd->add_option("--wrench", a->wrench_text, "With --sustained: test a world-frame wrench wx,wy,wm (exact numbers)");
  add_run_options(cmd, a->run);
  return {cmd, [a] {
            arm_run_control(a->run);
            if (a->scene_paths.size() > 1 && !a->svg_path.empty())
              throw InputError("--svg", a->svg_path, "draws one scene: give a single scene file");
            return run_batch(a->scene_paths, a->json, [a](const std::string& p) {
              a->scene_path = p;
              return run_seat(*a);
            });
          }};
}

Command add_dump(CLI::App& app) {
  auto a = std::make_shared<DumpArgs>();
  auto* cmd = app.add_subcommand("dump", "Write S as an OFF file, clipped to a stated box");
  cmd->add_option("scene", a->scene_path, "Scene file (JSON, docs/formats.md); - reads standard input")->required();
  cmd->add_option("--off", a->off_dir, "Output directory")->required();
  cmd->add_option("--length", a->length_text, "Box holds apex + LENGTH * r for every ray r (default 1)");
  cmd->add_flag("--guaranteed", a->guaranteed, "Also write the pieces of the guaranteed set G");
  cmd->add_flag("--sustained", a->sustained, "Also write the cones of the sustained-push set J (clipped, display)");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_dump(*a); }};
}

}  // namespace fixel::cli
