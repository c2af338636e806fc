// The fixel command line: parses arguments and calls the library.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>

#include "fixel/error.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/region_target.h"
#include "fixel/scene.h"
#include "fixel/seated_pose.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"
#include "fixel/svg.h"
#include "fixel/verify.h"

namespace {

// Exit codes: 0 success, 1 a verification failed, 2 bad input or usage,
// 3 a bug in fixel, 4 --max-seconds reached, 130 interrupted (Ctrl-C).
constexpr int kExitBadInput = 2;
constexpr int kExitBug = 3;
constexpr int kExitTimeLimit = 4;
constexpr int kExitInterrupted = 130;
constexpr const char* kReportLine =
    "fixel: this is a bug in fixel, please report it with the command line and the scene file\n";

// The run's control block; the SIGINT handler only sets its lock-free flag.
fixel::RunControl g_run;
bool g_progress_shown = false;

extern "C" void on_sigint(int) {
  g_run.cancel.store(true);
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
}

// Progress on stderr, rewriting one line (only installed on a terminal).
void show_progress(const char* task, long done, long total, const char* unit) {
  const double seconds = std::chrono::duration<double>(fixel::RunControl::Clock::now() - g_run.start).count();
  if (total > 0)
    std::fprintf(stderr, "\r%s: %ld of %ld %s (%.1f%%), %.0f s", task, done, total, unit, 100.0 * done / total,
                 seconds);
  else
    std::fprintf(stderr, "\r%s: %ld %s, %.0f s", task, done, unit, seconds);
  std::fflush(stderr);
  g_progress_shown = true;
}

void end_progress() {
  if (g_progress_shown) std::fputs("\n", stderr);
  g_progress_shown = false;
}

// Arms g_run for a long command: deadline, progress, Ctrl-C.
void arm_run_control(double max_seconds, bool quiet) {
  if (max_seconds < 0 || !std::isfinite(max_seconds))
    throw fixel::InputError("--max-seconds", std::to_string(max_seconds), "must be > 0");
  if (max_seconds > 0)
    g_run.deadline = g_run.start + std::chrono::duration_cast<fixel::RunControl::Clock::duration>(
                                       std::chrono::duration<double>(max_seconds));
  if (!quiet && isatty(STDERR_FILENO)) g_run.on_progress = show_progress;
  std::signal(SIGINT, on_sigint);
}

// Test hook for the exit-3 path: FIXEL_TEST_FAULT=internal or =std.
void maybe_inject_fault() {
  const char* fault = std::getenv("FIXEL_TEST_FAULT");
  if (!fault) return;
  if (std::string(fault) == "internal") throw fixel::InternalError("injected by FIXEL_TEST_FAULT=internal");
  if (std::string(fault) == "std") throw std::runtime_error("injected by FIXEL_TEST_FAULT=std");
}

// A pusher μ, or an interval "lo,hi": the region shrinks as the pusher's μ
// grows (docs/theory.md §10), so an interval is judged at its upper end.
fixel::Rational parse_pusher_mu(const std::string& text) {
  const auto mu = fixel::parse_rational_list(text, "--pusher-mu");
  if (mu.size() > 2) throw fixel::InputError("--pusher-mu", text, "must be M or lo,hi");
  if (mu.size() == 2 && mu[1] < mu[0]) throw fixel::InputError("--pusher-mu", text, "has lo > hi");
  if (mu[0] < 0) throw fixel::InputError("--pusher-mu", text, "must be >= 0");
  return mu.back();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fixel: exact one-push part seating against a fixture (Egan, Berard & Trinkle)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("fixel 0.1.0"));

  std::string scene_path, impulse_text, off_dir, length_text = "1";
  bool json_out = false;

  auto* seat = app.add_subcommand("seat", "The seating impulse set S (paper §3): apex, rays and facets");
  seat->add_option("scene", scene_path, "Scene file (JSON, docs/formats.md)")->required();
  seat->add_flag("--json", json_out, "Print one JSON document on stdout");
  seat->add_option("--impulse", impulse_text, "Test an impulse: px,py[,ptheta] (exact numbers)");
  bool guaranteed = false, stable = false;
  std::string seat_svg;
  seat->add_flag("--guaranteed", guaranteed, "Also compute G, the impulses whose every outcome seats");
  seat->add_flag("--stable", stable, "Also give the seat-and-stay set S ∩ h·C_stab");
  seat->add_option("--svg", seat_svg, "With --guaranteed: draw the slice p_theta = const of S and G");
  bool sustained = false;
  std::string wrench_text;
  seat->add_flag("--sustained", sustained,
                 "The sustained-push wrench set J at the seated pose q* instead of S (past the paper)");
  seat->add_option("--wrench", wrench_text, "With --sustained: test a world-frame wrench wx,wy,wm (exact numbers)");

