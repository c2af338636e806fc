// fixel region and fixel sample: where on the boundary a push can seat.
#include <iostream>
#include <memory>
#include <optional>

#include <string>

#include "cli.h"
#include "fixel/approach.h"
#include "fixel/error.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/region_target.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"
#include "fixel/svg.h"

namespace fixel::cli {
namespace {

struct RegionArgs {
  std::vector<std::string> scene_paths;
  std::string scene_path, resolution_text = "1/1024", resolution_length_text, cone_text = "tight", pusher_mu_text,
                          svg_path, push_text = "step", time_text = "20";
  int validate = 0, digits = 0;
  bool json = false, guaranteed = false, exact = false, approach = false;
  bool resolution_given = false, cone_given = false;  // set when the option is on the command line
  EngineArgs engine;
  RunOptions run;
};

RegionOptions region_options(const RegionArgs& a) {
  RegionOptions options;
  if (a.resolution_text.find('m') != std::string::npos)
    throw InputError("--resolution", a.resolution_text,
                     "is a curve-parameter width, not a length: give a length in m with --resolution-length "
                     "(e.g. --resolution-length 1/2000 for 0.5 mm)");
  options.resolution = parse_rational(a.resolution_text, "--resolution");
  if (!a.resolution_length_text.empty()) {
    options.resolution_length = parse_rational(a.resolution_length_text, "--resolution-length");
    if (*options.resolution_length <= 0)
      throw InputError("--resolution-length", a.resolution_length_text, "must be > 0");
    if (a.exact)
      throw InputError("--resolution-length", a.resolution_length_text,
                       "cannot be combined with --exact (root isolation has no resolution)");
  }
  options.cone = a.cone_text == "paper" ? ConeMethod::kPaper : ConeMethod::kTight;
  // Root isolation uses neither: refused, not ignored (as --digits without --exact is).
  if (a.exact && a.resolution_given)
    throw InputError("--resolution", a.resolution_text,
                     "cannot be combined with --exact (root isolation has no resolution)");
  if (a.exact && a.cone_given)
    throw InputError("--cone", a.cone_text, "cannot be combined with --exact (root isolation builds no segment cones)");
  options.control = run_control();
  options.exact = a.exact;
  options.digits = a.digits;
  return options;
}

// The region text or JSON, with the Box2D validation when asked.
void print_region(const Scene& scene, const Region& r, const RegionArgs& a,
                  const std::optional<physics::RegionValidation>& v, const SeatedPose* seat = nullptr) {
  if (a.json) {
    const std::string doc = region_json(scene, r, seat);
    std::cout << (v ? physics::add_validation_json(doc, *v) : doc);
  } else {
    std::cout << region_text(scene, r);
    if (v) std::cout << physics::validation_text(r, *v);
  }
}

int run_sustained_region(const Scene& scene, const RegionArgs& a, const physics::PushOptions& push_options) {
  if (a.guaranteed) throw InputError("--guaranteed", "", "cannot be combined with --push sustained");
  RegionOptions options = region_options(a);
  if (!a.pusher_mu_text.empty()) options.pusher_mu = parse_pusher_mu(a.pusher_mu_text);
  const SustainedSet J = sustained_set(scene);
  const auto target = a.approach ? approach_target(approach_set(scene, J)) : sustained_target(J);
  const auto r = compute_region(scene, *target, options);
  end_progress();
  std::optional<physics::RegionValidation> v;
  if (a.validate != 0)  // the wrench at q*: what J judges (magnitude free)
    v = physics::validate_region(scene, r, physics::seated_push_model(scene), a.validate, 1, push_options);
  if (v) v->model = "sustained push: the unit wrench at q* held for T";
  print_region(scene, r, a, v, &J.pose);
  if (!a.json) std::cout << seat_rotation_note(J.pose);
  if (!a.svg_path.empty()) {
    write_sustained_region_svg(a.svg_path, scene, J, r);
    if (!a.json) std::cout << "wrote " << a.svg_path << "\n";
  }
  return 0;
}

int run_region(const RegionArgs& a) {
  arm_run_control(a.run);
  check_writable(a.svg_path, "--svg");
  check_not_input(a.scene_path, a.svg_path, "--svg");
  const Scene scene = read_scene(a.scene_path);
  physics::PushOptions push_options;
  push_options.time = parse_rational(a.time_text, "--time");
  push_options.control = run_control();
  apply_engine_options(a.engine, push_options);
  if (push_options.time <= 0) throw InputError("--time", a.time_text, "must be > 0");
  if (a.push_text == "sustained") return run_sustained_region(scene, a, push_options);
  if (a.approach) throw InputError("--approach", "", "needs --push sustained (J' refines the sustained-push set J)");
  if (a.exact && a.validate != 0)
    throw InputError("--validate", std::to_string(a.validate),
                     "needs the certified magnitudes of subdivision: --exact gives none for the one-step push "
                     "(use --push sustained, or drop --exact)");
  const SeatingSet S = seating_set(scene);
  std::optional<GuaranteedSet> G;
  if (a.guaranteed && !a.exact) G = guaranteed_set(scene, S, run_control());
  if (a.guaranteed && a.exact)
    throw UnsupportedError("--exact", "",  // the library's words (as Python shows them), before G is built
                           "against G is not supported: G is a union of pieces minus non-seating "
                           "sets with strict rows, and its exact region is a separate project "
                           "(docs/theory.md §12); use subdivision");
  std::optional<Rational> mu;
  if (!a.pusher_mu_text.empty()) mu = parse_pusher_mu(a.pusher_mu_text);
  RegionOptions options = region_options(a);
  options.pusher_mu = mu;
  options.guaranteed = G ? &*G : nullptr;
  const auto r = compute_region(scene, S, options);
  end_progress();
  std::optional<physics::RegionValidation> v;
  if (a.validate != 0) {
    const auto model = physics::one_step_push_model(scene, S, r.pusher_mu);
    v = physics::validate_region(scene, r, model, a.validate, 1, push_options);
  }
  print_region(scene, r, a, v);
  if (!a.svg_path.empty()) {
    write_region_svg(a.svg_path, scene, S, r, G ? &*G : nullptr);
    if (!a.json) std::cout << "wrote " << a.svg_path << "\n";
  }
  return 0;
}

struct SampleArgs {
  std::string scene_path, pusher_mu_text;
  int points = 64;
  bool json = false, guaranteed = false;
  RunOptions run;
};

int run_sample(const SampleArgs& a) {
  arm_run_control(a.run);
  const Scene scene = read_scene(a.scene_path);
  const SeatingSet S = seating_set(scene);
  std::optional<GuaranteedSet> G;
  if (a.guaranteed) G = guaranteed_set(scene, S, run_control());
  std::optional<Rational> mu;
  if (!a.pusher_mu_text.empty()) mu = parse_pusher_mu(a.pusher_mu_text);
  const auto r = sample_region(scene, S, a.points, mu, G ? &*G : nullptr, run_control());
  end_progress();
  std::cout << (a.json ? region_json(scene, r) : region_text(scene, r));
  return 0;
}

const char* const kPusherMuHelp =
    "Pusher friction M, or an interval lo,hi (judged at hi); overrides the scene's pusher.mu";

}  // namespace

Command add_region(CLI::App& app) {
  auto a = std::make_shared<RegionArgs>();
  auto* cmd = app.add_subcommand("region", "The pushing region by exact recursive subdivision (paper §5)");
  cmd->add_option("scene", a->scene_paths,
                  "Scene file(s) with a boundary (JSON, docs/formats.md); - reads standard input")
      ->required();
  auto* resolution = cmd->add_option("--resolution", a->resolution_text,
                                     "Stop splitting at this curve-parameter width (default 1/1024)");
  resolution->each([a](const std::string&) { a->resolution_given = true; });
  cmd->add_option("--resolution-length", a->resolution_length_text,
                  "Stop splitting where a stretch is certainly at most L m long (exact; per piece, docs/cli.md)")
      ->excludes(resolution);
  cmd->add_option("--cone", a->cone_text, "Segment cone: tight (default) or paper")
      ->check(CLI::IsMember({"tight", "paper"}))
      ->each([a](const std::string&) { a->cone_given = true; });
  cmd->add_option("--pusher-mu", a->pusher_mu_text, kPusherMuHelp);
  cmd->add_option("--svg", a->svg_path, "Also draw the region to this SVG file");
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout (one line per scene for several)");
  cmd->add_flag("--guaranteed", a->guaranteed, "Classify against G instead of S (frictionless pusher only)");
  cmd->add_option("--push", a->push_text,
                  "Push model: step (default; one impulse, the set S) or sustained (a held wrench, the set J)")
      ->check(CLI::IsMember({"step", "sustained"}));
  cmd->add_flag("--approach", a->approach,
                "With --push sustained: classify against the approach-aware J' (no pair holds the part on its way "
                "to the seat, docs/theory.md 10.7)");
  auto* validate = cmd->add_option("--validate", a->validate, "Run N pushes per IN interval in Box2D (docs/physics.md)")
                       ->transform(decimal_integer())
                       ->check(CLI::Validator(
                           [](std::string& text) {
                             try {
                               if (std::stol(text) >= 1) return std::string();
                             } catch (const std::exception&) {
                             }
                             return text + " must be >= 1 (a whole number of pushes per IN interval)";
                           },
                           "N >= 1"));
  // The contract's grammar nests these: [--validate N [--time T]], [--exact [--digits D]].
  cmd->add_option("--time", a->time_text, "With --validate: hold each push for T time steps h (default 20)")
      ->needs(validate);
  add_engine_options(cmd, a->engine, validate);
  auto* exact =
      cmd->add_flag("--exact", a->exact,
                    "Exact ends by root isolation instead of subdivision: no partial stretch (docs/theory.md §12)");
  cmd->add_option("--digits", a->digits, "With --exact: refine irrational ends to width 10^-D (default 0: as isolated)")
      ->transform(decimal_integer())
      ->needs(exact);
  add_run_options(cmd, a->run);
  return {cmd, [a] {
            if (a->scene_paths.size() > 1 && !a->svg_path.empty())
              throw InputError("--svg", a->svg_path, "draws one scene: give a single scene file");
            return run_batch(a->scene_paths, a->json, [a](const std::string& p) {
              a->scene_path = p;
              return run_region(*a);
            });
          }};
}

Command add_sample(CLI::App& app) {
  auto a = std::make_shared<SampleArgs>();
  auto* cmd = app.add_subcommand("sample", "The point-sampling baseline: N exact point tests per curve");
  cmd->add_option("scene", a->scene_path, "Scene file with a boundary (JSON, docs/formats.md); - reads standard input")
      ->required();
  cmd->add_option("--points", a->points, "Points per curve (default 64)")->transform(decimal_integer());
  cmd->add_option("--pusher-mu", a->pusher_mu_text, kPusherMuHelp);
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout");
  cmd->add_flag("--guaranteed", a->guaranteed, "Test against G instead of S (frictionless pusher only)");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_sample(*a); }};
}

}  // namespace fixel::cli