  auto* dump = app.add_subcommand("dump", "Write S as an OFF file, clipped to a stated box");
  dump->add_option("scene", scene_path, "Scene file (JSON, docs/formats.md)")->required();
  dump->add_option("--off", off_dir, "Output directory")->required();
  dump->add_option("--length", length_text, "Box holds apex + LENGTH * r for every ray r (default 1)");
  dump->add_flag("--guaranteed", guaranteed, "Also write the pieces of the guaranteed set G");
  dump->add_flag("--sustained", sustained, "Also write the cones of the sustained-push set J (clipped, display)");

  int steps = 1;
  auto* simulate = app.add_subcommand("simulate", "Time-step the part under an impulse with the exact LCP solver");
  simulate->add_option("scene", scene_path, "Scene file (JSON, docs/formats.md)")->required();
  simulate->add_option("--impulse", impulse_text, "External impulse of step 1: px,py[,ptheta]")->required();
  simulate->add_option("--steps", steps, "Number of steps (default 1); later steps get no impulse");
  simulate->add_flag("--json", json_out, "Print one JSON document on stdout");
  double max_seconds = 0;
  bool quiet = false;
  auto add_run_options = [&](CLI::App* cmd) {
    cmd->add_option("--max-seconds", max_seconds, "Stop with exit 4 after this many seconds (default: no limit)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--quiet", quiet, "No progress line on stderr (shown on a terminal after 1 s)");
  };
  add_run_options(simulate);

  auto* solutions = app.add_subcommand("solutions", "Every outcome of one step (all LCP solutions, by contact mode)");
  solutions->add_option("scene", scene_path, "Scene file (JSON, docs/formats.md)")->required();
  solutions->add_option("--impulse", impulse_text, "External impulse: px,py[,ptheta]")->required();
  solutions->add_flag("--json", json_out, "Print one JSON document on stdout");
  add_run_options(solutions);

  std::string resolution_text = "1/1024", cone_text = "tight", pusher_mu_text, svg_path, push_text = "step";
  auto* region = app.add_subcommand("region", "The pushing region by exact recursive subdivision (paper §5)");
  region->add_option("scene", scene_path, "Scene file with a boundary (JSON, docs/formats.md)")->required();
  region->add_option("--resolution", resolution_text, "Stop splitting at this curve-parameter width (default 1/1024)");
  region->add_option("--cone", cone_text, "Segment cone: tight (default) or paper")
      ->check(CLI::IsMember({"tight", "paper"}));
  region->add_option("--pusher-mu", pusher_mu_text,
                     "Pusher friction M, or an interval lo,hi (judged at hi); overrides the scene's pusher.mu");
  region->add_option("--svg", svg_path, "Also draw the region to this SVG file");
  region->add_flag("--json", json_out, "Print one JSON document on stdout");
  region->add_flag("--guaranteed", guaranteed, "Classify against G instead of S (frictionless pusher only)");
  region
      ->add_option("--push", push_text,
                   "Push model: step (default; one impulse, the set S) or sustained (a held wrench, the set J)")
      ->check(CLI::IsMember({"step", "sustained"}));
  int validate = 0;
  std::string time_text = "20";
  region->add_option("--validate", validate, "Run N pushes per IN interval in Box2D (docs/physics.md)");
  region->add_option("--time", time_text, "With --validate: hold each push for T time steps h (default 20)");
  add_run_options(region);

  int points = 64;
  auto* sample = app.add_subcommand("sample", "The point-sampling baseline: N exact point tests per curve");
  sample->add_option("scene", scene_path, "Scene file with a boundary (JSON, docs/formats.md)")->required();
  sample->add_option("--points", points, "Points per curve (default 64)");
  sample->add_option("--pusher-mu", pusher_mu_text,
                     "Pusher friction M, or an interval lo,hi (judged at hi); overrides the scene's pusher.mu");
  sample->add_flag("--json", json_out, "Print one JSON document on stdout");
  sample->add_flag("--guaranteed", guaranteed, "Test against G instead of S (frictionless pusher only)");
  add_run_options(sample);

  std::string at_text, push_svg;
  auto* push = app.add_subcommand("push", "Run a constant push in the Box2D physics engine (docs/physics.md)");
  push->add_option("scene", scene_path, "Scene file with a boundary (JSON, docs/formats.md)")->required();
  auto* wrench_opt =
      push->add_option("--wrench", wrench_text, "World-frame wrench wx,wy,wm (force at the centre of mass)");
  push->add_option("--at", at_text, "Frictionless unit push at parameter U of curve K, at the seated pose: K:U")
      ->excludes(wrench_opt);
  push->add_option("--time", time_text, "Hold the wrench for T time steps h (default 20)");
  push->add_option("--svg", push_svg, "Draw the trajectory to this SVG file");
  push->add_flag("--json", json_out, "Print one JSON document on stdout");

  auto* verify = app.add_subcommand("verify", "Run the built-in verification suite (the paper's examples)");
  verify->add_flag("--json", json_out, "Print one JSON document on stdout");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitBadInput;
  }

  try {
    maybe_inject_fault();
    if (*simulate || *solutions || *region || *sample) arm_run_control(max_seconds, quiet);
    if (*verify) {
      const auto checks = fixel::run_verification();
      std::cout << (json_out ? fixel::verification_json(checks) : fixel::verification_text(checks));
      for (const auto& c : checks)
        if (!c.passed) return 1;
      return 0;
    }
    const fixel::Scene scene = fixel::load_scene(scene_path);
    if (*simulate) {
      const auto sim = fixel::simulate(scene, {fixel::parse_impulse(impulse_text, scene.body.dof)}, steps, &g_run);
      end_progress();
      std::cout << (json_out ? fixel::simulation_json(scene, sim) : fixel::simulation_text(scene, sim));
      return 0;
    }
    if (*solutions) {
      const fixel::VectorQ p = fixel::parse_impulse(impulse_text, scene.body.dof);
      const auto outcomes = fixel::enumerate_outcomes(scene, p, &g_run);
      end_progress();
      std::cout << (json_out ? fixel::outcomes_json(scene, p, outcomes) : fixel::outcomes_text(scene, p, outcomes));
      return 0;
    }
    fixel::physics::PushOptions push_options;
    push_options.time = fixel::parse_rational(time_text, "--time");
    if (push_options.time <= 0) throw fixel::InputError("--time", time_text, "must be > 0");
    if (*push) {
      if (wrench_text.empty() && at_text.empty()) throw fixel::InputError("--wrench", "missing", "or --at is required");
      fixel::physics::Wrench w;
      if (!at_text.empty()) {
        const auto at = fixel::physics::parse_curve_point(scene, at_text, "--at");
        const auto q = fixel::seated_pose(scene).approx;
        w = fixel::physics::push_wrench_at(scene, at.curve, at.u, {q[0], q[1], q[2]}, "--at");
      } else {
        w = fixel::physics::parse_wrench(wrench_text, scene.body.dof, "--wrench");
      }
      const auto r = fixel::physics::push(scene, w, push_options);
      std::cout << (json_out ? fixel::physics::push_json(scene, w, r) : fixel::physics::push_text(scene, w, r));
      if (!push_svg.empty()) {
        fixel::physics::write_push_svg(push_svg, scene, r);
        if (!json_out) std::cout << "wrote " << push_svg << "\n";
      }
      return 0;
    }
    if (*seat && sustained) {
      if (guaranteed || stable || !seat_svg.empty() || !impulse_text.empty())
        throw fixel::InputError("--sustained", "",
                                "cannot be combined with --guaranteed, --stable, --svg or --impulse");
      std::optional<fixel::VectorQ> wrench;
      if (!wrench_text.empty()) wrench = fixel::parse_impulse(wrench_text, 3, "--wrench");
      const fixel::SustainedSet J = fixel::sustained_set(scene);
      std::cout << (json_out ? fixel::sustained_json(scene, J, wrench) : fixel::sustained_text(scene, J, wrench));
      return 0;
    }
    if (!wrench_text.empty()) throw fixel::InputError("--wrench", wrench_text, "needs --sustained");
    if (*dump && sustained) {
      const fixel::SustainedSet J = fixel::sustained_set(scene);
      for (const auto& path : fixel::dump_sustained_off(scene, J, off_dir)) std::cout << "wrote " << path << "\n";
    }
    if (*region && push_text == "sustained") {
      if (guaranteed) throw fixel::InputError("--guaranteed", "", "cannot be combined with --push sustained");
      fixel::RegionOptions options;
      options.resolution = fixel::parse_rational(resolution_text, "--resolution");
      options.cone = cone_text == "paper" ? fixel::ConeMethod::kPaper : fixel::ConeMethod::kTight;
      if (!pusher_mu_text.empty()) options.pusher_mu = parse_pusher_mu(pusher_mu_text);
      options.control = &g_run;
      const fixel::SustainedSet J = fixel::sustained_set(scene);
      const auto target = fixel::sustained_target(J);
      const auto r = fixel::compute_region(scene, *target, options);
      end_progress();
      std::optional<fixel::physics::RegionValidation> v;
      if (validate != 0)  // the wrench at q*: what J judges (magnitude free)
        v = fixel::physics::validate_region(scene, r, fixel::physics::seated_push_model(scene), validate, 1,
                                            push_options);
      if (v) v->model = "sustained push: the unit wrench at q* held for T";
      if (json_out) {
        const std::string doc = fixel::region_json(scene, r, cone_text, options.resolution, r.pusher_mu);
        std::cout << (v ? fixel::physics::add_validation_json(doc, *v) : doc);
      } else {
        std::cout << fixel::region_text(scene, r, cone_text, options.resolution, r.pusher_mu);
        if (v) std::cout << fixel::physics::validation_text(r, *v);
      }
      if (!svg_path.empty()) {
        fixel::write_sustained_region_svg(svg_path, scene, J, r, cone_text, options.resolution, r.pusher_mu);
        if (!json_out) std::cout << "wrote " << svg_path << "\n";
      }
      return 0;
    }
    const fixel::SeatingSet S = fixel::seating_set(scene);
    std::optional<fixel::GuaranteedSet> G;
    if (guaranteed) G = fixel::guaranteed_set(scene, S);
    const fixel::GuaranteedSet* g = G ? &*G : nullptr;
    if (*seat) {
      std::optional<fixel::VectorQ> impulse;
      if (!impulse_text.empty()) impulse = fixel::parse_impulse(impulse_text, scene.body.dof);
      if (!seat_svg.empty() && !g) throw fixel::InputError("--svg", seat_svg, "needs --guaranteed");
      // Every input check before any output (the picture is a p_theta slice).
      if (!seat_svg.empty() && scene.body.dof != 3)
        throw fixel::InputError("--svg", seat_svg, "the S/G picture needs dof 3 (a slice at constant p_theta)");
      std::cout << (json_out ? fixel::seat_json(scene, S, impulse, g, stable)
                             : fixel::seat_text(scene, S, impulse, g, stable));
      if (!seat_svg.empty()) {
        fixel::write_guaranteed_svg(seat_svg, scene, S, *g, impulse ? (*impulse)[2] : S.apex[2], impulse);
        if (!json_out) std::cout << "wrote " << seat_svg << "\n";
      }
      return 0;
    }
    if (*region || *sample) {
      std::optional<fixel::Rational> mu;
      if (!pusher_mu_text.empty()) mu = parse_pusher_mu(pusher_mu_text);
      const fixel::Rational used_mu = mu.value_or(scene.pusher_mu_upper());
      if (*sample) {
        const auto r = fixel::sample_region(scene, S, points, mu, g, &g_run);
        end_progress();
        std::cout << (json_out ? fixel::region_json(scene, r, "sample", std::nullopt, used_mu)
                               : fixel::region_text(scene, r, "sample", std::nullopt, used_mu));
        return 0;
      }
      fixel::RegionOptions options;
      options.resolution = fixel::parse_rational(resolution_text, "--resolution");
      options.cone = cone_text == "paper" ? fixel::ConeMethod::kPaper : fixel::ConeMethod::kTight;
      options.pusher_mu = mu;
      options.guaranteed = g;
      options.control = &g_run;
      const auto r = fixel::compute_region(scene, S, options);
      end_progress();
      std::optional<fixel::physics::RegionValidation> v;
      if (validate != 0) {
        const auto model = fixel::physics::one_step_push_model(scene, S, used_mu);
        v = fixel::physics::validate_region(scene, r, model, validate, 1, push_options);
      }
      if (json_out) {
        const std::string doc = fixel::region_json(scene, r, cone_text, options.resolution, used_mu);
        std::cout << (v ? fixel::physics::add_validation_json(doc, *v) : doc);
      } else {
        std::cout << fixel::region_text(scene, r, cone_text, options.resolution, used_mu);
        if (v) std::cout << fixel::physics::validation_text(r, *v);
      }
      if (!svg_path.empty()) {
        fixel::write_region_svg(svg_path, scene, S, r, cone_text + (g ? ", against G" : ""), options.resolution,
                                used_mu);
        if (!json_out) std::cout << "wrote " << svg_path << "\n";
      }
      return 0;
    }
    if (*dump) {
      const fixel::Rational length = fixel::parse_rational(length_text, "--length");
      for (const auto& path : fixel::dump_off(scene, S, off_dir, length, g)) std::cout << "wrote " << path << "\n";
      return 0;
    }
  } catch (const fixel::StoppedError& e) {
    end_progress();
    std::cerr << "fixel: stopped: " << e.what() << "\n";
    return e.reason() == fixel::StopReason::kInterrupted ? kExitInterrupted : kExitTimeLimit;
  } catch (const fixel::InternalError& e) {
    end_progress();
    std::cerr << "fixel: internal error: " << e.what() << "\n" << kReportLine;
    return kExitBug;
  } catch (const fixel::Error& e) {
    end_progress();
    std::cerr << "fixel: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    end_progress();
    std::cerr << "fixel: internal error: " << e.what() << "\n" << kReportLine;
    return kExitBug;
  }
  return 0;
}
